#!/usr/bin/env python3
"""Canned hole cycles from the command line (docs/cycles.md): `ncc run` gives the cycle's
moves, the same with --defer (the VM prepares the blocks with the same lowering and passes),
`--print-after=lower` shows the holes as data, and a bad cycle block is the dialect's alarm at
its line and column with no output file written.

Run by ctest as: test_cycles.py NCC_BINARY
"""
import os
import subprocess
import sys
import unittest

sys.dont_write_bytecode = True

from cli_harness import ScratchDirTest, move_list as moves  # noqa: E402

NCC = None


def ncc(*args, cwd=None):
    return subprocess.run([NCC, *args], capture_output=True, text=True, cwd=cwd, timeout=120)


# G83 peck drilling, G99, K2 in G91: two holes, pecks of 4 with d = 1 mm (peck_clearance).
PECK = "G90 G00 Z20.\nG99 G91 G83 X10. R-18. Z-10. Q4. F100. K2\nG80\nM30\n"


class CycleCli(ScratchDirTest):
    def test_run_gives_the_peck_sequence(self):
        prog = self.write("peck.nc", PECK)
        proc = ncc("run", prog, "--emit=moves")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        got = [(m["kind"], m["to"]["X"], m["to"]["Z"]) for m in moves(proc.stdout)]
        # R = 20 - 18 = 2, bottom = 2 - 10 = -8: feed -2, rapid 2, rapid -1, feed -6, rapid 2,
        # rapid -5, feed -8, rapid 2 (G99); the second hole 10 further in X.
        hole = lambda x: [("line", x, -2.0), ("rapid", x, 2.0), ("rapid", x, -1.0), ("line", x, -6.0),
                          ("rapid", x, 2.0), ("rapid", x, -5.0), ("line", x, -8.0), ("rapid", x, 2.0)]
        expected = ([("rapid", 0.0, 20.0), ("rapid", 10.0, 20.0), ("rapid", 10.0, 2.0)] + hole(10.0) +
                    [("rapid", 20.0, 2.0)] + hole(20.0))
        self.assertEqual(got, expected)

    def test_deferred_run_gives_the_same_moves(self):
        prog = self.write("peck.nc", PECK)
        plain = ncc("run", prog, "--emit=moves")
        deferred = ncc("run", "--defer", prog, "--emit=moves")
        self.assertEqual(plain.returncode, 0, plain.stderr)
        self.assertEqual(deferred.returncode, 0, deferred.stderr)
        self.assertEqual(plain.stdout, deferred.stdout)

    def test_print_after_lower_shows_the_holes(self):
        prog = self.write("peck.nc", PECK)
        proc = ncc("compile", prog, "--emit=ir", "--print-after=lower", "-o", self.path("out.ir"))
        self.assertEqual(proc.returncode, 0, proc.stderr)
        text = proc.stdout
        if os.path.exists(self.path("out.ir")):
            with open(self.path("out.ir")) as f:
                text += f.read()
        self.assertEqual(text.count("cycle G83 peck"), 2, text)

    def test_bad_cycle_is_the_alarm_and_writes_nothing(self):
        for dialect, text, where in [
                ("mazak-m", "G90 G00 Z50.\nG98 G73 X10. Y10. Z-20. R2. Q0 F100\nM30\n", ("2", "29", "809")),
                ("siemens-iso-m", "M3 S100\nG00 Z10.\nG83 X1. R2. Z-5. F100.\nM30\n", ("3", "1", "61808")),
                ("fanuc-m", "G00 Z10.\nG81 X1. R2. F100.\nM30\n", ("2", "1", "NCC2096"))]:
            with self.subTest(dialect=dialect):
                prog = self.write("bad.nc", text)
                out = self.path("bad.ncb")
                proc = ncc("compile", prog, "--dialect", dialect, "-o", out)
                self.assertEqual(proc.returncode, 1, proc.stderr)
                line, col, code = where
                self.assertIn(f"bad.nc:{line}:{col}: error[{code}]", proc.stderr)
                self.assertFalse(os.path.exists(out))


if __name__ == "__main__":
    NCC = sys.argv.pop(1)
    unittest.main()
