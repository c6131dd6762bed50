#!/usr/bin/env python3
"""`ncc plot` with cutter radius compensation (issue 24): the programmed path (the program
compiled with compensation off) drawn thin and dashed under the tool centre's path, each named
in the legend; a compensation alarm of the compile (an interference: FANUC PS0041, Mazak 837,
Siemens NCC2127) drawn on the programmed path with a marker at the alarm's block, the SVG
written whole and exit 1. Programs without compensation are drawn as before.

Run by ctest as: test_plot_compensation.py NCC_BINARY
"""
import os
import re
import subprocess
import sys
import unittest
import xml.etree.ElementTree as ET

from cli_harness import ScratchDirTest

NCC = None
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SVG = "{http://www.w3.org/2000/svg}"

# Cutter radius registers: D1 5 mm, D2 8 mm (a 16 mm cutter).
MACHINE = "[machine]\naxes = [\"X\", \"Y\", \"Z\"]\n[machine.offsets]\nD1 = 5.0\nD2 = 8.0\n"

# A 40 x 30 rectangle, clockwise: G41 (left of the direction) is outside it.
SQUARE = """G90 G17 G21
T1 M06
G00 X-20. Y-20. Z5.
G01 Z-1. F500.
G41 X0 Y0 D1
G01 Y30.
X40.
Y0
X0
G40 X-20. Y-20.
G00 Z5.
M30
"""

# G42 (right of the direction) inside a rectangle closed by a G02 half circle on top.
ARC = """G90 G17 G21
T1 M06
G00 X-20. Y-20. Z5.
G01 Z-1. F500.
G42 X0 Y0 D1
G01 Y30.
G02 X40. Y30. R20.
G01 Y0
X0
G40 X-20. Y-20.
M30
"""

# A 6 mm wide slot going 20 mm into the contour: the 16 mm cutter (D2) cannot enter it.
SLOT = """G90 G17 G21
T1 M06
G00 X-20. Y10. Z5.
G01 Z-1. F500.
G41 X0 Y0 D2
G01 X30.
Y-20.
X36.
Y0
X60.
G40 X70. Y10.
M30
"""

# A left turn from a line into a small G03 arc: with the 5 mm cutter on the inside (G41) the
# offset line (Y5) and the offset arc (radius 0.59 about X4.5 Y1) do not meet.
NO_INTERSECTION = """G90 G17 G21
G00 X-20. Y-10. Z5.
G01 Z-1. F500.
G41 X-10. Y0 D1
G01 X10.
G03 X4.5 Y6.59 I-5.5 J1.
G01 X-10.
G40 X-20. Y-10.
M30
"""


def ncc(*args, stdin=None, timeout=120):
    return subprocess.run([NCC, *args], capture_output=True, text=True, timeout=timeout,
                          input=stdin)


def view(root, name):
    return root.find(f".//{SVG}g[@id='view-{name}']")


def move_paths(g):
    """The tool centre's moves (the moves drawn before compensation existed)."""
    return [p for p in g.iter(f"{SVG}path") if p.get("class") in ("rapid", "feed")]


def programmed_paths(g):
    return [p for p in g.iter(f"{SVG}path") if p.get("class") == "programmed"]


def title_of(element):
    t = element.find(f"{SVG}title")
    return t.text if t is not None else None


def titles(paths):
    return [title_of(p) for p in paths]


def legend_paths(root):
    legend = root.find(f".//{SVG}g[@id='legend']")
    return {g.get("data-path"): g.find(f"{SVG}text").text
            for g in legend.findall(f"{SVG}g[@class='legend-path']")}


def end_point(d):
    """The last point of a path's `d` attribute (screen coordinates)."""
    numbers = re.findall(r"-?\d+\.\d+", d)
    return float(numbers[-2]), float(numbers[-1])


