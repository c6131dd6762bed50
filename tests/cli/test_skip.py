#!/usr/bin/env python3
"""G31 skip with a simulated probe, end to end: [machine.probe] and `ncc run --probe`, the
skip position in #5061.. (`--emit=vars`), the stop point in the moves, the blocks after G31
that need where it stopped (prepared by the VM while the program runs), and bad probe values.

Run by ctest as: test_skip.py NCC_BINARY; with NCC_TEST_DEFER=1 (ctest cli_skip_deferred)
every command also runs with --defer and must give the same (cli_harness.run_ncc).
"""
import json
import sys
import unittest

from cli_harness import ScratchDirTest, run_ncc

NCC = None

PROBING = "G90 G00 X10. Y10. Z10.\nG31 Z-50. F100.\nG00 Z20.\nM30\n"
PROBE_TOML = "[machine.probe]\nZ = -42.5\n"


def ncc(*args):
    return run_ncc(NCC, args, timeout=120)


def moves(stdout):
    return [json.loads(line) for line in stdout.splitlines() if line.strip()]


class SkipTest(ScratchDirTest):
    def run_vars(self, *args):
        proc = ncc("run", "--emit=vars", *args)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        return json.loads(proc.stdout)

    def test_probe_in_the_machine_file_stops_the_move_and_fills_5061(self):
        prog = self.write("probe.nc", PROBING)
        machine = self.write("m.toml", PROBE_TOML)
        proc = ncc("run", "--machine", machine, "--emit=moves", prog)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        m = moves(proc.stdout)
        self.assertEqual(len(m), 3)
        self.assertEqual(m[1]["kind"], "line")
        self.assertEqual(m[1]["to"], {"X": 10.0, "Y": 10.0, "Z": -42.5})
        self.assertEqual(m[1]["feed"], 100.0)
        self.assertEqual(m[2]["to"], {"X": 10.0, "Y": 10.0, "Z": 20.0})
        variables = self.run_vars("--machine", machine, prog)
        self.assertEqual(variables, {"#5061": 10.0, "#5062": 10.0, "#5063": -42.5})
        # The summary's path: 52.5 mm of feed (10 down to -42.5), not 60.
        summary = ncc("run", "--machine", machine, prog)
        self.assertIn("path length        52.500 mm feed", summary.stdout)

    def test_without_a_signal_the_move_runs_to_its_end(self):
        prog = self.write("probe.nc", PROBING)
        self.assertEqual(self.run_vars(prog)["#5063"], -50.0)
        self.assertEqual(self.run_vars("--probe", "Z=-60", prog)["#5063"], -50.0)

    def test_probe_option_sets_and_overrides(self):
        prog = self.write("probe.nc", PROBING)
        machine = self.write("m.toml", PROBE_TOML)
        self.assertEqual(self.run_vars("--probe", "Z=-45", prog)["#5063"], -45.0)
        self.assertEqual(self.run_vars("--machine", machine, "--probe", "Z=-30", prog)["#5063"], -30.0)
        # Two planes: X's (met halfway along the diagonal) stops the move first.
        diag = self.write("diag.nc", "G90 G00 X10. Y10. Z10.\nG31 X-50. Z-50. F100.\nG00 X0 Z20.\nM30\n")
        v = self.run_vars("--probe", "Z=-42.5", "--probe", "X=-20", diag)
        self.assertEqual((v["#5061"], v["#5063"]), (-20.0, -20.0))

    def test_skip_position_is_in_work_coordinates(self):
        prog = self.write("probe.nc", "G90 G54 G00 X10. Y10. Z10.\nG31 Z-50. F100.\nG00 Z20.\nM30\n")
        machine = self.write("w.toml", "[machine.work]\nG54 = { X = 100, Z = -10 }\n" + PROBE_TOML)
        v = self.run_vars("--machine", machine, prog)
        self.assertEqual(v, {"#5061": 10.0, "#5062": 10.0, "#5063": -32.5})  # -42.5 - (-10)

    def test_the_compiled_program_runs_against_any_probe(self):
        prog = self.write("probe.nc", PROBING)
        ncb = self.path("probe.ncb")
        self.assertEqual(ncc("compile", prog, "-o", ncb).returncode, 0)
        dis = ncc("dis", ncb).stdout
        self.assertIn("SKIP X10 Y10 Z-50 F100 origin X0 Y0 Z0 #5061 exact-stop fixed-override", dis)
        self.assertTrue(dis.startswith("; ncc bytecode 2.3"))
        self.assertEqual(self.run_vars("--probe", "Z=-12.25", ncb)["#5063"], -12.25)
        self.assertEqual(self.run_vars("--probe", "Z=-40", ncb)["#5063"], -40.0)

    def run_moves(self, *args):
        proc = ncc("run", "--emit=moves", *args)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        return moves(proc.stdout)

    def test_incremental_move_after_g31_starts_where_it_stopped(self):
        prog = self.write("inc.nc", "G90 G00 X10. Y10. Z10.\nG31 Z-50. F100.\nG91 G00 Z5.\nM30\n")
        for surface in (-42.5, -12.0):
            m = self.run_moves("--probe", f"Z={surface}", prog)
            self.assertEqual(m[1]["to"]["Z"], surface)
            self.assertEqual(m[2]["to"]["Z"], surface + 5.0)
        # The compiler says where the VM takes over, and writes PREPARE after the SKIP.
        ncb = self.path("inc.ncb")
        proc = ncc("compile", prog, "-o", ncb)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertIn("inc.nc:3:9: note[NCC0023]: the program is prepared while it runs from "
                      "here: the incremental Z starts from the position where G31 stopped",
                      proc.stderr)
        dis = ncc("dis", ncb).stdout
        ops = [line.split()[2] for line in dis.splitlines() if not line.startswith(";")]
        self.assertEqual(ops, ["RAPID", "SKIP", "PREPARE", "END"])
        self.assertIn("; blocks ", dis)
        # One .ncb, any probe: the block after G31 is prepared when it runs.
        self.assertEqual(self.run_moves("--probe", "Z=-20", ncb)[2]["to"]["Z"], -15.0)

    def test_a_move_that_keeps_the_skipped_axis_leaves_it_where_it_stopped(self):
        prog = self.write("keep.nc", "G90 G00 X10. Y10. Z10.\nG31 Z-50. F100.\nG00 X20.\nM30\n")
        m = self.run_moves("--probe", "Z=-33", prog)
        self.assertEqual(m[2]["to"], {"X": 20.0, "Y": 10.0, "Z": -33.0})

    def test_a_probing_macro_follows_the_probed_position(self):
        # Touch the top, then cut 2 mm below it and come back up by a relative move: every
        # move after the probe depends on where it stopped.
        prog = self.write("touch.nc", "\n".join([
            "G90 G54 G00 X0 Y0 Z20.",
            "G31 Z-50. F100.",
            "#100=#5063",
            "IF[#100 LT -30.]GOTO9",
            "G01 Z[#100-2.] F200.",
            "X[#100*-2.]",
            "G91 Z3.",
            "N9 G90 G00 Z50.",
            "M30", ""]))
        machine = self.write("w.toml", "[machine.work]\nG54 = { Z = -10 }\n")
        m = self.run_moves("--machine", machine, "--probe", "Z=-15", prog)  # work Z -5
        self.assertEqual([x["kind"] for x in m], ["rapid", "line", "line", "line", "line", "rapid"])
        self.assertEqual(m[1]["to"]["Z"], -15.0)                 # the skip stop
        self.assertEqual(m[2]["to"]["Z"], -17.0)                 # work -7: 2 below the surface
        self.assertEqual(m[3]["to"], {"X": 10.0, "Y": 0.0, "Z": -17.0})
        self.assertEqual(m[4]["to"]["Z"], -14.0)                 # 3 up from there
        self.assertEqual(m[5]["to"]["Z"], 40.0)
        deep = self.run_moves("--machine", machine, "--probe", "Z=-45", prog)  # work Z -35
        self.assertEqual([x["kind"] for x in deep], ["rapid", "line", "rapid"])  # GOTO9
        variables = self.run_vars("--machine", machine, "--probe", "Z=-45", prog)
        self.assertEqual(variables["#100"], -35.0)

    def test_reading_the_skip_position_is_prepared_at_run_time(self):
        prog = self.write("var.nc", "G31 Z-50. F100.\n#1=#5063\nG00 Z[#1+5.]\nM30\n")
        self.assertEqual(self.run_moves("--probe", "Z=-8", prog)[1]["to"]["Z"], -3.0)
        proc = ncc("compile", prog, "-o", self.path("v.ncb"))
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertIn("var.nc:2:4: note[NCC0023]: the program is prepared while it runs from here: "
                      "#5063 (skip position) is where G31 stopped", proc.stderr)
        # The end point of the skipped axis (#5043 work position) likewise.
        prog2 = self.write("var2.nc", "G31 Z-50. F100.\n#101=#5043\nM30\n")
        self.assertEqual(self.run_vars("--probe", "Z=-8", prog2)["#101"], -8.0)

    def test_an_alarm_in_a_block_prepared_at_run_time_names_the_block(self):
        prog = self.write("alarm.nc", "G31 Z-50. F100.\n#1=#5063\n#2=1/[#1+8.]\nG00 Z#2\nM30\n")
        self.assertEqual(self.run_moves("--probe", "Z=-7", prog)[1]["to"]["Z"], 1.0)
        proc = ncc("run", "--probe", "Z=-8", prog)  # #1 + 8 = 0: division by zero
        self.assertEqual(proc.returncode, 3, proc.stderr)
        self.assertIn("alarm.nc:3:", proc.stderr)
        self.assertIn("NCC2402", proc.stderr)

    def test_absolute_retract_after_g31_is_fine(self):
        prog = self.write("ok.nc", "G90 G00 X10. Y10. Z10.\nG31 Z-50. F100.\nG00 Z20.\n"
                                   "G91 G00 Z5.\nG90 X0 Y0\nM30\n")
        proc = ncc("run", "--probe", "Z=-42.5", "--emit=moves", prog)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual(moves(proc.stdout)[3]["to"]["Z"], 25.0)

    def test_mazak_g31_needs_its_own_f_and_keeps_the_modal_f(self):
        prog = self.write("m.eia", "G90 G01 X1. F250.\nG31 Z-20. F40.\nG01 X30. Z0\nM30\n")
        proc = ncc("run", "--dialect", "mazak-m", "--probe", "Z=-5", "--emit=moves", prog)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        m = moves(proc.stdout)
        self.assertEqual((m[1]["to"]["Z"], m[1]["feed"]), (-5.0, 40.0))
        self.assertEqual(m[2]["feed"], 250.0)
        bad = self.write("n.eia", "G90 G01 X1. F250.\nG31 Z-20.\nM30\n")
        proc = ncc("compile", "--dialect", "mazak-m", bad, "-o", self.path("n.ncb"))
        self.assertEqual(proc.returncode, 1)
        self.assertIn("n.eia:2:1: error[", proc.stderr)
        self.assertIn("G31 needs its own F", proc.stderr)

    def test_bad_probe_options_are_usage_errors(self):
        prog = self.write("probe.nc", PROBING)
        for value, message in (("W=1", "unknown axis 'W' in 'W=1' (the machine's axes are X, Y, Z)"),
                               ("Z=abc", "'abc' in 'Z=abc' is not a number"),
                               ("Z", "'Z' is not AXIS=VALUE"),
                               ("Z=nan", "'nan' in 'Z=nan' is not a number"),
                               ("Z=1e9", "the trigger 1e9 of Z is beyond")):
            proc = ncc("run", "--probe", value, prog)
            self.assertEqual(proc.returncode, 2, value)
            self.assertIn("error[NCC0308]: --probe: " + message, proc.stderr)
            self.assertEqual(proc.stdout, "")

    def test_bad_probe_tables_are_machine_file_errors(self):
        prog = self.write("probe.nc", PROBING)
        machine = self.write("bad.toml", "[machine.probe]\nW = 1\nZ = \"a\"\nX = 2e7\n")
        proc = ncc("run", "--machine", machine, prog)
        self.assertEqual(proc.returncode, 2)
        self.assertIn("bad.toml:2:1: error[NCC0304]: unknown axis 'W' in 'machine.probe'", proc.stderr)
        self.assertIn("bad.toml:3:5: error[NCC0303]: wrong type for 'Z': expected a number", proc.stderr)
        self.assertIn("bad.toml:4:5: error[NCC0306]: the probe trigger of X is 2e+07", proc.stderr)
        machine = self.write("bad2.toml", "[machine]\nprobe = 3\n")
        proc = ncc("run", "--machine", machine, prog)
        self.assertEqual(proc.returncode, 2)
        self.assertIn("NCC0303", proc.stderr)


if __name__ == "__main__":
    NCC = sys.argv.pop(1)
    unittest.main(verbosity=2)
