#!/usr/bin/env python3
"""End-to-end tests of the `ncc` command line: commands, options, exit codes, output files.

Run by ctest as: test_cli.py NCC_BINARY
"""
import json
import math
import re
import os
import subprocess
import sys
import unittest

from cli_harness import ScratchDirTest

NCC = None

GOOD = "N10 G90 G00 X10. Y5.\nN20 G01 Z-2. F100.\nN30 G02 X20. Y5. R5.\nN40 G04 X1.5\nN50 M30\n"
BAD = "N10 G90 G00 X10.\nN20 G01 X20. Q@\nN30 G01 Y5.\nN40 M30\n"


def slurp(path, mode="r"):
    with open(path, mode) as f:
        return f.read()


def ncc(*args, cwd=None):
    return subprocess.run([NCC, *args], capture_output=True, text=True, timeout=60, cwd=cwd)


class CliTest(ScratchDirTest):
    def test_help_everywhere_exits_zero(self):
        for args in (["--help"], ["compile", "--help"], ["check", "--help"], ["dis", "--help"], ["run", "--help"]):
            proc = ncc(*args)
            self.assertEqual(proc.returncode, 0, args)
            self.assertIn("--", proc.stdout)

    def test_usage_errors_exit_two(self):
        self.assertEqual(ncc().returncode, 2)
        self.assertEqual(ncc("frobnicate").returncode, 2)
        good = self.write("a.nc", GOOD)
        self.assertEqual(ncc("run", good, "--emit=bogus").returncode, 2)
        proc = ncc("check", good, "--dialect", "heidenhain")
        self.assertEqual(proc.returncode, 2)
        self.assertIn("unknown dialect 'heidenhain'", proc.stderr)
        proc = ncc("check", os.path.join(self.dir, "missing.nc"))
        self.assertEqual(proc.returncode, 2)
        self.assertIn("no such file", proc.stderr)

    def test_unsupported_dialect_is_reported(self):
        good = self.write("a.nc", GOOD)
        proc = ncc("check", good, "--dialect", "fanuc-t")
        self.assertEqual(proc.returncode, 2)
        self.assertIn("dialect 'fanuc-t' is not supported yet", proc.stderr)
        # .mpf defaults to siemens-din: DIN text (an R parameter) is read.
        mpf = self.write("a.mpf", "R1=2\nG0 X=R1*2\nM30\n")
        proc = ncc("run", mpf, "--emit=moves")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertIn('"X": 4.0', proc.stdout)

    def test_check_clean_program(self):
        proc = ncc("check", self.write("a.nc", GOOD))
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual(proc.stderr, "")

    def test_errors_have_location_code_source_line_and_caret(self):
        bad = self.write("bad.nc", BAD)
        proc = ncc("check", bad)
        self.assertEqual(proc.returncode, 1)
        first = proc.stderr.splitlines()[0]
        self.assertRegex(first, r"bad\.nc:2:\d+: error\[[A-Z0-9]+\]: ")
        self.assertIn("  N20 G01 X20. Q@", proc.stderr)
        self.assertRegex(proc.stderr, r"\n +\^\n")

    def test_compile_writes_bytecode_and_no_partial_file_on_error(self):
        good = self.write("a.nc", GOOD)
        out = os.path.join(self.dir, "a.ncb")
        proc = ncc("compile", good, "-o", out)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual(slurp(out, "rb")[:4], b"NCCB")
        bad = self.write("bad.nc", BAD)
        bad_out = os.path.join(self.dir, "bad.ncb")
        self.assertEqual(ncc("compile", bad, "-o", bad_out).returncode, 1)
        self.assertFalse(os.path.exists(bad_out))
        self.assertFalse(os.path.exists(bad_out + ".tmp"))

    def test_failed_compile_keeps_previous_output(self):
        good = self.write("a.nc", GOOD)
        out = os.path.join(self.dir, "a.ncb")
        self.assertEqual(ncc("compile", good, "-o", out).returncode, 0)
        before = slurp(out, "rb")
        self.write("a.nc", BAD)
        self.assertEqual(ncc("compile", good, "-o", out).returncode, 1)
        self.assertEqual(slurp(out, "rb"), before)

    def test_emit_ast_and_ir(self):
        good = self.write("a.nc", GOOD)
        ast = ncc("compile", good, "--emit=ast")
        self.assertEqual(ast.returncode, 0, ast.stderr)
        self.assertEqual(len(ast.stdout.splitlines()), 5)
        self.assertIn("G2", ast.stdout.replace("G02", "G2"))
        ir = ncc("compile", good, "--emit=ir")
        self.assertEqual(ir.returncode, 0, ir.stderr)
        self.assertIn("arc", ir.stdout.lower())

    def test_run_moves_from_source_and_from_bytecode_agree(self):
        good = self.write("a.nc", GOOD)
        from_source = ncc("run", good, "--emit=moves")
        self.assertEqual(from_source.returncode, 0, from_source.stderr)
        moves = [json.loads(l) for l in from_source.stdout.splitlines()]
        self.assertEqual([m["kind"] for m in moves], ["rapid", "line", "arc", "dwell"])
        self.assertEqual(moves[0], {"line": 1, "file": "a.nc", "kind": "rapid", "to": {"X": 10.0, "Y": 5.0, "Z": 0.0}})
        self.assertEqual(moves[2]["center"], {"X": 15.0, "Y": 5.0})
        self.assertIs(moves[2]["cw"], True)
        self.assertEqual(moves[3]["seconds"], 1.5)
        out = os.path.join(self.dir, "a.ncb")
        self.assertEqual(ncc("compile", good, "-o", out).returncode, 0)
        from_bytecode = ncc("run", out, "--emit=moves")
        self.assertEqual(from_bytecode.returncode, 0, from_bytecode.stderr)
        self.assertEqual(from_bytecode.stdout, from_source.stdout)

    def test_run_summary_and_output_file(self):
        good = self.write("a.nc", GOOD)
        proc = ncc("run", good)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertRegex(proc.stdout, r"program time +\d+\.\d{3} s \(\d+ ticks of 1 ms\)")
        self.assertIn("max following error  X ", proc.stdout)
        self.assertIn("max contour error", proc.stdout)
        self.assertIn("limit violations", proc.stdout)
        self.assertIn("final position     X20.0 Y5.0 Z-2.0", proc.stdout)
        self.assertIn("status             completed", proc.stdout)
        out = os.path.join(self.dir, "moves.jsonl")
        proc = ncc("run", good, "--emit=moves", "-o", out)
        self.assertEqual(proc.returncode, 0)
        self.assertEqual(len(slurp(out).splitlines()), 4)

    def disassemble(self, source):
        ncb = source + ".ncb"
        proc = ncc("compile", source, "-o", ncb)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        proc = ncc("dis", ncb)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        return proc.stdout

    def test_run_overrides_scale_the_program_time(self):
        # A single long G01 at F600: at 50 % feed override the cruise takes twice as long.
        prog = self.write("long.nc", "G21 G90 G94 G17\nG01 X100. F600.\nM30\n")
        def seconds(*extra):
            proc = ncc("run", prog, *extra)
            self.assertEqual(proc.returncode, 0, proc.stderr)
            return float(re.search(r"program time +(\d+\.\d+) s", proc.stdout).group(1))
        full, half = seconds(), seconds("--feed-override=50")
        self.assertAlmostEqual(half / full, 2.0, delta=0.02)
        rapid = self.write("rapid.nc", "G21 G90\nG00 X400.\nM30\n")
        proc_full = ncc("run", rapid)
        proc_slow = ncc("run", rapid, "--rapid-override=25")
        t_full = float(re.search(r"program time +(\d+\.\d+) s", proc_full.stdout).group(1))
        t_slow = float(re.search(r"program time +(\d+\.\d+) s", proc_slow.stdout).group(1))
        self.assertGreater(t_slow, 3.0 * t_full)
        # G63 (tapping mode) fixes the feed override at 100 % for its moves: the same time at
        # 50 % as at 100 %; after G64 the override applies again.
        tap = self.write("tap.nc", "G21 G90 G94 G17\nS500 M03\nG63 G01 Z-100. F600.\nM30\n")
        self.assertIn("fixed-override", self.disassemble(tap))
        tap_full = float(re.search(r"program time +(\d+\.\d+) s", ncc("run", tap).stdout).group(1))
        tap_half = float(re.search(r"program time +(\d+\.\d+) s",
                                   ncc("run", tap, "--feed-override=50").stdout).group(1))
        self.assertEqual(tap_full, tap_half)
        cut = self.write("cut.nc", "G21 G90 G94 G17\nG63 G01 Z-1. F600.\nG64 G01 X100. F600.\nM30\n")
        listing = self.disassemble(cut)
        self.assertEqual(listing.count("fixed-override"), 1, listing)
        for bad in ("--feed-override=0", "--feed-override=250", "--rapid-override=150"):
            proc = ncc("run", prog, bad)
            self.assertEqual(proc.returncode, 2, bad)
            self.assertIn("override", proc.stderr)

    def long_line_seconds(self, prog, *extra):
        # `ncc run` of a G01 X300 program that completes on X300: its program time.
        proc = ncc("run", prog, *extra)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertIn("status             completed", proc.stdout)
        self.assertIn("final position     X300.0", proc.stdout)
        return float(re.search(r"program time +(\d+\.\d+) s", proc.stdout).group(1))

    def test_run_feed_override_turned_during_the_run(self):
        # G01 X300 at F6000 (100 mm/s): turned to 50 % at 1 s, the remaining 200 mm or so run
        # at half speed, about 2 s longer; turned back to 100 % at 2 s, the second in between
        # covers 50 mm instead of 100: 0.5 s longer. Written unsorted, the turns apply in
        # time order. A bad turn is a usage error naming it, and writes no output file.
        prog = self.write("long300.nc", "G21 G90 G94 G17\nG01 X300. F6000.\nM30\n")
        seconds = lambda *extra: self.long_line_seconds(prog, *extra)
        full = seconds()
        halved = seconds("--feed-override-at", "1=50")
        self.assertAlmostEqual(halved - full, 2.0, delta=0.1)
        back = seconds("--feed-override-at", "2=100", "--feed-override-at", "1=50")
        self.assertAlmostEqual(back - full, 0.5, delta=0.1)
        # Turned up from 50 % to 100 % at 1 s: planned for 100 %, the rest at full speed.
        up = seconds("--feed-override=50", "--feed-override-at", "1=100")
        self.assertAlmostEqual(up - full, 0.5, delta=0.1)
        out = os.path.join(self.dir, "turned.csv")
        for bad in ("1", "x=50", "1=0", "1=250", "-1=50", "1=50%", "inf=50", "1=0x32", "0x1=50",
                    " 1=50", "+1=50", "1=50 "):
            proc = ncc("run", prog, "--feed-override-at", bad, "--emit=trace", "-o", out)
            self.assertEqual(proc.returncode, 2, bad)
            self.assertIn("--feed-override-at '%s'" % bad, proc.stderr)
            self.assertFalse(os.path.exists(out), bad)

    def test_run_rapid_override_turned_during_the_run(self):
        # A linear G00 X2000 at 500 mm/s (path a 2000 mm/s2, j 45000 mm/s3): 4.294 s. Turned
        # to 25 % at 1 s, it brakes 500 -> 125 mm/s (0.232 s, 72.5 mm) and runs the rest at
        # 125 mm/s: 1 + 0.232 + 1494.4 / 125 + 0.107 (the stop) = 13.294 s, 9.0 s longer.
        # Turned back at 2 s, the second in between covers about 125 mm instead of 500: 0.75 s
        # longer. A non-linear G00 along X alone moves like the linear one, turn included, but
        # with the whole jerk (it is at rest at both ends; the linear one is planned before its
        # end is known): its three ramps take 4.5 ms less. Bad values are usage errors naming
        # them.
        prog = self.write("rapid2000.nc", "G21 G90 G17\nG00 X2000.\nM30\n")
        linear = self.write("linear.toml", '[machine.params]\nrapid_type = "linear"\n')
        per_axis = self.write("per_axis.toml", '[machine.params]\nrapid_type = "per_axis"\n')

        def seconds(machine, *extra):
            proc = ncc("run", prog, "--machine", machine, *extra)
            self.assertEqual(proc.returncode, 0, proc.stderr)
            self.assertIn("final position     X2000.0", proc.stdout)
            return float(re.search(r"program time +(\d+\.\d+) s", proc.stdout).group(1))

        full = seconds(linear)
        slowed = seconds(linear, "--rapid-override-at", "1=25")
        self.assertAlmostEqual(full, 4.294, delta=0.002)
        self.assertAlmostEqual(slowed - full, 9.0, delta=0.003)
        back = seconds(linear, "--rapid-override-at", "2=100", "--rapid-override-at", "1=25")
        self.assertAlmostEqual(back - full, 0.75, delta=0.05)
        self.assertAlmostEqual(seconds(per_axis, "--rapid-override-at", "1=25"), slowed - 0.0045,
                               delta=0.0015)
        for bad in ("1", "1=0", "1=150", "x=50", "-1=50", "1=0x32"):
            proc = ncc("run", prog, "--rapid-override-at", bad)
            self.assertEqual(proc.returncode, 2, bad)
            self.assertIn("--rapid-override-at '%s'" % bad, proc.stderr)

    def test_run_feed_hold_during_the_run(self):
        # Held at 1 s for 2 s, and at 5 s (after the end) for 1 s: the long line stops on its
        # path, goes on, and the run takes 2 s longer; overlapping or malformed holds are usage
        # errors naming the value.
        prog = self.write("hold300.nc", "G21 G90 G94 G17\nG01 X300. F6000.\nM30\n")
        seconds = lambda *extra: self.long_line_seconds(prog, *extra)
        full = seconds()
        held = seconds("--feed-hold-at", "1=2", "--feed-hold-at", "9=1")
        self.assertAlmostEqual(held - full, 2.0, delta=0.002)
        for bad in ("1", "1=-2", "x=1", "nan=1", "1=0x2", "1=0", "1=1e7"):
            proc = ncc("run", prog, "--feed-hold-at", bad)
            self.assertEqual(proc.returncode, 2, bad)
            self.assertIn("--feed-hold-at '%s'" % bad, proc.stderr)
        proc = ncc("run", prog, "--feed-hold-at", "1=2", "--feed-hold-at", "2=1")
        self.assertEqual(proc.returncode, 2)
        self.assertIn("overlap", proc.stderr)

    def test_run_blends_line_arc_corners_within_the_tolerance(self):
        # G64 at F600: a line, a half circle R5 entered at 90 degrees, a line, another half
        # circle. With corner_tolerance 0 every corner stops; with 0.1 and 1 mm the corners are
        # blended (a shorter path) and the program gets faster; the end point is exact.
        prog = self.write("arcs.nc", "G21 G17 G90 G64\nG00 X0 Y0 Z0\nG01 X10. F600.\n"
                          "G02 X20. Y0 R5.\nG01 X30.\nG03 X40. Y0 R5.\nG01 X50.\nM30\n")
        times, paths = [], []
        for tol in ("0", "0.1", "1"):
            machine = self.write("m%s.toml" % tol, "[machine]\ncorner_tolerance = %s\n" % tol)
            proc = ncc("run", prog, "--machine", machine)
            self.assertEqual(proc.returncode, 0, proc.stderr)
            self.assertIn("status             completed", proc.stdout)
            self.assertIn("final position     X50.0", proc.stdout)
            times.append(float(re.search(r"program time +(\d+\.\d+) s", proc.stdout).group(1)))
            paths.append(float(re.search(r"path length +(\d+\.\d+) mm feed", proc.stdout).group(1)))
        # Programmed: 30 mm of lines and two half circles of R5.
        self.assertAlmostEqual(paths[0], 30.0 + 10.0 * math.pi + 0.0, delta=0.001)
        self.assertLess(paths[1], paths[0] - 0.1)
        self.assertLess(paths[2], paths[1] - 1.0)
        self.assertLess(times[1], times[0] - 0.1)
        self.assertLess(times[2], times[1] - 0.1)

    def test_run_lookahead_depth_from_the_machine_file(self):
        # A circle r10 in 0.01 mm chords at F6000: 64 segments (0.64 mm) cannot hold the
        # braking distance from F; lookahead_segments = 4096 can, so the circle runs faster.
        # Out of range is a machine-file error naming the key.
        n = 6283
        lines = ["G21 G90 G94 G17", "G00 X10. Y0.", "G64 G01 F6000."]
        for i in range(1, n + 1):
            t = 2.0 * math.pi * i / n
            x, y = (10.0, 0.0) if i == n else (10.0 * math.cos(t), 10.0 * math.sin(t))
            lines.append(f"X{x:.9f} Y{y:.9f}")
        prog = self.write("circle.nc", "\n".join(lines + ["M30", ""]))
        def seconds(*extra):
            proc = ncc("run", prog, *extra)
            self.assertEqual(proc.returncode, 0, proc.stderr)
            return float(re.search(r"program time +(\d+\.\d+) s", proc.stdout).group(1))
        deep = self.write("deep.toml", '[machine]\naxes = ["X", "Y", "Z"]\nlookahead_segments = 4096\n')
        shallow = self.write("shallow.toml", '[machine]\naxes = ["X", "Y", "Z"]\nlookahead_segments = 64\n')
        self.assertLess(seconds("--machine", deep), seconds("--machine", shallow) - 0.5)
        # The summary says how often the depth held the speed down, and names the key.
        def limited(*extra):
            out = ncc("run", prog, *extra).stdout
            m = re.search(r"look-ahead limited +(\d+\.\d) % of the time \((\d+) segments: "
                          r"\[machine\] lookahead_segments\)", out)
            self.assertIsNotNone(m, out)
            return float(m.group(1)), int(m.group(2))
        self.assertGreater(limited("--machine", shallow)[0], 50.0)
        self.assertEqual(limited("--machine", shallow)[1], 64)
        self.assertEqual(limited("--machine", deep), (0.0, 4096))
        self.assertEqual(limited()[1], 1024)
        bad = self.write("bad.toml", '[machine]\naxes = ["X", "Y", "Z"]\nlookahead_segments = 8\n')
        proc = ncc("run", prog, "--machine", bad)
        self.assertNotEqual(proc.returncode, 0)
        self.assertIn("lookahead_segments", proc.stderr)

    def test_run_vars_is_a_json_object(self):
        proc = ncc("run", self.write("a.nc", GOOD), "--emit=vars")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertIsInstance(json.loads(proc.stdout), dict)

    def test_dis_lists_instructions(self):
        good = self.write("a.nc", GOOD)
        out = os.path.join(self.dir, "a.ncb")
        self.assertEqual(ncc("compile", good, "-o", out).returncode, 0)
        proc = ncc("dis", out)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        text = proc.stdout.upper()
        for mnemonic in ("RAPID", "LINE", "ARC", "DWELL", "END"):
            self.assertIn(mnemonic, text)

    def test_dis_and_run_reject_corrupt_bytecode(self):
        good = self.write("a.nc", GOOD)
        out = os.path.join(self.dir, "a.ncb")
        self.assertEqual(ncc("compile", good, "-o", out).returncode, 0)
        data = bytearray(slurp(out, "rb"))
        data[len(data) // 2] ^= 0xFF
        data = data[: len(data) - 7]
        with open(out, "wb") as f:
            f.write(data)
        for cmd in ("dis", "run"):
            proc = ncc(cmd, out)
            self.assertEqual(proc.returncode, 1, (cmd, proc.stderr))
            self.assertIn("invalid bytecode", proc.stderr)

    def test_bytecode_for_another_machine_is_refused(self):
        good = self.write("a.nc", GOOD)
        out = os.path.join(self.dir, "a.ncb")
        self.assertEqual(ncc("compile", good, "-o", out).returncode, 0)
        machine = self.write("m.toml", '[machine]\naxes = ["X", "Y", "Z"]\n[machine.work]\nG54 = [100.0, 0.0, 0.0]\n')
        proc = ncc("run", out, "--machine", machine)
        self.assertEqual(proc.returncode, 1)
        self.assertIn("machine", proc.stderr)

    def test_machine_file_errors_name_the_key(self):
        machine = self.write("m.toml", '[machine]\naxes = ["X", "Y", "Z"]\nbogus = 1\n')
        proc = ncc("check", self.write("a.nc", GOOD), "--machine", machine)
        self.assertEqual(proc.returncode, 2)
        self.assertIn("bogus", proc.stderr)
        self.assertIn("m.toml:3:", proc.stderr)

    def test_closing_percent_ends_the_program_and_warns_about_what_follows(self):
        prog = self.write("p.nc", "%\nO0001\nG00 X1.\n%\nG00 X50.\nM30\n")
        proc = ncc("run", prog, "--emit=moves")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        moves = [json.loads(l) for l in proc.stdout.splitlines()]
        self.assertEqual([m["to"]["X"] for m in moves], [1.0])
        self.assertRegex(proc.stderr, r"p\.nc:5:1: warning\[NCC0020\]: text after the closing '%'")

    def test_text_after_program_end_is_never_executed_and_only_warned_about(self):
        # Issue 21: what follows M02/M30 is never executed, so it is not an error (it was
        # parsed and its syntax errors rejected the program before).
        prog = self.write("after.nc", "G00 X1.\nM30\nG00 X@@@\n")
        proc = ncc("check", prog)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertRegex(proc.stderr, r"after\.nc:3:1: warning\[NCC0022\]")
        self.assertNotIn("error", proc.stderr)

    def test_compile_refuses_to_overwrite_its_source(self):
        good = self.write("same.nc", GOOD)
        proc = ncc("compile", good, "-o", good)
        self.assertEqual(proc.returncode, 2)
        self.assertIn("its own source", proc.stderr)
        self.assertEqual(slurp(good), GOOD)

    def test_unwritable_output_is_a_usage_error_everywhere(self):
        good = self.write("a.nc", GOOD)
        missing = os.path.join(self.dir, "no-such-dir", "out")
        for args in (["compile", good, "-o", missing], ["compile", good, "--emit=ir", "-o", missing],
                     ["run", good, "--emit=moves", "-o", missing]):
            proc = ncc(*args)
            self.assertEqual(proc.returncode, 2, (args, proc.stderr))
            self.assertIn("cannot write", proc.stderr)

    def test_directory_input_is_not_a_regular_file(self):
        proc = ncc("check", self.dir)
        self.assertEqual(proc.returncode, 2)
        self.assertIn("not a regular file", proc.stderr)

    def test_control_bytes_in_echoed_source_lines_are_replaced(self):
        path = os.path.join(self.dir, "ctl.nc")
        with open(path, "wb") as f:
            f.write(b"G00 X1.\x1b[2J Y\x00\n")
        proc = ncc("check", path)
        self.assertEqual(proc.returncode, 1)
        self.assertNotIn("\x1b", proc.stderr)
        self.assertNotIn("\x00", proc.stderr)
        self.assertIn("  G00 X1.?[2J Y?", proc.stderr)

    def test_instruction_budget_stops_a_run_with_an_alarm_recorded_in_the_moves(self):
        # Issue 21: the moves up to an alarm stay, and the file ends with the alarm (it used to
        # be discarded).
        good = self.write("a.nc", GOOD)
        out = os.path.join(self.dir, "moves.jsonl")
        proc = ncc("run", good, "--emit=moves", "-o", out, "--max-steps", "2")
        self.assertEqual(proc.returncode, 3, proc.stderr)
        self.assertIn("error[NCC7204]", proc.stderr)
        last = json.loads(slurp(out).splitlines()[-1])
        self.assertEqual((last["kind"], last["code"]), ("alarm", "NCC7204"))
        self.assertEqual(sorted(os.listdir(self.dir)), ["a.nc", "moves.jsonl"])
        self.assertEqual(ncc("run", good, "--emit=moves", "-o", out, "--max-steps", "0").returncode, 0)

    def test_feed_per_revolution_without_spindle_is_an_alarm_at_its_block(self):
        prog = self.write("g95.nc", "G21 G90 G17\nG01 X5. F600.\nG95 G01 X10. F0.1\nM30\n")
        proc = ncc("run", prog)
        self.assertEqual(proc.returncode, 3, proc.stderr)
        self.assertIn("g95.nc:3:1: error[NCC7207]: feed per revolution with the spindle stopped: "
                      "S is 0 (or not given) or M05 is active", proc.stderr)
        self.assertIn("final position     X5.0 Y0.0 Z0.0", proc.stdout + proc.stderr)

    def test_trace_csv_and_binary_agree_and_end_on_the_program_end(self):
        good = self.write("a.nc", GOOD)
        csv_path = os.path.join(self.dir, "t.csv")
        proc = ncc("run", good, "--emit=trace", "-o", csv_path)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        rows = slurp(csv_path).splitlines()
        self.assertEqual(rows[0], "t,X_cmd,Y_cmd,Z_cmd,X_act,Y_act,Z_act,line")
        ticks = re.search(r"\((\d+) ticks", proc.stdout)
        self.assertIsNotNone(ticks, proc.stdout)
        self.assertEqual(len(rows) - 1, int(ticks.group(1)))
        self.assertEqual(rows[1].split(",")[0], "0.000000")
        last = rows[-1].split(",")
        self.assertEqual(last[1:4], ["20.000000", "5.000000", "-2.000000"])
        nct = os.path.join(self.dir, "t.nct")
        self.assertEqual(ncc("run", good, "--emit=trace", "-o", nct).returncode, 0)
        data = slurp(nct, "rb")
        self.assertEqual(data[:4], b"NCCT")
        self.assertLess(len(data), len(slurp(csv_path, "rb")) // 3)

    def test_simulation_is_deterministic(self):
        good = self.write("a.nc", GOOD)
        a = os.path.join(self.dir, "a.csv")
        b = os.path.join(self.dir, "b.csv")
        self.assertEqual(ncc("run", good, "--emit=trace", "-o", a).returncode, 0)
        self.assertEqual(ncc("run", good, "--emit=trace", "-o", b).returncode, 0)
        self.assertEqual(slurp(a, "rb"), slurp(b, "rb"))


if __name__ == "__main__":
    NCC = sys.argv.pop(1)
    unittest.main(verbosity=2)
