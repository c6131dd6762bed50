#!/usr/bin/env python3
"""End-to-end tests of cutter compensation as lowering records it (issue 24, docs/semantics.md
"Cutter compensation: what lowering records"): `ncc compile --emit=ir --stop-after=lower` prints
each block's comp(...) record, the machine file's parameters and D registers reach it, and the
compensation alarms name the dialect's number at the word.

Run by ctest as: test_cutter_comp_lowering.py NCC_BINARY
"""
import re
import subprocess
import sys
import unittest

from cli_harness import ScratchDirTest

NCC = None

MACHINE = """[machine]
axes = ["X", "Y", "Z"]
[machine.offsets]
D1 = 5.0
[machine.work]
G54 = [0.0, 0.0, 0.0]
[machine.params]
{params}
[start]
position = {{ X = 0.0, Y = 0.0, Z = 0.0 }}
"""

CONTOUR = "G17 G90 G01 F100.\nG41 X10. Y10. D1\nX50. I1. J0\nG39\nY40.\nG40 X0 Y0 I-1. J0\nM30\n"


def ncc(*args):
    return subprocess.run([NCC, *args], capture_output=True, text=True, timeout=60)


class CutterCompLoweringTest(ScratchDirTest):
    def lower(self, program, dialect, params=""):
        nc = self.write("p.nc", program)
        machine = self.write("m.toml", MACHINE.format(params=params))
        return ncc("compile", nc, "--dialect", dialect, "--machine", machine, "--emit=ir",
                   "--stop-after=lower", "-o", "-")

    def write(self, name, text):
        with open(self.path(name), "w") as f:
            f.write(text)
        return self.path(name)

    def comps(self, stdout):
        return [(int(m.group(1)), m.group(2)) for m in
                (re.match(r"block \d+:(\d+):\d+ .* (comp\(.*\))$", line) for line in stdout.splitlines()) if m]

    def test_fanuc_records_the_contour_from_start_up_to_cancel(self):
        proc = self.lower(CONTOUR, "fanuc-m")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual(proc.stderr, "")
        self.assertEqual(self.comps(proc.stdout), [
            (2, "comp(left D1=5.000 commanded)"),
            (3, "comp(left D1=5.000 vector 1.000 0.000 0.000)"),
            (4, "comp(left D1=5.000 corner-arc)"),
            (5, "comp(left D1=5.000)"),
            (6, "comp(off D1=5.000 vector -1.000 0.000 0.000)"),
        ])

    def test_the_ij_vector_is_fanuc_only(self):
        proc = self.lower(CONTOUR, "siemens-iso-m")
        self.assertEqual(proc.returncode, 1)
        self.assertIn("p.nc:3:6: error[NCC2014]: address I has no meaning in this block", proc.stderr)

    def test_alarms_carry_the_dialect_number_at_the_word(self):
        cases = [
            ("fanuc-m", "G17 G02 G41 X10. Y0 R5. D1 F100.\n", "p.nc:1:9: error[PS0034]"),
            ("mazak-m", "G17 G01 G41 X10. D1 F100.\nG02 X20. Y10. R10.\nG40\n", "p.nc:3:1: error[835]"),
            ("fanuc-m", "G17 G01 G41 X10. D1 F100.\nX20.\nG18 X30.\n", "p.nc:3:1: error[PS0037]"),
            ("fanuc-m", "G17 G01 G41 X10. D1 F100.\nG31 X20.\n", "p.nc:2:1: error[PS0035]"),
            ("siemens-iso-m", "G17 G01 G41 X10. D1 F100.\nG91 G28 Z0\n", "p.nc:2:5: error[NCC2123]"),
            ("mazak-m", "G17 G00 G41 X1. Y1. Z1. I0 J0 K1. D1 M03\nG81 X2. Z-5. R1. F100.\n", "p.nc:2:1: error[901]"),
            ("mazak-m", "G17 G01 G41 X10. D200 F100.\n", "p.nc:1:18: error[839]"),
        ]
        for dialect, program, expected in cases:
            with self.subTest(dialect=dialect, program=program):
                proc = self.lower(program + "M30\n", dialect)
                self.assertEqual(proc.returncode, 1, proc.stderr)
                self.assertIn(expected, proc.stderr)

    def test_parameters_reach_the_record(self):
        # No.19625 = 6 and type B apply in fanuc-m now (recorded, no 'not applied' warning).
        proc = self.lower(CONTOUR, "fanuc-m", 'tnrc_lookahead_blocks = 6\nstartup_type = "B"\n')
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertNotIn("NCC0307", proc.stderr)
        # comp3d_normal_length is Mazak's (F11): elsewhere it is not applied.
        proc = self.lower(CONTOUR, "fanuc-m", "comp3d_normal_length = 2.0\n")
        self.assertIn("NCC0307", proc.stderr)
        proc = self.lower("G17 G01 G42 X10. I1. J0 K0 D1 F100.\nM30\n", "mazak-m",
                          "comp3d_normal_length = 2.5\n")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual(self.comps(proc.stdout)[0], (1, "comp(right D1=5.000 commanded 3d -2.000 0.000 0.000)"))

    def test_macro_variable_4007_reads_the_side_in_force(self):
        # #4007: the group 07 code in force (FANUC system variables), 41 while G41, 40 after G40.
        program = "G17 G01 G41 X10. D1 F100.\n#100=#4007\nG01 X#100\nG40 X0\n#101=#4007\nG01 Y#101\nM30\n"
        proc = self.lower(program, "fanuc-m")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertIn("line work X41.000 Y0.000", proc.stdout)
        self.assertIn("line work X0.000 Y40.000", proc.stdout)

    def test_variable_writes_while_compensating_carry_the_record(self):
        # #2601 (radius geometry D1) = 7.: the writes' block (the writes of lines 2 and 3, one
        # block at the last of them) and the next ones hold 7.
        program = "G17 G01 G41 X10. D1 F100.\n#2601=7.\n#100=1\nX20.\nG40 X0\nM30\n"
        proc = self.lower(program, "fanuc-m")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual(self.comps(proc.stdout), [
            (1, "comp(left D1=5.000 commanded)"), (3, "comp(left D1=7.000)"),
            (4, "comp(left D1=7.000)"), (5, "comp(off D1=7.000)")])

    def test_the_corpus_step_block_lowers_with_its_d_register(self):
        # As corpus enier-mill_240806_step_block_1.nc: G41 D02 never cancelled before M30;
        # every block to the end is recorded.
        program = "G17 G90 G00 X-1. Y-1.\nG01 F10.\nG41 D02 X0.2 Y0.2\nY1.6\nX3.6\nM09\nM30\n"
        proc = self.lower(program, "fanuc-m")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual([line for line, _ in self.comps(proc.stdout)], [3, 4, 5, 6, 7])


if __name__ == "__main__":
    NCC = sys.argv.pop(1)
    unittest.main(verbosity=2)
