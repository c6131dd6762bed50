#!/usr/bin/env python3
"""End-to-end tests of `ncc run`'s summary (text and --emit=summary-json), its trace (line
column, --trace-every, CSV and .nct) and `ncc trace` (issue 21).

Run by ctest as: test_summary_trace.py NCC_BINARY
"""
import json
import os
import re
import subprocess
import sys
import unittest

from cli_harness import ScratchDirTest

NCC = None
EXAMPLES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples")

# Rapid to (10, 5), feed down to Z-2 and along X to 20, rapid up to Z5.
EXTENTS = "N10 G90 G00 X10. Y5.\nN20 G01 Z-2. F300.\nN30 X20.\nN40 G00 Z5.\nN50 M30\n"
# A line into a tangent full circle (line 3) and a tangent line out, then a rapid home.
ARC = ("N10 G90 G00 X20. Y-10.\nN20 G01 Y0 F3000.\nN30 G03 X20. Y0 I-10. J0\nN40 G01 Y10.\n"
       "N50 G00 X0 Y0\nN60 M30\n")
# Non-linear rapids only (each axis at its own speed: the path bends where one arrives).
RAPIDS = "N10 G90 G00 X100. Y30.\nN20 X0 Y80. Z-20.\nN30 X60. Y0 Z10.\nN40 M30\n"


def slurp(path, mode="r"):
    with open(path, mode) as f:
        return f.read()


def ncc(*args):
    return subprocess.run([NCC, *args], capture_output=True, text=True, timeout=120)


def field(text, pattern):
    match = re.search(pattern, text, re.MULTILINE)
    if match is None:
        raise AssertionError(f"no {pattern!r} in:\n{text}")
    return match


