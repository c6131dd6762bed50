#!/usr/bin/env python3
"""The Siemens DIN language end to end (docs/din.md): programs run with `ncc run` and their
moves, variables and alarms are checked against values worked out by hand. ctest runs the file
twice, the second time with every command also run with --defer (cli_harness.run_ncc).

Run by ctest as: test_din.py NCC_BINARY
"""
import json
import re
import sys
import unittest

from cli_harness import ScratchDirTest, run_ncc

NCC = None
DIAGNOSTIC = re.compile(r"^(?P<file>[^:\s]+):(?P<line>\d+):(?P<col>\d+): (?P<severity>error|warning)\[(?P<code>[^\]]+)\]: (?P<message>.*)$")


def ncc(*args, cwd=None):
    return run_ncc(NCC, args, cwd=cwd, timeout=120)


def errors(stderr):
    return [m.groupdict() for m in map(DIAGNOSTIC.match, stderr.splitlines()) if m and m["severity"] == "error"]


class DinTest(ScratchDirTest):
    def run_din(self, text, name="p.mpf", *extra):
        path = self.write(name, text)
        moves = ncc("run", path, "--emit=moves", *extra)
        return moves, [json.loads(line) for line in moves.stdout.splitlines() if line.strip()]

    def variables(self, text, name="p.mpf"):
        proc = ncc("run", self.write(name, text), "--emit=vars")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        return json.loads(proc.stdout)

    def assertAlarm(self, text, code, line, col=None, message=None):
        proc = ncc("run", self.write("p.mpf", text), "--emit=moves")
        self.assertNotEqual(proc.returncode, 0, proc.stdout)
        found = errors(proc.stderr)
        self.assertTrue(found, proc.stderr)
        self.assertEqual(found[0]["code"], code, proc.stderr)
        self.assertEqual(int(found[0]["line"]), line, proc.stderr)
        if col is not None:
            self.assertEqual(int(found[0]["col"]), col, proc.stderr)
        if message is not None:
            self.assertIn(message, found[0]["message"])
        return proc

    # ---- values and variables -----------------------------------------------------------

    def test_operator_priority_as_the_manual_lists_it(self):
        # Fundamentals "priority of the operations": * / DIV MOD before + -, left to right.
        proc, moves = self.run_din(
            "G0 X=2+3*4\nX=10-6/2\nX=2+6 DIV 4\nX=1+7 MOD 4\nX=(2+3)*4\nX=2*-3\nX=100-10*2+5\nM30\n")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual([m["to"]["X"] for m in moves], [14.0, 7.0, 3.0, 4.0, 20.0, -6.0, 85.0])

    def test_functions_and_logic(self):
        vars_ = self.variables(
            "R1=SQRT(16)+ABS(-2)+POT(3)\n"      # 4 + 2 + 9
            "R2=TRUNC(-2.7)+ROUND(2.5)\n"       # -2 + 3
            "R3=ATAN2(1,-1)\n"                  # 135 degrees
            "R4=MINVAL(3,-1)*10+MAXVAL(3,-1)\n"  # -10 + 3
            "R5=(1<2) AND (5==5)\n"             # logic AND of two truths
            "R6=6 AND 1\n"                      # DIN's AND is logic: true
            "R7=6 B_AND 3\n"                    # bits: 2
            "R8=NOT (1>2)\n"
            "R9=7 DIV 2\n"
            "R10=2<>2 OR 1==1\n"                # comparisons bind last: 2 <> (2 OR 1) == 1
            "M30\n")
        self.assertEqual(vars_["R1"], 15.0)
        self.assertEqual(vars_["R2"], 1.0)
        self.assertAlmostEqual(vars_["R3"], 135.0)
        self.assertEqual(vars_["R4"], -7.0)
        self.assertEqual(vars_["R5"], 1.0)
        self.assertEqual(vars_["R6"], 1.0)
        self.assertEqual(vars_["R7"], 2.0)
        self.assertEqual(vars_["R8"], 1.0)
        self.assertEqual(vars_["R9"], 3.0)
        self.assertEqual(vars_["R10"], 1.0)

    def test_def_types_arrays_and_case(self):
        vars_ = self.variables(
            "DEF INT I=2.6, J\n"          # INT rounds: 3; J starts at 0
            "DEF BOOL B=5\n"              # BOOL: 1
            "DEF REAL A[2,3]\n"
            "A[1,2]=I*10 a[0,0]=-1\n"     # names are case-insensitive
            "j=A[1,2]+1\n"
            "R[J-30]=A[0,0]\n"            # R[expr]
            "M30\n")
        self.assertEqual(vars_["I"], 3.0)
        self.assertEqual(vars_["J"], 31.0)
        self.assertEqual(vars_["B"], 1.0)
        self.assertEqual(vars_["A[1,2]"], 30.0)
        self.assertEqual(vars_["A[0,0]"], -1.0)
        self.assertEqual(vars_["A[0,1]"], 0.0)
        self.assertEqual(vars_["R1"], -1.0)

    def test_a_block_runs_left_to_right(self):
        # R2 sees the R1 written before it in the same block; X the R1 of this block.
        proc, moves = self.run_din("R1=5 R2=R1*2 G0 X=R1+R2\nR1=1 X=R1 R1=7\nM30\n")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual([m["to"]["X"] for m in moves], [15.0, 1.0])

    # ---- jumps ------------------------------------------------------------------------------

    def test_gotof_gotob_goto_gotoc_and_block_numbers(self):
        # A loop by label (GOTOB), jumps forward past blocks (GOTOF to a label and to N90),
        # GOTOC to a missing label falls through, GOTO searches forward then from the start.
        program = (
            "N10 R1=30 R2=10 R4=3\n"
            "N20 GOTOF MIDDLE\n"
            "N30 G0 X=999\n"
            "N40 REPEAT_HERE: G0 X=R1\n"
            "N50 R1=R1+R2 R4=R4-1\n"
            "N60 IF R4>0 GOTOB REPEAT_HERE\n"
            "N70 GOTOF N90\n"
            "N80 G0 X=999\n"
            "N90 GOTOC NOWHERE\n"
            "N100 GOTO FINISH\n"
            "N110 G0 X=999\n"
            "N120 FINISH: M30\n"
            "MIDDLE: G0 Y=1\n"
            "GOTOB REPEAT_HERE\n")
        proc, moves = self.run_din(program)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual([(m["to"]["X"], m["to"]["Y"]) for m in moves],
                         [(0.0, 1.0), (30.0, 1.0), (40.0, 1.0), (50.0, 1.0)])

    def test_goto_loop_back_over_a_g291_switch_in_iso_mode(self):
        # siemens-iso-m: a DIN loop after G290 that jumps back, then ISO again after G291.
        program = ("G90 G0 X1. Y1.\n"
                   "G290\n"
                   "DEF INT K=0\n"
                   "LOOP1: K=K+1 G0 X=K*10\n"
                   "IF K<3 GOTOB LOOP1\n"
                   "G291\n"
                   "G0 Y5.\n"
                   "M30\n")
        path = self.write("iso.nc", program)
        proc = ncc("run", path, "--dialect", "siemens-iso-m", "--emit=moves")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        moves = [json.loads(line) for line in proc.stdout.splitlines()]
        self.assertEqual([(m["to"]["X"], m["to"]["Y"]) for m in moves],
                         [(1.0, 1.0), (10.0, 1.0), (20.0, 1.0), (30.0, 1.0), (30.0, 5.0)])

    def test_an_iso_macro_call_runs_a_proc_body_in_din_with_c_arguments(self):
        # 840D ISO §4.11: a G65 body whose first block is PROC is DIN; $C_X is the argument X,
        # $C_X_PROG whether it was given. Its DEF variables are its own: a second call declares
        # them afresh. Arguments move nothing (§4.10.2).
        self.write("0010.spf", "%_N_0010_SPF\n; macro body\nPROC 0010\nDEF REAL XA=$C_X, N=R1\n"
                               "R1=N+1\nR2=XA\nR3=$C_Z_PROG\nR4=$C_Y_PROG\nM17\n")
        path = self.write("iso.nc", "G0 X1. Y1.\nG65 P10 X7. Y2.\nG65 P10 X8.\nG0 X2.\nM30\n")
        proc = ncc("run", path, "--dialect", "siemens-iso-m", "--emit=vars")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        got = json.loads(proc.stdout)
        self.assertEqual({k: got[k] for k in ("R1", "R2", "R3", "R4")},
                         {"R1": 2.0, "R2": 8.0, "R3": 0.0, "R4": 0.0})
        moves = ncc("run", path, "--dialect", "siemens-iso-m", "--emit=moves")
        self.assertEqual([json.loads(l)["to"]["X"] for l in moves.stdout.splitlines()], [1.0, 2.0])

    def test_g290_g291_several_switches_calls_a_jump_back_and_a_skip_across_them(self):
        # siemens-iso-m: an ISO G65 call of a DIN body, a DIN loop whose GOTOB goes back over a
        # G291 ... G290 pair (the ISO block between is read as ISO again), then a G31 whose end
        # is known only when the program runs: the blocks after it, a G290 among them, are
        # prepared in the VM ($AA_IW[X] read there). Worked out by hand: R1 = 3 from the call;
        # X = K*10 + 3 for K = 1, 2; the skip (no signal) ends at X50, and Y goes to it.
        self.write("0020.spf", "PROC 0020\nR1=$C_X\nM17\n")
        program = ("G90 G0 X1. Y1. Z0\n"
                   "G65 P20 X3.\n"
                   "G290\n"
                   "DEF INT K=0\n"
                   "MA1: K=K+1\n"
                   "G0 X=K*10+R1\n"
                   "G291\n"
                   "G0 Y2.\n"
                   "G290\n"
                   "IF K<2 GOTOB MA1\n"
                   "G291\n"
                   "G31 X50. F100.\n"
                   "G290\n"
                   "G0 Y=$AA_IW[X]\n"
                   "G291\n"
                   "G0 Z5.\n"
                   "M30\n")
        path = self.write("iso.nc", program)
        proc = ncc("run", path, "--dialect", "siemens-iso-m", "--emit=moves")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        moves = [json.loads(line) for line in proc.stdout.splitlines()]
        got = [(m["line"], m["to"]["X"], m["to"]["Y"], m["to"]["Z"]) for m in moves]
        self.assertEqual(got, [(1, 1, 1, 0), (6, 13, 1, 0), (8, 13, 2, 0), (6, 23, 2, 0),
                               (12, 50, 2, 0), (14, 50, 50, 0), (16, 50, 50, 5)])
        self.assertEqual((moves[4]["kind"], moves[4]["feed"]), ("line", 100.0))  # the G31 move

    def test_setal_stops_the_program_or_warns(self):
        proc = self.assertAlarm("G0 X1\nSETAL(61000)\nG0 X2\nM30\n", "61000", 2, 1, "SETAL(61000)")
        self.assertNotIn('"X": 2.0', proc.stdout)
        proc, moves = self.run_din("G0 X1\nSETAL(62001)\nG0 X2\nM30\n")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertIn("warning[62001]", proc.stderr)
        self.assertEqual([m["to"]["X"] for m in moves], [1.0, 2.0])
        self.assertAlarm("SETAL(12345)\nM30\n", "NCC2406", 1, 7, "60000 to 69999")
        self.assertAlarm("G0 X1\nSETAL()\nM30\n", "NCC2406", 2, 1, "the alarm number (and a text): it is missing")
        self.assertAlarm("G0 X1\nSETAL(61000, 1, 2)\nM30\n", "12340", 2, 1, "SETAL takes the alarm number")

    # ---- alarms at their block ----------------------------------------------------------

    # ---- control structures --------------------------------------------------------------

    def test_if_else_endif_nested(self):
        # The outer IF is false: its ELSE branch runs, and in it a nested IF ... ELSE.
        proc, moves = self.run_din(
            "DEF INT A=2\nG0 X-1 Y0\n"
            "IF A==1\n  X1\n  IF A>0\n    X2\n  ENDIF\nELSE\n"
            "  IF A==2\n    X3\n  ELSE\n    X4\n  ENDIF\n  Y5\nENDIF\nX6\nM30\n")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual([m["to"] for m in moves[1:]],
                         [{"X": 3.0, "Y": 0.0, "Z": 0.0}, {"X": 3.0, "Y": 5.0, "Z": 0.0},
                          {"X": 6.0, "Y": 5.0, "Z": 0.0}])

    def test_while_for_repeat_loop_and_their_counts(self):
        vars_ = self.variables(
            "DEF INT I, N=0, K\n"
            "WHILE I<5\n  I=I+1\n  N=N+I\nENDWHILE\n"        # N = 1+2+3+4+5 = 15
            "FOR K=2 TO 4\n  R1=R1+K\nENDFOR\n"              # R1 = 9, K ends at 5
            "FOR R2=3 TO 1\n  R3=99\nENDFOR\n"               # never runs
            "REPEAT\n  R4=R4+1\nUNTIL R4>=3\n"                # runs 3 times
            "LOOP\n  R5=R5+2\n  IF R5>=6 GOTOF OUT\nENDLOOP\n"  # left by a jump
            "OUT: R6=1\nM30\n")
        self.assertEqual(vars_["I"], 5.0)
        self.assertEqual(vars_["N"], 15.0)
        self.assertEqual(vars_["R1"], 9.0)
        self.assertEqual(vars_["K"], 5.0)
        self.assertEqual(vars_["R2"], 3.0)
        self.assertNotIn("R3", vars_)  # never written
        self.assertEqual(vars_["R4"], 3.0)
        self.assertEqual(vars_["R5"], 6.0)
        self.assertEqual(vars_["R6"], 1.0)

    def test_repeat_program_sections(self):
        # Job Planning, program section repetition: REPEAT START P=n runs START .. the REPEAT n
        # more times; REPEATB one labelled block; REPEAT START END a section elsewhere (after
        # M30 here), then on after the REPEAT; ENDLABEL: ends a section early; sections nest.
        proc, moves = self.run_din(
            "G0 X0 Y0 Z0\n"
            "N10 MA1: G91 G1 X1 F100\n"
            "N20 G90\n"
            "N30 REPEAT MA1 P=2\n"           # X 1, 2, 3
            "N40 ONE: G91 Y2\n"              # Y 2
            "N45 G90\n"
            "N50 REPEATB ONE P=2\n"          # Y 4, 6 (ONE in G91 again)
            "N55 G90\n"
            "N60 REPEAT SEC SECEND P=2\n"    # Z -1, -2
            "N65 OUTER: G91 X10\n"
            "N66 INNER: Y10\n"
            "N67 G90 REPEAT INNER P=1\n".replace("G90 REPEAT", "REPEAT") +
            "N68 ENDLABEL: G90\n"
            "N69 Z=IC(5)\n"
            "N70 REPEAT OUTER P=1\n"         # OUTER .. ENDLABEL again, not N69
            "N80 M30\n"
            "N90 SEC: G91 G1 Z-1\n"
            "N95 SECEND: G90\n")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual(proc.stderr.count("warning"), 0, proc.stderr)
        got = [(m["to"]["X"], m["to"]["Y"], m["to"]["Z"]) for m in moves]
        self.assertEqual(got, [(1, 0, 0), (2, 0, 0), (3, 0, 0), (3, 2, 0), (3, 4, 0), (3, 6, 0),
                               (3, 6, -1), (3, 6, -2),
                               (13, 6, -2), (13, 16, -2), (13, 26, -2), (13, 26, 3),
                               (23, 26, 3), (23, 36, 3), (23, 46, 3)])
        # A REPEAT inside the section it repeats does not start it again; a jump or a loop in
        # the section's last block wins over the repetition and closes the sections it leaves.
        proc, moves = self.run_din("MA1: REPEATB MA1 P=3\nAA: G0 X1\nREPEAT AA BB P=2\nBB: G0 X0\nM30\n")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual([m["to"]["X"] for m in moves], [1.0, 0.0, 1.0, 0.0])  # X1, then AA..BB twice
        vars_ = self.variables("DEF INT K\nR1=0\nST: R1=R1+1\nENDS: IF R1>=2 GOTOF OUT\n"
                               "REPEAT ST ENDS P=5\nR7=1\nOUT: R8=1\n"
                               "SEC: R2=R2+1\nFOR K=1 TO 2\nR3=R3+1\nFEND: ENDFOR\nREPEAT SEC FEND P=1\nM30\n")
        self.assertEqual((vars_["R1"], vars_["R8"]), (2.0, 1.0))
        self.assertNotIn("R7", vars_)  # jumped over
        self.assertEqual((vars_["R2"], vars_["R3"]), (2.0, 4.0))  # the FOR loop runs whole each time
        self.assertAlarm("G0 X1\nREPEAT NOWHERE P=2\nM30\n", "14080", 2, 1, "label NOWHERE")
        self.assertAlarm("MA: G0 X1\nREPEAT MA P=0\nM30\n", "NCC2406", 2, 13, "1 to 9999 times")
        self.assertAlarm("MA: G0 X1\nREPEAT MA Q=2\nM30\n", "NCC1006", 2, 11, "P=n")
        self.assertAlarm("MA: G0 X1\nREPEATB MA EB P=2\nM30\n", "NCC1006", 2, 12, "one label")
        self.assertAlarm("MA: G0 X1\nREPEAT MA P=2 X5\nM30\n", "NCC1006", 2, 15, "stands alone")

    def test_nested_for_loops_move_a_grid(self):
        proc, moves = self.run_din(
            "DEF INT I, J\nFOR J=0 TO 1\n  FOR I=1 TO 2\n    G1 X=I*10 Y=J*5 F100\n"
            "  ENDFOR\nENDFOR\nM30\n")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual([(m["to"]["X"], m["to"]["Y"]) for m in moves],
                         [(10.0, 0.0), (20.0, 0.0), (10.0, 5.0), (20.0, 5.0)])

    def test_case_jumps_to_the_matching_constant_or_default(self):
        program = ("DEF INT V={v}\nG0 X0\nCASE(V+1) OF 7 GOTOF LA7 -2 GOTOF LM DEFAULT GOTOF LD\n"
                   "LA7: X7\nGOTOF ENDE\nLM: X-2\nGOTOF ENDE\nLD: X99\nENDE: M30\n")
        for v, x in ((6, 7.0), (-3, -2.0), (0, 99.0)):
            proc, moves = self.run_din(program.format(v=v))
            self.assertEqual(proc.returncode, 0, proc.stderr)
            self.assertEqual(moves[-1]["to"]["X"], x, v)
        # No DEFAULT and no match: the next block.
        proc, moves = self.run_din("G0 X0\nCASE(5) OF 1 GOTOF ENDE\nX5\nENDE: M30\n")
        self.assertEqual(moves[-1]["to"]["X"], 5.0)

    def test_a_while_loop_that_never_ends_is_stopped(self):
        proc = ncc("run", self.write("p.mpf", "LOOP\nR1=R1+1\nENDLOOP\nM30\n"), "--emit=moves",
                   "--max-back-jumps", "1000")
        self.assertNotEqual(proc.returncode, 0)
        self.assertEqual(errors(proc.stderr)[0]["code"], "NCC2419", proc.stderr)

    def test_control_structure_alarms(self):
        self.assertAlarm("G0 X1\nENDIF\nM30\n", "12640", 2, 1, "ENDIF without IF")
        self.assertAlarm("R1=1\nIF R1==0\nX1\nM30\n", "12640", 2, 1, "IF without ENDIF")
        self.assertAlarm("WHILE 0\nX1\nENDFOR\nM30\n", "12640", 3, 1, "ENDFOR where ENDWHILE")
        self.assertAlarm("UNTIL 1\nM30\n", "12640", 1, 1, "UNTIL without REPEAT")
        deep = "".join("IF 1\n" for _ in range(17)) + "".join("ENDIF\n" for _ in range(17)) + "M30\n"
        self.assertAlarm(deep, "12641", 17, 1, "nested more than 16")
        # A structure stands alone in its block.
        self.assertAlarm("IF 1 X10\nENDIF\nM30\n", "NCC1006", 1, 6, "stands alone")
        self.assertAlarm("REPEAT MA1 P=2\nM30\n", "14080", 1, 1, "label MA1 not found")

    # ---- subprograms ----------------------------------------------------------------------

    def test_subprograms_by_name_with_parameters(self):
        # POS1 takes two REAL parameters; an omitted trailing one is 0 (cycles notes §1.3.4).
        self.write("POS1.spf", "%_N_POS1_SPF\n;$PATH=/_N_SPF_DIR\nPROC POS1 (REAL XW, REAL YW) DISPLOF\n"
                               "N10 G0 X=XW Y=YW\nN20 M17\n")
        self.write("CONTOUR.spf", "G1 X=R1 F100\nY=R1\nRET\n")  # no PROC: no parameters
        proc, moves = self.run_din("R1=3\nPOS1(10, 20)\nPOS1 (5)\nCONTOUR\nX=R1+1\nM30\n")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual([(m["to"]["X"], m["to"]["Y"]) for m in moves],
                         [(10.0, 20.0), (5.0, 0.0), (3.0, 0.0), (3.0, 3.0), (4.0, 3.0)])

    def test_l_subprograms_and_p_repeats(self):
        # L10 and L0010 are different programs (the digits as written); P repeats the call, each
        # run with its own DEF variables and PROC parameters.
        self.write("L10.spf", "G91 G1 X1 F100\nG90\nM17\n")
        self.write("L0010.spf", "G0 Z5\nM17\n")
        self.write("KONT.spf", "PROC KONT(REAL D)\nDEF REAL E=D\nG91 G1 Y=E F100\nG90\nRET\n")
        proc, moves = self.run_din("G0 X0 Y0 Z0\nL10 P3\nKONT(2) P2\nL0010\nM30\n")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual([(m["to"]["X"], m["to"]["Y"], m["to"]["Z"]) for m in moves],
                         [(1, 0, 0), (2, 0, 0), (3, 0, 0), (3, 2, 0), (3, 4, 0), (3, 4, 5)])
        self.assertAlarm("L10 P0\nM30\n", "NCC2406", 1, 5, "1 to 9999 times")
        self.assertAlarm("G0 X1\nL99999999\nM30\n", "NCC2406", 2, 1, "subprogram numbers are 0 to 9999999")
        self.assertAlarm("G0 X1\nL99\nM30\n", "12550", 2, 1, "L99")

    def test_var_parameters_write_back_and_locals_are_the_subprograms_own(self):
        self.write("ADD.spf", "PROC ADD(VAR REAL V, INT N)\nDEF REAL A=100\nV=V+N+A-100\nR2=A\nRET\n")
        self.write("FILL.spf", "PROC FILL(VAR REAL E)\nE=7\nM17\n")
        vars_ = self.variables("DEF REAL A=1, T[3]\nADD(A, 2)\nADD(A, 3)\nFILL(T[1])\nFILL(R5)\n"
                               "R1=A\nR3=T[1]\nM30\n")
        self.assertEqual(vars_["A"], 6.0)   # 1 + 2 + 3: the caller's A, not ADD's own A
        self.assertEqual(vars_["R1"], 6.0)
        self.assertEqual(vars_["R2"], 100.0)
        self.assertEqual(vars_["R3"], 7.0)  # an array element by reference
        self.assertEqual(vars_["R5"], 7.0)  # an R parameter by reference

    def test_mcall_calls_after_each_move_until_cancelled(self):
        # Fundamentals, modal subprogram call: after every later block that moves an axis, with
        # the arguments as they were at the MCALL; a new MCALL replaces it, MCALL alone ends it.
        self.write("POS.spf", "PROC POS(REAL D)\nG91 G1 Z=-D F100\nZ=D\nG90\nRET\n")
        proc, moves = self.run_din("R1=2\nG0 X0 Y0 Z10\nMCALL POS(R1)\nG0 X10\nR1=5\nY10\n"
                                   "MCALL POS(1)\nX20\nMCALL\nX30\nM30\n")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual([(m["file"], m["to"]["X"], m["to"]["Y"], m["to"]["Z"]) for m in moves],
                         [("p.mpf", 0, 0, 10), ("p.mpf", 10, 0, 10), ("POS.spf", 10, 0, 8),
                          ("POS.spf", 10, 0, 10), ("p.mpf", 10, 10, 10), ("POS.spf", 10, 10, 8),
                          ("POS.spf", 10, 10, 10), ("p.mpf", 20, 10, 10), ("POS.spf", 20, 10, 9),
                          ("POS.spf", 20, 10, 10), ("p.mpf", 30, 10, 10)])
        self.assertAlarm("MCALL CYCLE81(10, 0, 2, -5)\nM30\n", "NCC2010", 1, 7, "Siemens cycle")
        # MCALL L10 is modal too; an MCALL given in a subprogram ends with it.
        self.write("L10.spf", "G91 G0 Z-1\nZ1\nG90\nM17\n")
        self.write("SETM.spf", "MCALL POS(3)\nG0 X1\nRET\n")
        proc, moves = self.run_din("G0 X0 Y0 Z10\nMCALL L10\nX5\nMCALL\nSETM\nX7\nM30\n")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual([(m["file"], m["to"]["X"], m["to"]["Z"]) for m in moves],
                         [("p.mpf", 0, 10), ("p.mpf", 5, 10), ("L10.spf", 5, 9), ("L10.spf", 5, 10),
                          ("SETM.spf", 1, 10), ("POS.spf", 1, 7), ("POS.spf", 1, 10), ("p.mpf", 7, 10)])
        self.assertAlarm("MCALL NOPE\nG0 X1\nM30\n", "12550", 1, 1, "NOPE")

    def test_m17_ends_a_main_program(self):
        proc, moves = self.run_din("G0 X1\nM17\nX2\nM30\n")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual([m["to"]["X"] for m in moves], [1.0])

    def test_subprogram_alarms(self):
        self.write("TWO.spf", "PROC TWO(REAL A, REAL B)\nG0 X=A\nM17\n")
        self.write("REF.spf", "PROC REF(VAR REAL A)\nA=1\nM17\n")
        self.write("NOPROC.spf", "G0 X1\nM17\n")
        self.write("LATE.spf", "G0 X1\nPROC LATE\nM17\n")
        self.write("DEEP.spf", "PROC DEEP\nDEEP\nM17\n")
        self.assertAlarm("G0 X0\nTWO(1, 2, 3)\nM30\n", "12340", 2, 1, "TWO takes 2")
        self.assertAlarm("G0 X0\nNOPROC(1)\nM30\n", "12340", 2, 1, "too many parameters")
        self.assertAlarm("G0 X0\nREF(5)\nM30\n", "12320", 2, 5, "VAR")
        self.assertAlarm("G0 X0\nMISSING(1)\nM30\n", "12550", 2, 1, "MISSING.spf")
        self.assertAlarm("G0 X0\nLATE\nM30\n", "NCC2430", 2, 1, "first block")
        self.assertAlarm("G0 X0\nDEEP\nM30\n", "NCC2413", 2, 1, "nested more than 15")
        self.assertAlarm("G0 X0\nTRAFOOF\nM30\n", "NCC2010", 2, 1, "kinematic transformation")
        self.assertAlarm("G0 X0\nPROC A (REAL B) SAVE\nM30\n", "NCC1090", 2, 17, "SAVE")

    def test_cr_arcs_and_chf_chr_rnd_corners(self):
        # CHF=2 on a 90-degree corner: legs of 2/sqrt(2); RND=1: an arc of radius 1 tangent to
        # both lines; CHR=1: legs of 1, the second measured along the chord of the next arc;
        # CR=5: the arc's radius.
        proc, moves = self.run_din("G0 X0 Y0\nG1 X10 F100 CHF=2\nY10 RND=1\nX0 CHR=1\n"
                                   "G2 X-5 Y5 CR=5\nM30\n")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        got = [(m["kind"], round(m["to"]["X"], 4), round(m["to"]["Y"], 4)) for m in moves]
        self.assertEqual(got, [("line", 8.5858, 0.0), ("line", 10.0, 1.4142), ("line", 10.0, 9.0),
                               ("arc", 9.0, 10.0), ("line", 1.0, 10.0), ("line", -0.1, 9.005),
                               ("arc", -5.0, 5.0)])
        self.assertEqual((moves[3]["center"]["X"], moves[3]["center"]["Y"]), (9.0, 9.0))
        self.assertEqual((moves[6]["center"]["X"], moves[6]["center"]["Y"]), (-5.0, 10.0))

    def test_ic_and_ac_give_one_word_its_distance_mode(self):
        proc, moves = self.run_din("G90 G0 X10\nX=IC(5)\nG91 X=AC(2) Y=IC(1)\nX5\nM30\n")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual([(m["to"]["X"], m["to"]["Y"]) for m in moves],
                         [(10.0, 0.0), (15.0, 0.0), (2.0, 1.0), (7.0, 1.0)])
        self.assertAlarm("R1=IC(5)\nM30\n", "NCC2406", 1, 4, "IC()")

    def test_programmable_frames_replace_or_add_in_the_frames_coordinates(self):
        # TRANS/ROT/SCALE/MIRROR replace the whole programmable frame (alone: delete it); the
        # A-forms act in the coordinates of the frame in force. Worked out by hand: after
        # TRANS X100, AROT RPL=90 the point (10, 0) turns to (0, 10), then shifts to (100, 10);
        # ATRANS X5 shifts along the turned X (the machine's Y).
        proc, moves = self.run_din(
            "G1 X0 Y0 Z0 F1000\nROT RPL=90\nX10 Y0\nAROT RPL=-90\nX10 Y0\nTRANS X100\n"
            "AROT RPL=90\nX10\nATRANS X5\nX0 Y0\nSCALE X2 Y2\nX10 Y10\nASCALE X0.5\nX10 Y10\n"
            "MIRROR X0\nX10 Y10\nAMIRROR X0\nX10 Y10\nROT Z90\nX10 Y0\nROT X90\nX0 Y10 Z0\n"
            "TRANS\nX0 Y0 Z0\nM30\n")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        got = [(m["line"], round(m["to"]["X"], 6), round(m["to"]["Y"], 6), round(m["to"]["Z"], 6))
               for m in moves]
        self.assertEqual(got, [(3, 0, 10, 0), (5, 10, 0, 0), (8, 100, 10, 0), (10, 100, 5, 0),
                               (12, 20, 20, 0), (14, 10, 20, 0), (16, -10, 10, 0), (18, 10, 10, 0),
                               (20, 0, 10, 0), (22, 0, 0, 10), (24, 0, 0, 0)])

    def test_a_mirrored_arc_turns_the_other_way_and_ic_moves_in_the_frame(self):
        proc, moves = self.run_din("G1 X0 Y0 F100\nMIRROR Y0\nG2 X10 Y0 CR=5\nTRANS X100\n"
                                   "G1 X=IC(1)\nX=IC(2)\nM30\n")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual((moves[0]["kind"], moves[0]["cw"], moves[0]["center"]["X"]), ("arc", False, 5.0))
        # MD42440 = 1: an incremental word traverses the new offset too (10 + 100 + 1).
        self.assertEqual([m["to"]["X"] for m in moves[1:]], [111.0, 113.0])

    def test_d_activates_the_edges_length_and_radius(self):
        # Flat D numbers: D n is the machine file's H n (length) and D n (radius). The length
        # acts on Z (G17) when Z is next programmed; G41 offsets left by the radius; D0 ends it.
        machine = self.write("m.toml", "[machine.offsets]\nH1 = 100.0\nD1 = 5.0\nH2 = 50.0\nD2 = 2.0\n")
        proc, moves = self.run_din("G0 X0 Y-20 Z200\nT1 M6\nD1\nG0 Z10\nG41 G1 X0 Y0 F100\nX30\n"
                                   "Y30\nG40 X50 Y50\nD2\nZ20\nD0\nZ30\nM30\n", "p.mpf",
                                   "--machine", machine)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        got = [(m["line"], m["to"]["X"], m["to"]["Y"], m["to"]["Z"]) for m in moves]
        # The corner at (30, 0) is inside the left offset: the paths meet at (25, 5).
        self.assertEqual(got, [(1, 0, -20, 200), (4, 0, -20, 110), (5, 0, 5, 110), (6, 25, 5, 110),
                               (7, 25, 30, 110), (8, 50, 50, 110), (10, 50, 50, 70), (12, 50, 50, 30)])

    def test_g4_dwells_f_seconds_or_s_revolutions_and_keeps_the_feed(self):
        # G4 F2: 2 s; G4 S10 at S600: 10 revolutions = 1 s. The feed (100) and the spindle speed
        # (600) stay: the moves after the dwells run at F100.
        proc, moves = self.run_din("G1 X10 F100\nG4 F2\nX20\nM3 S600\nG4 S10\nX30\nM30\n")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        lines = [m for m in moves if m["kind"] == "line"]
        self.assertEqual([(m["to"]["X"], m["feed"]) for m in lines], [(10.0, 100.0), (20.0, 100.0), (30.0, 100.0)])
        dwells = [m for m in moves if m["kind"] == "dwell"]
        self.assertEqual([(m["line"], m.get("seconds"), m.get("revolutions")) for m in dwells],
                         [(2, 2.0, None), (5, 10.0, True)])
        self.assertAlarm("G4 F1 X5\nM30\n", "NCC2014", 1, 7, "no meaning in a G4 block")
        self.assertAlarm("G4 F1 S5\nM30\n", "NCC2014", 1, 7, "not both")
        self.assertAlarm("G4\nM30\n", "NCC2014", 1, 1, "needs F")
        self.assertAlarm("G4 F1 M3\nM30\n", "NCC2014", 1, 7, "address M cannot be given")

    def test_frame_instruction_alarms(self):
        self.assertAlarm("TRANS X10 F100\nM30\n", "NCC2112", 1, 11, "block of its own")
        self.assertAlarm("G0 TRANS X10\nM30\n", "NCC2112", 1, 1, "G")
        self.assertAlarm("ROT RPL=10 Z5\nM30\n", "NCC2014", 1, None, "RPL=")
        self.assertAlarm("SCALE X0\nM30\n", "NCC2116", 1, 7, "cannot be 0")
        self.assertAlarm("G0 X1 RPL=5\nM30\n", "NCC2014", 1, 7, "ROT or AROT")
        self.assertAlarm("TRANS(1)\nM30\n", "NCC2010", 1, 1, "not in parentheses")
        self.assertAlarm("TRANS X1\nG0 X0\nM30\n".replace("TRANS X1", "TRANS X1 AROT Z5"), "NCC2021", 1, 10,
                         "one frame instruction per block")
        machine = self.write("a.toml", "[machine]\naxes = [\"X\", \"Y\", \"Z\", \"A\"]\n")
        proc = ncc("run", self.write("p.mpf", "TRANS A10\nM30\n"), "--machine", machine, "--emit=moves")
        found = errors(proc.stderr)
        self.assertEqual((proc.returncode, found[0]["code"], found[0]["line"], found[0]["col"]),
                         (1, "NCC2011", "1", "7"), proc.stderr)
        self.assertIn("frames on axes other than X, Y and Z are not supported yet", found[0]["message"])

    def test_actual_positions_by_system_variable(self):
        # $AA_IM: where the tool is (machine); $AA_IW: the same in the workpiece coordinates of
        # every frame in force; $P_EP: the programmed end point.
        got = self.variables("G1 X0 Y0 Z10 F100\nTRANS Z100\nR1=$AA_IW[Z]\nR2=$AA_IM[Z]\n"
                             "R3=$P_EP[Z]\nG1 X5\nR4=$AA_IM[Z]\nR5=$AA_IW[X]\nM30\n")
        self.assertEqual(got, {"R1": -90.0, "R2": 10.0, "R3": 10.0, "R4": 110.0, "R5": 5.0})
        self.assertAlarm("R1=$AA_IW[Q]\nM30\n", "12550", 1, 4, "an axis of the machine")
        self.assertAlarm("R1=$AA_FOO[X]\nM30\n", "NCC2010", 1, 4, "$AA_FOO")
        self.assertAlarm("R1=$AA_IW[20000000000]\nM30\n", "NCC2403", 1, 11, "the index of $AA_IW is out of range")

    def test_alarms_carry_the_sinumerik_numbers_and_positions(self):
        self.assertAlarm("G0 X1\nR1=UNKNOWN+1\nM30\n", "12550", 2, 4, "'UNKNOWN' is not defined")
        self.assertAlarm("DEF REAL A[3]\nA[3]=1\nM30\n", "17020", 2, None, "index 3 is outside 0 to 2")
        self.assertAlarm("N10 G0 X1\nGOTOB NOWHERE\nM30\n", "14080", 2, 1, "label NOWHERE")
        self.assertAlarm("N10 GOTOF N5\nN5 X1\nM30\n".replace("N5 X1", "N6 X1"), "14080", 1, 5)
        self.assertAlarm("DEF INT A\nDEF REAL A\nM30\n", "12170", 2, 10, "declared already")
        self.assertAlarm("R1=1/0\nM30\n", "NCC2402", 1)

    def test_what_is_not_built_yet_is_refused_at_its_position(self):
        self.assertAlarm("G0 X=ACP(5)\nM30\n", "NCC1090", 1, 6, "function 'ACP'")
        self.assertAlarm("G0 X1\nCYCLE81(10, 0, 2, -5)\nM30\n", "NCC2010", 2, 1, "Siemens cycle")
        self.assertAlarm("DEF AXIS A\nM30\n", "NCC2010", 1, 10, "AXIS")
        self.assertAlarm("G2 X10 Y0 AR=90\nM30\n", "NCC2011", 1, 11, "opening angle of an arc")
        # A name no DEF declared and no axis has: the Sinumerik "name not defined".
        self.assertAlarm("E_MULT = 1\nM30\n", "12550", 1, 1, "'E_MULT' is not defined")
        self.assertAlarm('T="BALL_8MM" M6\nM30\n', "NCC2010", 1, 1, "tools by name")

    def test_set_and_rep_give_arrays_their_values(self):
        # Job Planning, array initialisation: values in memory order (the last index fastest),
        # an omitted one left as it is; REP to the end or n elements; from the element named.
        vars_ = self.variables(
            "DEF REAL F[3,2]=SET(1,,3,4)\n"
            "DEF INT G[2,3] = REP(2)\n"
            "DEF STRING[4] S[3] = SET(\"A\", \"BC\")\n"
            "F[2,0] = SET(7, 8)\n"
            "G[1,1] = REP(5, 1)\n"
            "R1 = STRLEN(S[0] << S[1] << S[2])\n"
            "M30\n")
        self.assertEqual([vars_[f"F[{i},{j}]"] for i in range(3) for j in range(2)],
                         [1.0, 0.0, 3.0, 4.0, 7.0, 8.0])
        self.assertEqual([vars_[f"G[{i},{j}]"] for i in range(2) for j in range(3)],
                         [2.0, 2.0, 2.0, 2.0, 5.0, 2.0])
        self.assertEqual(vars_["R1"], 3.0)
        self.assertAlarm("DEF REAL F[3]=SET(1,2,3,4)\nM30\n", "12260", 1, 25, "4 values, 3 elements")
        self.assertAlarm("DEF REAL F[3]\nF[1]=REP(1,3)\nM30\n", "12260", 2, 12, "2 elements are left")
        self.assertAlarm("R1=SET(1)\nM30\n", "12150", 1, 4, "R1 is no array")
        self.assertAlarm("DEF REAL F[3]\nG0 X=REP(1)\nM30\n", "12150", 2, 6, "not a value")
        self.assertAlarm("DEF INT F[3]=SET(1,\"A\")\nM30\n", "12150", 1, 14, "a string is not a number")

    def test_msg_texts_are_notes_in_program_order(self):
        proc, moves = self.run_din('R1=2\nMSG("PASS " << R1)\nG0 X1\nMSG()\nMSG("DONE", 1)\nM30\n')
        self.assertEqual(proc.returncode, 0, proc.stderr)
        notes = [l for l in proc.stderr.splitlines() if "note[NCC2440]" in l]
        self.assertEqual(len(notes), 2, proc.stderr)
        self.assertTrue(notes[0].endswith(":2:1: note[NCC2440]: MSG: PASS 2"), notes[0])
        self.assertTrue(notes[1].endswith(":5:1: note[NCC2440]: MSG: DONE"), notes[1])
        self.assertAlarm('MSG("A", 1, 2)\nM30\n', "12340", 1, 1, "MSG takes the text")
        # STOPRE: each block is evaluated with what the blocks before it left.
        proc, moves = self.run_din("G0 X5\nSTOPRE\nR1=$AA_IM[X]\nG0 Y=R1\nM30\n")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual(moves[-1]["to"]["Y"], 5.0)

    # ---- strings -----------------------------------------------------------------------

    def test_strings_concatenation_comparison_and_functions(self):
        # Job Planning, strings: STRING[n] variables, `<<` (numbers as their shortest text),
        # comparisons by character codes, the string functions; positions count from 0.
        proc, moves = self.run_din(
            'DEF STRING[28] CAL = "move_grid_baseline"\n'
            'DEF STRING[8] TAG = "A-7", NOTE = ""\n'
            'DEF CHAR FORM = "E"\n'
            'DEF INT N\nDEF REAL V\n'
            'TAG = "B-2"\n'
            'NOTE = TAG << "/" << 3.5\n'                        # "B-2/3.5"
            'N = STRLEN(NOTE)\n'                                # 7
            'V = NUMBER("12.5") + INDEX(NOTE, "/") + MATCH(CAL, "grid")\n'  # 12.5 + 3 + 5
            'G1 X=N Y=V Z=RINDEX(CAL, "e") F100\n'              # 17
            'IF (NOTE == "B-2/3.5") AND (FORM == "E") AND ("ABC" < "ABD") GOTOF OK\n'
            'SETAL(61000)\n'
            'OK: NOTE = TOUPPER(SUBSTR(CAL, 5, 4))\n'           # "GRID"
            'X=STRLEN(SPRINT("%5.2F|%D|%S", 1.5, 2.6, NOTE))\n'  # " 1.50|3|GRID": 12
            'X=ISNUMBER("1e3") + ISNUMBER("A1") + MINDEX(CAL, "_b") + FORM\n'  # 1 + 0 + 4 + 69
            'X=STRLEN(TOLOWER(NOTE) << NOTE[0])\n'               # "gridG": 5
            'M30\n')
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual([(m["to"]["X"], m["to"]["Y"], m["to"]["Z"]) for m in moves],
                         [(7.0, 20.5, 17.0), (12.0, 20.5, 17.0), (74.0, 20.5, 17.0), (5.0, 20.5, 17.0)])

    def test_case_on_strings_and_string_parameters(self):
        self.write("SHOW.spf", 'PROC SHOW(STRING[10] NAME, VAR STRING[10] BACK, CHAR C)\n'
                               'BACK = NAME << "!" << C\nG0 X=STRLEN(BACK)\nRET\n')
        proc, moves = self.run_din(
            'DEF STRING[10] TAG = "B", OUT\n'
            'CASE (TAG) OF "A" GOTOF ONE "B" GOTOF TWO DEFAULT GOTOF ONE\n'
            'ONE: SETAL(61000)\n'
            'TWO: SHOW("AB", OUT, "Z")\n'
            'IF OUT <> "AB!Z" GOTOB ONE\n'
            'M30\n')
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual([m["to"]["X"] for m in moves], [4.0])
        # A CHAR given to a STRING parameter is its character; CASE compares a CHAR as == does.
        self.write("LEN.spf", "PROC LEN(STRING[4] T)\nG0 X=STRLEN(T << T)\nRET\n")
        proc, moves = self.run_din('DEF CHAR C="B"\nLEN(C)\nCASE (C) OF 66 GOTOF OK DEFAULT GOTOF BAD\n'
                                   'BAD: SETAL(61000)\nOK: CASE (C) OF "B" GOTOF OK2\nSETAL(61001)\nOK2: M30\n')
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual([m["to"]["X"] for m in moves], [2.0])

    def test_string_alarms(self):
        self.assertAlarm('DEF STRING[4] S="ABCDE"\nM30\n', "NCC2404", 1, 15, "STRING[4]")
        self.assertAlarm('DEF STRING[4] S\nDEF REAL A\nA=S\nM30\n', "12150", 3, 1, "a string is not a number")
        self.assertAlarm('R1="X" << 1\nM30\n', "12150", 1, 1, "R1 is REAL")
        self.assertAlarm('DEF STRING[9] S="AB"\nIF S==1 GOTOF L\nL: M30\n', "12150", 2, 7, "compared with a number")
        self.assertAlarm('DEF STRING[9] S="AB"\nR1=STRLEN(S[5])\nM30\n', "17020", 2, None, "character 5")
        self.assertAlarm('DEF STRING[9] S\nS=SPRINT("%D %D", 1)\nM30\n', "NCC2403", 2, 3, "more % than values")
        self.assertAlarm('DEF CHAR C="AB"\nM30\n', "12150", 1, 10, "one character")
        self.assertAlarm('DEF CHAR C\nC=300\nM30\n', "NCC2404", 2, 1, "0 to 255")
        self.assertAlarm('DEF STRING[4] S="5"\nCASE (S) OF 5 GOTOF L\nL: M30\n', "12150", 2, 13, "CASE compares")
        self.assertAlarm('DEF STRING S\nM30\n', "NCC1006", 1, 5, "STRING[n]")
        self.assertAlarm('DEF STRING[201] S\nM30\n', "NCC1015", 1, 12, "1 to 200")
        self.assertAlarm('R1=NUMBER("12A")\nM30\n', "12150", 1, 11, "not a number")
        self.assertAlarm('G0 X="A"\nM30\n', "12150", 1, 6, "a string where a number is needed")

    def test_syntax_errors_name_the_place(self):
        self.assertAlarm("G0 X1\nX=(1+2\nM30\n", "NCC1003", 2, 3)
        self.assertAlarm("DEF FOO A\nM30\n", "NCC1019", 1, 5, "unknown type 'FOO'")
        self.assertAlarm("X=\"abc\nM30\n", "NCC1018", 1, 3)
        self.assertAlarm("X=SIN(1,2)\nM30\n", "NCC1011", 1, 3)
        self.assertAlarm("G0 X1 @\nM30\n", "NCC1001", 1, 7)

    def test_an_axis_named_e_is_the_axis(self):
        machine = self.write("e.toml", "[machine]\naxes = [\"X\", \"Y\", \"Z\", \"E\"]\n")
        proc = ncc("run", self.write("p.mpf", "G1 X1 E=2.5 F100\nM30\n"), "--machine", machine,
                   "--emit=moves")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual(json.loads(proc.stdout.splitlines()[0])["to"]["E"], 2.5)

    def test_nothing_is_written_after_an_alarm(self):
        path = self.write("p.mpf", "G0 X1\nR1=NOPE\nM30\n")
        out = self.path("p.ncb")
        proc = ncc("compile", path, "-o", out)
        self.assertNotEqual(proc.returncode, 0)
        import os
        self.assertFalse(os.path.exists(out))

    def test_bytecode_keeps_the_names(self):
        path = self.write("p.mpf", "DEF REAL SUM=1.5\nR7=2\nG0 X=SUM\nM30\n")
        out = self.path("p.ncb")
        self.assertEqual(ncc("compile", path, "-o", out).returncode, 0)
        dis = ncc("dis", out)
        self.assertIn("; variable   #10007 R7", dis.stdout)
        self.assertIn("; variable   #11000 SUM", dis.stdout)
        proc = ncc("run", out, "--emit=vars")
        self.assertEqual(json.loads(proc.stdout), {"R7": 2.0, "SUM": 1.5})


if __name__ == "__main__":
    NCC = sys.argv.pop(1)
    unittest.main(verbosity=2)
