#!/usr/bin/env python3
"""Issue 21: travel limits are alarms, and every run ends.

- A move beyond a stored stroke limit stops the run before the move with the dialect's alarm
  (FANUC OT0500/OT0501, Sinumerik 10720, Mazak NCC7210), naming the line and the axis; an arc
  whose end points are inside but whose extent is not is caught too.
- A run has a simulated-time limit (--max-time, NCC7208); absurd machine files are refused
  (NCC0306) and a start position outside the travel is a machine-file error.
- Each reproducer must end within seconds.

Run by ctest as: test_bounds.py NCC_BINARY
"""
import json
import os
import re
import struct
import subprocess
import sys
import time
import unittest

from cli_harness import ScratchDirTest

from test_bytecode import seal  # the documented checksum, for files edited on purpose

NCC = None

# Exit codes (docs/cli.md): 1 errors in the program, 2 an invalid machine file, 3 the run
# stopped on an alarm.
ALARM_EXIT = 3
ERROR_EXIT = 1
SETUP_EXIT = 2

TRAVEL_MACHINE = """[machine]
axes = ["X", "Y", "Z"]

[machine.axis.X]
min_travel = -10.0
max_travel = 10.0

[machine.axis.Y]
min_travel = -20.0
max_travel = 20.0
"""


def ncc(*args, timeout=30):
    return subprocess.run([NCC, *args], capture_output=True, text=True, timeout=timeout)


