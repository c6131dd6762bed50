#!/usr/bin/env python3
"""Both ways: every program prepared ahead of time by the compiler and, with --defer, block by
block by the VM while it runs (docs/runtime.md) must give identical results.

  - every conformance case (tests/conformance/<dialect>/<id>, the `ncc run` command line of the
    conformance runner): the same exit code, moves, diagnostics and, when the run succeeds,
    variables; passing and expected-failure cases alike;
  - every corpus program in a supported dialect: the same exit code, moves and diagnostics;
  - the examples: the same moves and the same summary (cycle time included), the same trace
    byte for byte, and bolt-circle's moves are its golden file's;
  - the deferred bytecode is PREPARE and END and the block store, and runs as the source does;
  - bad programs give the same alarm at the same file:line:col both ways, whether it is found
    at compile time or while the VM prepares (after a G31, from the probe's value);
  - a damaged block store is an alarm (NCC7212, or the alarm of the block it became), never a
    crash.

The macro and subprogram CLI tests run both ways too: ctest cli_*_deferred (NCC_TEST_DEFER=1,
cli_harness.run_ncc).

Run by ctest as: test_defer.py NCC_BINARY REPO_ROOT
"""
import concurrent.futures
import hashlib
import json
import os
import re
import struct
import subprocess
import sys
import tempfile
import unittest

sys.dont_write_bytecode = True  # no __pycache__ in the conformance copy (conformance_in_sync)

from cli_harness import ScratchDirTest, diagnostic_lines  # noqa: E402
from test_bytecode import seal  # noqa: E402

NCC = None
ROOT = None

DIAGNOSTIC = re.compile(r"^(?P<file>.+):(?P<line>\d+):(?P<col>\d+): (?P<severity>error|warning)\[(?P<code>[^\]]+)\]: ")
UNIT_TABLE = 48  # header: unit table offset, size (docs/bytecode.md); the block store follows it
STORE_MAGIC = b"NCBS"
EXAMPLES_USING_MACROS = ("bolt-circle.nc",)  # `#`, M98, G65: checked to still be so below


def ncc(*args, cwd=None, timeout=120):
    return subprocess.run([NCC, *map(str, args)], capture_output=True, text=True, errors="replace",
                          timeout=timeout, cwd=cwd)


def deferred(args):
    """`args` (command first) with --defer right after the command."""
    return [args[0], "--defer", *args[1:]]


def alarms(stderr):
    """(file, line, col, code) of every error and warning."""
    found = [m.groupdict() for m in map(DIAGNOSTIC.match, stderr.splitlines()) if m]
    return [(os.path.basename(d["file"]), d["line"], d["col"], d["code"]) for d in found]


def not_a_crash(test, proc, what):
    test.assertIn(proc.returncode, (0, 1, 2, 3), f"{what}: crash or unknown exit code\n{proc.stderr}")
    test.assertNotIn("Sanitizer", proc.stderr, what)
    if proc.returncode != 0:
        test.assertTrue(alarms(proc.stderr) or "error[" in proc.stderr,
                        f"{what}: exit {proc.returncode} without a diagnostic\n{proc.stderr}")


# ---- conformance cases ------------------------------------------------------------------------

def conformance_runner():
    sys.path.insert(0, os.path.join(ROOT, "tests", "conformance"))
    from runner import case, run  # noqa: E402
    return case, run


def with_output(command, path):
    command = list(command)
    command[command.index("-o") + 1] = str(path)
    return command


def run_command(command, out_path):
    """(exit code, the -o file's text or None, stderr) of one command."""
    proc = subprocess.run(command, capture_output=True, text=True, errors="replace",
                          timeout=120)
    out = None
    if os.path.isfile(out_path):
        with open(out_path) as f:
            out = f.read()
    return proc.returncode, out, proc.stderr