class PlotCompensationTest(ScratchDirTest):
    def setUp(self):
        super().setUp()
        self.machine = self.write("mill.toml", MACHINE)

    def plot(self, source, *args):
        path = self.write("part.nc", source)
        out = self.path("out.svg")
        r = ncc("plot", path, "-o", out, "--machine", self.machine, *args)
        root = ET.parse(out).getroot() if os.path.exists(out) else None
        return r, root

    def test_both_paths_with_their_legend(self):
        r, root = self.plot(SQUARE)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(r.stderr, "")
        self.assertEqual(legend_paths(root), {"tool-centre": "tool centre (G41/G42)",
                                              "programmed": "programmed path"})
        heading = root.find(f"{SVG}text[@id='heading']").text
        self.assertEqual(heading, "part.nc (9 moves; programmed path: 9 moves)")
        for name in ("top", "front", "side", "iso"):
            g = view(root, name)
            programmed, centre = programmed_paths(g), move_paths(g)
            self.assertEqual(len(programmed), 9, name)
            self.assertEqual(len(centre), 9, name)
            # The programmed path is thin and dashed in its own colour, under the tool centre.
            group = g.find(f"{SVG}g[@class='programmed-path']")
            self.assertTrue(group.get("stroke-dasharray"))
            self.assertEqual(group.get("stroke"), "#ff00ff")
            self.assertNotIn("#ff00ff", {p.get("stroke") for p in centre})
            children = list(g)
            self.assertLess(children.index(group),
                            children.index(g.find(f"{SVG}g[@class='moves']")))
        top = view(root, "top")
        # The programmed points, as written.
        self.assertEqual(titles(programmed_paths(top))[4:8], [
            "programmed: part.nc:7: G01 X40.000 Y30.000 Z-1.000 (T1)",
            "programmed: part.nc:8: G01 X40.000 Y0.000 Z-1.000 (T1)",
            "programmed: part.nc:9: G01 X0.000 Y0.000 Z-1.000 (T1)",
            "programmed: part.nc:10: G01 X-20.000 Y-20.000 Z-1.000 (T1)"])
        # The tool centre 5 mm outside the rectangle: its corners offset by (±5, ±5).
        self.assertEqual(titles(move_paths(top))[3:6], [
            "part.nc:6: G01 X-5.000 Y35.000 Z-1.000 (T1)",
            "part.nc:7: G01 X45.000 Y35.000 Z-1.000 (T1)",
            "part.nc:8: G01 X45.000 Y-5.000 Z-1.000 (T1)"])
        # Both are inside the panel: the views are fitted to both paths.
        for p in programmed_paths(top) + move_paths(top):
            x, y = end_point(p.get("d"))
            self.assertTrue(0 <= x <= 600 and 28 <= y <= 440, (x, y))

    def test_g42_with_an_arc(self):
        r, root = self.plot(ARC)
        self.assertEqual(r.returncode, 0, r.stderr)
        top = view(root, "top")
        programmed = {int(p.get("data-line")): title_of(p) for p in programmed_paths(top)}
        centre = {int(p.get("data-line")): title_of(p) for p in move_paths(top)}
        self.assertEqual(programmed[7], "programmed: part.nc:7: G02 X40.000 Y30.000 Z-1.000 (T1)")
        # Right of the half circle is inside it: radius 15 about X20 Y30, ending at X35 Y30;
        # the corner at X40 Y0 is an inner one, at the offset lines' intersection.
        self.assertEqual(centre[6], "part.nc:6: G01 X5.000 Y30.000 Z-1.000 (T1)")
        self.assertEqual(centre[7], "part.nc:7: G02 X35.000 Y30.000 Z-1.000 (T1)")
        self.assertEqual(centre[8], "part.nc:8: G01 X35.000 Y5.000 Z-1.000 (T1)")
        # Each drawn face-on as an SVG arc, of radius 20 and 15 at the view's scale.
        arc_p = next(p for p in programmed_paths(top) if p.get("data-line") == "7").get("d")
        arc_c = next(p for p in move_paths(top) if p.get("data-line") == "7").get("d")
        r_p = float(re.search(r" A(\S+) ", arc_p).group(1))
        r_c = float(re.search(r" A(\S+) ", arc_c).group(1))
        self.assertAlmostEqual(r_c / r_p, 15.0 / 20.0, places=3)

    def test_without_compensation_nothing_more(self):
        # A G40 (the usual safety block) is no compensation: drawn exactly as before.
        for source in ("G90 G00 X10. Y5. Z2.\nG01 X12.5 F100.\nM30\n",
                       "G40 G90 G17\nG00 X10. Y5. Z2.\nG01 X12.5 F100.\nM30\n"):
            r, root = self.plot(source)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertIsNone(root.find(f".//{SVG}g[@class='programmed-path']"))
            self.assertEqual(legend_paths(root), {})
            self.assertEqual(root.find(f"{SVG}text[@id='heading']").text, "part.nc (2 moves)")
            with open(self.path("out.svg"), encoding="utf-8") as f:
                self.assertNotIn("programmed", f.read())

    def test_interference_draws_the_programmed_path_and_marks_the_alarm(self):
        r, root = self.plot(SLOT)
        self.assertEqual(r.returncode, 1, r.stderr)
        self.assertRegex(r.stderr, r"part\.nc:8:1: error\[PS0041\]: interference")
        # A whole document, not a partial one.
        with open(self.path("out.svg"), encoding="utf-8") as f:
            self.assertTrue(f.read().endswith("</svg>\n"))
        self.assertEqual(legend_paths(root), {"programmed": "programmed path"})
        self.assertEqual(root.find(f"{SVG}text[@id='heading']").text,
                         "part.nc (0 moves; programmed path: 9 moves)")
        for name in ("top", "front", "side", "iso"):
            g = view(root, name)
            self.assertEqual(move_paths(g), [], "no tool centre's path: the compile stopped")
            programmed = programmed_paths(g)
            self.assertEqual(len(programmed), 9)
            alarms = g.findall(f"{SVG}g[@class='alarm']")
            self.assertEqual(len(alarms), 1, name)
            alarm = alarms[0]
            self.assertTrue(title_of(alarm).startswith("alarm PS0041 at part.nc:8: interference"),
                            title_of(alarm))
            self.assertEqual(alarm.find(f"{SVG}text").text, "alarm PS0041")
            # The marker is where the alarm's block (line 8, X36.) ends on the programmed path.
            circle = alarm.find(f"{SVG}circle")
            block = next(p for p in programmed if p.get("data-line") == "8")
            self.assertEqual((float(circle.get("cx")), float(circle.get("cy"))),
                             end_point(block.get("d")))
        self.assertEqual(
            [title_of(p) for p in programmed_paths(view(root, "top")) if p.get("data-line") == "8"],
            ["programmed: part.nc:8: G01 X36.000 Y-20.000 Z-1.000 (T1)"])

    def test_interference_alarm_numbers_of_each_dialect(self):
        for dialect, code in (("fanuc-m", "PS0041"), ("mazak-m", "837"),
                              ("siemens-iso-m", "NCC2127")):
            r, root = self.plot(SLOT, "--dialect", dialect)
            self.assertEqual(r.returncode, 1, dialect)
            self.assertIn(f"part.nc:8:1: error[{code}]:", r.stderr)
            alarm = view(root, "top").find(f"{SVG}g[@class='alarm']")
            self.assertTrue(title_of(alarm).startswith(f"alarm {code} at part.nc:8: "), dialect)

    def test_no_intersection_alarm_of_each_dialect(self):
        for dialect, code in (("fanuc-m", "PS0033"), ("mazak-m", "836"),
                              ("siemens-iso-m", "NCC2126")):
            r, root = self.plot(NO_INTERSECTION, "--dialect", dialect)
            self.assertEqual(r.returncode, 1, dialect)
            self.assertIn(f"part.nc:6:1: error[{code}]: the offset paths", r.stderr)
            top = view(root, "top")
            self.assertEqual(move_paths(top), [])
            self.assertEqual(len(programmed_paths(top)), 7)
            alarm = top.find(f"{SVG}g[@class='alarm']")
            self.assertTrue(title_of(alarm).startswith(f"alarm {code} at part.nc:6: "), dialect)
            arc = next(p for p in programmed_paths(top) if p.get("data-line") == "6")
            circle = alarm.find(f"{SVG}circle")
            self.assertEqual((float(circle.get("cx")), float(circle.get("cy"))),
                             end_point(arc.get("d")))

    def test_a_warning_of_compensation_still_draws_both(self):
        # Three blocks without motion in the plane: FANUC keeps the corner over one only, a
        # warning (NCC2128), not an error; the drawing is made as for any compensated program.
        r, root = self.plot("G90 G17 G21\nG00 X-20. Y-20. Z5.\nG01 Z-1. F500.\nG41 X0 Y0 D1\n"
                            "G01 Y30.\nZ-2.\nZ-3.\nZ-4.\nX40.\nG40 X60. Y40.\nM30\n")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("part.nc:9:1: warning[NCC2128]", r.stderr)
        top = view(root, "top")
        self.assertIsNone(top.find(f"{SVG}g[@class='alarm']"))
        self.assertEqual(len(programmed_paths(top)), 9)
        self.assertGreaterEqual(len(move_paths(top)), 9)  # with the corner's own moves
        self.assertEqual(r.stderr.count("warning[NCC2128]"), 1, "the warning printed once")

    def test_run_time_alarm_draws_both_up_to_it_and_exits_3(self):
        # G95 with the spindle stopped (alarm NCC7207) on line 8, in compensation mode.
        r, root = self.plot(SQUARE.replace("Y0\n", "G95 Y0 F0.1\n"))
        self.assertEqual(r.returncode, 3, r.stderr)
        self.assertIn("part.nc:8:", r.stderr)
        self.assertIn("NCC7207", r.stderr)
        top = view(root, "top")
        self.assertEqual(legend_paths(root), {"tool-centre": "tool centre (G41/G42)",
                                              "programmed": "programmed path"})
        centre = move_paths(top)
        self.assertTrue(all(int(p.get("data-line")) < 8 for p in centre))
        self.assertTrue(all(int(p.get("data-line")) < 8 for p in programmed_paths(top)))
        alarm = top.find(f"{SVG}g[@class='alarm']")
        self.assertTrue(title_of(alarm).startswith("alarm NCC7207 at part.nc:8: "))
        # Where the tool centre's last move ends, as for any run-time alarm.
        circle = alarm.find(f"{SVG}circle")
        self.assertEqual((float(circle.get("cx")), float(circle.get("cy"))),
                         end_point(centre[-1].get("d")))

    def test_a_smaller_cutter_fits_the_slot(self):
        r, root = self.plot(SLOT.replace("D2", "D1").replace("X36.", "X42."))
        self.assertEqual(r.returncode, 0, r.stderr)
        top = view(root, "top")
        self.assertIsNone(top.find(f"{SVG}g[@class='alarm']"))
        self.assertEqual(len(programmed_paths(top)), 9)
        self.assertEqual(len(move_paths(top)), len(programmed_paths(top)))
        # The slot's bottom (line 8, to X42 Y-20): the centre 5 mm above it, between the walls.
        self.assertEqual([title_of(p) for p in move_paths(top) if p.get("data-line") == "8"],
                         ["part.nc:8: G01 X37.000 Y-15.000 Z-1.000 (T1)"])

    def test_other_errors_still_write_nothing(self):
        # An error the compile gives with compensation off too: as before, no file.
        r, root = self.plot(SQUARE.replace("X40.", "X#"))
        self.assertEqual(r.returncode, 1)
        self.assertIsNone(root)
        self.assertRegex(r.stderr, r"part\.nc:7:\d+: error\[")

    def test_from_to_applies_to_both_paths(self):
        r, root = self.plot(SQUARE, "--from", "7", "--to", "8")
        self.assertEqual(r.returncode, 0, r.stderr)
        top = view(root, "top")
        self.assertEqual({p.get("data-line") for p in programmed_paths(top)}, {"7", "8"})
        self.assertEqual({p.get("data-line") for p in move_paths(top)}, {"7", "8"})

    def test_standard_input_and_stdout(self):
        r = ncc("plot", "-", "--machine", self.machine, stdin=SLOT)
        self.assertEqual(r.returncode, 1)
        root = ET.fromstring(r.stdout.encode())
        alarm = view(root, "top").find(f"{SVG}g[@class='alarm']")
        self.assertTrue(title_of(alarm).startswith("alarm PS0041 at <stdin>:8: "))

    def test_deferred_program_draws_the_tool_centre_only(self):
        # The VM prepares the blocks (and compensates them): no programmed path to compare.
        r, root = self.plot(SQUARE, "--defer")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIsNone(root.find(f".//{SVG}g[@class='programmed-path']"))
        self.assertEqual(titles(move_paths(view(root, "top")))[4],
                         "part.nc:7: G01 X45.000 Y35.000 Z-1.000 (T1)")

    def test_docs_drawing_is_current(self):
        """docs/images/plot-compensation.svg is what the commands of docs/cli.md ("ncc plot",
        cutter compensation) draw today."""
        with open(os.path.join(ROOT, "docs", "cli.md"), encoding="utf-8") as f:
            doc = f.read()
        contour = re.search(r"^\$ printf '(.*)' > contour\.nc$", doc, re.M).group(1)
        machine = re.search(r"^\$ printf '(.*)' > mill\.toml$", doc, re.M).group(1)
        command = re.search(r"^\$ ncc plot contour\.nc (.*) -o contour\.svg$", doc, re.M).group(1)
        self.write("contour.nc", contour.replace("\\n", "\n"))
        self.write("mill.toml", machine.replace("\\n", "\n"))
        r = subprocess.run([NCC, "plot", "contour.nc", *command.split(), "-o", "contour.svg"],
                           capture_output=True, text=True, timeout=120, cwd=self.dir)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(self.path("contour.svg"), encoding="utf-8") as a, \
                open(os.path.join(ROOT, "docs", "images", "plot-compensation.svg"),
                     encoding="utf-8") as b:
            self.assertEqual(a.read(), b.read())


if __name__ == "__main__":
    NCC = os.path.abspath(sys.argv.pop(1))
    unittest.main()
