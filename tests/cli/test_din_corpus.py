#!/usr/bin/env python3
"""Golden tests for the Sinumerik 840D DIN programs of tests/corpus/siemens-din/ (from the
CEAD-group nc-gcode-interpreter project, MIT): each program is run with `ncc run --emit=moves`
and every move it prints is compared, in order, with the positions worked out by hand from the
program text and the Siemens DIN rules (docs/din.md): jumps and labels, CASE, IF, WHILE,
REPEAT..UNTIL, R parameters and DEF variables, operator priority, DIV/MOD, trig functions,
strings, IC(), frames (TRANS/ATRANS).

Conventions the expectations follow:
  - the machine starts at X0 Y0 Z0 and positions are machine positions with every axis;
  - a block whose end point equals its start point is no motion and prints nothing
    (docs/semantics.md), so `G1 X0 Y0 Z0 F1000` at the start moves nothing;
  - positions are kept at the control's 0.001 mm resolution (1/3 is 0.333);
  - a frame acts on the whole programmed point: the next move goes to its image, an axis not
    written in the block included, and an IC() word adds to the programmed point
    (MD42440 FRAME_OFFSET_INCR_PROG = 1: the offset is traversed too).

ctest runs the file twice, the second time with every command also run with --defer
(cli_harness.run_ncc).

Run by ctest as: test_din_corpus.py NCC_BINARY
"""
import json
import os
import sys
import unittest

from cli_harness import ScratchDirTest, run_ncc

NCC = None
CORPUS = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "corpus", "siemens-din"))


def ncc(*args, cwd=None):
    return run_ncc(NCC, args, cwd=cwd, timeout=120)


