"""Unit tests of the conformance runner: a fake ncc emits known output and the comparator must
catch each kind of difference (and accept the right output)."""
import json
import os
import signal
import sys
import tempfile
import textwrap
import tomllib
import unittest
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))

from runner import case as case_mod  # noqa: E402
from runner import compare, expected_failures, run, toml_emit  # noqa: E402
import run_case  # noqa: E402

FAKE_NCC = HERE / "fake_ncc.py"

CASE_HEAD = """\
title = "test case"
source = "unit test"
dialect = "mazak-m"
confidence = "stated"
derivation = ""
notes = ""

[machine]
axes = ["X", "Y", "Z"]
diameter_axes = []
[machine.offsets]
H1 = 100.0
T1 = { x = 0.0, z = 0.0, radius = 0.4, tip = 3 }
[machine.work]
G54 = [0.0, 0.0, 0.0]
[machine.params]
decimal_point = "standard"
t_code_digits = 4
block_skip = true
[start]
position = { X = 0.0, Y = 0.0, Z = 0.0 }

[expect]
tolerance = 0.001
"""

EXPECT_MOVES = """\
moves = [
  { kind = "rapid", to = { X = 10.0, Y = 20.0 } },
  { kind = "line",  to = { Z = -15.0 }, feed = 100.0 },
  { kind = "arc",   to = { X = 0.0, Y = 10.0 }, center = { X = 0.0, Y = 0.0 }, cw = false, feed = 100.0 },
  { kind = "dwell", seconds = 1.5 },
]
moves_subset = false
final = { X = 0.0, Y = 10.0, Z = -15.0 }
"""

GOOD_MOVES = [
    {"line": 2, "file": "program.nc", "kind": "rapid", "to": {"X": 10.0, "Y": 20.0, "Z": 0.0}},
    {"line": 3, "file": "program.nc", "kind": "line", "to": {"X": 10.0, "Y": 20.0, "Z": -15.0}, "feed": 100.0},
    {"line": 4, "file": "program.nc", "kind": "arc", "to": {"X": 0.0, "Y": 10.0, "Z": -15.0},
     "center": {"X": 0.0, "Y": 0.0}, "cw": False, "feed": 100.0},
    {"line": 5, "file": "program.nc", "kind": "dwell", "seconds": 1.5},
]


def altered(moves, index, **changes):
    out = json.loads(json.dumps(moves))
    for key, val in changes.items():
        if val is None:
            out[index].pop(key, None)
        elif isinstance(val, dict) and isinstance(out[index].get(key), dict):
            out[index][key].update(val)
        else:
            out[index][key] = val
    return out


