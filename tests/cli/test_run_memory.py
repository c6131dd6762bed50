#!/usr/bin/env python3
"""`ncc run` streams: its peak memory does not grow with the program's length (issue 21).

The code and line table of a run stay in a file (the .ncb, or for a source an anonymous
scratch file in $TMPDIR) and are read through a bounded window. Each run's maximum resident
set size is measured in a fresh Python process (getrusage(RUSAGE_CHILDREN) sees only that
one child). A 200,000-block program holds about 10 MB of code and line table (50 bytes a
block), so a copy of it in memory would exceed the bound by far.

Run by ctest as: test_run_memory.py NCC_BINARY
"""
import os
import subprocess
import sys
import tempfile
import time
import unittest

NCC = None

SMALL, LARGE = 20_000, 200_000
# Bytes of RSS the large run may take beyond the small one: well under the ~10 MB its code
# and line table would take in memory (and the 20 MB more the run took before it streamed).
BOUND_KB = 3 * 1024

MEASURE = """
import resource, subprocess, sys
proc = subprocess.run(sys.argv[1:], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
if proc.returncode != 0:
    sys.stderr.write(proc.stderr.decode())
    sys.exit(100 + proc.returncode)
print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)
"""


def peak_kb(*args, env=None):
    """Maximum resident set size of `ncc *args`, in KiB."""
    proc = subprocess.run([sys.executable, "-c", MEASURE, NCC, *args], capture_output=True,
                          text=True, timeout=600, env=env)
    if proc.returncode != 0:
        raise AssertionError(f"ncc {' '.join(args)} failed: {proc.stderr}")
    return int(proc.stdout)


def write_program(path, blocks):
    # Moves of a micrometre at a high feed: each block takes less than one IPO tick, so the run
    # is quick while its code grows like any program's.
    with open(path, "w") as f:
        f.write("G90 G01 F6000.\n")
        for i in range(blocks):
            f.write(f"X{(i % 2) * 0.001:.3f} Y{(i % 3) * 0.001:.3f}\n")
        f.write("M30\n")


@unittest.skipIf(os.environ.get("NCC_TEST_SANITIZED"),
                 "RSS under AddressSanitizer measures its shadow memory; the release stage measures ncc")
class RunMemoryTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.dir = cls.tmp.name
        cls.scratch = os.path.join(cls.dir, "scratch")
        os.mkdir(cls.scratch)
        # Under AddressSanitizer (CI's instrumented build) freed blocks wait in a quarantine of
        # up to 256 MB before reuse, so the peak grows with the number of allocations, not with
        # what is live: no quarantine here, so the test measures the program, not the tool.
        # (The option means nothing to an uninstrumented ncc.)
        asan = os.environ.get("ASAN_OPTIONS", "")
        asan = (asan + ":" if asan else "") + "quarantine_size_mb=0:thread_local_quarantine_size_kb=0"
        cls.env = dict(os.environ, TMPDIR=cls.scratch, ASAN_OPTIONS=asan)
        cls.source = {}
        cls.bytecode = {}
        for n in (SMALL, LARGE):
            cls.source[n] = os.path.join(cls.dir, f"p{n}.nc")
            write_program(cls.source[n], n)
            cls.bytecode[n] = os.path.join(cls.dir, f"p{n}.ncb")
            proc = subprocess.run([NCC, "compile", cls.source[n], "-o", cls.bytecode[n]],
                                  capture_output=True, text=True, timeout=600)
            assert proc.returncode == 0, proc.stderr

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def assertFlat(self, emit, inputs):
        small = peak_kb("run", inputs[SMALL], f"--emit={emit}", env=self.env)
        large = peak_kb("run", inputs[LARGE], f"--emit={emit}", env=self.env)
        self.assertLess(large - small, BOUND_KB,
                        f"--emit={emit}: {SMALL} blocks peak at {small} KiB, "
                        f"{LARGE} blocks at {large} KiB")

    def test_source_summary_is_flat(self):
        self.assertFlat("summary", self.source)

    def test_source_moves_are_flat(self):
        self.assertFlat("moves", self.source)

    def test_bytecode_summary_is_flat(self):
        self.assertFlat("summary", self.bytecode)

    def test_bytecode_moves_are_flat(self):
        self.assertFlat("moves", self.bytecode)

    def test_scratch_file_is_gone_after_the_run(self):
        proc = subprocess.run([NCC, "run", self.source[SMALL]], capture_output=True, text=True,
                              timeout=600, env=self.env)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual(os.listdir(self.scratch), [])

    def test_scratch_file_is_gone_after_a_compile_error(self):
        bad = os.path.join(self.dir, "bad.nc")
        with open(bad, "w") as f:
            f.write("G01 X1. F100.\nG01 X2. Q@\nM30\n")
        proc = subprocess.run([NCC, "run", bad], capture_output=True, text=True, timeout=60,
                              env=self.env)
        self.assertEqual(proc.returncode, 1, proc.stderr)
        self.assertEqual(os.listdir(self.scratch), [])

    def test_scratch_file_is_never_visible_even_on_sigkill(self):
        # The scratch file is unlinked as soon as it is made: neither during the run nor after
        # a SIGKILL (which no handler can clean up after) is there anything in $TMPDIR.
        proc = subprocess.Popen([NCC, "run", self.source[LARGE], "--emit=moves"],
                                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                                env=self.env)
        try:
            for _ in range(20):
                time.sleep(0.05)
                self.assertEqual(os.listdir(self.scratch), [])
        finally:
            proc.kill()
            proc.wait()
        self.assertEqual(os.listdir(self.scratch), [])

    def test_unusable_tmpdir_is_a_precise_error(self):
        env = dict(os.environ, TMPDIR=os.path.join(self.dir, "no-such-folder"))
        proc = subprocess.run([NCC, "run", self.source[SMALL]], capture_output=True, text=True,
                              timeout=60, env=env)
        self.assertEqual(proc.returncode, 2, proc.stderr)
        self.assertIn("ncc: error[NCC0004]", proc.stderr)
        self.assertIn("no-such-folder", proc.stderr)

    def test_source_and_bytecode_runs_agree(self):
        outputs = []
        for path in (self.source[SMALL], self.bytecode[SMALL]):
            proc = subprocess.run([NCC, "run", path, "--emit=moves"], capture_output=True,
                                  text=True, timeout=600, env=self.env)
            self.assertEqual(proc.returncode, 0, proc.stderr)
            outputs.append(proc.stdout)
        self.assertEqual(outputs[0], outputs[1])


if __name__ == "__main__":
    NCC = sys.argv.pop(1)
    unittest.main()
