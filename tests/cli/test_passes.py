#!/usr/bin/env python3
"""End-to-end tests of the named pass pipeline (issue 22): `ncc compile --emit=ir` and `ncc check`
with --print-after (each pass's IR under a `; after PASS` line), --stop-after, --verify-each,
and the usage errors NCC0015 (no such pass in the command's pipeline) and NCC0016 (not with
--emit=ir), which leave no output file behind.

Run by ctest as: test_passes.py NCC_BINARY; with NCC_TEST_DEFER=1 (ctest cli_passes_deferred)
every command also runs with --defer and must give the same (cli_harness.run_ncc).
"""
import os
import sys
import unittest

from cli_harness import ScratchDirTest, run_ncc

NCC = None

# A work offset, a tool length and a G52 shift: lower keeps the targets in work space with the
# frame beside them, work-to-machine adds the frame.
PROGRAM = "G90 G10 L2 P1 X100. Y50.\nG10 L10 P1 R20.\nG54 G43 H1 G00 X10. Y10. Z5.\nG52 X5.\nG01 X0 F300.\nM30\n"
COMPILE_PASSES = ["lower", "cycles", "corners", "transform", "compensation", "work-to-machine"]


def ncc(*args, stdin=None):
    return run_ncc(NCC, args, timeout=120, stdin=stdin)


def headers(text):
    return [line for line in text.splitlines() if line.startswith("; after ")]


def without_headers(text):
    return "".join(line + "\n" for line in text.splitlines() if not line.startswith("; after "))


