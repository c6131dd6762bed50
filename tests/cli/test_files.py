#!/usr/bin/env python3
"""Hostile files around ncc's inputs and outputs (issue 31, "every run bounded, no file
clobbered"): a --vars file that is a device, a FIFO or huge; outputs that are devices, FIFOs,
symbolic links or the --vars file; inputs whose read fails; run limits that are no limits.

Every ncc call has a timeout: a command that waits on a FIFO fails the test instead of
hanging it. Tests that write to /dev/null or /dev/full first try the same command on a private character
device with the same numbers in the scratch folder when the test runs as root, so that an ncc
that replaces devices fails there and never gets to replace the machine's own.

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
    # Not under AddressSanitizer, which reserves terabytes of address space for its shadow
    # memory at start (the timeout still ends a reader there).
    if os.environ.get("NCC_TEST_SANITIZED") != "1":
        resource.setrlimit(resource.RLIMIT_AS, (2 << 30, 2 << 30))


def is_char_device(path):
    return stat.S_ISCHR(os.stat(path).st_mode)


class FilesTest(ScratchDirTest):
    def assertDriverError(self, proc, code):
        self.assertEqual(proc.returncode, 2, proc.stderr)
        self.assertIn(f"ncc: error[{code}]: ", proc.stderr)

    def private_device(self, device):
        """A character device with the numbers of `device` in the scratch folder; None when it
        cannot be made (not root)."""
        path = self.path("private-" + os.path.basename(device))
        try:
            os.mknod(path, 0o666 | stat.S_IFCHR, os.stat(device).st_rdev)
        except OSError:
            return None
        return path

    def run_on_device(self, device, make_args, check):
        """Runs ncc with the args `make_args(path)` gives, on a private copy of the character
        device `device` first, then on `device` itself; `check(proc)` judges each run. The
        device stays a character device."""
        private = self.private_device(device)
        if private is not None:
            proc = ncc(*make_args(private))
            self.assertTrue(is_char_device(private),
                            f"ncc replaced a character device (not trying {device})")
            check(proc)
        if not is_char_device(device):  # not this ncc's doing: it is checked after each run
            self.skipTest(f"{device} is no character device on this machine")
        proc = ncc(*make_args(device))
        self.assertTrue(is_char_device(device), f"ncc replaced {device}")
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


# ---- 2. outputs: devices and FIFOs as streams, links written through, one file one output ------

class OutputTest(FilesTest):
    def test_dev_null_stays_a_device(self):
        good = self.write("a.nc", GOOD)

        def succeeds(proc):
            self.assertEqual(proc.returncode, 0, proc.stderr)

        for args in (["run", good, "--emit=moves"], ["run", good, "--emit=trace"],
                     ["compile", good], ["compile", good, "--emit=ir"], ["plot", good]):
            self.run_on_device("/dev/null", lambda device: [*args, "-o", device], succeeds)
        self.assertEqual(self.leftovers(), [])

    def test_full_device_is_a_write_error(self):
        if not os.path.exists("/dev/full"):
            self.skipTest("no /dev/full")
        good = self.write("a.nc", GOOD)

        def write_error(proc):
            self.assertDriverError(proc, "NCC0004")

        self.run_on_device("/dev/full", lambda device: ["run", good, "--emit=moves", "-o", device],
                           write_error)

    def read_fifo(self, fifo, args):
        """Runs ncc with `-o fifo` while a thread reads the FIFO; returns (proc, bytes read)."""
        got = []

        def reader():
            with open(fifo, "rb") as f:  # waits for ncc to open it for writing
                got.append(f.read())

        thread = threading.Thread(target=reader, daemon=True)
        thread.start()
        proc = ncc(*args, "-o", fifo)
        thread.join(10)
        if thread.is_alive() and stat.S_ISFIFO(os.stat(fifo).st_mode):
            os.close(os.open(fifo, os.O_WRONLY | os.O_NONBLOCK))  # let the reader go
            thread.join(10)
        self.assertTrue(stat.S_ISFIFO(os.stat(fifo).st_mode), "the FIFO was replaced")
        self.assertEqual(len(got), 1, "the reader got nothing")
        return proc, got[0]

    def test_fifo_gets_the_bytes_and_stays_a_fifo(self):
        good = self.write("a.nc", GOOD)
        fifo = self.path("out.fifo")
        os.mkfifo(fifo)
        for args in (["run", good, "--emit=moves"], ["compile", good]):
            expected = subprocess.run([NCC, *args, "-o", "-"], capture_output=True,
                                      timeout=TIMEOUT).stdout
            self.assertTrue(expected)
            proc, data = self.read_fifo(fifo, args)
            self.assertEqual(proc.returncode, 0, proc.stderr)
            self.assertEqual(data, expected, args)  # bytecode too: buffered, then written whole
        self.assertEqual(self.leftovers(), [])

    def test_symbolic_link_is_written_through(self):
        good = self.write("a.nc", GOOD)
        expected = ncc("run", good, "--emit=moves").stdout
        os.mkdir(self.path("out"))
        target = self.write("out/moves.jsonl", "old\n")
        os.chmod(target, 0o640)
        link = self.path("link")
        os.symlink("out/moves.jsonl", link)  # relative to the link's folder
        proc = ncc("run", good, "--emit=moves", "-o", link)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertTrue(os.path.islink(link))
        self.assertEqual(os.readlink(link), "out/moves.jsonl")
        with open(target) as f:
            self.assertEqual(f.read(), expected)
        self.assertEqual(stat.S_IMODE(os.stat(target).st_mode), 0o640)  # the target's own mode
        self.assertEqual(self.leftovers(), [])
        self.assertEqual(sorted(os.listdir(self.path("out"))), ["moves.jsonl"])

    def test_dangling_link_creates_its_target(self):
        good = self.write("a.nc", GOOD)
        link = self.path("a.ncb")
        os.symlink("built.ncb", link)
        proc = ncc("compile", good, "-o", link)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertTrue(os.path.islink(link))
        with open(self.path("built.ncb"), "rb") as f:
            self.assertEqual(f.read(4), b"NCCB")

    def test_failed_compile_leaves_a_linked_target_as_it_was(self):
        bad = self.write("bad.nc", BAD)
        target = self.write("kept.ncb", "kept")
        link = self.path("link.ncb")
        os.symlink(target, link)
        proc = ncc("compile", bad, "-o", link)
        self.assertEqual(proc.returncode, 1)
        self.assertTrue(os.path.islink(link))
        with open(target) as f:
            self.assertEqual(f.read(), "kept")
        self.assertEqual(self.leftovers(), [])

    def test_output_naming_the_vars_file_is_refused(self):
        good = self.write("a.nc", GOOD)
        vars_path = self.path("v.toml")
        for command in ("run", "compile", "plot"):
            proc = ncc(command, good, "--vars", vars_path, "-o", vars_path)
            self.assertDriverError(proc, "NCC0005")
            self.assertIn("variables file", proc.stderr)
            self.assertFalse(os.path.exists(vars_path), command)  # nothing written
        # Another spelling, and a link to the file once it exists.
        proc = ncc("run", good, "--vars", vars_path, "-o", os.path.join(self.dir, ".", "v.toml"))
        self.assertDriverError(proc, "NCC0005")
        self.assertFalse(os.path.exists(vars_path))
        self.write("v.toml", '"#500" = 7.0\n')
        os.symlink("v.toml", self.path("vlink"))
        proc = ncc("run", good, "--vars", vars_path, "-o", self.path("vlink"))
        self.assertDriverError(proc, "NCC0005")
        with open(vars_path) as f:
            self.assertEqual(f.read(), '"#500" = 7.0\n')

    def test_output_naming_an_input_is_still_refused(self):
        good = self.write("a.nc", GOOD)
        os.symlink("a.nc", self.path("alias.nc"))
        for args in (["compile", good, "-o", good], ["run", good, "-o", self.path("alias.nc")]):
            proc = ncc(*args)
            self.assertDriverError(proc, "NCC0005")
        with open(good) as f:
            self.assertEqual(f.read(), GOOD)
        trace = self.path("t.nct")
        self.assertEqual(ncc("run", good, "--emit=trace", "-o", trace).returncode, 0)
        size = os.path.getsize(trace)
        proc = ncc("trace", trace, "-o", trace)
        self.assertDriverError(proc, "NCC0005")
        self.assertEqual(os.path.getsize(trace), size)

    def test_vars_written_back_through_a_link(self):
        good = self.write("a.nc", GOOD)
        self.write("state.toml", '"#500" = 41.0\n')
        link = self.path("vars.toml")
        os.symlink("state.toml", link)
        proc = ncc("run", good, "--vars", link)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertTrue(os.path.islink(link))
        with open(self.path("state.toml")) as f:
            self.assertIn('"#500" = 42.0', f.read())

    def test_vars_on_dev_null_is_refused_and_not_replaced(self):
        good = self.write("a.nc", GOOD)

        def refused(proc):
            self.assertDriverError(proc, "NCC0019")

        self.run_on_device("/dev/null", lambda device: ["run", good, "--vars", device], refused)


# ---- 3. inputs whose read fails are NCC0001, not an empty program --------------------------------

class InputReadTest(FilesTest):
    def test_proc_self_mem_is_unreadable(self):
        # A "regular file" that opens but whose read fails (EIO at offset 0).
        out = self.path("out")
        for args in (["run", "/proc/self/mem"], ["check", "/proc/self/mem"],
                     ["compile", "/proc/self/mem", "-o", out], ["plot", "/proc/self/mem", "-o", out],
                     ["run", "/proc/self/mem", "--defer", "-o", out]):
            proc = ncc(*args)
            self.assertDriverError(proc, "NCC0001")
            self.assertIn("cannot read '/proc/self/mem'", proc.stderr)
            self.assertNotIn("status", proc.stdout)  # nothing ran
            self.assertFalse(os.path.exists(out), args)
        self.assertEqual(self.leftovers(), [])

    def test_subprogram_whose_read_fails(self):
        main = self.write("main.nc", "G90 G00 X1.\nM98 P1234\nM30\n")
        os.symlink("/proc/self/mem", self.path("O1234.nc"))
        out = self.path("main.ncb")
        for args in (["run", main], ["compile", main, "-o", out], ["compile", main, "--defer", "-o", out]):
            proc = ncc(*args)
            self.assertDriverError(proc, "NCC0001")
            self.assertIn("O1234.nc", proc.stderr)
            self.assertFalse(os.path.exists(out), args)

    def test_folder_on_stdin_is_unreadable(self):
        fd = os.open(self.dir, os.O_RDONLY)
        try:
            for command in ("run", "check"):
                os.lseek(fd, 0, os.SEEK_SET)
                proc = ncc(command, "-", stdin=fd)
                self.assertDriverError(proc, "NCC0001")
                self.assertIn("standard input", proc.stderr)
                self.assertNotIn("status", proc.stdout)
        finally:
            os.close(fd)

    def test_folder_as_input_is_unreadable(self):
        proc = ncc("run", self.dir)
        self.assertDriverError(proc, "NCC0001")


# ---- 4. run limits are limits ---------------------------------------------------------------

class RunLimitTest(FilesTest):
    def test_bad_limits_are_usage_errors(self):
        good = self.write("a.nc", GOOD)
        for command in ("run", "plot"):
            for option, value in (("--max-time", "nan"), ("--max-time", "-nan"),
                                  ("--max-time", "-1"), ("--max-time", "inf"),
                                  ("--max-time", "1e13"), ("--max-steps", "-1"),
                                  ("--max-steps", " -5")):
                proc = ncc(command, good, option, value, "-o", self.path("out"))
                self.assertDriverError(proc, "NCC0010")
                self.assertIn(option, proc.stderr)
                self.assertFalse(os.path.exists(self.path("out")), (command, option, value))
            proc = ncc(command, good, "--max-time=nan")
            self.assertDriverError(proc, "NCC0010")
            self.assertIn("finite number from 0 (no limit)", proc.stderr)
            proc = ncc(command, good, "--max-steps=-1")
            self.assertDriverError(proc, "NCC0010")
            self.assertIn("negative", proc.stderr)

    def test_good_limits_still_run(self):
        good = self.write("a.nc", GOOD)
        for args in (["--max-time", "0", "--max-steps", "0"], ["--max-time", "3600.5"],
                     ["--max-steps", "1000000"], ["--max-time", "1e12"]):
            for command in ("run", "plot"):
                proc = ncc(command, good, *args, "-o", self.path("out"))
                self.assertEqual(proc.returncode, 0, (command, args, proc.stderr))
        proc = ncc("run", good, "--max-steps", "2")
        self.assertEqual(proc.returncode, 3)
        self.assertIn("NCC7204", proc.stderr)


if __name__ == "__main__":
    NCC = os.path.abspath(sys.argv.pop(1))
    unittest.main()
