#!/usr/bin/env python3
"""`,C` / `,R` corners and Mazak G45-G48 from the command line (docs/semantics.md "Corner
chamfer and rounding"): the inserted moves, the same moves with --defer and when the corner
block is the last one prepared ahead of a block the VM prepares (after a G31), alarms that
write nothing, and the request shown by --print-after=lower.

Run by ctest as: test_corners.py NCC_BINARY
"""
import json
import os
import subprocess
import sys
import unittest

from cli_harness import ScratchDirTest

NCC = None

SQUARE = "G90 G01 X50. F100. ,R10.\nY50. ,C5.\nX0\nM30\n"
# FANUC #5063: where the G31 stopped on Z. Block 3 needs it, so it is prepared by the VM while
# the compiler has prepared block 2, the corner block, ahead: the VM inserts the chamfer.
AFTER_SKIP = "G90 G31 Z-10. F100.\nG01 X50. Y0 Z0 F100. ,C5.\nY[#5063+50.]\nM30\n"


def ncc(*args, cwd=None):
    return subprocess.run([NCC, *map(str, args)], capture_output=True, text=True, timeout=60, cwd=cwd)


def moves(stdout):
    return [json.loads(line) for line in stdout.splitlines()]


class CornersTest(ScratchDirTest):
    def run_both(self, text, *extra):
        prog = self.write("part.nc", text)
        plain = ncc("run", prog, "--emit=moves", *extra)
        late = ncc("run", "--defer", prog, "--emit=moves", *extra)
        self.assertEqual(plain.returncode, 0, plain.stderr)
        self.assertEqual((late.returncode, late.stdout), (0, plain.stdout), late.stderr)
        return moves(plain.stdout)

    def test_rounding_and_chamfer_both_ways(self):
        got = self.run_both(SQUARE)
        self.assertEqual([m["kind"] for m in got], ["line", "arc", "line", "line", "line"])
        self.assertAlmostEqual(got[0]["to"]["X"], 40.0)
        self.assertAlmostEqual(got[1]["to"]["Y"], 10.0)
        self.assertAlmostEqual(got[2]["to"]["Y"], 45.0)
        self.assertAlmostEqual(got[3]["to"]["X"], 45.0)
        self.assertAlmostEqual(got[3]["to"]["Y"], 50.0)

    def test_corner_block_prepared_ahead_of_a_run_time_block(self):
        got = self.run_both(AFTER_SKIP, "--probe", "Z=-20.")  # never reached: G31 ends at Z-10
        kinds = [m["kind"] for m in got]
        self.assertEqual(kinds[-3:], ["line", "line", "line"], got)
        self.assertAlmostEqual(got[-3]["to"]["X"], 45.0)
        self.assertAlmostEqual(got[-2]["to"]["X"], 50.0)
        self.assertAlmostEqual(got[-2]["to"]["Y"], 5.0)
        self.assertAlmostEqual(got[-1]["to"]["Y"], 40.0)

    def test_alarm_writes_nothing(self):
        prog = self.write("bad.nc", "G91 G01 X5.,C10. F100\nX100. Y100.\nM30\n")
        out = self.path("bad.ncb")
        proc = ncc("compile", prog, "--dialect", "mazak-m", "-o", out)
        self.assertEqual(proc.returncode, 1, proc.stderr)
        self.assertIn("bad.nc:1:12: error[913]", proc.stderr)
        self.assertFalse(os.path.exists(out))

    def test_print_after_lower_shows_the_request(self):
        prog = self.write("part.nc", SQUARE)
        proc = ncc("compile", prog, "--emit=ir", "--print-after=lower,corners")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        lower, corners = proc.stdout.split("; after corners\n", 1)
        self.assertIn(" round(10.000)\n", lower)
        self.assertNotIn("round(", corners)  # consumed: the arc is an operation now

    def test_mazak_g45_g48(self):
        # D1 = 10: G46 X40. -> 30; G48 X30. -> 30 - 20; G45 X0 -> +10; G46 X-0 -> +10 (§12-3).
        got = self.run_both("G91 G46 G00 X40. Y40. D01\nG48 G01 X30. F200\nG45 X0\nG46 X-0\nM30\n",
                            "--dialect", "mazak-m", "--machine", self.machine())
        self.assertEqual([(round(m["to"]["X"], 3), round(m["to"]["Y"], 3)) for m in got],
                         [(30.0, 30.0), (40.0, 30.0), (50.0, 30.0), (60.0, 30.0)])

    def machine(self):
        return self.write("m.toml", '[machine]\naxes = ["X", "Y", "Z"]\n[machine.offsets]\nD1 = 10.0\n'
                                    '[machine.work]\nG54 = [0.0, 0.0, 0.0]\n')


if __name__ == "__main__":
    NCC = os.path.abspath(sys.argv.pop(1))
    unittest.main(verbosity=2)
