#!/usr/bin/env python3
"""`ncc plot`: the path a program runs drawn as SVG (issue 23). The drawing is checked by its
elements: views, one path per move, dashed rapids, colours per tool, titles with source lines,
--from/--to, the extents text, --view, --size, and bad inputs (exit codes, nothing written).

Run by ctest as: test_plot.py NCC_BINARY
"""
import json
import os
import re
import subprocess
import sys
import unittest
import xml.etree.ElementTree as ET

from cli_harness import ScratchDirTest

NCC = None
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
EXAMPLES = os.path.join(ROOT, "examples")
SVG = "{http://www.w3.org/2000/svg}"

# Two tools (M06), a rapid, feed lines and a full circle in G17, an arc in G18.
TOOLS = """G21 G90 G17 G94
T1 M06
G00 X10. Y0 Z5.
G01 Z-1. F200.
G01 X20.
G02 X20. Y0 I5. J0
T2 M06
G00 Z10.
G18 G03 X40. Z10. I10. K0
G17 G00 X0 Y0
M30
"""


def ncc(*args, cwd=None, stdin=None, timeout=120):
    return subprocess.run([NCC, *args], capture_output=True, text=True, timeout=timeout, cwd=cwd,
                          input=stdin)


def moves_of(path, *extra):
    """The motion primitives `ncc run --emit=moves` gives for the program (no dwells, no alarm)."""
    r = ncc("run", path, "--emit=moves", *extra)
    rows = [json.loads(line) for line in r.stdout.splitlines()]
    return [m for m in rows if m["kind"] in ("rapid", "line", "arc")]


def view(root, name):
    g = root.find(f".//{SVG}g[@id='view-{name}']")
    return g


def move_paths(g):
    return [p for p in g.iter(f"{SVG}path") if p.get("class") in ("rapid", "feed")]


def title_of(element):
    t = element.find(f"{SVG}title")
    return t.text if t is not None else None