class FakeNccTest(unittest.TestCase):
    """Builds a case folder and a fake-ncc script in a temp dir."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.root = Path(self.tmp.name)
        self.log = self.root / "log.jsonl"
        os.environ["FAKE_NCC_LOG"] = str(self.log)

    def tearDown(self):
        os.environ.pop("FAKE_NCC_SCRIPT", None)
        os.environ.pop("FAKE_NCC_LOG", None)
        self.tmp.cleanup()

    def make_case(self, expect_text, case_id="t1", head=CASE_HEAD):
        folder = self.root / "mazak-m" / case_id
        folder.mkdir(parents=True)
        (folder / "case.toml").write_text(head + expect_text)
        (folder / "program.nc").write_text("G90\nG00 X10. Y20.\n")
        return folder

    def script(self, **script):
        path = self.root / "script.json"
        path.write_text(json.dumps(script))
        os.environ["FAKE_NCC_SCRIPT"] = str(path)

    def judge(self, expect_text, **script):
        self.script(**script)
        return run.judge(FAKE_NCC, case_mod.load(self.make_case(expect_text)), timeout=20)

    def assertFails(self, result, *fragments):
        self.assertFalse(result.passed, "the comparator accepted a wrong output")
        for fragment in fragments:
            self.assertIn(fragment, result.report)


class MovesTest(FakeNccTest):
    def test_matching_output_passes(self):
        r = self.judge(EXPECT_MOVES, moves=GOOD_MOVES)
        self.assertTrue(r.passed, r.report)

    def test_wrong_listed_axis(self):
        r = self.judge(EXPECT_MOVES, moves=altered(GOOD_MOVES, 0, to={"Y": 20.5}))
        self.assertFails(r, "move #1 differs", "to.Y: expected 20, got 20.5", "program.nc:2")

    def test_within_tolerance_passes(self):
        r = self.judge(EXPECT_MOVES, moves=altered(GOOD_MOVES, 0, to={"Y": 20.0009}))
        self.assertTrue(r.passed, r.report)

    def test_unlisted_axis_moved(self):
        # The case lists only Z for the line: X must stay at 10.
        r = self.judge(EXPECT_MOVES, moves=altered(GOOD_MOVES, 1, to={"X": 12.0}))
        self.assertFails(r, "move #2 differs", "to.X: moved from 10 to 12", "unlisted axis must not move")

    def test_unlisted_axis_moved_on_first_move_is_checked_against_start(self):
        r = self.judge(EXPECT_MOVES, moves=altered(GOOD_MOVES, 0, to={"Z": 5.0}))
        self.assertFails(r, "to.Z: moved from 0 to 5")

    def test_wrong_kind(self):
        r = self.judge(EXPECT_MOVES, moves=altered(GOOD_MOVES, 1, kind="rapid", feed=None))
        self.assertFails(r, "move #2 differs", "kind: expected line, got rapid")

    def test_missing_move(self):
        r = self.judge(EXPECT_MOVES, moves=GOOD_MOVES[:3])
        self.assertFails(r, "ncc emitted 3 moves, the case lists 4", "first missing move is #4: dwell 1.5 s")

    def test_extra_move(self):
        extra = {"line": 6, "file": "program.nc", "kind": "rapid", "to": {"X": 0.0, "Y": 10.0, "Z": 50.0}}
        r = self.judge(EXPECT_MOVES, moves=GOOD_MOVES + [extra])
        self.assertFails(r, "ncc emitted 5 moves, the case lists 4", "first extra move is ncc move #5 (program.nc:6)")

    def test_wrong_center(self):
        r = self.judge(EXPECT_MOVES, moves=altered(GOOD_MOVES, 2, center={"Y": 1.0}))
        self.assertFails(r, "center.Y: expected 0, got 1")

    def test_missing_center(self):
        r = self.judge(EXPECT_MOVES, moves=altered(GOOD_MOVES, 2, center=None))
        self.assertFails(r, "center.X: expected 0, ncc reported none")

    def test_wrong_direction(self):
        r = self.judge(EXPECT_MOVES, moves=altered(GOOD_MOVES, 2, cw=True))
        self.assertFails(r, "cw: expected false, got true")

    def test_wrong_feed(self):
        r = self.judge(EXPECT_MOVES, moves=altered(GOOD_MOVES, 1, feed=1000.0))
        self.assertFails(r, "feed: expected 100, got 1000")

    def test_missing_feed(self):
        r = self.judge(EXPECT_MOVES, moves=altered(GOOD_MOVES, 1, feed=None))
        self.assertFails(r, "feed: expected 100, ncc reported none")

    def test_wrong_dwell_seconds(self):
        r = self.judge(EXPECT_MOVES, moves=altered(GOOD_MOVES, 3, seconds=1.0))
        self.assertFails(r, "seconds: expected 1.5, got 1")

    def test_axis_missing_from_output(self):
        moves = altered(GOOD_MOVES, 0, to=None)
        moves[0]["to"] = {"X": 10.0, "Z": 0.0}
        r = self.judge(EXPECT_MOVES, moves=moves)
        self.assertFails(r, "to.Y: expected 20, ncc reported no Y axis")

    def test_feed_not_listed_is_not_compared(self):
        expect = 'moves = [ { kind = "line", to = { X = 5.0 } } ]\n'
        r = self.judge(expect, moves=[{"line": 2, "kind": "line", "to": {"X": 5.0, "Y": 0.0, "Z": 0.0}, "feed": 7.0}])
        self.assertTrue(r.passed, r.report)

    def test_unknown_key_in_case_is_a_case_error(self):
        with self.assertRaises(compare.CaseError):
            self.judge('moves = [ { kind = "line", to = { X = 5.0 }, feedrate = 1.0 } ]\n', moves=[])


class SubsetTest(FakeNccTest):
    EXPECT = """\