class SummaryTest(ScratchDirTest):
    def run_ok(self, *args):
        proc = ncc(*args)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        return proc.stdout

    def test_program_time_as_hours_minutes_seconds(self):
        # A dwell of 3723 s: 1 h 2 min 3 s.
        out = self.run_ok("run", self.write("dwell.nc", "N10 G04 P3723000\nN20 M30\n"))
        m = field(out, r"^program time +(\d+\.\d{3}) s \(\d+ ticks of 1 ms\) = (\d+):(\d\d):(\d\d)$")
        self.assertAlmostEqual(float(m.group(1)), 3723.0, delta=0.01)
        self.assertEqual(m.group(2, 3, 4), ("1", "02", "03"))
        # Rounded to the second: coordinates.nc runs 27.394 s.
        out = self.run_ok("run", os.path.join(EXAMPLES, "coordinates.nc"))
        m = field(out, r"^program time +(\d+\.\d{3}) s .* = (\d+:\d\d:\d\d)$")
        seconds = round(float(m.group(1)))
        self.assertEqual(m.group(2), f"{seconds // 3600}:{seconds // 60 % 60:02d}:{seconds % 60:02d}")

    def test_extents_of_feed_and_rapid_motion(self):
        out = self.run_ok("run", self.write("ext.nc", EXTENTS))
        self.assertIn("extents feed       X 10.000 .. 20.000  Y 5.000 .. 5.000  Z -2.000 .. 0.000 mm\n", out)
        self.assertIn("extents rapid      X 0.000 .. 20.000  Y 0.000 .. 5.000  Z -2.000 .. 5.000 mm\n", out)
        summary = json.loads(self.run_ok("run", self.write("ext.nc", EXTENTS), "--emit=summary-json"))
        self.assertEqual(summary["feed_extents"], {"X": {"min": 10.0, "max": 20.0},
                                                   "Y": {"min": 5.0, "max": 5.0},
                                                   "Z": {"min": -2.0, "max": 0.0}})
        self.assertEqual(summary["rapid_extents"], {"X": {"min": 0.0, "max": 20.0},
                                                    "Y": {"min": 0.0, "max": 5.0},
                                                    "Z": {"min": -2.0, "max": 5.0}})

    def test_worst_contour_error_names_the_arc(self):
        out = self.run_ok("run", self.write("arc.nc", ARC))
        m = field(out, r"^max contour error  (\d+\.\d{4}) mm \(t = \d+\.\d{3} s, (.+):(\d+)\)$")
        self.assertGreater(float(m.group(1)), 0.0)
        self.assertEqual(m.group(2, 3), ("arc.nc", "3"))
        summary = json.loads(self.run_ok("run", self.write("arc.nc", ARC), "--emit=summary-json"))
        self.assertEqual(summary["max_contour_error_file"], "arc.nc")
        self.assertEqual(summary["max_contour_error_line"], 3)

    def test_rapids_alone_have_no_contour_error(self):
        out = self.run_ok("run", self.write("rapids.nc", RAPIDS))
        self.assertIn("\nmax contour error  0.0000 mm\n", out)
        self.assertIn("extents feed       none\n", out)
        summary = json.loads(self.run_ok("run", self.write("rapids.nc", RAPIDS), "--emit=summary-json"))
        self.assertEqual(summary["max_contour_error"], 0.0)
        self.assertIsNone(summary["max_contour_error_line"])
        self.assertIsNone(summary["feed_extents"])
        self.assertGreater(summary["rapid_length"], 200.0)

    def test_summary_json_matches_the_text_summary(self):
        for program in ("coordinates.nc", "motion-basics.nc"):
            path = os.path.join(EXAMPLES, program)
            text = self.run_ok("run", path)
            raw = self.run_ok("run", path, "--emit=summary-json")
            self.assertEqual(raw.count("\n"), 1, "one object on one line")
            s = json.loads(raw)
            self.assertEqual(list(s), [
                "status", "alarm", "program_time", "program_time_hms", "ticks", "tick_seconds",
                "feed_length", "rapid_length", "feed_extents", "rapid_extents",
                "max_following_error", "max_contour_error", "max_contour_error_time",
                "max_contour_error_file", "max_contour_error_line", "limit_violations",
                "limit_violations_travel", "limit_violations_velocity",
                "limit_violations_acceleration", "lookahead_limited_percent",
                "lookahead_segments", "final_position"])
            m = field(text, r"^program time +(\S+) s \((\d+) ticks of (\S+) ms\) = (\S+)$")
            self.assertEqual(f"{s['program_time']:.3f}", m.group(1))
            self.assertEqual(s["ticks"], int(m.group(2)))
            self.assertEqual(s["tick_seconds"] * 1000, float(m.group(3)))
            self.assertEqual(s["program_time_hms"], m.group(4))
            m = field(text, r"^path length +(\S+) mm feed, (\S+) mm rapid$")
            self.assertEqual((f"{s['feed_length']:.3f}", f"{s['rapid_length']:.3f}"), m.group(1, 2))
            for kind in ("feed", "rapid"):
                line = field(text, rf"^extents {kind} +(.*) mm$").group(1)
                expected = "  ".join(f"{axis} {v['min']:.3f} .. {v['max']:.3f}"
                                     for axis, v in s[f"{kind}_extents"].items())
                self.assertEqual(line, expected)
            line = field(text, r"^max following error  (.*) mm$").group(1)
            self.assertEqual(line, "  ".join(f"{a} {v:.4f}" for a, v in s["max_following_error"].items()))
            m = field(text, r"^max contour error  (\S+) mm \(t = (\S+) s, (.+):(\d+)\)$")
            self.assertEqual(f"{s['max_contour_error']:.4f}", m.group(1))
            self.assertEqual(f"{s['max_contour_error_time']:.3f}", m.group(2))
            self.assertEqual((s["max_contour_error_file"], s["max_contour_error_line"]),
                             (m.group(3), int(m.group(4))))
            self.assertEqual(program, s["max_contour_error_file"])
            m = field(text, r"^limit violations   (\d+) \(servo actual: (\d+) travel, (\d+) velocity, (\d+) acceleration ticks\)$")
            self.assertEqual([s["limit_violations"], s["limit_violations_travel"],
                              s["limit_violations_velocity"], s["limit_violations_acceleration"]],
                             [int(g) for g in m.groups()])
            m = field(text, r"^look-ahead limited (\S+) % of the time \((\d+) segments")
            self.assertEqual(f"{s['lookahead_limited_percent']:.1f}", m.group(1))
            self.assertEqual(s["lookahead_segments"], int(m.group(2)))
            line = field(text, r"^final position     (.*)$").group(1)
            self.assertEqual(line, " ".join(f"{a}{v!r}" for a, v in s["final_position"].items()))
            self.assertEqual((s["status"], s["alarm"]), ("completed", None))
            self.assertIn("status             completed", text)

    def test_summary_json_of_an_alarm(self):
        prog = self.write("g95.nc", "G21 G90 G17\nG01 X5. F600.\nG95 G01 X10. F0.1\nM30\n")
        proc = ncc("run", prog, "--emit=summary-json")
        self.assertEqual(proc.returncode, 3, proc.stderr)
        self.assertIn("g95.nc:3:1: error[NCC7207]", proc.stderr)
        # The summary goes where it always goes (stdout), its status saying the alarm.
        s = json.loads(proc.stdout)
        self.assertEqual((s["status"], s["alarm"]), ("alarm", "NCC7207"))
        self.assertEqual(s["final_position"]["X"], 5.0)


