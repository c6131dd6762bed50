#!/usr/bin/env python3
"""Issue 31: bounds that end every endless program and no real one, in every command.

- A program that moves or dwells is bounded by its simulated time (--max-time, NCC7208) and its
  instructions (--max-steps, NCC7204) in `compile` and `check` as in `run`: the compiler, which
  runs every loop ahead of time, stops where the run would.
- A loop that neither moves nor dwells stops after --max-idle-blocks blocks (NCC2419 at its jump
  back); a real macro loop of hundreds of thousands of turns is never refused.
- Memory stays flat for a loop of assignments and for a hole of 99 000 pecks.
- A G95 move that cannot end before the limit stops the run at once, as in G94.

Run by ctest as: test_run_bounds.py NCC_BINARY
"""
import os
import re
import subprocess
import sys
import time
import unittest

from cli_harness import ScratchDirTest

NCC = None
ERROR_EXIT, USAGE_EXIT, ALARM_EXIT = 1, 2, 3
SANITIZED = os.environ.get("NCC_TEST_SANITIZED") == "1"

MEASURE = """
import resource, subprocess, sys
proc = subprocess.run(sys.argv[1:], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
sys.stderr.write(proc.stderr.decode())
print(proc.returncode, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)
"""


def ncc(*args, timeout=120):
    return subprocess.run([NCC, *args], capture_output=True, text=True, timeout=timeout)


DIAGNOSTIC = re.compile(r"^(?P<file>[^:\s]+):(?P<line>\d+):(?P<col>\d+): (?P<severity>\w+)"
                        r"\[(?P<code>\w+)\]: (?P<message>.*)$")


def errors(stderr):
    """(line, column, code, message) of each error diagnostic."""
    found = [m.groupdict() for m in map(DIAGNOSTIC.match, stderr.splitlines()) if m]
    return [(d["line"], d["col"], d["code"], d["message"]) for d in found if d["severity"] == "error"]


def codes(stderr):
    return [e[2] for e in errors(stderr)]


