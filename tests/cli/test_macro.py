#!/usr/bin/env python3
"""End-to-end tests of Macro B and subprograms (issue 22) through the ncc CLI: variables and
their values at the end of a run, control flow, calls found in the file and in the program
folder, and bad input: each fault is the controller's alarm (or an NCC code where the manual
gives none) at the offending block, exit 1, and no output file.

Run by ctest as: test_macro.py NCC_BINARY; with NCC_TEST_DEFER=1 (ctest cli_macro_deferred)
every command also runs with --defer and must give the same (cli_harness.run_ncc).
"""
import json
import os
import re
import sys
import unittest

from cli_harness import ScratchDirTest, run_ncc

NCC = None
DIAGNOSTIC = re.compile(r"^(?P<file>.+):(?P<line>\d+):(?P<col>\d+): (?P<severity>error|warning)\[(?P<code>[^\]]+)\]: (?P<message>.*)$")


def ncc(*args, cwd=None):
    return run_ncc(NCC, args, cwd=cwd, timeout=120)


def errors(stderr):
    found = [m.groupdict() for m in map(DIAGNOSTIC.match, stderr.splitlines()) if m]
    return [(d["line"], d["col"], d["code"], d["message"]) for d in found if d["severity"] == "error"]


class MacroTest(ScratchDirTest):
    def run_vars(self, name, text, *extra):
        prog = self.write(name, text)
        out = self.path("vars.json")
        proc = ncc("run", prog, "--emit=vars", "-o", out, *extra)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        with open(out) as f:
            return json.load(f)

    def moves(self, prog, *extra, cwd=None):
        proc = ncc("run", prog, "--emit=moves", *extra, cwd=cwd)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        return [json.loads(line) for line in proc.stdout.splitlines()]

    def assert_alarm(self, name, text, line, code, *extra, col=None, dialect="mazak-m",
                     message=None):
        """The program is refused with `code` at `line` (and `col`, with `message`), and -o
        writes nothing."""
        prog = self.write(name, text)
        out = self.path(name + ".ncb")
        proc = ncc("compile", prog, "--dialect", dialect, "-o", out, *extra)
        self.assertEqual(proc.returncode, 1, proc.stderr)
        found = errors(proc.stderr)
        self.assertTrue(found, proc.stderr)
        self.assertEqual((found[0][0], found[0][2]), (str(line), code), proc.stderr)
        if col is not None:
            self.assertEqual(found[0][1], str(col), proc.stderr)
        if message is not None:
            self.assertEqual(found[0][3], message, proc.stderr)
        self.assertFalse(os.path.exists(out))
        return proc.stderr

    # ---- values ------------------------------------------------------------------------------

    def test_vars_hold_the_values_the_program_left(self):
        got = self.run_vars("v.nc", "#100=3\n#101=#100*2+1\n#102=SQRT[16]\n#500=#0\n"
                                    "#103=ATAN[1]/[1]\n#104=[#101 GT #100]\nM30\n",
                            "--dialect", "fanuc-m")
        self.assertEqual(got, {"#100": 3.0, "#101": 7.0, "#102": 4.0, "#103": 45.0, "#104": 1.0})

    def test_a_vacant_variable_drops_its_address(self):
        # §13-9-3: G0 X#1 Y1000. with #1 vacant is G0 Y1000.
        prog = self.write("d.nc", "G90 G00 X5. Y0\nG00 X#1 Y10.\nM30\n")
        got = self.moves(prog, "--dialect", "mazak-m")
        self.assertEqual([m["to"]["X"] for m in got if m["kind"] == "rapid"], [5.0, 5.0])
        self.assertEqual([m["to"]["Y"] for m in got if m["kind"] == "rapid"], [0.0, 10.0])

    def test_variable_values_are_lengths_with_a_point(self):
        # Under decimal_point = "standard", X10 is 0.010 mm but X#1 with #1 = 10 is 10 mm.
        prog = self.write("p.nc", "#1=10\nG90 G00 X#1\nG00 X10\nM30\n")
        got = self.moves(prog, "--dialect", "fanuc-m")
        self.assertEqual([m["to"]["X"] for m in got], [10.0, 0.01])

    # ---- control flow ------------------------------------------------------------------------

    def test_while_loop_moves_and_counts(self):
        prog = self.write("w.nc", "#1=0\nG91\nWHILE[#1LT3]DO1\nG01 X1. F100.\n#1=#1+1\nEND1\n"
                                  "#100=#1\nM30\n")
        got = self.moves(prog, "--dialect", "fanuc-m")
        self.assertEqual([m["to"]["X"] for m in got if m["kind"] == "line"], [1.0, 2.0, 3.0])

    def test_nested_loops_with_the_same_number_after_each_other(self):
        got = self.run_vars("n.nc", "#100=0\n#1=0\nWHILE[#1LT2]DO1\n#2=0\nWHILE[#2LT3]DO2\n"
                                    "#100=#100+1\n#2=#2+1\nEND2\n#1=#1+1\nEND1\n"
                                    "WHILE[#1GT0]DO1\n#1=#1-1\nEND1\nM30\n", "--dialect", "mazak-m")
        self.assertEqual(got["#100"], 6.0)

    def test_a_loop_skipped_when_false_at_once(self):
        got = self.run_vars("s.nc", "#100=1\nWHILE[#100GT5]DO1\n#100=99\nEND1\n#101=2\nM30\n",
                            "--dialect", "mazak-m")
        self.assertEqual(got, {"#100": 1.0, "#101": 2.0})

    def test_an_endless_loop_stops_at_the_limit_at_its_jump(self):
        self.assert_alarm("e.nc", "N1 #100=1\nGOTO1\nM30\n", 2, "NCC2419", "--max-back-jumps", "50",
                          message="the program jumped back 50 times here: an endless loop? "
                                  "(the limit is --max-back-jumps)")

    # ---- calls -------------------------------------------------------------------------------

    def test_m98_finds_the_program_in_the_folder_by_name_and_by_its_o_number(self):
        self.write("O1234.nc", "O1234\nG91 G01 X1. F100.\nM99\n")
        self.write("other.nc", "%\nO5678\nG91 G01 Y1. F100.\nM99\n%\n")
        prog = self.write("main.nc", "G90 G00 X0 Y0\nM98 P1234 L2\nM98 P5678\nG90 G00 X0 Y0\nM30\n")
        got = self.moves(prog, "--dialect", "mazak-m")
        self.assertEqual([(m["to"]["X"], m["to"]["Y"]) for m in got if m["kind"] == "line"],
                         [(1.0, 0.0), (2.0, 0.0), (2.0, 1.0)])

    def test_fanuc_repeat_count_in_the_high_digits_of_p(self):
        self.write("O0021.nc", "O0021\n#100=#100+1\nM99\n")
        got = self.run_vars("m.nc", "#100=0\nM98 P30021\nM30\n", "--dialect", "fanuc-m")
        self.assertEqual(got["#100"], 3.0)

    def test_g65_arguments_are_locals_of_their_own_level(self):
        got = self.run_vars("g.nc", "#1=5\nG65 P9000 A1. B2. I3. J4. I5.\n#100=#1\nM30\n"
                                    "O9000\n#101=#1+#2\n#102=#4\n#103=#7\n#104=#5\n#1=99\nM99\n",
                            "--dialect", "fanuc-m")
        # Specification II: the second I is #7; the caller's #1 is untouched by the macro's.
        self.assertEqual(got, {"#1": 5.0, "#100": 5.0, "#101": 3.0, "#102": 3.0, "#103": 5.0,
                               "#104": 4.0})

    def test_m99_p_returns_to_a_sequence_number_of_the_caller(self):
        got = self.run_vars("r.nc", "#100=0\nM98 P10\n#100=1\nN50 #101=2\nM30\nO10\nM99 P50\n",
                            "--dialect", "mazak-m")
        self.assertEqual(got, {"#100": 0.0, "#101": 2.0})

    def test_m98_h_calls_a_sequence_of_the_same_program(self):
        got = self.run_vars("h.nc", "#100=0\nM98 H20\nM98 H20\nGOTO 99\nN20 #100=#100+1\nM99\n"
                                    "N99 M30\n", "--dialect", "mazak-m")
        self.assertEqual(got["#100"], 2.0)

    def test_g66_1_calls_the_macro_for_every_block(self):
        got = self.run_vars("c.nc", "#100=0\nG66.1 P9100\nX1.\nY2.\nG67\nM30\n"
                                    "O9100\n#100=#100+1\n#[100+#100]=#24+#25\nM99\n",
                            "--dialect", "mazak-m")
        self.assertEqual(got, {"#100": 2.0, "#101": 1.0, "#102": 2.0})

    def test_words_before_m98_run_first(self):
        # Mazak §13-4: `X100. M98 P100` moves, then calls.
        prog = self.write("o.nc", "G90 G00 X5. M98 P7\nM30\nO7\nG00 Y3.\nM99\n")
        got = self.moves(prog, "--dialect", "mazak-m")
        self.assertEqual([(m["to"]["X"], m["to"]["Y"]) for m in got], [(5.0, 0.0), (5.0, 3.0)])

    def test_system_variables_read_the_controller_model(self):
        machine = self.write("m.toml", "[machine]\naxes = [\"X\", \"Y\", \"Z\"]\n"
                                       "[machine.work]\nG55 = [10.0, 20.0, 30.0]\n"
                                       "[machine.offsets]\nH3 = 7.5\n")
        got = self.run_vars("s.nc", "G90 G55 G00 X1. Y2.\n#100=#5001\n#101=#5242\n#102=#2003\n"
                                    "#103=#4012\n#2003=8.5\nG43 H3 Z0\n#104=#5023\n#105=#5003\nM30\n",
                            "--dialect", "mazak-m", "--machine", machine)
        self.assertEqual(got["#100"], 1.0)    # end point X, work coordinates
        self.assertEqual(got["#101"], 20.0)   # G55 Y (#5241 + 20 k + axis)
        self.assertEqual(got["#102"], 7.5)    # H3 length geometry
        self.assertEqual(got["#103"], 55.0)   # Mazak group 12: G55
        self.assertEqual(got["#104"], 38.5)   # machine Z = G55 30 + H3 8.5 (the value just written)
        self.assertEqual(got["#105"], 0.0)
        self.assertEqual(got["#2003"], 8.5)

    def test_code_macros_of_the_machine_file(self):
        machine = self.write("m.toml", '[machine]\naxes = ["X", "Y", "Z"]\n[machine.params]\n'
                                       'm_code_macros = { M6 = "TOOLCHG", M60 = "9020" }\n'
                                       'g_code_macros = { G100 = "9010" }\n')
        # By name: TOOLCHG.nc in the folder; inside it M6 is the plain tool change.
        self.write("TOOLCHG.nc", "#100=#100+1\n#101=#20\nM6\nM99\n")
        got = self.run_vars("c.nc", "#100=0\nM6 T5\nM60 A2.\nG100 X3. Y4.\nM30\n"
                                    "O9020\n#102=#1\nM99\nO9010\n#103=#24*#25\nM99\n",
                            "--dialect", "fanuc-m", "--machine", machine)
        self.assertEqual((got["#100"], got["#101"], got["#102"], got["#103"]), (1.0, 5.0, 2.0, 12.0))
        # Keys are checked where the machine file is read: each at its line and column.
        bad = self.write("b.toml", '[machine.params]\nm_code_macros = { X6 = "9020", M7 = "" }\n'
                                   'g_code_macros = { G10A = "9010" }\n')
        proc = ncc("compile", self.path("c.nc"), "--dialect", "fanuc-m", "--machine", bad,
                   "-o", self.path("c.ncb"))
        self.assertEqual(proc.returncode, 2, proc.stderr)  # an invalid machine file
        found = [m.groupdict() for m in map(DIAGNOSTIC.match, proc.stderr.splitlines()) if m]
        self.assertEqual([(d["line"], d["col"], d["code"]) for d in found],
                         [("2", "19", "NCC0306"), ("2", "37", "NCC0306"), ("3", "19", "NCC0306")],
                         proc.stderr)
        self.assertEqual(found[0]["message"],
                         "'X6' in 'm_code_macros' is not a M code (M and a whole number, e.g. M6)")
        self.assertEqual(found[1]["message"], "'m_code_macros' M7: the program to call is empty")
        self.assertIn("'G10A' in 'g_code_macros' is not a G code", found[2]["message"])
        self.assertFalse(os.path.exists(self.path("c.ncb")))

    # ---- variables file ----------------------------------------------------------------------

    def test_vars_file_keeps_the_persistent_commons_between_runs(self):
        prog = self.write("c.nc", "#500=#500+1\n#100=#500\nM30\n")
        saved = self.path("v.toml")
        for expected in (1.0, 2.0):
            got = self.run_vars("c.nc", "#500=#500+1\n#100=#500\nM30\n", "--vars", saved)
            self.assertEqual(got["#500"], expected)
            with open(saved) as f:
                text = f.read()
            self.assertIn(f'"#500" = {expected}', text)
            self.assertNotIn("#100", text)  # not kept through power-off on FANUC

    def test_vars_file_keeps_the_variables_the_program_does_not_write(self):
        saved = self.write("v.toml", '"#500" = 4.0\n"#501" = 7.5\n')
        got = self.run_vars("i.nc", "#500=#500+1\nM30\n", "--vars", saved)
        self.assertEqual(got, {"#500": 5.0, "#501": 7.5})
        with open(saved) as f:
            text = f.read()
        self.assertIn('"#500" = 5.0', text)
        self.assertIn('"#501" = 7.5', text)

    def test_vars_file_is_not_written_after_an_alarm(self):
        saved = self.write("v.toml", '"#500" = 4.0\n')
        prog = self.write("a.nc", "#500=9\nG95 G01 X1. F1.\nM30\n")  # no spindle: alarm
        proc = ncc("run", prog, "--vars", saved)
        self.assertEqual(proc.returncode, 3, proc.stderr)
        with open(saved) as f:
            self.assertEqual(f.read(), '"#500" = 4.0\n')

    def test_bad_vars_files(self):
        prog = self.write("p.nc", "#1=#500\nM30\n")
        cases = (('"#100" = 1.0\n', 1, 1, "#100 is not a variable the controller keeps across runs "
                                         "(its persistent common variables)"),
                 ('"#500" = "x"\n', 1, 10, "#500: the value must be a finite number"),
                 ('"#500 = 1\n', 1, 10, None),  # toml++'s own message
                 ('x = 1.0\n', 1, 1, "'x' is not a variable: keys are \"#n\""))
        for text, line, col, message in cases:
            saved = self.write("bad.toml", text)
            proc = ncc("compile", prog, "--vars", saved, "-o", self.path("p.ncb"))
            self.assertEqual(proc.returncode, 1, proc.stderr)
            found = errors(proc.stderr)
            self.assertEqual(found[0][2], "NCC0017", proc.stderr)
            self.assertEqual(found[0][0], str(line), proc.stderr)
            self.assertEqual(found[0][1], str(col), proc.stderr)
            if message:
                self.assertEqual(found[0][3], message, proc.stderr)
            self.assertFalse(os.path.exists(self.path("p.ncb")))
        ncb = self.write("q.ncb", b"")
        proc = ncc("run", ncb, "--vars", self.path("v.toml"))
        self.assertEqual(proc.returncode, 2, proc.stderr)
        self.assertIn("ncc: error[NCC0018]: --vars needs a source program: a bytecode file's "
                      "variables were fixed when it was compiled", proc.stderr)

    # ---- bad input ---------------------------------------------------------------------------

    def test_each_fault_is_the_controllers_alarm_at_its_block(self):
        cases = [  # name, program, line, column, code, message, dialect
            ("vn", "#1=1\n#[0-5]=1\nM30\n", 2, 1, "NCC2400", "variable number -5 is negative", "mazak-m"),
            ("vs", "#1=#20000\nM30\n", 1, 4, "NCC2400", "#20000 is not a system variable of fanuc-m", "fanuc-m"),
            ("dz", "#1=0\n#2=5/#1\nM30\n", 2, 5, "860", "division by zero", "mazak-m"),
            ("ln", "#1=LN[-5]\nM30\n", 1, 4, "860", "LN[-5]: the logarithm needs a number greater than 0", "mazak-m"),
            ("ed", "#1=1\nEND1\nM30\n", 2, 1, "NCC2407", "END 1 without WHILE ... DO 1", "mazak-m"),
            ("dn", "WHILE[1]DO1\nWHILE[1]DO2\nWHILE[1]DO3\nWHILE[1]DO1\nM30\n", 4, 1, "NCC2408",
             "WHILE ... DO nested more than 3 deep", "fanuc-m"),
            ("di", "WHILE[1]DO200\nM30\n", 1, 1, "NCC2409", "DO 200: loop numbers are 1 to 127", "mazak-m"),
            ("lp", "WHILE[0]DO1\n#1=1\nM30\n", 1, 1, "NCC2410", "WHILE ... DO 1 has no END 1", "mazak-m"),
            ("gt", "#1=1\nGOTO 77\nM30\n", 2, 1, "843", "no block starts with N77 in this program", "mazak-m"),
            ("sp", "M98 P4321\nM30\n", 1, 1, "844", "program O4321 not found (in this file or the program folder)",
             "mazak-m"),
            ("cn", "M98 P10\nM30\nO10\nM98 P10\nM99\n", 4, 1, "842", "calls nested more than 8 deep", "mazak-m"),
            ("mn", "G65 P9 A1.\nM30\nO9\nG65 P9\nM99\n", 4, 1, "NCC2414", "macro calls nested more than 4 deep",
             "mazak-m"),
            ("ua", "#3000=25 (TOOL BROKEN)\nM30\n", 1, 1, "3025", "user alarm #3000 = 25: TOOL BROKEN", "mazak-m"),
            ("ub", "#3000=5\nM30\n", 1, 1, "984", "user alarm #3000 = 5", "mazak-m"),
            ("g67", "G67\nM30\n", 1, 1, "857", "G67 without a modal macro call (G66) in force", "mazak-m"),
            ("w0", "#0=1\nM30\n", 1, 1, "NCC2401", "#0 is always vacant and cannot be assigned", "mazak-m"),
            ("pi", "#1=1.5\nGOTO#1\nM30\n", 2, 1, "809", "the GOTO target must be an integer, not 1.5",
             "mazak-m"),
            # Figure rotation (§13-7 notes 3 and 4): nested, with G68 either way; FANUC has none.
            ("fr", "M98 P10 I1. L2\nM30\nO10\nM98 P20 I1. L2\nM99\nO20\nX1.\nM99\n", 4, 1, "849",
             "a figure rotation (M98 with I J K) cannot be called inside another one", "mazak-m"),
            ("fg", "G68 X0 Y0 R10.\nM98 P10 I1. L2\nM30\nO10\nX1.\nM99\n", 2, 1, "850",
             "a figure rotation (M98 with I J K) cannot be called while G68 is in force", "mazak-m"),
            ("fh", "M98 P10 I1. L2\nM30\nO10\nG68 X0 Y0 R10.\nM99\n", 4, 1, "850",
             "G68 cannot be given during a figure rotation (M98 with I J K)", "mazak-m"),
            ("fi", "M98 P10 I1.\nM30\nO10\nX1.\nM99\n", 1, 9, "NCC2406", "address I has no meaning in M98",
             "fanuc-m"),
        ]
        for name, text, line, col, code, message, dialect in cases:
            with self.subTest(name):
                self.assert_alarm(name + ".nc", text, line, code, col=col, dialect=dialect, message=message)

    def test_user_stop_is_a_warning_with_its_message(self):
        prog = self.write("st.nc", "#3006=1 (CHECK PART)\nG00 X1.\nM30\n")
        proc = ncc("run", prog, "--dialect", "mazak-m", "--emit=moves")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        found = [m.groupdict() for m in map(DIAGNOSTIC.match, proc.stderr.splitlines()) if m]
        self.assertEqual([(d["severity"], d["line"], d["code"], d["message"]) for d in found],
                         [("warning", "1", "NCC2416", "program stop #3006: CHECK PART")])

    def test_the_user_alarm_message_is_shown(self):
        stderr = self.assert_alarm("ua.nc", "#3000=25 (TOOL BROKEN)\nM30\n", 1, "3025")
        self.assertIn("TOOL BROKEN", stderr)

    def test_a_run_time_variable_the_vm_does_not_simulate_is_refused_clearly(self):
        stderr = self.assert_alarm("lag.nc", "G00 X1.\nIF[#5101 EQ 1]GOTO5\nM30\n", 2, "NCC2010",
                                   col=4)
        self.assertIn("#5101 (servo deviation) is known only when the program runs, and the VM "
                      "does not simulate it yet", stderr)

    def test_timers_count_the_run_time_when_the_block_is_prepared(self):
        # 400 moves of 1 mm at 600 mm/min: 40 s and more (each starts and stops). The timers restart at their writes and read
        # the run's time when the block reading them is prepared (the look-ahead runs ahead
        # of the motion, at most to the end of the program).
        lines = ["G90 G00 X0 Y0 Z0", "#3001=5000", "#3002=0"]
        lines += [f"G01 X{i % 2}. F600." for i in range(1, 401)]
        lines += ["#101=#3001", "#102=#3002", "M30", ""]
        prog = self.write("timer.nc", "\n".join(lines))
        proc = ncc("run", "--dialect", "fanuc-m", "--emit=vars", prog)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        v = json.loads(proc.stdout)
        self.assertGreaterEqual(v["#101"], 5000.0)
        self.assertLessEqual(v["#101"], 5000.0 + 60000.0)
        self.assertEqual(v["#101"], round(v["#101"]))           # whole milliseconds
        self.assertAlmostEqual(v["#102"], (v["#101"] - 5000.0) / 3600e3, delta=1e-6)  # hours
        # Mazak counts both in ms (§13-9-4 8.).
        proc = ncc("run", "--dialect", "mazak-m", "--emit=vars", prog)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        v = json.loads(proc.stdout)
        self.assertEqual(v["#102"], v["#101"] - 5000.0)
        # Reading a timer is where the compiler leaves the program to the VM.
        proc = ncc("check", "--dialect", "fanuc-m", prog)
        self.assertIn("timer.nc:2:1: note[NCC0023]: the program is prepared while it runs from "
                      "here: #3001 (timer, ms) restarts at the time of the write", proc.stderr)

    def test_interface_signals(self):
        # Inputs are the machine's, known when the program runs: the VM prepares the blocks
        # from the first that reads one. Outputs are what the program wrote.
        prog = self.write("sig.nc", "G90 G00 X0 Y0 Z10.\nIF[#1005 EQ 1]GOTO10\nG01 X10. F100.\n"
                                    "M30\nN10 G01 Y10. F100.\n#1100=1\n#1133=7\n#101=#1132+#1133\n"
                                    "#102=#1032\nM30\n")

        def run(*extra):
            proc = ncc("run", "--dialect", "fanuc-m", "--emit=moves", prog, *extra)
            self.assertEqual(proc.returncode, 0, proc.stderr)
            return [json.loads(line)["to"] for line in proc.stdout.splitlines()]

        self.assertEqual(run()[-1], {"X": 10.0, "Y": 0.0, "Z": 10.0})
        self.assertEqual(run("--signal", "1005=1")[-1], {"X": 0.0, "Y": 10.0, "Z": 10.0})
        machine = self.write("sig.toml", "[machine.signals]\n1005 = 1\n\"#1001\" = 1\n")
        self.assertEqual(run("--machine", machine)[-1], {"X": 0.0, "Y": 10.0, "Z": 10.0})
        self.assertEqual(run("--machine", machine, "--signal", "1005=0")[-1],
                         {"X": 10.0, "Y": 0.0, "Z": 10.0})
        proc = ncc("run", "--dialect", "fanuc-m", "--emit=vars", "--machine", machine,
                   "--signal", "#1003=1", prog)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        v = json.loads(proc.stdout)
        self.assertEqual((v["#101"], v["#102"], v["#1100"]), (8.0, 2.0 + 8.0 + 32.0, 1.0))
        # The compiler says where the VM takes over.
        proc = ncc("check", "--dialect", "fanuc-m", prog)
        self.assertIn("sig.nc:2:4: note[NCC0023]: the program is prepared while it runs from "
                      "here: #1005 (interface input signals) is known only when the program runs",
                      proc.stderr)
        # Inputs are read only; bad values are refused where they are given.
        self.assert_alarm("w.nc", "#1005=1\nM30\n", 1, "NCC2401", dialect="fanuc-m")
        for bad in ("1032=1", "1005=2", "999=1", "1033=-1", "1005"):
            proc = ncc("run", "--signal", bad, prog)
            self.assertEqual(proc.returncode, 2, bad)
            self.assertIn("error[NCC0310]: --signal: ", proc.stderr)
        for text, code in (("1005 = 3", "NCC0306"), ("foo = 1", "NCC0302"), ("1032 = 0", "NCC0306")):
            proc = ncc("check", "--machine", self.write("bad.toml", f"[machine.signals]\n{text}\n"), prog)
            self.assertEqual(proc.returncode, 2, text)
            self.assertIn(f"bad.toml:2:", proc.stderr)
            self.assertIn(f"error[{code}]", proc.stderr)


if __name__ == "__main__":
    NCC = sys.argv.pop(1)
    unittest.main(verbosity=2)
