#!/usr/bin/env python3
"""Hostile files around ncc's inputs and outputs (issue 31, "every run bounded, no file
clobbered"): a --vars file that is a device, a FIFO or huge; outputs that are devices, FIFOs,
symbolic links or the --vars file; inputs whose read fails; run limits that are no limits.

Every ncc call has a timeout: a command that waits on a FIFO fails the test instead of
hanging it. Tests that write to /dev/null first try the same command on a private character
device (1,3) in the scratch folder when the test runs as root, so that an ncc that replaces
devices fails there and never gets to replace the machine's /dev/null.

Run by ctest as: test_files.py NCC_BINARY
"""
import os
import resource
import stat
import subprocess
import sys
import threading
import unittest

from cli_harness import ScratchDirTest

NCC = None

# Moves, and a persistent common variable for --vars to write back.
GOOD = "G90 G00 X10. Y5.\n#500=#500+1\nG01 X20. F500.\nM30\n"
BAD = "G90 G00 X10.\nG01 X20. Q@\nM30\n"
TIMEOUT = 30  # s; any command here takes well under a second


def ncc(*args, timeout=TIMEOUT, stdin=None, preexec_fn=None, cwd=None):
    try:
        return subprocess.run([NCC, *args], capture_output=True, text=True, timeout=timeout,
                              stdin=stdin, preexec_fn=preexec_fn, cwd=cwd)
    except subprocess.TimeoutExpired:
        raise AssertionError(f"ncc {' '.join(args)} did not end within {timeout} s") from None


def limit_memory():
    # An ncc that reads /dev/zero whole would take the machine's memory before the timeout.
    resource.setrlimit(resource.RLIMIT_AS, (2 << 30, 2 << 30))


def is_char_device(path):
    return stat.S_ISCHR(os.stat(path).st_mode)


class FilesTest(ScratchDirTest):
    def assertDriverError(self, proc, code):
        self.assertEqual(proc.returncode, 2, proc.stderr)
        self.assertIn(f"ncc: error[{code}]: ", proc.stderr)

    def private_null(self):
        """A character device (1,3), the null device, in the scratch folder; None when it cannot
        be made (not root)."""
        path = self.path("null")
        try:
            os.mknod(path, 0o666 | stat.S_IFCHR, os.makedev(1, 3))
        except (PermissionError, OSError):
            return None
        return path

    def run_on_null(self, make_args, check):
        """Runs ncc with the args `make_args(device)` gives, on a private null device first, then
        on /dev/null; `check(proc)` judges each run. /dev/null stays a character device."""
        private = self.private_null()
        if private is not None:
            proc = ncc(*make_args(private))
            self.assertTrue(is_char_device(private),
                            "ncc replaced a character device (not trying /dev/null)")
            check(proc)
        proc = ncc(*make_args("/dev/null"))
        self.assertTrue(is_char_device("/dev/null"))
        check(proc)

    def leftovers(self):
        return sorted(n for n in os.listdir(self.dir) if n.startswith("."))


# ---- 1. --vars: a regular file of bounded size, or none yet ------------------------------------

class VarsFileTest(FilesTest):
    def test_dev_zero_is_refused(self):
        good = self.write("a.nc", GOOD)
        out = ["-o", self.path("a.out")]
        for args in (["run", *out], ["compile", *out], ["check"], ["plot", *out]):
            proc = ncc(*args, good, "--vars", "/dev/zero", preexec_fn=limit_memory)
            self.assertDriverError(proc, "NCC0019")
            self.assertIn("'/dev/zero': not a regular file", proc.stderr)
            self.assertFalse(os.path.exists(self.path("a.out")))

    def test_fifo_is_refused_without_waiting(self):
        good = self.write("a.nc", GOOD)
        fifo = self.path("vars.toml")
        os.mkfifo(fifo)
        proc = ncc("run", good, "--vars", fifo, timeout=10)
        self.assertDriverError(proc, "NCC0019")
        self.assertIn("not a regular file", proc.stderr)
        self.assertTrue(stat.S_ISFIFO(os.stat(fifo).st_mode))

    def test_folder_is_refused(self):
        good = self.write("a.nc", GOOD)
        os.mkdir(self.path("vars"))
        proc = ncc("run", good, "--vars", self.path("vars"))
        self.assertDriverError(proc, "NCC0019")

    def test_oversize_file_is_refused(self):
        good = self.write("a.nc", GOOD)
        big = self.path("big.toml")
        with open(big, "wb") as f:  # sparse: 16 MiB and one byte, no disk space
            f.truncate((16 << 20) + 1)
        proc = ncc("run", good, "--vars", big)
        self.assertDriverError(proc, "NCC0019")
        self.assertIn("larger than 16 MiB", proc.stderr)
        self.assertEqual(os.path.getsize(big), (16 << 20) + 1)  # not written back either

    def test_missing_file_is_still_created(self):
        good = self.write("a.nc", GOOD)
        vars_path = self.path("vars.toml")
        proc = ncc("run", good, "--vars", vars_path)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        with open(vars_path) as f:
            self.assertIn('"#500" = 1.0', f.read())
        proc = ncc("run", good, "--vars", vars_path)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        with open(vars_path) as f:
            self.assertIn('"#500" = 2.0', f.read())


if __name__ == "__main__":
    NCC = os.path.abspath(sys.argv.pop(1))
    unittest.main()
