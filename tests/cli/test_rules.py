#!/usr/bin/env python3
"""End-to-end tests of the foundation's rules against the manuals (issue 21), through `ncc`:
helical turns and full-circle repeats, the helical feed, Mazak's inch dwell, the mixed
decimal-point warning (NCC2034) and the codes that are real but not supported yet.
docs/semantics.md ("The foundation's rules against the manuals") lists the rules.

Run by ctest as: test_rules.py NCC_BINARY
"""
import json
import os
import re
import subprocess
import sys
import unittest

from cli_harness import ScratchDirTest

NCC = None


def ncc(*args):
    return subprocess.run([NCC, *args], capture_output=True, text=True, timeout=60)


class RulesTest(ScratchDirTest):
    def moves(self, program, dialect):
        proc = ncc("run", self.write("p.nc", program), "--dialect", dialect, "--emit=moves")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        return [json.loads(line) for line in proc.stdout.splitlines()]

    def ir_arcs(self, program, dialect):
        proc = ncc("compile", self.write("p.nc", program), "--dialect", dialect, "--emit=ir")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        return [line for line in proc.stdout.splitlines() if " arc " in f" {line.strip()} "]

    def run_seconds(self, program, dialect):
        """Simulated program time from the `ncc run` summary."""
        proc = ncc("run", self.write("p.nc", program), "--dialect", dialect)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        found = re.search(r"program time\s+([0-9.]+) s", proc.stdout)
        self.assertIsNotNone(found, proc.stdout)
        return float(found.group(1))

    # ---- arcs ---------------------------------------------------------------------------

    def test_mazak_helical_p_adds_turns(self):
        arcs = self.ir_arcs("G00 X10. Y0\nG17 G03 X0 Y10. Z-9. I-10. P2 F100.\nM30\n", "mazak-m")
        self.assertEqual(len(arcs), 1, arcs)
        self.assertIn("turns 2", arcs[0])
        # Without P the same arc has no extra turn.
        arcs = self.ir_arcs("G00 X10. Y0\nG17 G03 X0 Y10. Z-9. I-10. F100.\nM30\n", "mazak-m")
        self.assertNotIn("turns", arcs[0])

    def test_siemens_full_circle_l_repeats_and_takes_that_long(self):
        once = "G17 G02 I10. J0 F600.\nM30\n"
        thrice = "G17 G02 I10. J0 F600. L3\nM30\n"
        self.assertIn("turns 2", self.ir_arcs(thrice, "siemens-iso-m")[0])
        # 62.8 mm per turn at 600 mm/min: about 6.3 s a turn, so three turns take ~12.6 s more.
        t1 = self.run_seconds(once, "siemens-iso-m")
        t3 = self.run_seconds(thrice, "siemens-iso-m")
        self.assertAlmostEqual(t3 - t1, 2 * 2 * 3.14159265 * 10 / 10.0, delta=0.2)

    def test_l_on_an_open_arc_has_no_meaning(self):
        proc = ncc("check", self.write("p.nc", "G02 X20. Y0 I10. F100. L2\n"),
                   "--dialect", "siemens-iso-m")
        self.assertEqual(proc.returncode, 1)
        self.assertIn("p.nc:1:24: error[NCC2014]: address L has no meaning in this block",
                      proc.stderr)

    def test_helical_feed_fanuc_along_the_arc_mazak_along_the_helix(self):
        program = "G00 X10. Y0\nG17 G03 X0 Y10. Z-5. I-10. F100.\nM30\n"
        fanuc = [m for m in self.moves(program, "fanuc-m") if m["kind"] == "arc"]
        mazak = [m for m in self.moves(program, "mazak-m") if m["kind"] == "arc"]
        self.assertAlmostEqual(fanuc[0]["feed"], 104.943851, places=5)
        self.assertAlmostEqual(mazak[0]["feed"], 100.0, places=6)

    # ---- dwell --------------------------------------------------------------------------

    def test_helical_feed_follows_the_htg_parameter(self):
        # fanuc-m: F along the arc (HTG = 0), so the IR feed is F x helix length / arc length;
        # helical_feed_along_arc = false (HTG = 1) takes F along the helix as it stands.
        program = "G90 G17 G00 X10. Y0 Z0\nG03 X-10. Y0 Z-10. R10. F100.\nM30\n"
        along_arc = self.moves(program, "fanuc-m")[-1]["feed"]
        arc = 3.141592653589793 * 10.0
        self.assertAlmostEqual(along_arc, 100.0 * (arc * arc + 100.0) ** 0.5 / arc, places=6)
        machine = self.write("m.toml", "[machine.params]\nhelical_feed_along_arc = false\n")
        proc = ncc("run", self.path("p.nc"), "--dialect", "fanuc-m", "--machine", machine, "--emit=moves")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual(json.loads(proc.stdout.splitlines()[-1])["feed"], 100.0)

    def test_a_plane_of_a_parallel_axis_is_refused_not_misread(self):
        # Mazak §6-2: `G17 U_ Y_` selects the UY plane; not built yet, so an error at U rather
        # than arcs in the XY plane. With its base axis beside it, U just moves (base first).
        machine = self.write("u.toml", '[machine]\naxes = ["X", "Y", "Z", "U"]\n')
        plane = self.write("u.nc", "G90 G00 X0 Y0 U0\nG17 U10. Y0\nG02 U20. Y0 I5. J0 F100.\nM30\n")
        proc = ncc("check", plane, "--dialect", "mazak-m", "--machine", machine)
        self.assertEqual(proc.returncode, 1, proc.stderr)
        self.assertIn("u.nc:2:5: error[NCC2010]: a plane selected by the parallel axis U (instead of X)",
                      proc.stderr)
        both = self.write("b.nc", "G90 G17 G00 X0 Y0 U0\nG02 X10. Y0 U5. I5. J0 F100.\nM30\n")
        proc = ncc("run", both, "--dialect", "mazak-m", "--machine", machine, "--emit=moves")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        arc = json.loads(proc.stdout.splitlines()[-1])
        self.assertEqual((arc["kind"], arc["to"]["X"], arc["to"]["U"]), ("arc", 10.0, 5.0))

    def test_default_feed_before_any_f(self):
        # Sinumerik SD42110 DEFAULT_FEED: the feed of a cutting move before any F.
        program = "G90 G01 X10. Y0\nG01 X20.\nF100.\nG01 X30.\nM30\n"
        proc = ncc("run", self.write("p.nc", program), "--dialect", "siemens-iso-m", "--emit=moves")
        self.assertEqual(proc.returncode, 1, proc.stderr)
        self.assertIn("error[10860]", proc.stderr)  # without the setting
        machine = self.write("m.toml", "[machine.params]\ndefault_feed = 500.0\n")
        proc = ncc("run", self.path("p.nc"), "--dialect", "siemens-iso-m", "--machine", machine,
                   "--emit=moves")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        feeds = [json.loads(line)["feed"] for line in proc.stdout.splitlines()]
        self.assertEqual(feeds, [500.0, 500.0, 100.0])  # until the first F
        # A G95 move is not given a per-minute default.
        g95 = self.write("r.nc", "G90 G95 S1000 M03\nG01 X10.\nM30\n")
        proc = ncc("run", g95, "--dialect", "siemens-iso-m", "--machine", machine)
        self.assertEqual(proc.returncode, 1, proc.stderr)
        self.assertIn("error[10860]", proc.stderr)

    def test_mazak_inch_x_before_g04_is_fifty_seconds(self):
        dwells = [m for m in self.moves("G20\nX5. G04\nG04 X5.\nM30\n", "mazak-m")
                  if m["kind"] == "dwell"]
        self.assertEqual([d["seconds"] for d in dwells], [50.0, 5.0])

    def test_siemens_dwell_block_alone(self):
        proc = ncc("check", self.write("p.nc", "G04 X1. M08\n"), "--dialect", "siemens-iso-m")
        self.assertEqual(proc.returncode, 1)
        self.assertIn("p.nc:1:9: error[NCC2014]: M cannot be given in a dwell (G04) block",
                      proc.stderr)

    # ---- decimal points -----------------------------------------------------------------

    def test_mixed_decimal_points_warn_once_with_the_count(self):
        program = "G00 X10. Y5.\nG01 Z3 F100.\nX20 Y1.5\nG00 X30. Y5\nM30\n"
        path = self.write("cam.nc", program)
        proc = ncc("check", path)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual(proc.stderr.count("warning[NCC2034]"), 1, proc.stderr)
        self.assertIn("cam.nc:2:5: warning[NCC2034]: 3 coordinate words without a decimal point "
                      "are read as least input increments (the first: Z3 = 0.003 mm)", proc.stderr)
        # The program still runs as written: Z goes to 0.003 mm.
        lines = [m for m in self.moves(program, "fanuc-m") if m["kind"] == "line"]
        self.assertAlmostEqual(lines[0]["to"]["Z"], 0.003, places=6)

    def test_one_notation_only_draws_no_warning(self):
        for text in ("G00 X10. Y5.\nG01 Z3. F100.\nM30\n", "G91 G00 X20000 Y20000\nG01 X2000 F300\nM30\n"):
            proc = ncc("check", self.write("p.nc", text))
            self.assertEqual(proc.returncode, 0, proc.stderr)
            self.assertNotIn("NCC2034", proc.stderr)

    # ---- codes not supported yet --------------------------------------------------------

    def test_real_codes_say_not_supported_yet_as_written(self):
        proc = ncc("check", self.write("p.nc", "G00 X0 Y0\nG05.1 Q1\nG5.1\nG68.2\nG14\nM30\n"))
        self.assertEqual(proc.returncode, 1)
        self.assertIn("p.nc:2:1: error[NCC2010]: G05.1 (AI contour control / nano smoothing) is "
                      "not supported yet", proc.stderr)
        self.assertIn("p.nc:3:1: error[NCC2010]: G5.1 (AI contour control", proc.stderr)
        self.assertIn("p.nc:4:1: error[NCC2010]: G68.2 (tilted working plane command) is not "
                      "supported yet", proc.stderr)
        self.assertIn("p.nc:5:1: error[PS0010]: G14 is not a G code of fanuc-m", proc.stderr)
        self.assertNotIn("G05.1 is not a G code", proc.stderr)


if __name__ == "__main__":
    NCC = sys.argv.pop(1)
    unittest.main()
