#!/usr/bin/env python3
"""The `.ncb` file through the `ncc` command line (docs/bytecode.md): its checksum, its value
bounds, its independence of how the source path was spelled, and `ncc dis` without a machine.

Run by ctest as: test_bytecode.py NCC_BINARY
"""
import os
import re
import struct
import subprocess
import sys
import unittest

from cli_harness import ScratchDirTest

NCC = None

GOOD = "N10 G90 G00 X10. Y5.\nN20 G01 Z-2. F100.\nN30 G02 X20. Y5. R5.\nN40 G04 X1.5\nN50 M30\n"

# A five-axis machine (two rotary axes) that is not the built-in one.
FIVE_AXES = """[machine]
axes = ["X", "Y", "Z", "A", "C"]
[start]
position = { X = 0.0, Y = 0.0, Z = 100.0, A = 0.0, C = 0.0 }
"""
FIVE_AXIS_PROGRAM = "N10 G90 G00 X10. Y5. Z50. A30. C45.\nN20 G01 A-15. C90. F500.\nN30 M30\n"

CHECKSUM_OFFSET = 56
FIXED_HEADER = 64


def ncc(*args, cwd=None, timeout=60):
    return subprocess.run([NCC, *args], capture_output=True, text=True, timeout=timeout, cwd=cwd)


def fnv1a64(data, h=0xCBF29CE484222325):
    for b in data:
        h = ((h ^ b) * 0x100000001B3) & 0xFFFFFFFFFFFFFFFF
    return h


def seal(data):
    """Writes the documented checksum into a file edited on purpose."""
    data = bytearray(data)
    fixed = bytes(data[:CHECKSUM_OFFSET]) + bytes(8) + bytes(data[CHECKSUM_OFFSET + 8:FIXED_HEADER])
    h = fnv1a64(fixed, fnv1a64(data[FIXED_HEADER:]))
    data[CHECKSUM_OFFSET:CHECKSUM_OFFSET + 8] = struct.pack("<Q", h)
    return bytes(data)


def code_offset(data):
    return struct.unpack_from("<I", data, 24)[0]


