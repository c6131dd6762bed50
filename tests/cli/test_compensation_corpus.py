#!/usr/bin/env python3
"""Cutter compensation on shop programs of tests/corpus/fanuc-m, checked by hand against
FANUC's rules (docs/compensation.md): the tool-centre points of every compensated move, and the
interference alarm where a slot entry runs backwards. The programs are inch (G20) and written
for "control" compensation (D holds the tool radius): the machine files give D the radii of the
end mills their headers name. Expected points are in inches, worked out with the rules:

- an inner corner ends where the two offset lines meet; an outer corner between lines meets at
  P + r (n1 + n2) / (1 + n1.n2) (FANUC linear connection), n the left normals (G41);
- start-up type A (FANUC default): an inner start-up corner is the intersection too;
- G40 after a move: the cancel block's corner by the same rules, then its programmed end point;
  G40 alone: the vector perpendicular to the last move stays until the next move.

Run by ctest as: test_compensation_corpus.py NCC_BINARY
"""
import json
import os
import subprocess
import sys
import unittest

sys.dont_write_bytecode = True

from cli_harness import ScratchDirTest, move_list  # noqa: E402

NCC = None
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CORPUS = os.path.join(ROOT, "tests", "corpus", "fanuc-m")
INCH = 25.4


def machine(d1, d2=0.0):
    """A three-axis machine with D1/D2 radii in inches and zero lengths."""
    return ("[machine]\naxes = [\"X\", \"Y\", \"Z\"]\n[machine.offsets]\n"
            f"D1 = {d1 * INCH!r}\nD2 = {d2 * INCH!r}\nH1 = 0.0\nH2 = 0.0\nH3 = 0.0\nH10 = 0.0\n")