def both_ways(case_mod, run, folder):
    """Runs one case as the conformance runner does, then the same command with --defer;
    returns (name, [(what, plain, deferred)]) for moves and, when the run succeeds, vars."""
    case = case_mod.load(folder)
    found = []
    with tempfile.TemporaryDirectory(prefix="ncc-defer-conf-") as tmp:
        machine = os.path.join(tmp, "machine.toml")
        with open(machine, "w") as f:
            f.write(run.machine_file_text(case))
        for emit in ("moves", "vars"):
            plain = run.invoke(NCC, case, machine, emit, os.path.join(tmp, f"plain.{emit}"))
            out = os.path.join(tmp, f"deferred.{emit}")
            command = with_output(plain.command, out)  # [ncc, "run", ...]
            code, text, stderr = run_command(command[:1] + deferred(command[1:]), out)
            found.append((emit, plain.command,
                          (plain.exit_code, plain.output, diagnostic_lines(plain.stderr)),
                          (code, text, diagnostic_lines(stderr))))
            if plain.exit_code != 0:
                break  # vars only where the run succeeds
    return case.name, found


# In the instrumented CI stage (.ci/run sets NCC_TEST_SANITIZED) every third case and program
# runs: the release stage runs them all, ASan looks for memory faults, which a sample finds.
SAMPLE = 3 if os.environ.get("NCC_TEST_SANITIZED") else 1


class ConformanceBothWaysTest(unittest.TestCase):
    def test_every_case_gives_the_same_moves_and_variables_both_ways(self):
        case_mod, run = conformance_runner()
        folders = case_mod.find_cases(os.path.join(ROOT, "tests", "conformance"))
        self.assertGreater(len(folders), 100)
        folders = folders[::SAMPLE]
        with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
            results = list(pool.map(lambda f: both_ways(case_mod, run, f), folders))
        for name, runs in results:
            for emit, command, plain, late in runs:
                with self.subTest(case=name, emit=emit):
                    report = (f"conformance case {name}: --emit={emit} differs with --defer\n"
                              f"  command: {' '.join(map(str, command))} (+ --defer)")
                    self.assertEqual(late[0], plain[0], f"{report}: exit code\n{plain[2]}\n{late[2]}")
                    self.assertEqual(late[1], plain[1], f"{report}: output")
                    self.assertEqual(late[2], plain[2], f"{report}: diagnostics")
                    if plain[0] == 0:  # a program may make no move, but the file is written
                        self.assertIsNotNone(plain[1], f"{report}: exit 0 and no -o file")


# ---- corpus -----------------------------------------------------------------------------------

# The corpus folders in a supported dialect (tests/corpus/corpus_check.py FOLDER_DIALECT).
CORPUS_DIALECT = {"cam-iso": "fanuc-m", "fanuc-m": "fanuc-m"}
# A simulated hour: a longer program stops with NCC7208 at the same block both ways.
CORPUS_MAX_TIME = "3600"


def corpus_both_ways(program):
    dialect = CORPUS_DIALECT[os.path.basename(os.path.dirname(program))]
    args = ["run", program, "--dialect", dialect, "--emit=moves", "--max-time", CORPUS_MAX_TIME]
    plain, late = ncc(*args, timeout=300), ncc(*deferred(args), timeout=300)
    return [(p.returncode, p.stdout, diagnostic_lines(p.stderr)) for p in (plain, late)]