class BoundsTest(ScratchDirTest):
    def run_timed(self, *args, limit=20):
        start = time.monotonic()
        proc = ncc(*args, timeout=limit + 10)
        self.assertLess(time.monotonic() - start, limit, args)
        return proc

    # --- travel limits ---------------------------------------------------------------------

    def test_rapid_beyond_travel_is_an_alarm_per_dialect(self):
        machine = self.write("m.toml", TRAVEL_MACHINE)
        prog = "N10 G90 G00 X5.\nN20 G00 X50.\nN30 M30\n"
        path = self.write("p.nc", prog)
        for dialect, code in (("fanuc-m", "OT0500"), ("mazak-m", "NCC7210"),
                              ("siemens-iso-m", "10720")):
            proc = ncc("run", path, "--machine", machine, "--dialect", dialect)
            self.assertEqual(proc.returncode, ALARM_EXIT, (dialect, proc.stdout, proc.stderr))
            # The block (line 2, its column) and the axis are named.
            self.assertRegex(proc.stderr, r"p\.nc:2:\d+: error\[" + code + r"\]", dialect)
            self.assertIn("axis X", proc.stderr)
            self.assertIn("max_travel 10", proc.stderr)

    def test_minus_direction_uses_the_minus_alarm(self):
        machine = self.write("m.toml", TRAVEL_MACHINE)
        path = self.write("p.nc", "N10 G90 G01 Y-30. F1000.\nN20 M30\n")
        proc = ncc("run", path, "--machine", machine)
        self.assertEqual(proc.returncode, ALARM_EXIT, proc.stderr)
        self.assertRegex(proc.stderr, r"p\.nc:1:\d+: error\[OT0501\]")
        self.assertIn("axis Y", proc.stderr)
        self.assertIn("min_travel -20", proc.stderr)

    def test_the_move_is_not_started(self):
        # The alarm comes before the move: the last setpoint is where the block before ended.
        machine = self.write("m.toml", TRAVEL_MACHINE)
        path = self.write("p.nc", "N10 G90 G00 X5.\nN20 G00 X50.\nN30 M30\n")
        proc = ncc("run", path, "--machine", machine, "--emit=trace")
        self.assertEqual(proc.returncode, ALARM_EXIT, proc.stderr)
        rows = proc.stdout.splitlines()
        xs = [float(r.split(",")[1]) for r in rows[1:]]
        self.assertLessEqual(max(xs), 5.0 + 1e-9)
        self.assertAlmostEqual(xs[-1], 5.0, places=6)

    def test_arc_extent_beyond_travel_while_its_ends_are_inside(self):
        # A half circle from X-5 to X5 around X0 Y0: G03 (counter-clockwise) passes the bottom
        # quadrant point Y-5, below min_travel -4, while both end points are at Y0.
        machine = self.write("m.toml", """[machine]
axes = ["X", "Y", "Z"]

[machine.axis.Y]
min_travel = -4.0
max_travel = 20.0
""")
        prog = "N10 G90 G00 X-5. Y0\nN20 G03 X5. Y0 I5. J0 F1000.\nN30 M30\n"
        path = self.write("p.nc", prog)
        proc = ncc("run", path, "--machine", machine)
        self.assertEqual(proc.returncode, ALARM_EXIT, proc.stderr)
        self.assertRegex(proc.stderr, r"p\.nc:2:\d+: error\[OT0501\]")
        self.assertIn("axis Y", proc.stderr)
        # The other way round (G02, through the top) stays within travel and runs.
        ok = self.write("q.nc", "N10 G90 G00 X-5. Y0\nN20 G02 X5. Y0 I5. J0 F1000.\nN30 M30\n")
        proc = ncc("run", ok, "--machine", machine)
        self.assertEqual(proc.returncode, 0, proc.stderr)

    def test_moves_emit_stops_at_the_travel_alarm_too(self):
        machine = self.write("m.toml", TRAVEL_MACHINE)
        path = self.write("p.nc", "N10 G90 G00 X5.\nN20 G00 X50.\nN30 M30\n")
        proc = ncc("run", path, "--machine", machine, "--emit=moves")
        self.assertEqual(proc.returncode, ALARM_EXIT, proc.stderr)
        # The move before the alarm, then the alarm record (the move beyond is not started).
        records = [json.loads(line) for line in proc.stdout.splitlines()]
        self.assertEqual([r["kind"] for r in records], ["rapid", "alarm"], proc.stdout)
        self.assertEqual((records[1]["code"], records[1]["line"]), ("OT0500", 2))
        self.assertIn("OT0500", proc.stderr)

    def test_start_position_outside_travel_is_a_machine_file_error(self):
        machine = self.write("m.toml", TRAVEL_MACHINE + "\n[start]\nposition = { X = 11.0 }\n")
        path = self.write("p.nc", "N10 M30\n")
        proc = ncc("run", path, "--machine", machine)
        self.assertEqual(proc.returncode, SETUP_EXIT, proc.stderr)
        self.assertRegex(proc.stderr, r"m\.toml:13:18: error\[NCC0306\]: start position 11 of X")

    # --- bounded runs ----------------------------------------------------------------------

    def test_max_time_stops_the_run_in_its_block(self):
        path = self.write("p.nc", "N10 G90 G01 X100. F60.\nN20 G01 X0\nN30 M30\n")
        # X100 at 1 mm/s takes 100 s: a 30 s limit stops it in line 1.
        proc = self.run_timed("run", path, "--max-time", "30")
        self.assertEqual(proc.returncode, ALARM_EXIT, proc.stderr)
        self.assertRegex(proc.stderr, r"p\.nc:1:\d+: error\[NCC7208\]")
        self.assertIn("needs at least 100 s", proc.stderr)
        # A limit the program stays within changes nothing.
        proc = ncc("run", path, "--max-time", "1000")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        # The clock: a feed hold of an hour in a program of 0.1 s stops at the 5 s limit.
        short = self.write("s.nc", "N10 G90 G01 X1. F600.\nN20 M30\n")
        proc = self.run_timed("run", short, "--max-time", "5", "--feed-hold-at", "0.05=3600")
        self.assertEqual(proc.returncode, ALARM_EXIT, proc.stderr)
        self.assertRegex(proc.stderr, r"s\.nc:1:\d+: error\[NCC7208\]: simulated time limit 5 s "
                         r"reached in this block")

    def test_a_block_beyond_the_limit_stops_at_once(self):
        # The dwell alone is longer than the limit: alarm when the move before it has run,
        # without simulating 10,000 s first.
        path = self.write("p.nc", "N10 G90 G00 X10.\nN20 G04 X10000.\nN30 M30\n")
        proc = self.run_timed("run", path, "--max-time", "60", limit=10)
        self.assertEqual(proc.returncode, ALARM_EXIT, proc.stderr)
        self.assertRegex(proc.stderr, r"p\.nc:2:\d+: error\[NCC7208\]")
        self.assertIn("at least 10000", proc.stderr)

    def test_huge_dwell_ends_within_seconds(self):
        # G04 of 1e300 s. Written out, the number is beyond the 8-digit format (PS0003); a macro
        # variable carries it: the VM's time limit ends the run (or, where the bytecode verifier
        # bounds dwells, the verifier), with a clear error either way.
        literal = self.write("l.nc", "N10 G04 X1" + "0" * 300 + ".\nN20 M30\n")
        proc = self.run_timed("run", literal)
        self.assertEqual(proc.returncode, ERROR_EXIT, proc.stderr)
        self.assertRegex(proc.stderr, r"l\.nc:1:\d+: error\[PS0003\]")
        # Macro variables are not compiled yet, so the dwell comes in bytecode: a compiled G04 X1.
        # patched. 1e300 s is beyond the verifier's bound on dwells (1e5 s, docs/bytecode.md):
        # refused before the run, exit 1.
        dwell = bytes([0x13, 0x00]) + struct.pack("<d", 1.0)
        ncb = self.patched("N10 G90 G00 X10.\nN20 G04 X1.\nN30 M30\n", dwell, 2, struct.pack("<d", 1e300))
        proc = self.run_timed("run", ncb, limit=10)
        self.assertEqual(proc.returncode, ERROR_EXIT, proc.stderr)
        self.assertIn("error[NCC7103]", proc.stderr)
        # A dwell the verifier lets through but the time limit does not: the run ends at once
        # with NCC7208 in the dwell's block, not after simulating it.
        ncb = self.patched("N10 G90 G00 X10.\nN20 G04 X1.\nN30 M30\n", dwell, 2, struct.pack("<d", 99999.0))
        proc = self.run_timed("run", ncb, "--max-time", "3600", limit=10)
        self.assertEqual(proc.returncode, ALARM_EXIT, proc.stderr)
        self.assertRegex(proc.stderr, r"p\.nc:2:\d+: error\[NCC7208\]")

    def patched(self, source, instruction, at, replacement):
        """Compiles `source` (as p.nc) and overwrites bytes of its one `instruction`."""
        path = self.write("p.nc", source)
        ncb = os.path.join(self.dir, "p.ncb")
        proc = ncc("compile", path, "-o", ncb)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        with open(ncb, "rb") as f:
            data = bytearray(f.read())
        found = data.find(instruction)
        self.assertGreaterEqual(found, 0, "instruction not found")
        self.assertEqual(data.find(instruction, found + 1), -1)
        data[found + at:found + at + len(replacement)] = replacement
        with open(ncb, "wb") as f:
            f.write(seal(data))
        return ncb

    def test_million_turn_arc_ends_within_seconds(self):
        # The compiler never writes extra turns; patch a compiled full circle. 10^6 turns are
        # beyond the verifier's bound (999, docs/bytecode.md): refused before the run, exit 1.
        source = "N10 G90 G00 X10. Y0\nN20 G03 X10. Y0 I-10. J0 F1000.\nN30 M30\n"
        arc = bytes([0x12, 0x00, 0x00, 0x00, 0x01]) + struct.pack("<I", 0)
        ncb = self.patched(source, arc, 5, struct.pack("<I", 1_000_000))
        proc = self.run_timed("run", ncb, limit=10)
        self.assertEqual(proc.returncode, ERROR_EXIT, proc.stderr)
        self.assertIn("error[NCC7103]", proc.stderr)
        # 999 turns of r 10 at F1000 take over an hour: a 600 s limit ends the run at once.
        ncb = self.patched(source, arc, 5, struct.pack("<I", 999))
        proc = self.run_timed("run", ncb, "--max-time", "600", limit=10)
        self.assertEqual(proc.returncode, ALARM_EXIT, proc.stderr)
        self.assertRegex(proc.stderr, r"p\.nc:2:\d+: error\[NCC7208\]")

    def test_absurd_machine_values_are_refused(self):
        path = self.write("p.nc", "N10 G01 X1. F100.\nN20 M30\n")
        cases = [
            ("[machine]\nipo_cycle = 1e-300\n", "ipo_cycle"),
            ("[machine]\nchord_tolerance = 1e-300\n", "chord_tolerance"),
            ("[machine]\ncorner_tolerance = 1e-300\n", "corner_tolerance"),
            ("[machine.axis.X]\nmax_jerk = 1e-300\n", "max_jerk"),
            ("[machine.axis.X]\nmax_acceleration = 1e-300\n", "max_acceleration"),
            ("[machine.axis.X]\nmax_velocity = 1e-300\n", "max_velocity"),
            ("[machine.axis.X]\nrapid_velocity = 1e300\n", "rapid_velocity"),
            ("[machine.axis.X]\nmax_travel = 1e300\n", "max_travel"),
            ("[start]\nposition = { X = 1e300 }\n", "position"),
            # Within the default travel (+-1e9) but beyond any program's coordinates (1e6): the
            # first rapid would be a simulation of days.
            ("[start]\nposition = { X = -99999999 }\n", "position"),
            ("[machine.work]\nG54 = { X = -1e300 }\n", "G54"),
        ]
        for text, key in cases:
            machine = self.write("m.toml", text)
            proc = self.run_timed("run", path, "--machine", machine, limit=10)
            self.assertEqual(proc.returncode, SETUP_EXIT, (text, proc.stderr))
            self.assertRegex(proc.stderr, r"m\.toml:\d+:\d+: error\[NCC0306\]", text)
            self.assertIn(key, proc.stderr, text)

    def test_max_time_option_is_checked(self):
        path = self.write("p.nc", "N10 M30\n")
        self.assertEqual(ncc("run", path, "--max-time", "-1").returncode, 2)
        self.assertEqual(ncc("run", path, "--max-time", "0").returncode, 0)

    # --- dialect of the machine file ------------------------------------------------------

    def test_machine_file_dialect_and_override(self):
        machine = self.write("m.toml", '[machine]\ndialect = "siemens-iso-m"\n\n'
                             '[machine.axis.X]\nmax_travel = 10.0\n')
        path = self.write("p.nc", "N10 G90 G00 X50.\nN20 M30\n")
        proc = ncc("run", path, "--machine", machine)
        self.assertEqual(proc.returncode, ALARM_EXIT, proc.stderr)
        self.assertIn("error[10720]", proc.stderr)
        proc = ncc("run", path, "--machine", machine, "--dialect", "fanuc-m")
        self.assertIn("error[OT0500]", proc.stderr)
        bad = self.write("b.toml", '[machine]\ndialect = "heidenhain"\n')
        proc = ncc("run", path, "--machine", bad)
        self.assertEqual(proc.returncode, SETUP_EXIT, proc.stderr)
        self.assertRegex(proc.stderr, r"b\.toml:2:\d+: error\[NCC0306\]: unknown dialect")

    def test_parameter_without_effect_is_a_warning(self):
        machine = self.write("m.toml", '[machine]\ndialect = "fanuc-m"\n\n[machine.params]\n'
                             'gcode_system = "B"\ndecimal_point = "calculator"\n')
        path = self.write("p.nc", "N10 G01 X1. F100.\nN20 M30\n")
        proc = ncc("run", path, "--machine", machine)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertRegex(proc.stderr,
                         r"m\.toml:5:\d+: warning\[NCC0307\]: parameter 'gcode_system' has no "
                         r"effect in fanuc-m")
        self.assertNotIn("decimal_point", proc.stderr)


if __name__ == "__main__":
    NCC = sys.argv.pop(1)
    unittest.main(verbosity=2)