class CorpusCompensation(ScratchDirTest):
    def run_program(self, name, machine_text, *extra):
        toml = self.write("machine.toml", machine_text)
        return subprocess.run([NCC, "run", os.path.join(CORPUS, name), "--dialect", "fanuc-m",
                               "--machine", toml, *extra], capture_output=True, text=True,
                              timeout=120)

    def xy_by_line(self, proc, lines):
        """(line, kind, x, y) in inches of the moves of the given source lines."""
        self.assertEqual(proc.returncode, 0, proc.stderr)
        out = []
        for m in move_list(proc.stdout):
            if m.get("line") in lines:
                out.append((m["line"], m["kind"], round(m["to"]["X"] / INCH, 5),
                            round(m["to"]["Y"] / INCH, 5)))
        return out

    def test_step_block_profile_with_a_half_inch_end_mill(self):
        # O4002: G41 D01 from (-1,-1) to (0.2,0.2), then clockwise round the block 0.2..3.6 x
        # 0.2..1.6 with the tool outside (r = 0.25), G40 alone after.
        proc = self.run_program("enier-mill_240806_step_block_2.nc", machine(0.25), "--emit=moves")
        self.assertEqual(self.xy_by_line(proc, range(17, 24)), [
            # Start-up, inner corner: the offset of the (1,1) diagonal meets x = -0.05.
            (17, "line", -0.05, 0.30355),
            (18, "line", -0.05, 1.85),   # outer corners: P + 0.25 (n1 + n2)
            (19, "line", 3.85, 1.85),
            (20, "line", 3.85, -0.05),
            (21, "line", -1.0, -0.05),   # G40 alone: perpendicular to at its end
            (23, "rapid", -1.0, 0.2),    # the next move takes the vector away
        ])

    def test_mill_hp_profile_two_laps_an_arc_and_a_nearly_straight_corner(self):
        proc = self.run_program("enier-mill_mill_hp_mill_hp_1_mill_hp_1.nc", machine(0.25),
                                "--emit=moves")
        self.assertEqual(self.xy_by_line(proc, range(24, 38)), [
            (24, "line", 0.0, -0.75),     # start-up along +X, inner corner with Y2.25
            (25, "line", 0.0, 2.5),
            (26, "line", 3.5, 2.5),
            (27, "line", 3.5, 0.0),
            (28, "line", 0.0, 0.0),       # outer corner into the second lap
            (30, "line", 0.0, 2.5),
            (31, "line", 2.75, 2.5),      # tangent into G02 R0.5: perpendicular, no corner move
            (32, "arc", 3.5, 1.75),       # radius 0.75 about (2.75, 1.75)
            (33, "line", 3.5, 0.0),
            # X0.8 then X0.25 Y0.6072: outer, obtuse; the offset of y = 0.25 is y = 0.
            (34, "line", 0.72594, 0.0),
            # X0.0 Y0.7695 turns 0.02 degrees left: inner, the nearly parallel offset lines meet
            # 0.25 from the corner.
            (35, "line", 0.11385, 0.39752),
            # G40, inner: the offset of the last diagonal meets y = 0.7695 - 0.25.
            (36, "line", -0.07403, 0.5195),
            (37, "line", -1.0, 0.7695),
        ])
        arc = [m for m in move_list(proc.stdout) if m["line"] == 32][0]
        self.assertAlmostEqual(arc["center"]["X"] / INCH, 2.75, places=6)
        self.assertAlmostEqual(arc["center"]["Y"] / INCH, 1.75, places=6)

    def test_nims_profile_corners_around_a_notch(self):
        proc = self.run_program("enier-mill_240904_nims.nc", machine(0.25, 0.1), "--emit=moves")
        self.assertEqual(self.xy_by_line(proc, range(55, 65)), [
            (55, "line", 0.05, -0.75),
            (56, "line", 0.05, 2.35),
            (57, "line", 3.45, 2.35),
            (58, "line", 3.45, 0.05),
            (59, "line", 0.05, 0.05),
            (60, "line", 0.05, 1.836),    # tangent into G02 R0.264
            (61, "arc", 0.564, 2.35),     # radius 0.514
            # X1.35 then G03 down into the notch: outer corner, the tangent lines meet at
            # (1.6, 2.35), then down to perpendicular to the arc's start.
            (62, "line", 1.6, 2.35),
            (62, "line", 1.6, 2.1),
            (63, "arc", 1.9, 2.1),        # radius 0.4 - 0.25 on the inside
            (63, "line", 1.9, 2.35),      # out of the notch: outer corner again
            # X2.865 then the diagonal to X3.2 Y1.865: P + r (n1 + n2) / (1 + n1.n2).
            (64, "line", 2.94394, 2.35),
        ])

    def test_nims_slot_entry_with_the_quarter_inch_end_mill_is_an_interference(self):
        # G41 D02 X1.575 Y0.56 then G01 Y0.55: the start-up's inner corner lands 0.002 in below
        # the end of the 0.01 in move, which then runs backwards: FANUC's direction check.
        out = os.path.join(self.dir, "moves.jsonl")
        proc = self.run_program("enier-mill_240904_nims.nc", machine(0.25, 0.125),
                                "--emit=moves", "-o", out)
        self.assertEqual(proc.returncode, 1, proc.stderr)
        self.assertIn("enier-mill_240904_nims.nc:194:1: error[PS0041]: interference", proc.stderr)
        self.assertIn("backwards by 0.052 mm", proc.stderr)
        self.assertFalse(os.path.exists(out), "nothing is written")