class PlotTest(ScratchDirTest):
    def plot(self, source_or_path, *args, name="part.nc"):
        path = source_or_path if os.path.exists(source_or_path) else self.write(name, source_or_path)
        out = self.path("out.svg")
        r = ncc("plot", path, "-o", out, *args)
        root = ET.parse(out).getroot() if os.path.exists(out) else None
        return r, root, path

    def test_views_and_one_path_per_move(self):
        r, root, path = self.plot(os.path.join(EXAMPLES, "bolt-circle.nc"))
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(root.tag, f"{SVG}svg")
        self.assertEqual((root.get("width"), root.get("height")), ("1200", "900"))
        self.assertEqual(root.get("viewBox"), "0 0 1200 900")
        moves = moves_of(path)
        self.assertGreater(len(moves), 10)
        for name in ("top", "front", "side", "iso"):
            g = view(root, name)
            self.assertIsNotNone(g, name)
            paths = move_paths(g)
            self.assertEqual(len(paths), len(moves), name)
            rapids = [p for p in paths if p.get("class") == "rapid"]
            feeds = [p for p in paths if p.get("class") == "feed"]
            self.assertEqual(len(rapids), sum(m["kind"] == "rapid" for m in moves))
            self.assertEqual(len(feeds), sum(m["kind"] != "rapid" for m in moves))
            for p in rapids:
                self.assertTrue(p.get("stroke-dasharray"), "a rapid is dashed")
            for p in feeds:
                self.assertIsNone(p.get("stroke-dasharray"), "a feed move is solid")
            # The titles name the source line of each move, in run order.
            lines = [int(re.match(r"bolt-circle\.nc:(\d+): G0[0-3] ", title_of(p)).group(1))
                     for p in paths]
            self.assertEqual(lines, [m["line"] for m in moves])
            self.assertEqual([int(p.get("data-line")) for p in paths], lines)
            # The work zero is marked in every view.
            self.assertIsNotNone(g.find(f".//{SVG}g[@class='work-zero']"))
        # No scripts, images or external references: readable with nothing else.
        with open(self.path("out.svg"), encoding="utf-8") as f:
            text = f.read()
        for banned in ("<script", "<image", "href", "@import", "url("):
            self.assertNotIn(banned, text)

    def test_titles_carry_the_end_point(self):
        r, root, _ = self.plot("G90 G00 X10. Y5. Z2.\nG01 X12.5 F100.\nM30\n")
        self.assertEqual(r.returncode, 0, r.stderr)
        titles = [title_of(p) for p in move_paths(view(root, "top"))]
        self.assertEqual(titles, ["part.nc:1: G00 X10.000 Y5.000 Z2.000 (T0)",
                                  "part.nc:2: G01 X12.500 Y5.000 Z2.000 (T0)"])

    def test_colours_follow_the_tool(self):
        r, root, path = self.plot(TOOLS)
        self.assertEqual(r.returncode, 0, r.stderr)
        paths = move_paths(view(root, "top"))
        self.assertEqual([p.get("data-tool") for p in paths], ["1"] * 4 + ["2"] * 3)
        colour = {p.get("data-tool"): p.get("stroke") for p in paths}
        self.assertNotEqual(colour["1"], colour["2"])
        for p in paths:
            self.assertEqual(p.get("stroke"), colour[p.get("data-tool")])
        legend = root.find(f".//{SVG}g[@id='legend']")
        tools = [g.get("data-tool") for g in legend.findall(f"{SVG}g[@class='legend-tool']")]
        self.assertEqual(tools, ["1", "2"])
        self.assertIn("(T2)", title_of(paths[-1]))

    def test_colour_changes_at_t_without_any_m06(self):
        r, root, _ = self.plot("T3\nG00 X1.\nT4\nG00 X2.\nM30\n")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual([p.get("data-tool") for p in move_paths(view(root, "top"))], ["3", "4"])

    def test_arcs(self):
        r, root, path = self.plot(TOOLS)
        self.assertEqual(r.returncode, 0, r.stderr)
        top = move_paths(view(root, "top"))
        front = move_paths(view(root, "front"))
        iso = move_paths(view(root, "iso"))
        # The G17 full circle (move 4): SVG arcs in the top view, a polyline elsewhere.
        self.assertIn(" A", top[3].get("d"))
        self.assertEqual(top[3].get("d").count(" A"), 3, "a full turn in three 120-degree arcs")
        self.assertNotIn(" A", front[3].get("d"))
        self.assertGreater(iso[3].get("d").count(" L"), 100)
        # The G18 arc (move 6): face-on in the front view only.
        self.assertIn(" A", front[5].get("d"))
        self.assertNotIn(" A", top[5].get("d"))

    def test_arc_direction(self):
        # On the screen (y down) a clockwise arc is SVG sweep-flag 1. G17 G02 is clockwise in the
        # top view; G18 G03 (counter-clockwise seen from +Y) is clockwise in the front view,
        # seen from -Y; G19 G02 is clockwise in the side view, seen from +X.
        r, root, _ = self.plot("G90 G17 G00 X10. Y0 Z0\nG02 X0 Y-10. R10. F100.\n"
                               "G03 X-10. Y0 R10.\nG18 G03 X0 Z10. R10.\n"
                               "G19 G00 Y0 Z0\nG02 Y10. Z10. R10.\nM30\n")
        self.assertEqual(r.returncode, 0, r.stderr)
        flags = lambda d: re.findall(r" A\S+ \S+ 0 0 ([01]) ", d)
        top = move_paths(view(root, "top"))
        self.assertEqual(flags(top[1].get("d")), ["1"])
        self.assertEqual(flags(top[2].get("d")), ["0"])
        self.assertEqual(flags(move_paths(view(root, "front"))[3].get("d")), ["1"])
        self.assertEqual(flags(move_paths(view(root, "side"))[5].get("d")), ["1"])

    def test_extents_of_the_feed_moves(self):
        r, root, _ = self.plot(TOOLS)
        self.assertEqual(r.returncode, 0, r.stderr)
        ext = {t.get("data-axis"): (t.get("data-min"), t.get("data-max"), t.text)
               for t in root.iter(f"{SVG}text") if t.get("class") == "extent"}
        # Feed moves: X 10..30 (the circle reaches X 30), Y -5..5, Z -1..10 (the G18 arc
        # from Z10 around Z10 X30 to X40 bulges to Z 20).
        self.assertEqual(ext["X"][:2], ("10.000", "40.000"))
        self.assertEqual(ext["Y"][:2], ("-5.000", "5.000"))
        self.assertEqual(ext["Z"][:2], ("-1.000", "20.000"))
        self.assertEqual(ext["X"][2], "X 10.000 to 40.000 (30.000)")
        # In the orthographic views a dashed box around them, its sizes written along it.
        for name, sizes in (("top", ["X 30.000", "Y 10.000"]), ("front", ["X 30.000", "Z 21.000"]),
                            ("side", ["Y 10.000", "Z 21.000"])):
            box = view(root, name).find(f"{SVG}g[@class='extents-box']")
            self.assertEqual([t.text for t in box.findall(f"{SVG}text")], sizes, name)
        self.assertIsNone(view(root, "iso").find(f"{SVG}g[@class='extents-box']"))

    def test_from_to_restricts_the_moves(self):
        r, root, path = self.plot(os.path.join(EXAMPLES, "bolt-circle.nc"), "--from", "15",
                                  "--to", "16")
        self.assertEqual(r.returncode, 0, r.stderr)
        moves = [m for m in moves_of(path) if 15 <= m["line"] <= 16]
        paths = move_paths(view(root, "top"))
        self.assertEqual(len(paths), len(moves))
        self.assertEqual(len(paths), 12)  # 6 holes, each a rapid and a plunge
        self.assertEqual({p.get("data-line") for p in paths}, {"15", "16"})
        r, root, _ = self.plot(path, "--from", "16")
        self.assertTrue(all(int(p.get("data-line")) >= 16 for p in move_paths(view(root, "top"))))
        r = ncc("plot", path, "--from", "9", "--to", "3", "-o", self.path("bad.svg"))
        self.assertEqual(r.returncode, 2)
        self.assertIn("NCC0010", r.stderr)
        self.assertFalse(os.path.exists(self.path("bad.svg")))

    def test_from_to_leaves_out_other_files(self):
        main = self.write("main.nc", "G90 G00 X1.\nM98 P1234\nG00 X2.\nM30\n")
        self.write("O1234.nc", "O1234\nG01 X5. F100.\nM99\n")
        r, root, _ = self.plot(main)
        self.assertEqual([title_of(p).split(": ")[0] for p in move_paths(view(root, "top"))],
                         ["main.nc:1", "O1234.nc:2", "main.nc:3"])
        r, root, _ = self.plot(main, "--from", "1", "--to", "3")
        self.assertEqual([title_of(p).split(": ")[0] for p in move_paths(view(root, "top"))],
                         ["main.nc:1", "main.nc:3"])

    def test_machine_without_y(self):
        machine = self.write("lathe.toml", '[machine]\naxes = ["X", "Z"]\n')
        r, root, _ = self.plot("G00 X10. Z5.\nG01 Z-5. F100.\nM30\n", "--machine", machine)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(title_of(move_paths(view(root, "front"))[1]),
                         "part.nc:2: G01 X10.000 Z-5.000 (T0)")
        extents = [t.get("data-axis") for t in root.iter(f"{SVG}text") if t.get("class") == "extent"]
        self.assertEqual(extents, ["X", "Z"])

    def test_view_and_size(self):
        r, root, _ = self.plot(TOOLS, "--view", "front", "--size", "640x480")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual((root.get("width"), root.get("height")), ("640", "480"))
        views = [g.get("id") for g in root.iter(f"{SVG}g") if g.get("class") == "view"]
        self.assertEqual(views, ["view-front"])
        # Every point of a single view lies inside the drawing.
        for p in move_paths(view(root, "front")):
            nums = [float(n) for n in re.findall(r"-?\d+\.\d+", p.get("d"))]
            xs, ys = nums[0::2], nums[1::2]
            if " A" in p.get("d"):
                continue
            self.assertTrue(all(0 <= x <= 640 for x in xs) and all(0 <= y <= 480 for y in ys))
        for bad in ("640", "10x10", "axb", "640x480x2", "-640x480"):
            r = ncc("plot", self.path("part.nc"), "--size", bad, "-o", self.path("b.svg"))
            self.assertEqual(r.returncode, 2, bad)
            self.assertFalse(os.path.exists(self.path("b.svg")))
        r = ncc("plot", self.path("part.nc"), "--view", "bottom", "-o", self.path("b.svg"))
        self.assertEqual(r.returncode, 2)

    def test_stdout_and_bytecode_input(self):
        src = self.write("p.nc", TOOLS)
        r = ncc("plot", src)
        self.assertEqual(r.returncode, 0, r.stderr)
        from_source = r.stdout
        ET.fromstring(from_source.encode())
        ncb = self.path("p.ncb")
        self.assertEqual(ncc("compile", src, "-o", ncb).returncode, 0)
        r = ncc("plot", ncb, "-o", "-")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(r.stdout, from_source, "the same drawing from the source and the .ncb")
        self.assertEqual(len(move_paths(view(ET.fromstring(r.stdout.encode()), "top"))), 7)
        # The standard input: named <stdin>, escaped in the XML.
        r = ncc("plot", "-", stdin=TOOLS)
        self.assertEqual(r.returncode, 0, r.stderr)
        first = move_paths(view(ET.fromstring(r.stdout.encode()), "top"))[0]
        self.assertTrue(title_of(first).startswith("<stdin>:3: G00 X10.000"))

    def test_program_errors_write_nothing(self):
        r, root, _ = self.plot("G01 X10. F100.\nG01 X#\nM30\n")
        self.assertEqual(r.returncode, 1)
        self.assertIsNone(root)
        self.assertRegex(r.stderr, r"part\.nc:2:\d+: error\[")

    def test_alarm_draws_up_to_it_and_exits_3(self):
        # G95 with the spindle stopped: alarm NCC7207 at line 3.
        r, root, _ = self.plot("G21 G90 G17\nG01 X5. F600.\nG95 G01 X10. F0.1\nM30\n")
        self.assertEqual(r.returncode, 3, r.stderr)
        self.assertIn("part.nc:3:", r.stderr)
        self.assertIn("NCC7207", r.stderr)
        top = view(root, "top")
        self.assertEqual(len(move_paths(top)), 1)
        alarm = top.find(f"{SVG}g[@class='alarm']")
        self.assertIsNotNone(alarm)
        self.assertTrue(title_of(alarm).startswith("alarm NCC7207 at part.nc:3: "))

    def test_outputs_never_replace_inputs(self):
        src = self.write("p.nc", TOOLS)
        with open(src) as f:
            before = f.read()
        r = ncc("plot", src, "-o", src)
        self.assertEqual(r.returncode, 2)
        self.assertIn("NCC0005", r.stderr)
        with open(src) as f:
            self.assertEqual(f.read(), before)
        r = ncc("plot", src, "-o", self.path("missing/out.svg"))
        self.assertEqual(r.returncode, 2)
        self.assertIn("NCC0004", r.stderr)
        self.assertEqual(sorted(os.listdir(self.dir)), ["p.nc"])

    def test_odd_file_names_stay_valid_xml(self):
        name = "a&b<c>\"d.nc"
        r, root, _ = self.plot("G00 X1.\nM30\n", name=name)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertTrue(title_of(move_paths(view(root, "top"))[0]).startswith(name + ":1: G00"))

    def test_docs_drawing_is_current(self):
        """docs/images/bolt-circle.svg is what the command draws today (regenerate: see
        docs/cli.md, "ncc plot")."""
        out = self.path("bolt.svg")
        r = ncc("plot", "examples/bolt-circle.nc", "-o", out, cwd=ROOT)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(out, encoding="utf-8") as a, \
                open(os.path.join(ROOT, "docs", "images", "bolt-circle.svg"), encoding="utf-8") as b:
            self.assertEqual(a.read(), b.read())


if __name__ == "__main__":
    NCC = sys.argv.pop(1)
    unittest.main()