class CorpusBothWaysTest(unittest.TestCase):
    def test_every_real_program_gives_the_same_moves_both_ways(self):
        corpus = os.path.join(ROOT, "tests", "corpus")
        programs = sorted(os.path.join(corpus, folder, name) for folder in CORPUS_DIALECT
                          for name in os.listdir(os.path.join(corpus, folder)))
        self.assertGreater(len(programs), 50)
        programs = programs[::SAMPLE]
        with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
            results = list(pool.map(corpus_both_ways, programs))
        ran = 0
        for program, (plain, late) in zip(programs, results):
            with self.subTest(program=os.path.relpath(program, corpus)):
                self.assertEqual(late[0], plain[0], f"exit code\n{plain[2]}\n{late[2]}")
                self.assertEqual(late[2], plain[2], "diagnostics")
                self.assertEqual(late[1], plain[1], "moves")
                ran += plain[0] in (0, 3)
        self.assertGreater(ran, 20 // SAMPLE)  # programs that run, not only rejected ones


# ---- examples ---------------------------------------------------------------------------------

def example_args(name):
    """The example's bare file name and the options its golden test runs it with (NAME.args,
    NAME.toml as --machine)."""
    stem = name.rsplit(".", 1)[0]
    golden, examples = os.path.join(ROOT, "tests", "golden"), os.path.join(ROOT, "examples")
    args = []
    if os.path.isfile(os.path.join(golden, stem + ".args")):
        with open(os.path.join(golden, stem + ".args")) as f:
            args += f.read().split()
    if os.path.isfile(os.path.join(examples, stem + ".toml")):
        args += ["--machine", stem + ".toml"]
    return [name, *args]


class ExamplesBothWaysTest(ScratchDirTest):
    def examples(self):
        folder = os.path.join(ROOT, "examples")
        return folder, sorted(n for n in os.listdir(folder) if n.endswith(".nc"))

    def test_the_macro_examples_still_use_macros(self):
        folder, _ = self.examples()
        for name in EXAMPLES_USING_MACROS:
            with open(os.path.join(folder, name)) as f:
                text = f.read()
            self.assertTrue(re.search(r"#\d|M98|G65", text), name)

    def test_every_example_gives_the_same_moves_summary_and_diagnostics(self):
        folder, names = self.examples()
        self.assertIn("bolt-circle.nc", names)
        for name in names:
            for emit in ("moves", "summary", "summary-json", "vars"):
                with self.subTest(example=name, emit=emit):
                    args = ["run", *example_args(name), f"--emit={emit}"]
                    plain = ncc(*args, cwd=folder)
                    late = ncc(*deferred(args), cwd=folder)
                    self.assertEqual(late.returncode, plain.returncode, f"{name}\n{plain.stderr}\n{late.stderr}")
                    self.assertEqual(late.stdout, plain.stdout, name)
                    self.assertEqual(diagnostic_lines(late.stderr), diagnostic_lines(plain.stderr), name)
                    if name in EXAMPLES_USING_MACROS:
                        self.assertEqual(plain.returncode, 0, plain.stderr)
                        self.assertTrue(plain.stdout.strip(), name)
                    if emit == "summary" and plain.returncode == 0:
                        self.assertIn("program time", plain.stdout)

    def test_bolt_circle_deferred_moves_are_the_golden_moves(self):
        folder = os.path.join(ROOT, "examples")
        with open(os.path.join(ROOT, "tests", "golden", "bolt-circle.moves.jsonl")) as f:
            golden = [json.loads(line) for line in f if line.strip()]
        proc = ncc("run", "--defer", "bolt-circle.nc", "--emit=moves", cwd=folder)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        got = [json.loads(line) for line in proc.stdout.splitlines()]
        self.assertEqual(len(got), len(golden))
        for g, m in zip(golden, got):
            self.assertEqual((m["line"], m["file"], m["kind"]), (g["line"], g["file"], g["kind"]))
            for axis, value in g["to"].items():
                self.assertAlmostEqual(m["to"][axis], value, delta=1e-6)

    def test_the_vm_is_deterministic_both_ways_tick_by_tick(self):
        folder = os.path.join(ROOT, "examples")
        traces = {}
        for way, extra in (("plain", []), ("deferred", ["--defer"])):
            for ext in ("nct", "csv"):
                out = self.path(f"{way}.{ext}")
                proc = ncc("run", *extra, "bolt-circle.nc", "--emit=trace", "-o", out, cwd=folder)
                self.assertEqual(proc.returncode, 0, proc.stderr)
                with open(out, "rb") as f:
                    traces[way, ext] = f.read()
            csv = ncc("trace", self.path(f"{way}.nct"))
            self.assertEqual(csv.returncode, 0, csv.stderr)
            self.assertEqual(csv.stdout.encode(), traces[way, "csv"], way)
        self.assertGreater(traces["plain", "csv"].count(b"\n"), 10000)  # 18.779 s at 1 ms
        for ext in ("nct", "csv"):
            self.assertEqual(hashlib.sha256(traces["deferred", ext]).hexdigest(),
                             hashlib.sha256(traces["plain", ext]).hexdigest(), ext)


# ---- the deferred bytecode --------------------------------------------------------------------

def instructions(listing):
    """The mnemonics of `ncc dis` (lines `OFFSET  FILE:LINE:COL  MNEMONIC ...`)."""
    rows = [line.split() for line in listing.splitlines() if line and not line.startswith(";")]
    return [row[2] for row in rows if len(row) >= 3]


class DeferredBytecodeTest(ScratchDirTest):
    def compile_deferred(self, name="bolt-circle.nc"):
        src = os.path.join(ROOT, "examples", name)
        ncb = self.path(name.rsplit(".", 1)[0] + ".ncb")
        proc = ncc("compile", "--defer", src, "-o", ncb)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        with open(ncb, "rb") as f:
            return src, ncb, f.read()

    def test_deferred_bytecode_is_prepare_end_and_the_block_store(self):
        src, ncb, data = self.compile_deferred()
        dis = ncc("dis", ncb)
        self.assertEqual(dis.returncode, 0, dis.stderr)
        self.assertEqual(instructions(dis.stdout), ["PREPARE", "END"], dis.stdout)
        offset, size = struct.unpack_from("<II", data, UNIT_TABLE)
        store = data[offset + size:]
        self.assertEqual(store[:4], STORE_MAGIC)
        self.assertRegex(dis.stdout, rf"(?m)^; blocks +{len(store)} bytes")
        # Ahead of time the same program is many instructions and no PREPARE.
        plain = self.path("plain.ncb")
        self.assertEqual(ncc("compile", src, "-o", plain).returncode, 0)
        ahead = instructions(ncc("dis", plain).stdout)
        self.assertNotIn("PREPARE", ahead)
        self.assertGreater(len(ahead), 20)

    def test_the_deferred_bytecode_runs_as_the_source(self):
        src, ncb, _ = self.compile_deferred()
        for emit in ("moves", "summary"):
            from_source = ncc("run", src, f"--emit={emit}")
            from_ncb = ncc("run", ncb, f"--emit={emit}")
            self.assertEqual(from_source.returncode, 0, from_source.stderr)
            self.assertEqual(from_ncb.returncode, 0, from_ncb.stderr)
            self.assertEqual(from_ncb.stdout, from_source.stdout, emit)


# ---- bad programs -----------------------------------------------------------------------------

# Found when the program is compiled: the compiler evaluates the whole program either way.
COMPILE_TIME_FAULTS = {
    "zero-in-loop.nc": "#1=0\nWHILE[#1LT3]DO1\nG91 G01 X1. F100.\n#2=1/#1\n#1=#1+1\nEND1\nM30\n",
    "goto-missing.nc": "G90 G00 X1.\n#1=2\nWHILE[#1GT0]DO1\n#1=#1-1\nEND1\nGOTO 50\nG00 X2.\nM30\n",
    "missing-sub.nc": "G90 G00 X1.\nM98 P4711\nM30\n",
    "missing-macro.nc": "G90 G00 X1.\nG65 P9876 A1.\nM30\n",
}
# Found while the VM prepares: a value from where G31 stopped (probe at Z -42.5).
PROBE = ("--probe", "Z=-42.5")
RUN_TIME_FAULTS = {
    "zero-after-skip.nc": "G90 G00 Z10.\nG31 Z-50. F100.\n#1=0\nWHILE[#1LT2]DO1\n"
                          "#2=1/[#5063+42.5]\n#1=#1+1\nEND1\nM30\n",
    "goto-after-skip.nc": "G90 G00 Z10.\nG31 Z-50. F100.\n#1=#5063+91.5\nGOTO #1\nN50 M30\n",
    "sub-after-skip.nc": "G90 G00 Z10.\nG31 Z-50. F100.\n#1=#5063+4753.5\nM98 P#1\nM30\nO4712\nM99\n",
}


class BadProgramsBothWaysTest(ScratchDirTest):
    def both(self, name, text, *extra):
        prog = self.write(name, text)
        plain = ncc("run", prog, "--emit=moves", *extra)
        late = ncc("run", "--defer", prog, "--emit=moves", *extra)
        not_a_crash(self, plain, name)
        not_a_crash(self, late, name + " --defer")
        self.assertEqual(late.returncode, plain.returncode, f"{plain.stderr}\n{late.stderr}")
        self.assertEqual(alarms(late.stderr), alarms(plain.stderr), f"{plain.stderr}\n{late.stderr}")
        self.assertEqual(late.stdout, plain.stdout, name)
        return plain

    def test_compile_time_faults_are_the_same_alarm_at_the_same_place(self):
        expected = {"zero-in-loop.nc": ("4", "NCC2402"), "goto-missing.nc": ("6", "NCC2411"),
                    "missing-sub.nc": ("2", "NCC2412"), "missing-macro.nc": ("2", "NCC2412")}
        for name, text in COMPILE_TIME_FAULTS.items():
            with self.subTest(program=name):
                plain = self.both(name, text)
                self.assertEqual(plain.returncode, 1, plain.stderr)
                found = alarms(plain.stderr)
                self.assertEqual((found[0][1], found[0][3]), expected[name], plain.stderr)

    def test_run_time_faults_are_the_same_alarm_at_the_same_place(self):
        expected = {"zero-after-skip.nc": ("5", "NCC2402"), "goto-after-skip.nc": ("4", "NCC2411"),
                    "sub-after-skip.nc": ("4", "NCC2412")}
        for name, text in RUN_TIME_FAULTS.items():
            with self.subTest(program=name):
                plain = self.both(name, text, *PROBE)
                self.assertEqual(plain.returncode, 3, plain.stderr)
                found = [a for a in alarms(plain.stderr)]
                self.assertEqual((found[0][1], found[0][3]), expected[name], plain.stderr)
                # The moves before the fault ran: the rapid and the skip move to the probe.
                moves = [json.loads(line) for line in plain.stdout.splitlines()]
                self.assertEqual(moves[1]["to"]["Z"], -42.5)

    def test_the_same_programs_run_where_the_probe_gives_good_values(self):
        # The faults above come from the probe's value: elsewhere, both ways run to the end.
        for name, text in RUN_TIME_FAULTS.items():
            with self.subTest(program=name):
                plain = self.both(name, text, "--probe", "Z=-41.5")
                self.assertEqual(plain.returncode, 0, plain.stderr)


# ---- the end of a program ---------------------------------------------------------------------

class EndOfProgramBothWaysTest(ScratchDirTest):
    """What follows M02/M30 or the closing % is never executed nor parsed (docs/cli.md, "The
    end of a program"): at most a warning, both ways."""

    PROGRAMS = {
        "after-m30.nc": ("G90 G00 X1.\nM30\nG00 X50. @@@\nG01 X60. Q1.\n", [("3", "NCC0022")]),
        "n-percent.nc": ("%\nO0001\nN10 G90 G00 X10.\nN193 M30\nN194 %\n", []),
        "after-percent.nc": ("%\nG90 G00 X1.\n%\nG00 X50. @@@\nG01 X60. Q1.\n", [("4", "NCC0020")]),
        # Prepared by the VM from line 3 on even without --defer (after G31).
        "probe-after-m30.nc": ("G90 G00 Z10.\nG31 Z-50. F100.\n#1=#5063\nG00 Z20.\nM30\nG00 X50. @@@\n",
                               [("6", "NCC0022")]),
    }

    def test_text_after_the_end_is_not_an_error_either_way(self):
        for name, (text, warnings) in self.PROGRAMS.items():
            prog = self.write(name, text)
            for extra in ([], ["--defer"]):
                with self.subTest(program=name, extra=extra):
                    proc = ncc("run", *extra, prog, "--emit=moves", *PROBE)
                    self.assertEqual(proc.returncode, 0, proc.stderr)
                    self.assertNotIn("50.0", proc.stdout)
                    self.assertEqual([(a[1], a[3]) for a in alarms(proc.stderr)], warnings, proc.stderr)


# ---- settings the block store carries ---------------------------------------------------------

class StoredSettingsBothWaysTest(ScratchDirTest):
    VARS = '"#500" = 4.0\n"#501" = 7.5\n'

    def run_with_vars(self, extra, program):
        prog = self.write("v.nc", program)
        saved = self.write("v.toml", self.VARS)
        proc = ncc("run", *extra, prog, "--emit=vars", "--vars", saved, *PROBE)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        with open(saved) as f:
            return json.loads(proc.stdout), f.read()

    def test_the_vars_file_is_read_by_blocks_the_vm_prepares(self):
        # #500 = #501 + 1 = 8.5 with the saved #501, however the block is prepared: ahead of
        # time, by the VM with --defer, by the VM after a G31; and #501 stays in the file.
        for program in ("#500=#501+1\nM30\n",
                        "G90 G00 Z10.\nG31 Z-50. F100.\n#1=#5063\n#500=#501+1\nM30\n"):
            for extra in ([], ["--defer"]):
                with self.subTest(program=program, extra=extra):
                    got, text = self.run_with_vars(extra, program)
                    self.assertEqual((got.get("#500"), got.get("#501")), (8.5, 7.5), got)
                    self.assertIn('"#501" = 7.5', text)  # never lost from the file

    def test_max_back_jumps_is_the_same_both_ways(self):
        loop = "#1=0\nN1 #1=#1+1\nIF[#1LT50]GOTO1\nG00 X#1\nM30\n"
        prog = self.write("loop.nc", loop)
        for limit, code in (("100", 0), ("10", 1)):
            with self.subTest(limit=limit):
                plain = ncc("run", prog, "--emit=moves", "--max-back-jumps", limit)
                late = ncc("run", "--defer", prog, "--emit=moves", "--max-back-jumps", limit)
                self.assertEqual(plain.returncode, code, plain.stderr)
                self.assertEqual(late.returncode, plain.returncode, late.stderr)
                self.assertEqual(late.stdout, plain.stdout)
                self.assertEqual(alarms(late.stderr), alarms(plain.stderr))


# ---- a damaged block store --------------------------------------------------------------------

class DamagedStoreTest(ScratchDirTest):
    def setUp(self):
        super().setUp()
        self.ncb = self.path("b.ncb")
        proc = ncc("compile", "--defer", os.path.join(ROOT, "examples", "bolt-circle.nc"), "-o", self.ncb)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        with open(self.ncb, "rb") as f:
            self.data = f.read()
        offset, size = struct.unpack_from("<II", self.data, UNIT_TABLE)
        self.store = offset + size
        self.assertEqual(self.data[self.store:self.store + 4], STORE_MAGIC)

    def run_damaged(self, data, what):
        path = self.write("d.ncb", seal(data))
        # A flipped byte can make an endless loop, of moves or of blocks without motion; the
        # step budget ends both (it also bounds the blocks prepared without motion). 2,000 runs
        # the whole program and ends such a loop in seconds of simulated motion, under the
        # sanitizers too (the 10,000-jump default that ended it before is gone).
        proc = ncc("run", path, "--emit=moves", "--max-steps", "2000", timeout=60)
        not_a_crash(self, proc, what)
        return proc

    def test_a_flipped_byte_in_the_store_is_an_alarm_never_a_crash(self):
        size = len(self.data) - self.store
        positions = sorted(set(range(0, 16)) | set(range(16, size, 13)) | {size - 2, size - 1})
        for pos in positions:
            for flip in (0xFF, 0x01):
                with self.subTest(store_byte=pos, xor=flip):
                    data = bytearray(self.data)
                    data[self.store + pos] ^= flip
                    proc = self.run_damaged(data, f"store byte {pos} ^ {flip:#x}")
                    if proc.returncode != 0:
                        self.assertEqual(proc.returncode, 3, proc.stderr)
                    if pos < 4:  # the NCBS mark
                        self.assertIn("error[NCC7212]", proc.stderr)
                        self.assertIn("no NCBS mark", proc.stderr)

    def test_a_truncated_store_is_refused(self):
        size = len(self.data) - self.store
        for keep in (0, 2, 4, 8, size // 2, size - 1):
            with self.subTest(store_bytes_kept=keep):
                proc = self.run_damaged(self.data[:self.store + keep], f"store cut to {keep} bytes")
                self.assertNotEqual(proc.returncode, 0, proc.stdout)
                # Refused before the first move: the moves are the alarm record only.
                records = [json.loads(line) for line in proc.stdout.splitlines()]
                self.assertEqual([r["kind"] for r in records], ["alarm"] if records else [], proc.stdout)
                code = "NCC7116" if keep == 0 else "NCC7212"  # PREPARE without a store
                self.assertIn(f"error[{code}]", proc.stderr)

    def test_the_undamaged_store_runs(self):
        proc = self.run_damaged(self.data, "undamaged")
        self.assertEqual(proc.returncode, 0, proc.stderr)


if __name__ == "__main__":
    NCC = os.path.abspath(sys.argv.pop(1))
    ROOT = os.path.abspath(sys.argv.pop(1))
    unittest.main(verbosity=2)
