#!/usr/bin/env python3
"""Cutter compensation's machine parameters from the command line (docs/compensation.md):
interference_avoidance turns the interference alarm of a short move into a warning and a path
that leaves it out; without it the alarm stops the run and nothing is written.

Run by ctest as: test_compensation.py NCC_BINARY
"""
import os
import subprocess
import sys
import unittest

sys.dont_write_bytecode = True

from cli_harness import ScratchDirTest, move_list  # noqa: E402

NCC = None

# G41 r = 5 along +X, a 1 mm chamfer at 45 degrees, then up: the chamfer's offset runs backwards.
PROGRAM = "G90 G00 X0 Y-10.\nG41 D1 G01 X0 Y0 F100.\nX20.\nX21. Y1.\nY20.\nG40 X30. Y30.\nM30\n"
MACHINE = ("[machine]\naxes = [\"X\", \"Y\", \"Z\"]\n[machine.offsets]\nD1 = 5.0\n"
           "[start]\nposition = { X = 0.0, Y = 0.0, Z = 0.0 }\n")


class InterferenceAvoidance(ScratchDirTest):
    def run_with(self, params, *extra):
        prog = self.write("c.nc", PROGRAM)
        toml = self.write("m.toml", MACHINE + ("[machine.params]\n" + params if params else ""))
        return subprocess.run([NCC, "run", prog, "--dialect", "fanuc-m", "--machine", toml,
                               *extra], capture_output=True, text=True, timeout=120)

    def test_without_avoidance_the_interference_is_the_alarm_and_nothing_is_written(self):
        out = self.path("moves.jsonl")
        proc = self.run_with("", "--emit=moves", "-o", out)
        self.assertEqual(proc.returncode, 1)
        self.assertIn("c.nc:4:1: error[PS0041]: interference", proc.stderr)
        self.assertFalse(os.path.exists(out))

    def test_with_avoidance_the_neighbours_meet_and_the_short_move_is_left_out(self):
        proc = self.run_with("interference_avoidance = true\n", "--emit=moves")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertIn("c.nc:4:1: warning[PS0041]: interference avoided", proc.stderr)
        points = [(m["line"], round(m["to"]["X"], 3), round(m["to"]["Y"], 3))
                  for m in move_list(proc.stdout)]
        # X20. ends where its offset y = 5 meets the offset of Y20. (x = 16); the chamfer (line
        # 4) stays there, so the VM has no move for it; the cancel corner is type A.
        self.assertEqual(points, [(1, 0.0, -10.0), (2, 0.0, 5.0), (3, 16.0, 5.0),
                                  (5, 16.0, 20.0), (6, 30.0, 30.0)])


if __name__ == "__main__":
    NCC = sys.argv.pop(1)
    unittest.main()