moves = [
  { kind = "rapid", to = { X = 10.0 } },
  { kind = "line", to = { Z = -5.0 }, feed = 50.0 },
]
moves_subset = true
"""
    STREAM = [
        {"line": 2, "kind": "rapid", "to": {"X": 0.0, "Y": 0.0, "Z": 10.0}},
        {"line": 3, "kind": "rapid", "to": {"X": 10.0, "Y": 0.0, "Z": 10.0}},
        {"line": 4, "kind": "dwell", "seconds": 1.0},
        {"line": 5, "kind": "line", "to": {"X": 10.0, "Y": 0.0, "Z": -5.0}, "feed": 50.0},
        {"line": 6, "kind": "rapid", "to": {"X": 10.0, "Y": 0.0, "Z": 10.0}},
    ]

    def test_listed_moves_in_order_with_others_between(self):
        r = self.judge(self.EXPECT, moves=self.STREAM)
        self.assertTrue(r.passed, r.report)

    def test_order_matters(self):
        # Both listed moves are there, but the line comes before the rapid.
        stream = [{"line": 2, "kind": "line", "to": {"X": 0.0, "Y": 0.0, "Z": -5.0}, "feed": 50.0},
                  {"line": 3, "kind": "rapid", "to": {"X": 10.0, "Y": 0.0, "Z": -5.0}},
                  {"line": 4, "kind": "dwell", "seconds": 1.0}]
        r = self.judge(self.EXPECT, moves=stream)
        self.assertFails(r, "listed move #2", "not found in order", "searched ncc moves #3..#3",
                         "ncc emitted no line move there")

    def test_unlisted_axis_checked_against_previous_ncc_move(self):
        # The line ends at the right Z, but X moved from 10 (where the previous ncc move was).
        stream = list(self.STREAM)
        stream[3] = dict(stream[3], to={"X": 11.0, "Y": 0.0, "Z": -5.0})
        r = self.judge(self.EXPECT, moves=stream)
        self.assertFails(r, "listed move #2", "nearest line is ncc move #4", "to.X: moved from 10 to 11")


class FinalAndVarsTest(FakeNccTest):
    def test_final_is_last_move(self):
        r = self.judge('final = { X = 0.0, Y = 10.0, Z = -16.0 }\n', moves=GOOD_MOVES)
        self.assertFails(r, "final.Z: expected -16, got -15")

    def test_final_without_moves_is_start(self):
        r = self.judge('final = { X = 0.0, Y = 0.0, Z = 0.0 }\n', moves=[])
        self.assertTrue(r.passed, r.report)
        r2 = self.judge_again('final = { X = 1.0 }\n', moves=[])
        self.assertFails(r2, "final.X: expected 1, got 0", "no move was emitted")

    def judge_again(self, expect, **script):
        self.script(**script)
        folder = self.make_case(expect, case_id=f"again{len(list(self.root.glob('mazak-m/*')))}")
        return run.judge(FAKE_NCC, case_mod.load(folder), timeout=20)

    def test_vars_match(self):
        r = self.judge('vars = { "#100" = 3.0, "R10" = 11.11 }\n', moves=[], vars={"#100": 3.0, "R10": 11.1104, "#1": 2})
        self.assertTrue(r.passed, r.report)

    def test_vars_wrong_value(self):
        r = self.judge('vars = { "#100" = 3.0 }\n', moves=[], vars={"#100": 4.0})
        self.assertFails(r, "vars #100: expected 3, got 4")

    def test_vars_vacant(self):
        r = self.judge('vars = { "#100" = 3.0 }\n', moves=[], vars={"#101": 3.0})
        self.assertFails(r, "vars #100: expected 3, ncc reports it vacant")

    def test_vars_run_uses_emit_vars(self):
        self.judge('vars = { "#100" = 3.0 }\n', moves=[], vars={"#100": 3.0})
        emits = [next(a for a in json.loads(line)["argv"] if a.startswith("--emit="))
                 for line in self.log.read_text().splitlines()]
        self.assertEqual(emits, ["--emit=moves", "--emit=vars"])


class AlarmTest(FakeNccTest):
    EXPECT = 'alarm = { code = "818", line = 2 }\n'
    DIAG = "program.nc:2:5: error[818]: arc end point not on the circle\n  G02 X10. R1.\n      ^\n"

    def test_alarm_at_run_time(self):
        r = self.judge(self.EXPECT, exit=3, stderr=self.DIAG)
        self.assertTrue(r.passed, r.report)

    def test_alarm_at_compile_time(self):
        r = self.judge(self.EXPECT, exit=1, stderr="note: something\n" + self.DIAG)
        self.assertTrue(r.passed, r.report)

    def test_wrong_line(self):
        r = self.judge(self.EXPECT, exit=1, stderr=self.DIAG.replace("program.nc:2:", "program.nc:3:"))
        self.assertFails(r, "expected alarm 818 at line 2", "code 818 was reported at line 3")

    def test_wrong_code(self):
        r = self.judge(self.EXPECT, exit=1, stderr=self.DIAG.replace("[818]", "[NCC2001]"))
        self.assertFails(r, "expected alarm 818 at line 2", "error[NCC2001]")

    def test_prefixed_code_is_not_the_manual_code(self):
        r = self.judge(self.EXPECT, exit=1, stderr=self.DIAG.replace("[818]", "[MAZAK818]"))
        self.assertFails(r, "expected alarm 818")

    def test_program_ran_to_the_end(self):
        r = self.judge(self.EXPECT, exit=0, moves=GOOD_MOVES)
        self.assertFails(r, "ran the program to the end (exit 0)")

    def test_usage_exit_is_not_an_alarm(self):
        r = self.judge(self.EXPECT, exit=2, stderr=self.DIAG)
        self.assertFails(r, "exited with 2")

    def test_no_diagnostic_line(self):
        r = self.judge(self.EXPECT, exit=1, stderr="something went wrong\n")
        self.assertFails(r, "printed no `file:line:col: error[CODE]:` line")


class InvocationTest(FakeNccTest):
    def test_command_line_and_machine_file(self):
        r = self.judge(EXPECT_MOVES, moves=GOOD_MOVES)
        self.assertTrue(r.passed, r.report)
        call = json.loads(self.log.read_text().splitlines()[0])
        argv = call["argv"]
        folder = self.root / "mazak-m" / "t1"
        self.assertEqual(argv[0:2], ["run", str((folder / "program.nc").resolve())])
        self.assertEqual(argv[argv.index("--dialect") + 1], "mazak-m")
        self.assertEqual(argv[argv.index("--program-dir") + 1], str(folder.resolve()))
        self.assertIn("--emit=moves", argv)
        case = tomllib.loads((folder / "case.toml").read_text())
        self.assertEqual(tomllib.loads(call["machine"]), {"machine": case["machine"], "start": case["start"]})

    def test_program_mpf(self):
        head = CASE_HEAD.replace('dialect = "mazak-m"', 'dialect = "siemens-din"')
        folder = self.root / "siemens-din" / "c"
        folder.mkdir(parents=True)
        (folder / "case.toml").write_text(head + "final = { X = 0.0 }\n")
        (folder / "program.mpf").write_text("M30\n")
        (folder / "SUB.spf").write_text("RET\n")
        self.script(moves=[])
        r = run.judge(FAKE_NCC, case_mod.load(folder), timeout=20)
        self.assertTrue(r.passed, r.report)
        self.assertTrue(json.loads(self.log.read_text())["argv"][1].endswith("program.mpf"))

    def test_rejected_program_reports_stderr(self):
        r = self.judge(EXPECT_MOVES, exit=1, stderr="program.nc:1:1: error[NCC1001]: unknown word Q\n")
        self.assertFails(r, "rejected the program at compile time (exit 1)", "error[NCC1001]: unknown word Q")

    def test_crash(self):
        r = self.judge(EXPECT_MOVES, signal=signal.SIGSEGV)
        self.assertFails(r, f"killed by signal {int(signal.SIGSEGV)} (crash)")

    def test_hang(self):
        self.script(moves=GOOD_MOVES, sleep=10)
        r = run.judge(FAKE_NCC, case_mod.load(self.make_case(EXPECT_MOVES)), timeout=0.5)
        self.assertFails(r, "timed out after 0.5 s")

    def test_malformed_output(self):
        r = self.judge(EXPECT_MOVES, moves_text='{"kind": "rapid", "to": {"X": "ten"}}\n')
        self.assertFails(r, "malformed --emit=moves output", "'X' is not a number")

    def test_dialect_must_match_folder(self):
        folder = self.make_case("final = { X = 0.0 }\n", head=CASE_HEAD.replace("mazak-m", "fanuc-m"))
        with self.assertRaises(compare.CaseError):
            case_mod.load(folder)


class ExpectedFailuresTest(unittest.TestCase):
    def load(self, text):
        with tempfile.NamedTemporaryFile("w", suffix=".txt", delete=False) as f:
            f.write(text)
        try:
            return expected_failures.load(f.name)
        finally:
            os.unlink(f.name)

    def test_parse(self):
        got = self.load("# comment\n\nmazak-m/a   macro variables are not evaluated yet\nfanuc-t/b lathe\n")
        self.assertEqual(got, {"mazak-m/a": "macro variables are not evaluated yet", "fanuc-t/b": "lathe"})

    def test_reason_required(self):
        with self.assertRaises(compare.CaseError):
            self.load("mazak-m/a\n")

    def test_listed_twice(self):
        with self.assertRaises(compare.CaseError):
            self.load("mazak-m/a x\nmazak-m/a y\n")

    def test_verdicts(self):
        passed, failed = run.Result(True), run.Result(False, "to.X: expected 1, got 2")
        self.assertEqual(run.verdict(passed, None).status, "PASS")
        self.assertEqual(run.verdict(failed, None).status, "FAIL")
        xfail = run.verdict(failed, "no macros yet")
        self.assertEqual(xfail.status, "XFAIL")
        self.assertTrue(xfail.ok)
        self.assertIn("no macros yet", xfail.report)
        self.assertIn("to.X: expected 1, got 2", xfail.report)
        xpass = run.verdict(passed, "no macros yet")
        self.assertEqual(xpass.status, "XPASS")
        self.assertFalse(xpass.ok)
        self.assertIn("unexpected pass: remove it from expected_failures.txt", xpass.report)


class CommandLineTest(FakeNccTest):
    def run_main(self, *args):
        from contextlib import redirect_stdout, redirect_stderr
        import io
        out, err = io.StringIO(), io.StringIO()
        with redirect_stdout(out), redirect_stderr(err):
            status = run_case.main([str(a) for a in args])
        return status, out.getvalue(), err.getvalue()

    def test_exit_status_follows_expected_failures(self):
        folder = self.make_case(EXPECT_MOVES)
        self.script(moves=GOOD_MOVES[:2])
        xf = self.root / "xf.txt"
        xf.write_text("")
        status, out, _ = self.run_main("--ncc", FAKE_NCC, "--case", folder, "--expected-failures", xf)
        self.assertEqual(status, 1)
        self.assertIn("FAIL: conformance/mazak-m/t1", out)
        xf.write_text("mazak-m/t1  dwell is not emitted yet\n")
        status, out, _ = self.run_main("--ncc", FAKE_NCC, "--case", folder, "--expected-failures", xf)
        self.assertEqual(status, 0)
        self.assertIn("XFAIL: conformance/mazak-m/t1\n  dwell is not emitted yet", out)
        self.script(moves=GOOD_MOVES)
        status, out, _ = self.run_main("--ncc", FAKE_NCC, "--case", folder, "--expected-failures", xf)
        self.assertEqual(status, 1)
        self.assertIn("XPASS", out)

    def test_summary_counts_and_stale_entries(self):
        self.make_case(EXPECT_MOVES, case_id="good")
        self.make_case(EXPECT_MOVES.replace("1.5", "2.5"), case_id="bad")
        self.script(moves=GOOD_MOVES)
        xf = self.root / "xf.txt"
        xf.write_text("mazak-m/bad  dwell time\nmazak-m/gone  no such case\n")
        status, out, err = self.run_main("--ncc", FAKE_NCC, "--all", self.root, "--expected-failures", xf,
                                         "--summary")
        row = next(line for line in out.splitlines() if line.strip().startswith("mazak-m"))
        self.assertEqual(row.split(), ["mazak-m", "1", "1", "0", "0", "2"])
        self.assertEqual(status, 1)
        self.assertIn("lists mazak-m/gone, which is no case", err)


class TomlEmitTest(unittest.TestCase):
    def test_values(self):
        tables = {"machine": {"axes": ["X", "Z"], "n": 4, "f": 0.5, "big": 1e-05, "on": True,
                              "s": 'a "quoted"\\ \u00e9 \n', "nested": {"T1": {"x": 1.0, "tip": 3}, "E": {}},
                              "key with space": 1.0},
                  "start": {"position": {"X": -0.0, "Z": 250.0}}}
        text = toml_emit.dumps(tables)
        back = tomllib.loads(text)
        self.assertEqual(back, tables)
        self.assertIsInstance(back["machine"]["n"], int)
        self.assertIsInstance(back["machine"]["nested"]["T1"]["x"], float)
        self.assertIn("[machine.nested]", text)

    def test_every_case_round_trips(self):
        folders = case_mod.find_cases(HERE.parent)
        self.assertGreater(len(folders), 100)
        for folder in folders:
            c = case_mod.load(folder)
            tables = {"machine": c.machine, "start": c.start}
            self.assertEqual(tomllib.loads(run.machine_file_text(c)), tables, c.name)

    def test_unsupported_type(self):
        import datetime
        with self.assertRaises(TypeError):
            toml_emit.dumps({"machine": {"when": datetime.date(2024, 1, 1)}})



class SyncCheckTest(unittest.TestCase):
    def test_detects_each_difference(self):
        import io
        from contextlib import redirect_stdout
        import sync_check
        with tempfile.TemporaryDirectory() as tmp:
            shared, copy = Path(tmp, "shared"), Path(tmp, "copy")
            for root in (shared, copy):
                (root / "d" / "c").mkdir(parents=True)
                (root / "d" / "c" / "case.toml").write_text("x = 1\n")
            (copy / "run_case.py").write_text("# project file\n")
            args = ["--copy", str(copy), "--shared", str(shared), "--own", "run_case.py"]
            with redirect_stdout(io.StringIO()):
                self.assertEqual(sync_check.main(args), 0)
            (shared / "d" / "c" / "case.toml").write_text("x = 2\n")
            (shared / "d" / "c" / "new.nc").write_text("M30\n")
            (copy / "d" / "stray.nc").write_text("M30\n")
            out = io.StringIO()
            with redirect_stdout(out):
                self.assertEqual(sync_check.main(args), 1)
            self.assertIn("differ: d/c/case.toml", out.getvalue())
            self.assertIn("missing from the copy: d/c/new.nc", out.getvalue())
            self.assertIn("only in the copy: d/stray.nc", out.getvalue())
            with redirect_stdout(io.StringIO()):
                self.assertEqual(sync_check.main(["--copy", str(copy), "--shared", str(Path(tmp, "none"))]), 77)


if __name__ == "__main__":
    unittest.main()