class RunBoundsTest(ScratchDirTest):
    def timed(self, *args, limit=20):
        """`ncc *args`, which must end within `limit` seconds of wall time."""
        start = time.monotonic()
        proc = ncc(*args, timeout=limit * 6)
        self.assertLess(time.monotonic() - start, limit * (4 if SANITIZED else 1), args)
        return proc

    def peak(self, *args):
        """(exit code, peak RSS in MiB) of `ncc *args`."""
        proc = subprocess.run([sys.executable, "-c", MEASURE, NCC, *args], capture_output=True,
                              text=True, timeout=600)
        rc, kb = proc.stdout.split()
        return int(rc), int(kb) / 1024.0

    # --- a program that moves: its simulated time -----------------------------------------------

    # The hostile case: 9999 holes a pass, and M99 starts the main program again for ever.
    ENDLESS_HOLES = "G91 G81 X.01 Z-1. R-1. F99999. K9999\nM99\n"

    def test_compile_and_check_stop_an_endless_moving_program_at_max_time(self):
        prog = self.write("holes.nc", self.ENDLESS_HOLES)
        out = self.path("holes.ncb")
        for command in (["compile", prog, "-o", out], ["check", prog]):
            proc = self.timed(*command, "--max-time", "1")
            self.assertEqual(proc.returncode, ERROR_EXIT, proc.stderr)
            self.assertEqual(codes(proc.stderr), ["NCC7208"], proc.stderr)
            self.assertIn("the limit is --max-time", proc.stderr)
            # The reproducer's own options: whichever bound comes first ends it.
            proc = self.timed(*command, "--max-time", "1", "--max-steps", "100")
            self.assertEqual(proc.returncode, ERROR_EXIT, proc.stderr)
            self.assertEqual(codes(proc.stderr), ["NCC7204"], proc.stderr)
        self.assertFalse(os.path.exists(out))
        self.assertEqual([f for f in os.listdir(self.dir) if ".ncb." in f], [])

    def test_run_stops_an_endless_moving_program_with_the_runs_own_alarm(self):
        prog = self.write("holes.nc", self.ENDLESS_HOLES)
        proc = self.timed("run", prog, "--max-time", "1")
        self.assertEqual(proc.returncode, ALARM_EXIT, proc.stderr)
        self.assertIn("NCC7208", proc.stderr + proc.stdout)

    def test_the_default_time_limit_bounds_the_compile(self):
        # 100 h of simulated time at the default: a slow feed reaches it in few blocks.
        prog = self.write("slow.nc", "G91 G01 X1000. F0.001\nM99\n")
        proc = self.timed("compile", prog, "-o", self.path("slow.ncb"))
        self.assertEqual(proc.returncode, ERROR_EXIT, proc.stderr)
        # At the move that passes the limit, with the run's code and the bound named.
        self.assertEqual([e[:3] for e in errors(proc.stderr)], [("1", "1", "NCC7208")], proc.stderr)
        self.assertRegex(errors(proc.stderr)[0][3],
                         r"^simulated time limit 360000 s reached: the run needs at least \S+ s by "
                         r"the end of this block \(at the machine's top speed; the limit is "
                         r"--max-time\)$")

    def test_max_steps_bounds_the_compile(self):
        prog = self.write("steps.nc", "G91 G00 X1.\nM99\n")
        proc = self.timed("check", prog, "--max-steps", "1000")
        self.assertEqual(proc.returncode, ERROR_EXIT, proc.stderr)
        self.assertEqual(errors(proc.stderr), [
            ("1", "1", "NCC7204", "step limit reached: the run needs more than 1000 VM "
                                  "instructions by this block (the limit is --max-steps)")])
        run = self.timed("run", prog, "--max-steps", "1000")
        self.assertEqual(run.returncode, ALARM_EXIT, run.stderr)
        self.assertIn("NCC7204", run.stderr + run.stdout)

    def test_a_program_within_the_limits_compiles(self):
        prog = self.write("ok.nc", "G91 G01 X10. F600.\nM30\n")  # 1 s
        self.assertEqual(ncc("check", prog, "--max-time", "5").returncode, 0)
        self.assertEqual(ncc("compile", prog, "-o", self.path("ok.ncb"), "--max-time", "5",
                             "--max-steps", "10").returncode, 0)

    def test_the_compile_bound_is_a_lower_bound_of_the_runs_time(self):
        # 60 s at F600 (100 % override); the compile's bound allows the highest override (200 %),
        # so a limit of 40 s passes the compile and the run stops on its own clock.
        prog = self.write("minute.nc", "G91 G01 X600. F600.\nM30\n")
        self.assertEqual(ncc("check", prog, "--max-time", "40").returncode, 0)
        run = ncc("run", prog, "--max-time", "40")
        self.assertEqual(run.returncode, ALARM_EXIT, run.stderr)
        self.assertIn("NCC7208", run.stderr + run.stdout)

    def test_a_g95_move_that_cannot_end_stops_the_run_at_once(self):
        # 99 999 mm at 0.1 mm/rev and S100 (10 mm/min): 600 000 s; G94 at the same speed too.
        for feed in ("G95 F0.1", "G94 F10."):
            prog = self.write("g95.nc", f"S100 M03\n{feed}\nG91 G01 X99999.\nM30\n")
            proc = self.timed("run", prog, "--max-time", "360000", "--machine",
                              self.write("m.toml", "[machine]\n[machine.axis.X]\n"
                                         "min_travel = -1e6\nmax_travel = 1e6\n"), limit=10)
            self.assertEqual(proc.returncode, ALARM_EXIT, feed + proc.stderr)
            self.assertIn("NCC7208", proc.stderr + proc.stdout, feed)

    # --- one verdict: check runs every check of compile ------------------------------------------

    def test_check_reports_a_value_beyond_the_bytecodes_bounds_as_compile_does(self):
        prog = self.write("far.nc", "#5221=999999.\nG54 G00 X999.\nM30\n")
        for command in (["check", prog], ["compile", prog, "-o", self.path("far.ncb")],
                        ["run", prog]):
            proc = ncc(*command)
            self.assertEqual(proc.returncode, ERROR_EXIT, command)
            self.assertEqual([(e[0], e[2]) for e in errors(proc.stderr)], [("2", "NCC7017")],
                             proc.stderr)

    def test_blocks_after_a_run_time_value_are_checked_for_their_words(self):
        # #3001 (the clock) is known only when the program runs: the block after it is prepared
        # then, but E (precise thread lead) is refused whatever its value.
        prog = self.write("late.nc", "#1=#3001\nG01 X1. F100. E5.\nM30\n")
        for command in (["check", prog], ["compile", prog, "-o", self.path("late.ncb")],
                        ["run", prog], ["check", "--defer", prog]):
            proc = ncc(*command)
            self.assertEqual(proc.returncode, ERROR_EXIT, (command, proc.stderr))
            self.assertEqual(errors(proc.stderr), [
                ("2", "15", "NCC2011", "address E (precise thread lead) is not supported yet")],
                proc.stderr)

    def test_words_whose_values_wait_for_the_run_are_left_to_it(self):
        # X#1 and G#2 take their values when the program runs (a computed G may be a call, so
        # that block is left to run time whole).
        prog = self.write("ok.nc", "#1=#3001\n#2=1\nG#2 X#1 F100.\nM30\n")
        proc = ncc("check", prog)
        self.assertEqual(proc.returncode, 0, proc.stderr)

    # --- a loop that neither moves nor dwells ---------------------------------------------------

    def test_a_long_macro_loop_that_moves_is_not_an_endless_loop(self):
        # 20 000 turns: the old default stopped at 10 000 jumps back (NCC2419).
        prog = self.write("surface.nc", "#1=0\nWHILE[#1LT20000]DO1\nG01 X[#1*0.001] F1000.\n"
                                        "#1=#1+1\nEND1\nM30\n")
        proc = ncc("compile", prog, "-o", self.path("surface.ncb"))
        self.assertEqual(proc.returncode, 0, proc.stderr)

    def test_a_loop_without_motion_stops_at_max_idle_blocks_at_its_jump(self):
        prog = self.write("idle.nc", "#1=0\nWHILE[#1GE0]DO1\n#1=#1+1\nEND1\nM30\n")
        for command in (["check", prog], ["run", prog]):
            proc = self.timed(*command, "--max-idle-blocks", "1000")
            self.assertEqual(proc.returncode, ERROR_EXIT, proc.stderr)
            found = errors(proc.stderr)
            self.assertEqual((found[0][0], found[0][2]), ("4", "NCC2419"), proc.stderr)
            self.assertIn("without a move or a dwell", found[0][3])
            self.assertIn("--max-idle-blocks", found[0][3])

    def test_the_runs_step_budget_bounds_blocks_prepared_at_run_time(self):
        # #3001 is known only when the program runs: the VM prepares the endless loop, which
        # executes no instruction; --max-steps bounds it (a damaged store cannot hang a run).
        prog = self.write("late.nc", "#1=#3001\n#2=0\nWHILE[#2GE0]DO1\n#2=#2+1\nEND1\nM30\n")
        ncb = self.path("late.ncb")
        self.assertEqual(ncc("compile", prog, "-o", ncb).returncode, 0)
        proc = self.timed("run", ncb, "--max-steps", "1000", limit=10)
        self.assertEqual(proc.returncode, ALARM_EXIT, proc.stderr)
        self.assertIn("NCC2419", proc.stderr + proc.stdout)

    def test_moves_reset_the_idle_count(self):
        # 300 turns of 10 assignments and a move: 3 300 blocks, never 1 000 without a move.
        body = "".join(f"#{i}=#1*2\n" for i in range(2, 12))
        prog = self.write("busy.nc", f"#1=0\nWHILE[#1LT300]DO1\n{body}G01 X[#1] F1000.\n"
                                     "#1=#1+1\nEND1\nM30\n")
        proc = ncc("check", prog, "--max-idle-blocks", "1000")
        self.assertEqual(proc.returncode, 0, proc.stderr)

    def test_max_back_jumps_is_still_a_limit_when_given(self):
        prog = self.write("b.nc", "#1=0\nWHILE[#1LT100]DO1\nG01 X[#1] F1000.\n#1=#1+1\nEND1\nM30\n")
        proc = ncc("check", prog, "--max-back-jumps", "50")
        self.assertEqual(proc.returncode, ERROR_EXIT, proc.stderr)
        self.assertIn("jumped back 50 times", proc.stderr)

    # --- flat memory ----------------------------------------------------------------------------

    @unittest.skipIf(SANITIZED, "RSS under ASan is the tool's")
    def test_a_loop_of_assignments_keeps_memory_flat(self):
        def loop(turns):
            return self.write(f"a{turns}.nc", f"#1=0\nWHILE[#1LT{turns}]DO1\n#2=#1*2\n#3=#2+1\n"
                                              "#1=#1+1\nEND1\nM30\n")
        rc_small, small = self.peak("run", loop(10_000), "--emit=vars")
        rc_large, large = self.peak("run", loop(400_000), "--emit=vars")
        self.assertEqual((rc_small, rc_large), (0, 0))
        # ~400 bytes a turn before: 160 MB more for the large one.
        self.assertLess(large - small, 8.0, (small, large))

    @unittest.skipIf(SANITIZED, "RSS under ASan is the tool's")
    def test_a_hole_of_99000_pecks_compiles_in_flat_memory(self):
        def hole(depth):
            return self.write(f"peck{depth}.nc", f"G90 G00 X0 Y0 Z5.\nG83 X1. Z-{depth}. R1. Q0.01 "
                                                  "F100.\nG80\nM30\n")
        rc_small, small = self.peak("compile", hole(10), "-o", self.path("small.ncb"))
        rc_large, large = self.peak("compile", hole(990), "-o", self.path("large.ncb"))
        self.assertEqual((rc_small, rc_large), (0, 0))
        self.assertLess(large - small, 8.0, (small, large))  # 315 MB before


if __name__ == "__main__":
    NCC = sys.argv.pop(1)
    unittest.main(verbosity=2)
