#!/usr/bin/env python3
"""End-to-end tests of error recovery and the end of a program (issue 21): one root cause gets
one diagnostic, long lines are quoted in a window, columns count characters, text after
M02/M30 or the closing '%' is never executed nor an error, and `ncc check` reports motion
beyond the machine's travel limits.

Run by ctest as: test_recovery.py NCC_BINARY; with NCC_TEST_DEFER=1 (ctest cli_recovery_deferred)
every command also runs with --defer and must give the same (cli_harness.run_ncc).
"""
import json
import os
import re
import sys
import unittest

from cli_harness import ScratchDirTest, run_ncc

NCC = None
CORPUS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "corpus")
DIAGNOSTIC = re.compile(r"^(?P<file>.+):(?P<line>\d+):(?P<col>\d+): (?P<severity>error|warning)\[(?P<code>[^\]]+)\]: ")


def ncc(*args):
    return run_ncc(NCC, args, timeout=120)


def diagnostics(stderr, severity=None):
    found = [m.groupdict() for m in map(DIAGNOSTIC.match, stderr.splitlines()) if m]
    return [d for d in found if severity is None or d["severity"] == severity]


class RecoveryTest(ScratchDirTest):
    # ---- one root cause, one diagnostic ----------------------------------------------------

    def test_enier_mill_1003_lowers_its_g41_blocks_and_judges_the_arcs_after_them(self):
        # Every G41 block was rejected before cutter compensation was lowered, and the arcs
        # after it were then not judged (PS0020 at N2680 before that). Now each G41/G42 block
        # records its compensation, so the arcs start where the program says and are judged:
        # lowering reports nothing. (The tool centre's path is the compensation pass's.)
        path = os.path.join(CORPUS, "fanuc-m", "enier-mill_240811_1003.nc")
        proc = ncc("compile", path, "--dialect", "fanuc-m", "--emit=ir", "--stop-after=lower", "-o", "-")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual(diagnostics(proc.stderr), [], proc.stderr)
        with open(path) as f:
            source = f.read().splitlines()
        headers = {int(m.group(1)): line for line in proc.stdout.splitlines()
                   for m in [re.match(r"block \d+:(\d+):\d+ ", line)] if m}
        starts = [n for n, text in enumerate(source, 1) if re.search(r"G4[12]\b", text)]
        self.assertTrue(starts)
        for n in starts:
            self.assertRegex(headers.get(n, ""), r"comp\((left|right) D1=0\.000 commanded\)", n)
        for n, text in enumerate(source, 1):
            if re.search(r"G40\b", text) and n in headers and "comp(" in headers[n]:
                self.assertIn("comp(off D1=", headers[n])

    def test_mach3_write_reports_the_g90_1_only(self):
        proc = ncc("check", os.path.join(CORPUS, "cam-iso", "pygcode-Mach3_write.tap"), "--dialect", "fanuc-m")
        self.assertEqual(proc.returncode, 1)
        errors = diagnostics(proc.stderr, "error")
        self.assertEqual(len(errors), 1, proc.stderr)
        self.assertEqual((errors[0]["line"], errors[0]["code"]), ("3", "PS0010"), proc.stderr)
        self.assertIn("G90.1", proc.stderr)

    def test_a_later_arc_depending_on_a_rejected_move_is_not_judged(self):
        prog = self.write("a.nc", "G90 G17 G00 X0 Y0\nG01 X10. Q1. F100.\nG02 X20. Y0 I5.\nM30\n")
        proc = ncc("check", prog)
        self.assertEqual(proc.returncode, 1)
        errors = diagnostics(proc.stderr, "error")
        self.assertEqual([(d["line"], d["code"]) for d in errors], [("2", "NCC2014")], proc.stderr)

    def test_an_absolute_move_determines_the_position_again(self):
        # After the rejected block, G00 X10. Y0 fixes X and Y: the wrong arc after it is judged.
        prog = self.write("b.nc", "G90 G00 X0 Y0\nG01 X10. Q1. F100.\nG00 X10. Y0\nG02 X20. Y0 I3. F100.\nM30\n")
        proc = ncc("check", prog)
        self.assertEqual(proc.returncode, 1)
        errors = diagnostics(proc.stderr, "error")
        self.assertEqual([(d["line"], d["code"]) for d in errors], [("2", "NCC2014"), ("4", "PS0020")], proc.stderr)

    def test_independent_errors_after_a_rejected_block_are_still_reported(self):
        # The second fault does not depend on what the first block would have done.
        prog = self.write("c.nc", "G90 G00 X0 Y0\nG01 X10. Q1. F100.\nG00 X5. Y5. M123456789\nM30\n")
        proc = ncc("check", prog)
        errors = diagnostics(proc.stderr, "error")
        self.assertEqual([d["line"] for d in errors], ["2", "3"], proc.stderr)

    def test_a_block_with_a_syntax_error_leaves_everything_unknown(self):
        # What `G01 X@` would have done is not known: the arc after it is not judged.
        prog = self.write("x.nc", "G90 G17 G00 X0 Y0\nG01 X@ F100.\nG02 X10. Y0 R2.\nM30\n")
        proc = ncc("check", prog)
        self.assertEqual(proc.returncode, 1)
        errors = diagnostics(proc.stderr, "error")
        self.assertEqual([(d["line"], d["code"]) for d in errors], [("2", "NCC1001")], proc.stderr)

    # ---- source lines in diagnostics -------------------------------------------------------

    def test_a_megabyte_line_gives_bounded_stderr(self):
        line = "G01 X1. " + "(" + "A" * (1 << 20) + ") Q1.\n"
        prog = self.write("long.nc", "G90 G00 X0\n" + line + "M30\n")
        proc = ncc("check", prog)
        self.assertEqual(proc.returncode, 1)
        self.assertLess(len(proc.stderr.encode()), 4096, proc.stderr[:500])
        errors = diagnostics(proc.stderr, "error")
        self.assertEqual(len(errors), 1, proc.stderr[:2000])
        self.assertIn("...", proc.stderr)
        quoted, caret = proc.stderr.splitlines()[1:3]
        self.assertEqual(quoted[caret.index("^")], "Q")

    def test_columns_count_characters(self):
        # 'é' and '°' are two bytes each in UTF-8: Q is byte 17, character 15.
        prog = os.path.join(self.dir, "u.nc")
        with open(prog, "w", encoding="utf-8") as f:
            f.write("G90 G00 X0\nG01 (é °) X1. Q1. F100.\nM30\n")
        proc = ncc("check", prog)
        errors = diagnostics(proc.stderr, "error")
        self.assertEqual([(d["line"], d["col"]) for d in errors], [("2", "15")], proc.stderr)
        quoted, caret = proc.stderr.splitlines()[1:3]
        self.assertEqual(quoted[caret.index("^")], "Q")

    # ---- the end of a program --------------------------------------------------------------

    def test_percent_with_a_sequence_number_after_m30_is_the_end(self):
        prog = self.write("e.nc", "%\nO0001\nN10 G90 G00 X10.\nN193 M30\nN194 %\n")
        proc = ncc("check", prog)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual(diagnostics(proc.stderr), [], proc.stderr)
        self.assertEqual(ncc("compile", prog, "-o", os.path.join(self.dir, "e.ncb")).returncode, 0)

    def test_text_after_the_closing_percent_never_executes(self):
        # The moves and the garbage after '%' are not run, not parsed, and not errors.
        prog = self.write("p.nc", "%\nG90 G00 X1.\n%\nG00 X50. @@@\nG01 X60. Q1.\n")
        proc = ncc("run", prog, "--emit=moves")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertIn('"X": 1.0', proc.stdout)
        self.assertNotIn("50.0", proc.stdout)
        warnings = diagnostics(proc.stderr, "warning")
        self.assertEqual([(d["line"], d["code"]) for d in warnings], [("4", "NCC0020")], proc.stderr)
        self.assertEqual(diagnostics(proc.stderr, "error"), [])

    def test_text_after_m30_is_a_warning_not_an_error(self):
        prog = self.write("t.nc", "G90 G00 X1.\nM30\nG00 X50. @@@\nG01 X60. Q1.\n")
        proc = ncc("run", prog, "--emit=moves")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertNotIn("50.0", proc.stdout)
        warnings = diagnostics(proc.stderr, "warning")
        self.assertEqual([(d["line"], d["code"]) for d in warnings], [("3", "NCC0022")], proc.stderr)

    def test_comments_after_m30_draw_no_warning(self):
        prog = self.write("k.nc", "G90 G00 X1.\nM30\n(end of program)\n\n%\n(trailer)\n")
        proc = ncc("check", prog)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual(diagnostics(proc.stderr), [], proc.stderr)

    def test_a_subprogram_after_m30_runs_only_when_called(self):
        # O2000 after M30 is a stored program: not executed on the way (nothing after M30 is),
        # not rejected (its Q is never read) and no warning, since it is not text left over.
        prog = self.write("s.nc", "O0001\nG90 G00 X1.\nM30\nO2000\nG01 X60. Q1.\nM99\n%\n")
        proc = ncc("run", prog, "--emit=moves")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertNotIn("60.0", proc.stdout)
        self.assertEqual(diagnostics(proc.stderr), [], proc.stderr)

    def test_m98_calls_the_program_stored_after_m30(self):
        prog = self.write("m.nc", "O0001\nG90 G00 X1.\nM98 P2000\nG00 X3.\nM30\nO2000\nG00 X2.\nM99\n")
        proc = ncc("run", prog, "--emit=moves")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        xs = [m["to"]["X"] for m in map(json.loads, proc.stdout.splitlines()) if m.get("kind") == "rapid"]
        self.assertEqual(xs, [1.0, 2.0, 3.0], proc.stdout)

    # ---- travel limits ---------------------------------------------------------------------

    def machine(self):
        return self.write("m.toml", '[machine]\naxes = ["X", "Y", "Z"]\n'
                                    '[machine.axis.X]\nmin_travel = -10.0\nmax_travel = 500.0\n'
                                    '[machine.axis.Z]\nmin_travel = -300.0\nmax_travel = 0.0\n')

    def test_check_reports_targets_beyond_the_travel_limits(self):
        prog = self.write("o.nc", "G90 G00 X100. Z0\nG01 X600. F1000.\nX0\nG00 Z-400.\nM30\n")
        proc = ncc("check", prog, "--machine", self.machine())
        self.assertEqual(proc.returncode, 1)
        errors = diagnostics(proc.stderr, "error")
        self.assertEqual([(d["line"], d["code"]) for d in errors], [("2", "OT0500"), ("4", "OT0501")], proc.stderr)
        self.assertIn("axis X would reach 600, beyond max_travel 500", proc.stderr)

    def test_travel_check_takes_the_frame_into_account_and_the_dialect_alarm(self):
        # G54 X = 450: X100. in the work system is X550. on the machine.
        machine = self.write("w.toml", '[machine]\naxes = ["X", "Y", "Z"]\n[machine.work]\nG54 = [450.0, 0.0, 0.0]\n'
                                       '[machine.axis.X]\nmin_travel = -10.0\nmax_travel = 500.0\n')
        prog = self.write("w.nc", "G90 G54 G00 X10.\nX100.\nM30\n")
        proc = ncc("check", prog, "--machine", machine, "--dialect", "siemens-iso-m")
        errors = diagnostics(proc.stderr, "error")
        self.assertEqual([(d["line"], d["code"]) for d in errors], [("2", "10720")], proc.stderr)
        self.assertIn("axis X would reach 550, beyond max_travel 500", proc.stderr)

    def test_check_within_limits_is_clean(self):
        prog = self.write("i.nc", "G90 G00 X100. Z-10.\nG01 X490. F1000.\nM30\n")
        proc = ncc("check", prog, "--machine", self.machine())
        self.assertEqual(proc.returncode, 0, proc.stderr)


if __name__ == "__main__":
    NCC = sys.argv.pop(1)
    unittest.main(verbosity=2)