class DinCorpusTest(ScratchDirTest):
    def program(self, name):
        path = os.path.join(CORPUS, name)
        self.assertTrue(os.path.isfile(path), path)
        return path

    def moves(self, name):
        """The moves of `ncc run NAME --emit=moves`; the run must end without an alarm."""
        proc = ncc("run", self.program(name), "--emit=moves", cwd=self.dir)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertNotIn("error[", proc.stderr)
        moves = [json.loads(line) for line in proc.stdout.splitlines() if line.strip()]
        for m in moves:
            self.assertEqual(m["file"], name)
        return moves

    def variables(self, name):
        proc = ncc("run", self.program(name), "--emit=vars", cwd=self.dir)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        return json.loads(proc.stdout)

    def assertMoves(self, moves, expected):
        """`expected`: (line, (X, Y, Z)) per move, in order."""
        self.assertEqual([(m["line"], (m["to"]["X"], m["to"]["Y"], m["to"]["Z"])) for m in moves],
                         [(line, tuple(float(v) for v in p)) for line, p in expected])

    # ---- jumps and branches ----------------------------------------------------------------

    def test_goto_gotof_gotob_gotoc_and_block_number_targets(self):
        moves = self.moves("cead-goto.mpf")
        # N10 R1=30 R2=10 R4=3; N20 GOTOF MIDDLE skips N30 (X=999) and everything to line 14:
        #   MIDDLE: Y=1                                                    -> (0, 1)
        # GOTOB REPEAT_HERE back to N40, which runs while R4 counts 3, 2, 1:
        #   X=R1 with R1 = 30, 40, 50 (N50 adds R2=10; N60 jumps back while R4>0)
        # N70 GOTOF 90 skips N80 (X=999); N90 GOTOC NOWHERE falls through; N100 GOTO FINISH
        # skips N110 (X=999) and ends at N120 M30: MIDDLE is never run twice.
        self.assertMoves(moves, [
            (14, (0, 1, 0)),
            (5, (30, 1, 0)),
            (5, (40, 1, 0)),
            (5, (50, 1, 0)),
        ])
        self.assertEqual({m["kind"] for m in moves}, {"rapid"})  # no G1 anywhere: rapid moves
        # After the third pass N50 left R1 = 60 and R4 = 0.
        self.assertEqual(self.variables("cead-goto.mpf"), {"R1": 60.0, "R2": 10.0, "R4": 0.0})

    def test_case_jumps_to_the_constant_equal_to_the_value(self):
        moves = self.moves("cead-case.mpf")
        # CASE(VAR1+VAR2-VAR3) = 4+6-3 = 7: GOTOF LABEL_1 -> X1, then GOTOF ENDE past X2, X3.
        self.assertMoves(moves, [(6, (1, 0, 0))])

    def test_nested_if_else_takes_the_true_branch_only(self):
        moves = self.moves("cead-if_statement.mpf")
        # IF TRUE: X1; the ELSE branch (with its own IF aa / ELSE: X5, X3 Y32) is skipped.
        self.assertMoves(moves, [(3, (1, 0, 0))])

    # ---- loops -------------------------------------------------------------------------------

    def test_while_loop_rasters_rows_inside_an_if(self):
        moves = self.moves("cead-loop.mpf")
        # F=mov_fr = 5000: to the start (920, 950, 1250), to the far corner (1250, 1050), back.
        head = [
            (21, (920, 950, 1250)),
            (23, (1250, 1050, 1250)),
            (26, (920, 950, 1250)),
        ]
        # F=mes_fr = 250; IF 950 <= 1050; WHILE y_current <= 1050 with y_current = 950 ... 1050
        # at the test: 101 turns. Turn i (from 0) goes along X to the other end (x_current
        # starts at x_start = 920, so turn 0 goes to x_end = 1250 on line 37, turn 1 back to
        # 920 on line 34, ...), then one row up on line 42: Y = 951 + i. The last turn (i = 100,
        # y_current 1050 at the test) ends at X1250 Y1051; 1051 > 1050 ends the loop, M2.
        rows = []
        for i in range(101):
            x, line = (1250, 37) if i % 2 == 0 else (920, 34)
            rows.append((line, (x, 950 + i, 1250)))
            rows.append((42, (x, 951 + i, 1250)))
        self.assertEqual(len(rows), 202)
        # Spelled out, the first and last turns:
        self.assertEqual(rows[:4], [(37, (1250, 950, 1250)), (42, (1250, 951, 1250)),
                                    (34, (920, 951, 1250)), (42, (920, 952, 1250))])
        self.assertEqual(rows[-2:], [(37, (1250, 1050, 1250)), (42, (1250, 1051, 1250))])
        self.assertMoves(moves, head + rows)
        self.assertEqual({m["kind"] for m in moves}, {"line"})
        self.assertEqual([m["feed"] for m in moves], [5000.0] * 3 + [250.0] * 202)
        vars_ = self.variables("cead-loop.mpf")
        self.assertEqual(vars_["X_CURRENT"], 1250.0)
        self.assertEqual(vars_["Y_CURRENT"], 1051.0)

    def test_repeat_until_reads_the_actual_work_position_and_trans(self):
        moves = self.moves("cead-actual_position.mpf")
        # G1 X0 Y0 Z0 F1000 is no motion. REPEAT X=IC(10) Z=IC(2) UNTIL $AA_IW[Z] > 8.95:
        # the body runs for Z = 2, 4, 6, 8, 10 (10 > 8.95 ends it): X 10..50, each pair of moves
        # on lines 8 and 9.
        loop = []
        for k in range(1, 6):
            loop += [(8, (10 * k, 0, 2 * (k - 1))), (9, (10 * k, 0, 2 * k))]
        self.assertEqual(loop[:3], [(8, (10, 0, 0)), (9, (10, 0, 2)), (8, (20, 0, 2))])
        self.assertEqual(loop[-1], (9, (50, 0, 10)))
        # TRANS Z100 moves nothing: the tool stays at machine Z10, which is work Z-90.
        # R1 = $AA_IW[Z] = -90, R2 = $AA_IM[Z] = 10, Y = R2 - R1 = 100. The move goes to the
        # image of the programmed point (50, 100, 10): machine (50, 100, 110).
        self.assertMoves(moves, loop + [(16, (50, 100, 110))])
        self.assertEqual([m["feed"] for m in moves], [1000.0] * 11)
        vars_ = self.variables("cead-actual_position.mpf")
        self.assertEqual((vars_["R1"], vars_["R2"]), (-90.0, 10.0))

    # ---- values: operators, functions, variables ---------------------------------------------

    def test_operator_priority(self):
        moves = self.moves("cead-precedence.mpf")
        self.assertMoves(moves, [
            (4, (14, 0, 0)),    # 2+3*4: * before +
            (5, (4, 0, 0)),     # 10-2*3
            (6, (7, 0, 0)),     # 10-6/2
            (7, (3, 0, 0)),     # 2+6 DIV 4 = 2+1
            (8, (4, 0, 0)),     # 1+7 MOD 4 = 1+3
            (9, (20, 0, 0)),    # (2+3)*4
            (10, (1, 0, 0)),    # -2+3: the sign binds first
            (11, (-6, 0, 0)),   # 2*-3
            (12, (85, 0, 0)),   # 100-10*2+5 = 100-20+5, left to right
        ])

    def test_division_div_and_mod(self):
        moves = self.moves("cead-basic_math.mpf")
        # X = 1+1-1+-1 = 0: no motion from X0.
        self.assertMoves(moves, [
            (2, (1, -0.667, 0)),      # X1 Y=-2/3
            (3, (2, -0.667, 0)),      # 7 DIV 3: integer part of 2.33
            (4, (2.333, -0.667, 0)),  # 7 / 3 is real division
            (5, (3, -0.667, 0)),      # 3 MOD 4
            (6, (2.9, -0.667, 0)),    # 7 MOD 4.1 = 7 - 1*4.1
            (7, (1, -0.667, 0)),      # 7 DIV 4.1: integer part of 1.7
            (8, (17, -0.667, 0)),     # 7 DIV 0.4: integer part of 17.5
        ])

    def test_trig_functions_in_degrees(self):
        moves = self.moves("cead-trig.mpf")
        # SIN(30) = 0.5; COS(60) = 0.5 again: line 5 is no motion and prints nothing.
        self.assertMoves(moves, [
            (4, (0.5, 0, 0)),
            (6, (1, 0, 0)),        # TAN(45)
            (7, (30, 0, 0)),       # ASIN(0.5)
            (8, (60, 0, 0)),       # ACOS(0.5)
            (9, (20.846, 0, 0)),   # ATAN2(30.5, 80.1) = atan(30.5/80.1) = 20.8455 deg
            (10, (5, 0, 0)),       # SQRT(3^2 + 4^2)
        ])

    def test_int_variables_divide_as_reals(self):
        moves = self.moves("cead-variables.mpf")
        # DEF INT aa=1, bb=3, total=1: "/" of two INTs is REAL: 1/3, then aa=2: 2/3; total=2+3.
        self.assertMoves(moves, [(2, (0.333, 0, 0)), (4, (0.667, 0, 0)), (6, (5, 0, 0))])
        self.assertEqual(self.variables("cead-variables.mpf"), {"AA": 2.0, "BB": 3.0, "TOTAL": 5.0})

    def test_logic_and_bit_operators(self):
        moves = self.moves("cead-logic_operators.mpf")
        # TRACK_X=1, TRACK_Y=0. G1 X0 Y0 Z0 is no motion.
        self.assertMoves(moves, [
            # (1==1 AND 0==1) is false: line 9 skipped.
            (12, (10, 0, 0)),   # (1==1) OR (0==1)
            (15, (20, 0, 0)),   # NOT 0
            (18, (20, 0, 5)),   # true XOR false
            (24, (20, 30, 5)),  # R11 = 150 >= 100 = 1; Y = 30*1
            (28, (22, 30, 5)),  # R12 = 6 B_AND 3 = 0b110 & 0b011 = 2; X = 20+2
        ])
        vars_ = self.variables("cead-logic_operators.mpf")
        self.assertEqual((vars_["R11"], vars_["R12"]), (1.0, 2.0))

    def test_variable_names_are_case_insensitive(self):
        moves = self.moves("cead-case_insensitive_variables.mpf")
        # lAYER_HEIGHT, LAYER_HEIGHT, layer_height, Layer_Height: one variable, 2.5.
        # Z=IC(2.5) twice from Z0; R1 = 2.5*4 = 10; X = r1.
        self.assertMoves(moves, [(9, (0, 0, 2.5)), (10, (0, 0, 5)), (12, (10, 0, 5))])
        self.assertEqual(self.variables("cead-case_insensitive_variables.mpf"),
                         {"R1": 10.0, "LAYER_HEIGHT": 2.5})

    def test_string_variables_leave_the_moves_alone(self):
        moves = self.moves("cead-def_string.mpf")
        # DEF STRING[n] with and without a value, reassigned: no effect on the path.
        self.assertMoves(moves, [(11, (10, 5, 0)), (13, (20, 10, 0))])

    def test_ic_adds_to_the_programmed_point(self):
        moves = self.moves("cead-increment.mpf")
        # X1; X=IC(2): 1+2; Y=IC(0.1*nn) with nn = 9: 0.9, X=IC(2/3): 3 + 0.667.
        self.assertMoves(moves, [(2, (1, 0, 0)), (3, (3, 0, 0)), (4, (3.667, 0.9, 0))])

    # ---- frames --------------------------------------------------------------------------------

    def test_trans_then_atrans_adds(self):
        moves = self.moves("cead-trans.mpf")
        # X1 Y1; TRANS X100 Y2: (1+100, 1+2); ATRANS X50 Y2 adds: offset (150, 4): (151, 5).
        self.assertMoves(moves, [(1, (1, 1, 0)), (3, (101, 3, 0)), (5, (151, 5, 0))])

    def test_trans_is_traversed_with_an_incremental_move(self):
        moves = self.moves("cead-trans2.mpf")
        # X1; TRANS X100; X=IC(1): programmed 1+1 = 2, machine 102 (MD42440 = 1);
        # X=IC(2): 104; X=IC(3): 107.
        self.assertMoves(moves, [(1, (1, 0, 0)), (3, (102, 0, 0)), (4, (104, 0, 0)), (5, (107, 0, 0))])

    def test_trans_replaces_the_frame_and_bare_trans_or_rot_deletes_it(self):
        moves = self.moves("cead-trans_reset.mpf")
        self.assertMoves(moves, [
            (5, (1, 1, 0)),      # no frame
            (7, (102, 22, 0)),   # TRANS X100 Y20
            (9, (13, 3, 0)),     # TRANS X10 replaces the frame: Y's offset is gone
            (11, (4, 4, 0)),     # TRANS alone deletes it
            (13, (55, 5, 0)),    # ATRANS X50 onto the empty frame
            (15, (6, 6, 0)),     # ROT alone deletes the whole frame, translation included
        ])

    # ---- on the machine the probes are written for (tests/corpus/machines/cead-din.toml) ------

    def machineMoves(self, name):
        machine = os.path.join(CORPUS, "..", "machines", "cead-din.toml")
        proc = ncc("run", self.program(name), "--machine", machine, "--emit=moves", cwd=self.dir)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        return [json.loads(line) for line in proc.stdout.splitlines() if line.strip()]

    def test_for_loop_turns_the_rotary_axis_in_sevenths(self):
        moves = self.machineMoves("cead-for_loop.mpf")
        # FOR COUNTER=0 TO 7: A=360*COUNTER/7; COUNTER 0 is A0, where A is: no move.
        self.assertEqual([m["to"]["A"] for m in moves],
                         [51.429, 102.857, 154.286, 205.714, 257.143, 308.571, 360.0])
        self.assertEqual({m["line"] for m in moves}, {4})

    def test_repeat_until_steps_the_rotary_axis(self):
        moves = self.machineMoves("cead-repeat.mpf")
        # REPEAT A=COUNTER COUNTER=COUNTER+1 UNTIL COUNTER>7: A 0 (no move), 1 .. 7.
        self.assertEqual([m["to"]["A"] for m in moves], [1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0])

    def test_defaults_move_x_y_with_the_extruder_axis_named(self):
        moves = self.machineMoves("cead-defaults.mpf")
        # aa=12+3, bb=9 are variables; X=1600 Y=900 Z=0 E=0: one rapid, E staying at 0.
        self.assertEqual([(m["to"]["X"], m["to"]["Y"], m["to"]["Z"], m["to"]["E"]) for m in moves],
                         [(1600.0, 900.0, 0.0, 0.0)])


if __name__ == "__main__":
    NCC = sys.argv.pop(1)
    unittest.main(verbosity=2)
