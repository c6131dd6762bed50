#!/usr/bin/env python3
"""Coordinate transforms from the command line: G68/G69 rotation, G51/G50 scaling, G51.1/G50.1
mirror and Mazak's G92.5 work coordinate rotation. `ncc run --emit=moves` goes to the mapped
points (worked out by hand from the manuals, the arithmetic in each comment), the same with
--defer; refused programs are an alarm at their line and column and `ncc compile -o` writes no
file; `--print-after=lower` shows the block's transform(...) and `--print-after=transform` the
mapped targets; the modal variables read the transform codes.

Run by ctest as: test_transforms.py NCC_BINARY
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


def xyz(move):
    return (round(move["to"]["X"], 3), round(move["to"]["Y"], 3), round(move["to"]["Z"], 3))


# R90 about the origin: the line to (10, 0) goes to (0, 10); the G02 (10, 0) -> (20, 0) about
# (15, 0) to (0, 20) about (0, 15), still clockwise; after G69 (30, 5) is reached as written.
ROTATION = "G17 G68 X0 Y0 R90.\nG01 X10. Y0 F100.\nG02 X20. Y0 I5. J0\nG69\nG01 X30. Y5.\nM30\n"
# Mirror X about 0, then R90 about the origin; the point (10, 0).
MIRROR_THEN_ROTATION = "G51.1 X0\nG68 X0 Y0 R90.\nG00 X10. Y0\nM30\n"
# Mazak §13-10 5.11 (G51 in G51 adds the Y axis, the last P for both), with G50 alone at the end.
MAZAK_RESCALE = ("G51 X-150. P0.75\nG00 X-50. Y-25.\nG01 X-250. F1000.\nG51 Y-125. P0.5\n"
                 "G00 X-100. Y-75.\nG01 X-200.\nG50\nM30\n")
# Mazak §14-13 example 1: G55 = (100, 100), rotation about the machine zero.
MAZAK_G92_5 = "G17 G90 G55\nG92.5 X0 Y0 R90.\nG00 X0 Y0\nG01 X100. F1000.\nY200.\nM30\n"
G55_MACHINE = ('[machine]\naxes = ["X", "Y", "Z"]\n[machine.work]\nG54 = [0.0, 0.0, 0.0]\n'
               "G55 = [100.0, 100.0, 0.0]\n")


class TransformsCli(ScratchDirTest):
    def run_both(self, prog, *args):
        """`ncc run --emit=moves`, plainly and with --defer: the same output; the moves."""
        plain = ncc("run", prog, *args, "--emit=moves")
        self.assertEqual(plain.returncode, 0, plain.stderr)
        deferred = ncc("run", "--defer", prog, *args, "--emit=moves")
        self.assertEqual(deferred.returncode, 0, deferred.stderr)
        self.assertEqual(plain.stdout, deferred.stdout)
        return moves(plain.stdout)

    def test_rotation_in_every_dialect(self):
        prog = self.write("rot.nc", ROTATION)
        for dialect in ("fanuc-m", "mazak-m", "siemens-iso-m"):
            with self.subTest(dialect=dialect):
                got = self.run_both(prog, "--dialect", dialect)
                self.assertEqual([m["kind"] for m in got], ["line", "arc", "line"])
                self.assertEqual([xy(m) for m in got], [(0.0, 10.0), (0.0, 20.0), (30.0, 5.0)])
                self.assertEqual(got[1]["center"], {"X": 0.0, "Y": 15.0})
                self.assertTrue(got[1]["cw"])

    def test_mazak_turns_before_mirroring(self):
        # Mazak §13-8 1.3: rotation before the mirror. Mirror X about 0, R90 about (0, 0):
        # (10, 0) -> (0, 10) -> (0, 10); about (5, 0): (10, 0) -> (5, 5) -> (-5, 5). (Mirroring
        # first would give (0, -10) and (5, -15).)
        for text, want in ((MIRROR_THEN_ROTATION, (0.0, 10.0)),
                           (MIRROR_THEN_ROTATION.replace("G68 X0", "G68 X5."), (-5.0, 5.0))):
            with self.subTest(text=text):
                prog = self.write("order.nc", text)
                self.assertEqual([xy(m) for m in self.run_both(prog, "--dialect", "mazak-m")],
                                 [want])

    def test_mazak_rescale_and_g50_moving_back(self):
        # X about -150 by 0.75: X-50 -> -75, X-250 -> -225; after `G51 Y-125. P0.5` both by 0.5:
        # X-100 -> -125, Y-75 -> -100, X-200 -> -175; G50 alone goes back to (-200, -75) in G01.
        prog = self.write("scale.nc", MAZAK_RESCALE)
        got = self.run_both(prog, "--dialect", "mazak-m")
        self.assertEqual([xy(m) for m in got],
                         [(-75.0, -25.0), (-225.0, -25.0), (-125.0, -100.0), (-175.0, -100.0),
                          (-200.0, -75.0)])
        self.assertEqual([m["kind"] for m in got], ["rapid", "line", "rapid", "line", "line"])

    def test_mazak_work_rotation_about_the_machine_zero(self):
        # Work (0, 0) = machine (100, 100) -> (-100, 100); (100, 0) = (200, 100) -> (-100, 200);
        # (100, 200) = (200, 300) -> (-300, 200).
        prog = self.write("g925.nc", MAZAK_G92_5)
        machine = self.write("m.toml", G55_MACHINE)
        got = self.run_both(prog, "--dialect", "mazak-m", "--machine", machine)
        self.assertEqual([xy(m) for m in got], [(-100.0, 100.0), (-100.0, 200.0), (-300.0, 200.0)])

    def test_siemens_3d_rotation_about_any_vector(self):
        # §3.1.10: 120 deg about (1, 1, 1) takes X to Y: (10, 0, 0) -> (0, 10, 0).
        prog = self.write("r3.nc", "G68 X0 Y0 Z0 I1. J1. K1. R120.\nG01 X10. Y0 Z0 F100.\nM30\n")
        got = self.run_both(prog, "--dialect", "siemens-iso-m")
        self.assertEqual([xyz(m) for m in got], [(0.0, 10.0, 0.0)])

    def test_refused_programs_are_alarms_and_write_nothing(self):
        per_axis = self.write("pa.toml", '[machine]\naxes = ["X", "Y", "Z"]\n'
                                         "[machine.params]\nscale_per_axis = true\n")
        for dialect, text, extra, where in [
                # FANUC: a scale factor beyond 999.999 (PS0142) at the P word.
                ("fanuc-m", "G51 X0 Y0 P1000.\nM30\n", [], ("1", "11", "PS0142")),
                # Mazak §13-10 3.A: above 99.999999, 809.
                ("mazak-m", "G51 X0 Y0 P100.\nM30\n", [], ("1", "11", "809")),
                # Mazak ch. 22: a 3-D G68 vector that is no unit axis, 807.
                ("mazak-m", "G68 X0 Y0 Z0 I1. J1. R90.\nM30\n", [], ("1", "1", "807")),
                # Mazak §14-13: an arc right after G92.5, 817 at the G02.
                ("mazak-m", "G92.5 X0 Y0 R90.\nG02 X10. Y0 I5. F100.\nM30\n", [],
                 ("2", "1", "817")),
                # Siemens §3.1.9: another G code in the G68 block.
                ("siemens-iso-m", "G90 G68 X0 Y0 R30.\nM30\n", [], ("1", "1", "NCC2112")),
                # Siemens §3.2.4: G51.1 while scaling is in force.
                ("siemens-iso-m", "G51 X0 Y0 P2.\nG51.1 X0\nM30\n", [], ("2", "1", "NCC2113")),
                # FANUC 3-D rotation nests twice; a third G68 is refused.
                ("fanuc-m", "G68 X0 Y0 Z0 I0 J0 K1. R10.\nG68 X0 Y0 Z0 I0 J0 K1. R10.\n"
                            "G68 X0 Y0 Z0 I0 J0 K1. R10.\nM30\n", [], ("3", "1", "NCC2115")),
                # x2 in X, x1 in Y: the arc's image is an ellipse.
                ("fanuc-m", "G51 X0 Y0 I2000 J1000\nG01 X10. Y0 F100.\nG02 X15. Y5. I5. J0\n"
                            "M30\n", ["--machine", per_axis], ("3", "1", "NCC2110")),
                ("fanuc-m", "G68 X0 Y0 R400.\nM30\n", [], ("1", "11", "NCC2116"))]:
            with self.subTest(dialect=dialect, text=text):
                prog = self.write("bad.nc", text)
                out = self.path("bad.ncb")
                proc = ncc("compile", prog, "--dialect", dialect, *extra, "-o", out)
                self.assertEqual(proc.returncode, 1, proc.stderr)
                line, col, code = where
                self.assertIn(f"bad.nc:{line}:{col}: error[{code}]", proc.stderr)
                self.assertFalse(os.path.exists(out))
                # ncc run stops with the same alarm.
                ran = ncc("run", prog, "--dialect", dialect, *extra, "--emit=moves")
                self.assertNotEqual(ran.returncode, 0)
                self.assertIn(f"bad.nc:{line}:{col}: error[{code}]", ran.stderr)

    def test_an_arc_starting_off_its_circle_after_g69_is_refused_when_compiling(self):
        # R90 leaves the tool at (0, 10) for the programmed (10, 0); after G69 the G02 to
        # (20, 0) with I5 starts off its circle (18.028 from its centre, 5 at the end). The
        # compiler's arc check (PS0020 on fanuc-m) refuses it at 4:1, rather than the VM stopping
        # on a bytecode file that was written (NCC7211 "was the file edited?").
        prog = self.write("g.nc", "G68 X0 Y0 R90.\nG01 X10. Y0 F100.\nG69\nG02 X20. Y0 I5.\nM30\n")
        out = self.path("g.ncb")
        proc = ncc("compile", prog, "--dialect", "fanuc-m", "-o", out)
        self.assertIn("g.nc:4:1: error[PS0020]", proc.stderr)
        self.assertEqual(proc.returncode, 1, proc.stderr)
        self.assertFalse(os.path.exists(out))

    def test_print_after_lower_and_transform(self):
        prog = self.write("rot.nc", ROTATION)
        proc = ncc("compile", prog, "--dialect", "fanuc-m", "--emit=ir",
                   "--print-after=lower,transform")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        text = proc.stdout
        lower = text[text.index("; after lower"):]
        lower = lower[:lower.index("; after transform")]
        # After lower the block carries the map (R90: x' = -y, y' = x) and the written target.
        self.assertIn("transform(0.000 -1.000 0.000 | 0.000; 1.000 0.000 0.000 | 0.000; "
                      "0.000 0.000 1.000 | 0.000)", lower)
        # The line's block, after each pass: written (10, 0), then mapped (0, 10), no map left.
        after = text.split("block 1:2:1")
        self.assertIn("line work X10.000 Y0.000 Z0.000", after[1])
        self.assertIn("transform(", after[1].splitlines()[0])
        self.assertIn("line work X0.000 Y10.000 Z0.000", after[2])
        self.assertNotIn("transform(", after[2].splitlines()[0])
        arc = text.split("block 1:3:1")[2]
        self.assertIn("arc work G17 cw X0.000 Y20.000 Z0.000 centre X0.000 Y15.000", arc)
        # After G69 no block carries a map.
        self.assertNotIn("transform(", text.split("block 1:5:1")[1].splitlines()[0])

    def test_modal_variables_read_the_transform_codes(self):
        prog = self.write("v.nc", "G68 X0 Y0 R10.\n#100=#4016\nG69\n#101=#4016\n"
                                  "G51 X0 Y0 P2.\n#102=#4011\nG50\n#103=#4011\n"
                                  "G51.1 X0\n#104=#4022\nG50.1\n#105=#4022\nM30\n")
        proc = ncc("run", prog, "--dialect", "fanuc-m", "--emit=vars")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual(json.loads(proc.stdout), {"#100": 68.0, "#101": 69.0, "#102": 51.0,
                                                   "#103": 50.0, "#104": 51.1, "#105": 50.1})
        # Mazak puts the mirror in group 19 (#4019).
        prog = self.write("m.nc", "G68 X0 Y0 R10.\n#100=#4016\nG51 X0 Y0 P2.\n#102=#4011\n"
                                  "G51.1 X0\n#104=#4019\nG50.1\n#105=#4019\nM30\n")
        proc = ncc("run", prog, "--dialect", "mazak-m", "--emit=vars")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual(json.loads(proc.stdout), {"#100": 68.0, "#102": 51.0, "#104": 51.1,
                                                   "#105": 50.1})


if __name__ == "__main__":
    NCC = sys.argv.pop(1)
    unittest.main()