class TraceTest(ScratchDirTest):
    def trace(self, program, name, *more):
        proc = ncc("run", program, "--emit=trace", "-o", self.path(name), *more)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        return self.path(name)

    def test_csv_has_the_source_line_of_each_tick(self):
        with open(self.path("arc.nc"), "w") as f:
            f.write(ARC)
        rows = slurp(self.trace(self.path("arc.nc"), "arc.csv")).splitlines()
        self.assertEqual(rows[0], "t,X_cmd,Y_cmd,Z_cmd,X_act,Y_act,Z_act,line")
        lines = [int(row.rsplit(",", 1)[1]) for row in rows[1:]]
        self.assertEqual(lines, sorted(lines), "blocks run in program order")
        self.assertEqual(sorted(set(lines)), [1, 2, 3, 4, 5])
        # The circle's ticks are on its radius 10 around (10, 0), up to the sampling.
        for row in rows[1:]:
            cells = row.split(",")
            if cells[-1] == "3":
                self.assertAlmostEqual(((float(cells[1]) - 10) ** 2 + float(cells[2]) ** 2) ** 0.5,
                                       10.0, delta=1e-6)

    def test_trace_every_10_keeps_every_10th_tick(self):
        program = os.path.join(EXAMPLES, "coordinates.nc")
        full = slurp(self.trace(program, "full.csv")).splitlines()
        thin = slurp(self.trace(program, "thin.csv", "--trace-every", "10")).splitlines()
        self.assertEqual(thin[0], full[0])
        self.assertEqual(thin[1:], full[1::10])
        self.assertEqual(len(thin) - 1, (len(full) - 2) // 10 + 1)
        ticks = [round(float(row.split(",")[0]) * 1000) for row in thin[1:]]
        self.assertEqual(ticks, list(range(0, 10 * len(ticks), 10)))
        # The binary trace thins alike, and converts to the same rows.
        nct = self.trace(program, "thin.nct", "--trace-every", "10")
        proc = ncc("trace", nct)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual(proc.stdout.splitlines(), thin)
        # 0 is no stride.
        self.assertEqual(ncc("run", program, "--emit=trace", "--trace-every", "0").returncode, 2)

    def test_nct_converts_to_the_direct_csv_byte_for_byte(self):
        # motion-basics.nc: some 66,000 ticks; version 1 traces differed from the CSV on 3 of them.
        program = os.path.join(EXAMPLES, "motion-basics.nc")
        csv = slurp(self.trace(program, "mb.csv"), "rb")
        ticks = int(re.search(r"\((\d+) ticks", ncc("run", program).stdout).group(1))
        self.assertGreater(ticks, 60000)
        self.assertEqual(csv.count(b"\n"), ticks + 1)  # a header, then a row per tick
        self.assertNotIn(b"-0.000000", csv)
        nct = self.trace(program, "mb.nct")
        self.assertLess(os.path.getsize(nct), len(csv) // 4)
        proc = subprocess.run([NCC, "trace", nct, "-o", self.path("conv.csv")], capture_output=True)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual(proc.stdout, b"")
        self.assertEqual(slurp(self.path("conv.csv"), "rb"), csv)
        proc = subprocess.run([NCC, "trace", nct], capture_output=True)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual(proc.stdout, csv)

    def test_malformed_traces_are_errors_with_a_code(self):
        with open(self.path("a.nc"), "w") as f:
            f.write(EXTENTS)
        good = slurp(self.trace(self.path("a.nc"), "a.nct"), "rb")
        cases = {
            "empty.nct": (b"", "NCC0050"),
            "csv.nct": (b"t,X_cmd\n0.0,0.0\n", "NCC0050"),
            "v1.nct": (good[:4] + b"\x01" + good[5:], "NCC0051"),
            "truncated.nct": (good[: len(good) // 2], "NCC0052"),
            "no-end.nct": (good[:-1], "NCC0052"),
            "junk-after.nct": (good + b"\x01", "NCC0052"),
            "bad-marker.nct": (good[:-1] + b"\x07", "NCC0052"),
        }
        for name, (data, code) in cases.items():
            with open(self.path(name), "wb") as f:
                f.write(data)
            out = self.path(name + ".csv")
            proc = ncc("trace", self.path(name), "-o", out)
            self.assertEqual(proc.returncode, 1, (name, proc.stderr))
            self.assertRegex(proc.stderr, rf"{re.escape(name)}: error\[{code}\]: .+ \(at byte \d+\)", name)
            self.assertFalse(os.path.exists(out), name)
            self.assertFalse(os.path.exists(out + ".tmp"), name)
        proc = ncc("trace", self.path("missing.nct"))
        self.assertEqual(proc.returncode, 2)
        self.assertIn("cannot read", proc.stderr)

    def test_help_names_the_trace_command(self):
        proc = ncc("trace", "--help")
        self.assertEqual(proc.returncode, 0)
        self.assertIn("CSV", proc.stdout)
        self.assertIn("trace", ncc("--help").stdout)


if __name__ == "__main__":
    NCC = sys.argv.pop(1)
    unittest.main(verbosity=2)