class PassesTest(ScratchDirTest):
    def setUp(self):
        super().setUp()
        self.prog = self.write("part.nc", PROGRAM)

    def emit_ir(self, *args):
        proc = ncc("compile", self.prog, "--emit=ir", *args)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual(proc.stderr, "")
        return proc.stdout

    # ---- --print-after --------------------------------------------------------------------

    def test_print_after_each_pass_writes_its_ir_under_one_header(self):
        final = self.emit_ir()
        blocks = [l for l in final.splitlines() if l.startswith("block ")]
        self.assertEqual(len(blocks), 6, final)
        for name in COMPILE_PASSES:
            out = self.emit_ir(f"--print-after={name}")
            self.assertTrue(out.startswith(f"; after {name}\nblock "), out)
            self.assertEqual(headers(out), [f"; after {name}"], out)
            self.assertEqual([l for l in out.splitlines() if l.startswith("block ")], blocks)
        lower = self.emit_ir("--print-after=lower")
        machine = self.emit_ir("--print-after=work-to-machine")
        # lower: work-space targets and the frame; work-to-machine: the frame added.
        self.assertIn("  rapid work X10.000 Y10.000 Z5.000 per-axis\n", lower)
        self.assertNotIn(" machine X", lower)
        self.assertIn("  rapid machine X110.000 Y60.000 Z25.000 per-axis\n", machine)
        self.assertIn("  line machine X105.000 Y60.000 Z25.000 F300.000\n", machine)
        # The last pass's IR is what --emit=ir writes.
        self.assertEqual(without_headers(machine), final)
        self.assertNotEqual(without_headers(lower), final)

    def test_several_passes_interleave_block_by_block(self):
        both = self.emit_ir("--print-after=lower,work-to-machine")
        repeated = self.emit_ir("--print-after", "lower", "--print-after", "work-to-machine")
        self.assertEqual(both, repeated)
        # The blocks stream: each leaves lower, then work-to-machine, before the next is read.
        self.assertEqual(headers(both), ["; after lower", "; after work-to-machine"] * 6, both)
        lines = both.splitlines()
        self.assertEqual(lines[0], "; after lower")
        second = lines.index("; after work-to-machine")
        self.assertEqual(lines[1], lines[second + 1])  # the same block line after either pass

    def test_print_after_into_a_file(self):
        out = self.path("part.ir")
        proc = ncc("compile", self.prog, "--emit=ir", "--print-after=lower", "-o", out)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        with open(out) as f:
            self.assertEqual(f.read(), self.emit_ir("--print-after=lower"))

    def test_an_empty_program_still_shows_each_pass(self):
        empty = self.write("empty.nc", "")
        proc = ncc("compile", empty, "--emit=ir", "--print-after=lower,work-to-machine")
        self.assertEqual((proc.returncode, proc.stdout), (0, "; after lower\n; after work-to-machine\n"), proc.stderr)

    def test_stdin(self):
        proc = ncc("compile", "-", "--emit=ir", "-o", "-", "--print-after=work-to-machine", stdin=PROGRAM)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual(proc.stdout, self.emit_ir("--print-after=work-to-machine"))

    def test_check_prints_after_travel_check_and_still_reports(self):
        machine = self.write("m.toml", "[machine.axis.X]\nmin_travel = -10.0\nmax_travel = 200.0\n")
        proc = ncc("check", self.prog, "--machine", machine, "--print-after=travel-check")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual(headers(proc.stdout), ["; after travel-check"])
        self.assertIn("  rapid machine X110.000 Y60.000 Z25.000 per-axis\n", proc.stdout)
        # Beyond the limit: the error as without --print-after, the IR printed all the same.
        tight = self.write("tight.toml", "[machine.axis.X]\nmin_travel = -10.0\nmax_travel = 100.0\n")
        proc = ncc("check", self.prog, "--machine", tight, "--print-after=travel-check")
        self.assertEqual(proc.returncode, 1)
        self.assertIn("part.nc:3:1: error[OT0500]", proc.stderr)
        self.assertIn("; after travel-check\n", proc.stdout)
        # Without --print-after, ncc check writes nothing to stdout.
        proc = ncc("check", self.prog, "--machine", tight)
        self.assertEqual((proc.returncode, proc.stdout), (1, ""))

    # ---- --stop-after ---------------------------------------------------------------------

    def test_stop_after_lower_writes_the_work_space_ir(self):
        out = self.emit_ir("--stop-after=lower")
        self.assertEqual(out, without_headers(self.emit_ir("--print-after=lower")))
        self.assertIn("  rapid work X10.000 Y10.000 Z5.000 per-axis\n", out)
        self.assertEqual(self.emit_ir("--stop-after=work-to-machine"), self.emit_ir())
        both = self.emit_ir("--stop-after=lower", "--print-after=lower")
        self.assertEqual(both, self.emit_ir("--print-after=lower"))

    def test_check_stop_after_work_to_machine_skips_the_travel_check(self):
        tight = self.write("tight.toml", "[machine.axis.X]\nmin_travel = -10.0\nmax_travel = 100.0\n")
        self.assertEqual(ncc("check", self.prog, "--machine", tight).returncode, 1)
        proc = ncc("check", self.prog, "--machine", tight, "--stop-after=work-to-machine")
        self.assertEqual((proc.returncode, proc.stderr), (0, ""))

    # ---- usage errors -----------------------------------------------------------------------

    def assert_usage_error(self, args, code, message, command="compile"):
        out = self.path("out.ir")
        proc = ncc(command, self.prog, *args, *(["-o", out] if command == "compile" else []))
        self.assertEqual(proc.returncode, 2, proc.stderr)
        self.assertEqual(proc.stderr, f"ncc: error[{code}]: {message}\n")
        self.assertEqual(proc.stdout, "")
        self.assertFalse(os.path.exists(out))
        # Nothing written: neither the output nor a temporary file beside it.
        self.assertEqual([f for f in os.listdir(self.dir) if not f.endswith((".nc", ".toml"))], [])

    def test_evaluate_prints_the_blocks_with_their_values(self):
        prog = self.write("w.nc", "#1=2\nWHILE[#1GT0]DO1\nG91 G01 X#1 F100.\n#1=#1-1\nEND1\nM30\n")
        proc = ncc("compile", prog, "--emit=ir", "--print-after=evaluate")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        # The loop runs twice: the statements are gone, X holds #1's value each time.
        self.assertEqual(proc.stdout, "; after evaluate\nG91 G1 X2. F100.\nG91 G1 X1. F100.\nM30\n")
        stop = ncc("compile", prog, "--emit=ir", "--stop-after=evaluate")
        self.assertEqual((stop.returncode, stop.stdout), (0, "G91 G1 X2. F100.\nG91 G1 X1. F100.\nM30\n"),
                         stop.stderr)
        both = ncc("compile", prog, "--emit=ir", "--print-after=evaluate,lower")
        self.assertEqual(headers(both.stdout)[:3], ["; after lower", "; after evaluate", "; after lower"],
                         both.stdout)
        self.assertIn("  set #1 = 2.000", both.stdout)

    def test_unknown_pass_lists_the_valid_names(self):
        listed = "; the passes of ncc compile: evaluate, lower, cycles, corners, transform, compensation, work-to-machine"
        self.assert_usage_error(["--emit=ir", "--print-after=bogus"], "NCC0015",
                                "--print-after: no pass is named 'bogus'" + listed)
        self.assert_usage_error(["--emit=ir", "--print-after=lower,Lower"], "NCC0015",
                                "--print-after: no pass is named 'Lower'" + listed)
        self.assert_usage_error(["--emit=ir", "--stop-after=codegen"], "NCC0015",
                                "--stop-after: no pass is named 'codegen'" + listed)
        self.assert_usage_error(["--emit=ir", "--print-after=travel-check"], "NCC0015",
                                "--print-after: pass 'travel-check' does not run in ncc compile (only in ncc check)" + listed)
        self.assert_usage_error(["--print-after=bogus"], "NCC0015",
                                "--print-after: no pass is named 'bogus'; the passes of ncc check: evaluate, lower, "
                                "cycles, corners, transform, compensation, work-to-machine, travel-check", command="check")

    def test_a_print_after_the_stop_is_refused(self):
        self.assert_usage_error(["--emit=ir", "--stop-after=lower", "--print-after=work-to-machine"], "NCC0015",
                                "--print-after: pass 'work-to-machine' does not run: the pipeline stops after 'lower' (--stop-after)")

    def test_print_and_stop_after_need_emit_ir(self):
        for emit in ([], ["--emit=bytecode"], ["--emit=ast"]):
            name = emit[0].split("=")[1] if emit else "bytecode"
            for option in ("--print-after=lower", "--stop-after=lower"):
                self.assert_usage_error(emit + [option], "NCC0016",
                                        f"--print-after and --stop-after write IR: use them with --emit=ir (not --emit={name})")
        self.assertFalse(os.path.exists(self.path("part.ncb")))

    def test_an_existing_output_is_untouched_on_a_usage_error(self):
        out = self.write("out.ir", "keep me\n")
        proc = ncc("compile", self.prog, "--emit=ir", "--print-after=bogus", "-o", out)
        self.assertEqual(proc.returncode, 2)
        with open(out) as f:
            self.assertEqual(f.read(), "keep me\n")

    def test_a_program_error_leaves_no_output_file(self):
        bad = self.write("bad.nc", "G90 G00 X1.\nG01 X2.\nM30\n")  # no feed: PS0011
        out = self.path("bad.ir")
        proc = ncc("compile", bad, "--emit=ir", "--print-after=lower", "-o", out)
        self.assertEqual(proc.returncode, 1)
        self.assertIn("bad.nc:2:1: error[PS0011]", proc.stderr)
        self.assertFalse(os.path.exists(out))
        self.assertEqual(sorted(os.listdir(self.dir)), ["bad.nc", "part.nc"])

    # ---- --verify-each ----------------------------------------------------------------------

    def test_verify_each_changes_no_output(self):
        for args in (["--emit=ir"], ["--emit=ir", "--print-after=lower"], ["--emit=ir", "--stop-after=lower"]):
            self.assertEqual(self.emit_ir(*args[1:], "--verify-each"), self.emit_ir(*args[1:]))
        plain, each = self.path("plain.ncb"), self.path("each.ncb")
        self.assertEqual(ncc("compile", self.prog, "-o", plain).returncode, 0)
        proc = ncc("compile", self.prog, "-o", each, "--verify-each")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        with open(plain, "rb") as a, open(each, "rb") as b:
            self.assertEqual(a.read(), b.read())
        bad = self.write("bad.nc", "G90 G00 X1.\nG01 X2.\nM30\n")
        self.assertEqual(ncc("check", bad, "--verify-each").stderr, ncc("check", bad).stderr)

    def test_help_names_the_options(self):
        for command in ("compile", "check"):
            proc = ncc(command, "--help")
            for option in ("--print-after PASS", "--stop-after PASS", "--verify-each"):
                self.assertIn(option, proc.stdout)


if __name__ == "__main__":
    NCC = sys.argv.pop(1)
    unittest.main(verbosity=2)