class MacroCompensation(ScratchDirTest):
    def test_selyaev_spiral_hole_milling_macro_with_a_4_mm_end_mill(self):
        # selyaev-3: G65 P3003 mills a 10 mm hole (D10.) from Z1 down to Z-10 in 1 mm helical
        # turns with G41 (E41), then a last flat turn and G40 back to the centre. D1 = 2 mm: the
        # tool centre runs on radius 5 - 2 = 3 (G41 on a counterclockwise circle is inside).
        toml = self.write("m.toml", "[machine]\naxes = [\"X\", \"Y\", \"Z\"]\n"
                                    "[machine.offsets]\nD1 = 2.0\nH1 = 0.0\n")
        proc = subprocess.run([NCC, "run", "selyaev-3.nc", "--dialect", "fanuc-m", "--machine",
                               toml, "--emit=moves"], capture_output=True, text=True,
                              timeout=120, cwd=CORPUS)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        moves = [(m["file"], m["line"], m["kind"], round(m["to"]["X"], 4), round(m["to"]["Y"], 4),
                  round(m["to"]["Z"], 4)) for m in move_list(proc.stdout)
                 if m["file"] == "selyaev-3003.nc" and m["line"] >= 16]
        root5 = round(-(5 ** 0.5), 4)  # x where y = -+2 meets the circle of radius 3
        expected = [
            # G91 G41 X-5.: start-up, inner corner with the circle: the offset of the leftward
            # move (y = -2) meets the offset circle (radius 3) nearest the wall point.
            ("selyaev-3003.nc", 16, "line", root5, -2.0, 1.0),
            # The first turn from there to perpendicular at the wall point (the next turn goes
            # on tangent), one helix pitch down.
            ("selyaev-3003.nc", 21, "arc", -3.0, 0.0, 0.0),
        ]
        # Ten more full turns to Z-10 (WHILE #1 >= -10 with #1 stepping 1 from 0).
        expected += [("selyaev-3003.nc", 21, "arc", -3.0, 0.0, float(-z)) for z in range(1, 11)]
        expected += [
            # N2: the flat turn ends where the circle meets the offset of the G40 move (y = 2).
            ("selyaev-3003.nc", 23, "arc", root5, 2.0, -10.0),
            ("selyaev-3003.nc", 24, "line", 0.0, 0.0, -10.0),  # G40 to the centre
            ("selyaev-3003.nc", 25, "rapid", 0.0, 0.0, 5.0),
        ]
        self.assertEqual(moves, expected)
        for m in move_list(proc.stdout):
            if m["kind"] == "arc":
                self.assertAlmostEqual(m["center"]["X"], 0.0, places=9)
                self.assertAlmostEqual(m["center"]["Y"], 0.0, places=9)


class SelyaevMacros(ScratchDirTest):
    """selyaev-1 and -2 each carry one fault of their own, which a FANUC 0i-MD rejects too; with
    that one character or variable corrected they run to the end (their G41 included)."""

    def copy_folder(self):
        import shutil
        for name in os.listdir(CORPUS):
            if name.startswith("selyaev-"):
                shutil.copy(os.path.join(CORPUS, name), self.dir)

    def run_here(self, program):
        return subprocess.run([NCC, "run", program, "--dialect", "fanuc-m", "--emit=summary"],
                              capture_output=True, text=True, timeout=120, cwd=self.dir)

    def test_selyaev_1_stops_at_its_impossible_corner_arc(self):
        # O3001 line 47: #621=#610+#18 (the right side plus R) where the left side plus R
        # (#620+#18) is meant: the G2 ... R#18 of line 66 then joins points 104.6 mm apart with
        # R0.2: PS0020, at the R word of the called program.
        self.copy_folder()
        proc = self.run_here("selyaev-1.nc")
        self.assertEqual(proc.returncode, 1)
        self.assertIn("selyaev-3001.nc:66:13: error[PS0020]: no arc of radius 0.200 joins the "
                      "start and end points 104.600 apart", proc.stderr)
        with open(os.path.join(self.dir, "selyaev-3001.nc")) as f:
            text = f.read()
        with open(os.path.join(self.dir, "selyaev-3001.nc"), "w") as f:
            f.write(text.replace("#621=#610+#18;", "#621=#620+#18;"))
        proc = self.run_here("selyaev-1.nc")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertIn("status             completed", proc.stdout)

    def test_selyaev_2_stops_at_its_colon(self):
        # Line 15 ends "#1=#1-#11:" - a colon (the ISO program-number address) for the ';'.
        self.copy_folder()
        proc = self.run_here("selyaev-2.nc")
        self.assertEqual(proc.returncode, 1)
        self.assertIn("selyaev-2.nc:15:11: error[NCC1010]", proc.stderr)
        with open(os.path.join(self.dir, "selyaev-2.nc")) as f:
            text = f.read()
        with open(os.path.join(self.dir, "selyaev-2.nc"), "w") as f:
            f.write(text.replace("#1=#1-#11:", "#1=#1-#11;"))
        proc = self.run_here("selyaev-2.nc")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertIn("status             completed", proc.stdout)


if __name__ == "__main__":
    NCC = sys.argv.pop(1)
    unittest.main()
