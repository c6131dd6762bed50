#!/usr/bin/env python3
"""G15/G16 polar coordinate command from the command line (docs/semantics.md "Polar
coordinates"): `ncc run` moves to the Cartesian points of radius and angle words, the same with
--defer, hole cycles drill round a bolt circle, #4017 reads the group-17 code, and refused
combinations are an alarm at their line and column with no output file.

Run by ctest as: test_polar.py NCC_BINARY
"""
import json
import os
import subprocess
import sys
import unittest

sys.dont_write_bytecode = True

from cli_harness import ScratchDirTest, move_list as moves  # noqa: E402

NCC = None


def ncc(*args, cwd=None):
    return subprocess.run([NCC, *args], capture_output=True, text=True, cwd=cwd, timeout=120)


def xy(move):
    return (round(move["to"]["X"], 3), round(move["to"]["Y"], 3))


# Siemens ISO §4.5 example E12, with decimal points (the default notation is "standard").
SIEMENS_E12 = "G17 G90 G00 X10. Y10.\nG16 X100. Y45.\nG91 X100. Y0\nG90 Y90.\nG15\nM30\n"
# FANUC's bolt hole circle: radius 100 at 30 deg, then two more holes 120 deg apart (K2).
BOLT_CIRCLE = "G17 G90 G16\nG81 X100. Y30. Z-20. R-5. F200.\nG91 Y120. K2\nG15 G80\nM30\n"


class PolarCli(ScratchDirTest):
    def test_siemens_manual_example(self):
        prog = self.write("e12.nc", SIEMENS_E12)
        proc = ncc("run", prog, "--dialect", "siemens-iso-m", "--emit=moves")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        # N15: the pole is the current position (G91), the angle 0 from +X; N20: no radius, so
        # the work origin is the pole and the radius sqrt(170.711^2 + 70.711^2) = 184.776.
        self.assertEqual([xy(m) for m in moves(proc.stdout)],
                         [(10.0, 10.0), (70.711, 70.711), (170.711, 70.711), (0.0, 184.776)])

    def test_the_same_program_reads_differently_on_fanuc(self):
        prog = self.write("e12.nc", SIEMENS_E12)
        proc = ncc("run", prog, "--dialect", "fanuc-m", "--emit=moves")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        # FANUC: the incremental angle 0 continues the 45 deg the position has about the origin:
        # 100 further at 45 deg -> (141.421, 141.421); then radius 200 at 90 deg.
        self.assertEqual([xy(m) for m in moves(proc.stdout)],
                         [(10.0, 10.0), (70.711, 70.711), (141.421, 141.421), (0.0, 200.0)])

    def test_bolt_circle_holes_and_deferred_run(self):
        prog = self.write("bolt.nc", BOLT_CIRCLE)
        plain = ncc("run", prog, "--emit=moves")
        self.assertEqual(plain.returncode, 0, plain.stderr)
        holes = [xy(m) for m in moves(plain.stdout) if m["kind"] == "line"]
        self.assertEqual(holes, [(86.603, 50.0), (-86.603, 50.0), (0.0, -100.0)])
        deferred = ncc("run", "--defer", prog, "--emit=moves")
        self.assertEqual(deferred.returncode, 0, deferred.stderr)
        self.assertEqual(plain.stdout, deferred.stdout)

    def test_modal_group_17_reads_g16(self):
        prog = self.write("v.nc", "G16\n#100=#4017\nG15\n#101=#4017\nM30\n")
        proc = ncc("run", prog, "--emit=vars")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual(json.loads(proc.stdout), {"#100": 16.0, "#101": 15.0})

    def test_after_g31_the_polar_point_is_taken_where_the_skip_stopped(self):
        # G31 towards radius 50 at 90 deg stops at Y30 (--probe); `G91 Y-90.` has no radius:
        # 30 about the origin, turned to 0 deg -> (30, 0). Only known when run (note NCC0023).
        prog = self.write("skip.nc", "G90 G16 G31 X50. Y90. F100.\nG91 Y-90.\nM30\n")
        proc = ncc("run", prog, "--probe", "Y=30", "--emit=moves")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertIn("note[NCC0023]", proc.stderr)
        self.assertEqual([xy(m) for m in moves(proc.stdout)], [(0.0, 30.0), (30.0, 0.0)])

    def test_refused_combinations_are_alarms(self):
        xz = self.write("xz.toml", '[machine]\naxes = ["X", "Z"]\n')
        for dialect, text, extra, where in [
                ("fanuc-m", "G16 X50. Y90.\nG28 X0\nM30\n", [], ("2", "1", "NCC2088")),
                ("fanuc-m", "G16 G01 X50. Y0 F100.\nG02 X50. Y-90. J-50.\nM30\n", [],
                 ("2", "16", "NCC2088")),
                ("siemens-iso-m", "G16 G01 X50. Y0 F100.\nG02 X50. Y-90. R50.\nM30\n", [],
                 ("2", "1", "NCC2088")),
                ("fanuc-m", "G17 G16\nM30\n", ["--machine", xz], ("1", "5", "NCC2080"))]:
            with self.subTest(dialect=dialect, text=text):
                prog = self.write("bad.nc", text)
                out = self.path("bad.ncb")
                proc = ncc("compile", prog, "--dialect", dialect, *extra, "-o", out)
                self.assertEqual(proc.returncode, 1, proc.stderr)
                line, col, code = where
                self.assertIn(f"bad.nc:{line}:{col}: error[{code}]", proc.stderr)
                self.assertFalse(os.path.exists(out))


if __name__ == "__main__":
    NCC = sys.argv.pop(1)
    unittest.main()