class BytecodeCliTest(ScratchDirTest):
    def compile(self, text, name="a.nc", *extra):
        src = self.write(name, text)
        out = os.path.join(self.dir, name.rsplit(".", 1)[0] + ".ncb")
        proc = ncc("compile", src, "-o", out, *extra)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        with open(out, "rb") as f:
            return out, f.read()

    def instruction_offsets(self, ncb, *extra):
        """Code offsets of the instructions, by mnemonic, from `ncc dis`."""
        proc = ncc("dis", ncb, *extra)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        found = {}
        for line in proc.stdout.splitlines():
            m = re.match(r"([0-9a-f]{6})\s+\S+\s+([A-Z_]+)", line)
            if m:
                found.setdefault(m.group(2), int(m.group(1), 16))
        return found

    # --- checksum -----------------------------------------------------------------------------

    def test_header_carries_the_documented_checksum(self):
        _, data = self.compile(GOOD)
        self.assertEqual(struct.unpack_from("<HH", data, 4), (2, 3))  # version 2.3
        self.assertEqual(seal(data), data)
        self.assertTrue(ncc("dis", self.write("b.ncb", data)).stdout.startswith("; ncc bytecode 2.3"))

    def test_every_flipped_byte_is_rejected(self):
        ncb, data = self.compile(GOOD)
        self.assertEqual(ncc("run", ncb, "--emit=moves").returncode, 0)
        bad = self.write("bad.ncb", b"")
        for i in range(len(data)):
            flipped = bytearray(data)
            flipped[i] ^= 1 << (i % 8)
            with open(bad, "wb") as f:
                f.write(flipped)
            # Only `dis` for every byte (fast); `run` for a sample below.
            proc = ncc("dis", bad)
            expected = "NCC7002" if i < 4 else "NCC7003" if i < 8 else "NCC7016"
            self.assertEqual(proc.returncode, 1, f"byte {i}: {proc.stderr}")
            self.assertIn(f"error[{expected}]", proc.stderr, f"byte {i}")
        for i in range(8, len(data), max(1, len(data) // 25)):
            for bit in (0, 7):
                flipped = bytearray(data)
                flipped[i] ^= 1 << bit
                with open(bad, "wb") as f:
                    f.write(flipped)
                proc = ncc("run", bad, "--emit=moves")
                self.assertEqual(proc.returncode, 1, f"byte {i} bit {bit}")
                self.assertIn("NCC7016", proc.stderr)
                self.assertIn("checksum mismatch", proc.stderr)
                self.assertEqual(proc.stdout, "", "no move of a damaged file is printed")

    def test_a_1x_file_is_refused_by_version(self):
        _, data = self.compile(GOOD)
        old = bytearray(data)
        old[4] = 1
        proc = ncc("run", self.write("old.ncb", bytes(old)))
        self.assertEqual(proc.returncode, 1)
        self.assertIn("NCC7003", proc.stderr)

    # --- value bounds -------------------------------------------------------------------------

    def run_bounded(self, data):
        """Runs a (sealed) edited file: it must end quickly with a verifier error."""
        path = self.write("edited.ncb", seal(data))
        for emit in ("summary", "moves"):
            proc = ncc("run", path, f"--emit={emit}", timeout=20)
            self.assertEqual(proc.returncode, 1, proc.stderr)
        return proc.stderr

    def test_coordinates_beyond_the_bound_are_refused(self):
        ncb, data = self.compile(GOOD)
        rapid = code_offset(data) + self.instruction_offsets(ncb)["RAPID"]
        for value in (1e6 * 1.5, 1e9, -1e12, 1e100, 1e308):
            edited = bytearray(data)
            struct.pack_into("<d", edited, rapid + 2, value)  # opcode, flags, then X
            stderr = self.run_bounded(bytes(edited))
            self.assertIn("NCC7103", stderr)
            self.assertIn("coordinate of X", stderr)
            self.assertIn("beyond the bound", stderr)
        # The bound itself runs (as the file checks go: it reaches the VM).
        edited = bytearray(data)
        struct.pack_into("<d", edited, rapid + 2, 1000.0)
        proc = ncc("run", self.write("ok.ncb", seal(bytes(edited))), "--emit=moves")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertIn('"X": 1000', proc.stdout)

    def test_dwell_and_turns_beyond_the_bound_are_refused(self):
        ncb, data = self.compile(GOOD)
        offsets = self.instruction_offsets(ncb)
        dwell = code_offset(data) + offsets["DWELL"]
        edited = bytearray(data)
        struct.pack_into("<d", edited, dwell + 2, 1e300)  # opcode, flags, then seconds
        stderr = self.run_bounded(bytes(edited))
        self.assertIn("NCC7103", stderr)
        self.assertIn("dwell of 1e+300 s", stderr)
        arc = code_offset(data) + offsets["ARC"]
        edited = bytearray(data)
        struct.pack_into("<I", edited, arc + 5, 1000000)  # opcode, flags, plane, axes, turns
        stderr = self.run_bounded(bytes(edited))
        self.assertIn("1000000 extra turns (at most 999)", stderr)

    def test_compiler_refuses_values_beyond_the_bounds_at_the_block(self):
        # No word can be written beyond 99999.999, but incremental moves add up and work
        # offsets add to them: the compiler refuses the block, the file is never written.
        machine = self.write("far.toml", '[machine]\naxes = ["X", "Y", "Z"]\n'
                                         '[machine.work]\nG54 = [950000.0, 0.0, 0.0]\n')
        incremental = "G90 G00 X0\nG91 X99999.999\n" + "X99999.999\n" * 10 + "Y1.\nM30\n"
        cases = [
            ("inc.nc", incremental, [], 12, "the X position 1099999.989"),
            ("far.nc", "G90 G54 G00 X0 Y0\nG01 Y10. X99999.999 F100.\nM30\n",
             ["--machine", machine], 2, "the X position 1049999.999"),
        ]
        for name, text, extra, line, what in cases:
            src = self.write(name, text)
            out = os.path.join(self.dir, name + ".ncb")
            proc = ncc("compile", src, "-o", out, *extra)
            self.assertEqual(proc.returncode, 1, text + proc.stderr)
            self.assertRegex(proc.stderr, rf"{re.escape(name)}:{line}:1: error\[NCC7017\]")
            self.assertIn(what, proc.stderr)
            self.assertIn("beyond +-1000000 mm", proc.stderr)
            self.assertFalse(os.path.exists(out), "no file the verifier would refuse")
            for emit in ("moves", "summary"):
                proc = ncc("run", src, f"--emit={emit}", *extra, timeout=20)
                self.assertEqual(proc.returncode, 1, proc.stderr)
                self.assertIn("NCC7017", proc.stderr)
        # One block less stays within the bound and runs.
        fine = "G90 G00 X0\nG91 X99999.999\n" + "X99999.999\n" * 9 + "M30\n"
        proc = ncc("run", self.write("fine.nc", fine), "--emit=moves")
        self.assertEqual(proc.returncode, 0, proc.stderr)

    # --- path spelling ------------------------------------------------------------------------

    def test_file_does_not_depend_on_how_the_path_was_spelled(self):
        sub = os.path.join(self.dir, "jobs")
        os.mkdir(sub)
        with open(os.path.join(sub, "part.nc"), "w") as f:
            f.write(GOOD)
        spellings = [("part.nc", sub), ("./part.nc", sub), (os.path.join(sub, "part.nc"), "/"),
                     ("jobs/../jobs/part.nc", self.dir)]
        files = []
        for i, (spelling, cwd) in enumerate(spellings):
            out = os.path.join(self.dir, f"out{i}.ncb")
            proc = ncc("compile", spelling, "-o", out, cwd=cwd)
            self.assertEqual(proc.returncode, 0, proc.stderr)
            with open(out, "rb") as f:
                files.append(f.read())
        for i, data in enumerate(files[1:], 1):
            self.assertEqual(data, files[0], spellings[i][0])
        listing = ncc("dis", os.path.join(self.dir, "out2.ncb")).stdout
        self.assertIn('; string 1   "part.nc"', listing)
        self.assertNotIn(self.dir, listing)

    # --- dis without --machine ----------------------------------------------------------------

    def test_dis_reads_the_axes_from_the_header(self):
        machine = self.write("five.toml", FIVE_AXES)
        ncb, _ = self.compile(FIVE_AXIS_PROGRAM, "five.nc", "--machine", machine)
        proc = ncc("dis", ncb)  # no --machine: the built-in machine has three axes
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertIn("; axes       X(linear) Y(linear) Z(linear) A(rotary) C(rotary)", proc.stdout)
        self.assertRegex(proc.stdout, r"RAPID X10 Y5 Z50 A30 C45\b")
        self.assertRegex(proc.stdout, r"LINE X10 Y5 Z50 A-15 C90 F500\b")
        self.assertEqual(proc.stdout, ncc("dis", ncb, "--machine", machine).stdout)
        # Running it needs its machine; on the built-in one the axes differ.
        proc = ncc("run", ncb, "--emit=moves")
        self.assertEqual(proc.returncode, 1)
        self.assertIn("NCC7113", proc.stderr)
        proc = ncc("run", ncb, "--emit=moves", "--machine", machine)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertIn('"C": 90', proc.stdout)


if __name__ == "__main__":
    NCC = os.path.abspath(sys.argv.pop(1))
    unittest.main(verbosity=2)
