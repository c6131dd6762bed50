#!/usr/bin/env python3
"""Bounded, deterministic fuzzing of `ncc run` (docs/testing.md, "Fuzz-style CLI test").

Mutants of three kinds are run in every output mode (summary, trace, moves, vars), each with
`-o` into an empty folder of its own:
  - source programs: the examples, small corpus programs and the conformance programs of the
    supported dialects (with their case's machine), with bytes flipped, lines cut, duplicated
    or swapped, tokens, blocks and huge numbers inserted;
  - `.ncb` files: those programs compiled, with bytes changed, half of them with the checksum
    written anew (docs/bytecode.md, "Checksum") so that the changes reach the verifier;
  - machine files: the documented example machine, the examples' and the conformance cases'
    machines with values replaced by huge, negative, zero, non-numeric or missing ones.
Each mutant must: exit with 0..3 (and print no sanitizer report, in an instrumented build),
exit with the same code in every mode, leave nothing in its output folder when the exit code
is 1 or 2 (after an alarm, exit 3, only the documented output: the moves ending with the alarm
record, the summary, the trace up to the alarm; nothing for vars), and end within TIMEOUT seconds (`--max-steps` bounds the VM's instructions and `--max-time` the simulated
time: a mutant's F1 in a peck cycle is hours of simulated motion, an alarm NCC7208 here). All failures are
collected and printed together.

The seed is fixed: the same mutants every run. NCC_FUZZ_CLI_SEED and NCC_FUZZ_CLI_COUNT
(environment) change seed and count for a longer run by hand.

Run by ctest as: test_fuzz_cli.py NCC_BINARY
"""
import concurrent.futures
import glob
import os
import random
import shutil
import subprocess
import sys
import tempfile
import time
import unittest

NCC = None
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SEED = int(os.environ.get("NCC_FUZZ_CLI_SEED", "21"))
# Mutants in all, about 40/30/30 %; half in the instrumented CI stage (NCC_TEST_SANITIZED), whose
# release stage runs all 400.
COUNT = int(os.environ.get("NCC_FUZZ_CLI_COUNT",
                           "200" if os.environ.get("NCC_TEST_SANITIZED") else "400"))
DIALECTS = ("mazak-m", "siemens-iso-m", "siemens-din")  # conformance folders of supported dialects
TIMEOUT = 30  # seconds per run: far above any seed's run time
MAX_SIMULATED_SECONDS = "600"  # simulated time per run (an instrumented build ticks slowly)
MAX_STEPS = "200000"
MODES = ("summary", "trace", "moves", "vars")
OUTPUT = {"summary": "out.txt", "trace": "out.trace", "moves": "out.jsonl", "vars": "out.json"}

# The machine of docs/machine-file.md's example, complete enough to mutate every kind of key.
MACHINE = """[machine]
axes = ["X", "Y", "Z", "B"]
ipo_cycle = 0.001
chord_tolerance = 0.001
corner_tolerance = 0.01
lookahead_segments = 1024
[machine.offsets]
H1 = 100.0
D1 = 5.0
[machine.work]
G54 = [-100.0, -50.0, -200.0, 0.0]
G55 = { X = 100.0 }
[machine.params]
decimal_point = "calculator"
reference_point_2 = { X = -100.0, Y = -50.0 }
[machine.axis.X]
min_travel = -500.0
max_travel = 10.0
[start]
position = { X = 0.0, Y = 0.0, Z = 100.0 }
"""
# Runs on every machine above: the mutated machine files are run with it.
MACHINE_PROGRAM = ("N10 G90 G54 G00 X0. Y0. Z50.\nN20 G43 H1 Z10.\nN30 G01 X5. Y5. F500.\n"
                   "N40 G02 X5. Y-5. R10.\nN50 G04 X0.1\nN60 G91 G28 Z0.\nN70 M30\n")

TOKENS = ["G", "X", "Y", "Z", "F", "M", "#", "[", "]", "=", "-", ".", "0", "9", "\n", " ",
          "G02", "G03", "G04", "G28", "G91", "G43H1", "M98P1", "M99", "GOTO1", "WHILE[#1LT9]DO1",
          "END1", "IF", "99999999", "99999.999", "1e300", "#1=#1*99999", "R0", "I0J0", "%",
          "(", ")", ";", "O1", "N1", "\x00", "\xff"]
# Whole blocks that often end a run differently: feed per revolution without a spindle, stops,
# reference returns and checks, registers, arcs that cannot be, far positions.
BLOCKS = ["G95 G01 X10. F0.1", "M05", "S0", "M03 S1000", "G04 X2.", "G04 P1500", "G28 X0 Y0",
          "G27 X0 Y0", "G02 X10. R1.", "G03 X0 Y0 I0 J0", "G91 G01 X999.999 F1000.",
          "G10 L2 P1 X900000.", "M00", "M01", "M99", "M98 P9999", "G43 H99 Z0", "G41 D1 X5.",
          "G40", "T1 M06", "G00 X-99999.999", "G01 F0 X1.", "G94 F1 X1.", "G61", "G63 G01 X2. F10.",
          "G20", "G21", "G17 G02 X1. Y1. R0.5", "G18 G03 Z1. X1. R0.5", "G19", "M30", "M02",
          "%", "O9999", "G90 G53 X0", "G92 X1000000.", "G52 X-900000.",
          # DIN control structures and jumps (in ISO text they are refused by the parser).
          "IF R1>2", "ELSE", "ENDIF", "WHILE R1<3", "ENDWHILE", "LOOP", "ENDLOOP", "REPEAT",
          "UNTIL R1>1", "R1=R1+1", "FOR R2=0 TO 3", "ENDFOR", "CASE(R1) OF 1 GOTOF MA1 DEFAULT GOTOB MA1",
          "MA1:", "GOTOB MA1",
          # DIN frames, system variables, alarms (lowering_frames.cpp, system_variables.cpp).
          "TRANS X10 Y5", "AROT RPL=30", "ROT Z45", "SCALE X0.5", "AMIRROR X0", "TRANS",
          "R3=$AA_IW[X]", "R4=$AA_IM[Z]", "SETAL(62000)", "SETAL(61000)"]
# Blocks that compile but stop the run with an alarm (exit 3): feed per revolution with the
# spindle stopped (NCC7207).
ALARM_BLOCKS = ["M05\nG95 G01 X20. Y20. F0.1", "S0\nG95 G01 X-20. F0.2", "M05\nG95 G04 X3.",
                "M05\nG95 G02 X0 Y0 I5. F0.1"]
HUGE = ["99999999", "-99999999", "0", "0.", "1e308", "nan", "inf", "-0.0", '"x"', "[]", "{}",
        "true", "1e-300", "-1", "4294967296"]


def read(path):
    with open(path, "rb") as f:
        return f.read()


def conformance_cases():
    """(program name, program bytes, dialect, machine file text) of the supported dialects."""
    cases = []
    for dialect in DIALECTS:
        for case in sorted(glob.glob(os.path.join(ROOT, "tests", "conformance", dialect, "*"))):
            programs = glob.glob(os.path.join(case, "program.*"))
            toml = os.path.join(case, "case.toml")
            if len(programs) != 1 or not os.path.exists(toml):
                continue
            text = read(toml).decode()
            # The case's machine file: its tables from [machine] up to [expect].
            start = text.find("[machine]")
            end = text.find("[expect]")
            if start < 0:
                continue
            machine = text[start:end if end > start else len(text)]
            cases.append((f"{dialect}/{os.path.basename(case)}", read(programs[0]), dialect,
                          machine.encode()))
    return cases


def source_seeds():
    """(name, program, extra options, extra files) to start mutants from."""
    paths = sorted(glob.glob(os.path.join(ROOT, "examples", "*.nc")))
    for folder in ("fanuc-m", "cam-iso", "siemens-din"):
        for path in sorted(glob.glob(os.path.join(ROOT, "tests", "corpus", folder, "*"))):
            if os.path.getsize(path) <= 4096:
                paths.append(path)
    seeds = []
    for path in paths:
        extra, files = [], {}
        toml = path[:-3] + ".toml"  # an example's own machine
        if os.path.exists(toml):
            extra, files = ["--machine", "m.toml"], {"m.toml": read(toml)}
        seeds.append((os.path.basename(path), read(path), extra, files))
    for name, program, dialect, machine in conformance_cases():
        seeds.append((name, program, ["--dialect", dialect, "--machine", "m.toml"],
                      {"m.toml": machine}))
    return seeds


def machine_seeds():
    """(name, machine file, program, dialect options) whose machine file is mutated."""
    seeds = [("doc.toml", MACHINE.encode(), MACHINE_PROGRAM.encode(), [])]
    for path in sorted(glob.glob(os.path.join(ROOT, "examples", "*.toml"))):
        seeds.append((os.path.basename(path), read(path), read(path[:-5] + ".nc"), []))
    for name, program, dialect, machine in conformance_cases():
        seeds.append((name, machine, program, ["--dialect", dialect]))
    return seeds


def mutate_source(rng, data):
    lines = data.split(b"\n")
    for _ in range(rng.randint(1, 2)):
        kind = rng.randrange(7)
        if kind == 0 and b"\n".join(lines):  # flip a bit (lines cut before may leave none)
            b = bytearray(b"\n".join(lines))
            i = rng.randrange(len(b))
            b[i] ^= 1 << rng.randrange(8)
            lines = bytes(b).split(b"\n")
        elif kind == 1 and len(lines) > 1:  # cut lines
            i = rng.randrange(len(lines))
            del lines[i:i + rng.randint(1, 3)]
        elif kind == 2 and lines:  # duplicate a line
            i = rng.randrange(len(lines))
            lines.insert(rng.randrange(len(lines) + 1), lines[i])
        elif kind == 3 and len(lines) > 1:  # swap two lines
            i, j = rng.randrange(len(lines)), rng.randrange(len(lines))
            lines[i], lines[j] = lines[j], lines[i]
        elif kind == 4 and lines:  # insert a token
            i = rng.randrange(len(lines))
            at = rng.randint(0, len(lines[i]))
            token = rng.choice(TOKENS).encode("latin-1")
            lines[i] = lines[i][:at] + token + lines[i][at:]
        elif kind == 5:  # insert a block
            block = rng.choice(BLOCKS if rng.random() < 0.6 else ALARM_BLOCKS)
            lines.insert(rng.randrange(len(lines) + 1), block.encode())
        elif lines:  # a huge or odd number after an address
            i = rng.randrange(len(lines))
            lines[i] += (rng.choice("XYZFGMPRIJKS") + rng.choice(HUGE[:4] + ["1e300"])).encode()
    return b"\n".join(lines)


def mutate_bytes(rng, data):
    b = bytearray(data)
    for _ in range(rng.randint(1, 4)):
        kind = rng.randrange(4)
        i = rng.randrange(len(b))
        if kind == 0:
            b[i] ^= 1 << rng.randrange(8)
        elif kind == 1:
            b[i] = rng.choice([0, 0xFF, 0x7F, 0x80, rng.randrange(256)])
        elif kind == 2:  # an 8-byte field (doubles, hashes) replaced
            b[i:i + 8] = rng.choice([b"\x00" * 8, b"\xff" * 8, b"\x00\x00\x00\x00\x00\x00\xf0\x7f",
                                     bytes(rng.randrange(256) for _ in range(8))])
        else:
            del b[i:i + rng.randint(1, 16)]
    return bytes(b)


def seal(data):
    """The documented checksum written anew (see test_bytecode.py)."""
    if len(data) < 64:
        return data
    def fnv(chunk, h):
        for x in chunk:
            h = ((h ^ x) * 0x100000001B3) & 0xFFFFFFFFFFFFFFFF
        return h
    h = fnv(data[:56] + bytes(8) + data[64:64], fnv(data[64:], 0xCBF29CE484222325))
    return data[:56] + h.to_bytes(8, "little") + data[64:]


def mutate_machine(rng, data):
    text = data.decode("utf-8", "replace")
    lines = text.split("\n")
    for _ in range(rng.randint(1, 3)):
        kind = rng.randrange(4)
        i = rng.randrange(len(lines))
        if kind <= 1 and "=" in lines[i]:  # a value replaced
            key, _, value = lines[i].partition("=")
            if "{" in value and rng.random() < 0.5:  # one field of an inline table
                inner = value.split(",")
                j = rng.randrange(len(inner))
                k, _, _ = inner[j].partition("=")
                inner[j] = f"{k}= {rng.choice(HUGE)}" + (" }" if j == len(inner) - 1 else "")
                value = ",".join(inner)
            else:
                value = " " + rng.choice(HUGE)
            lines[i] = key + "=" + value
        elif kind == 2:  # a line removed
            del lines[i]
            if not lines:
                lines = [""]
        else:  # a byte flipped
            b = bytearray(lines[i].encode())
            if b:
                b[rng.randrange(len(b))] ^= 1 << rng.randrange(7)
            lines[i] = b.decode("utf-8", "replace")
    return "\n".join(lines).encode()


class Mutant:
    def __init__(self, name, files, input_name, extra=(), max_steps=MAX_STEPS):
        self.name = name          # describes how it was made (reproducible with the seed)
        self.files = files        # name -> bytes, written into the mutant's folder
        self.input = input_name
        self.extra = list(extra)
        self.max_steps = max_steps


def make_mutants(workdir):
    rng = random.Random(SEED)
    sources = source_seeds()
    machines = machine_seeds()
    # Only programs that compile are mutated (as source, and compiled with the machine they are
    # for as bytecode): a mutant of a program the compiler refuses anyway tests little.
    compiled = []
    for k, (name, data, extra, files) in enumerate(sources):
        folder = os.path.join(workdir, f"seed{k}")
        os.mkdir(folder)
        for file, content in {"prog.nc": data, **files}.items():
            with open(os.path.join(folder, file), "wb") as f:
                f.write(content)
        proc = subprocess.run([NCC, "compile", "prog.nc", "-o", "prog.ncb", *extra], cwd=folder,
                              capture_output=True, timeout=TIMEOUT)
        if proc.returncode == 0:
            compiled.append((name, data, read(os.path.join(folder, "prog.ncb")), extra, files))
        shutil.rmtree(folder)
    assert len(compiled) >= 10, "too few seeds compiled: cannot fuzz bytecode"
    n_source = COUNT * 4 // 10
    n_ncb = COUNT * 3 // 10
    mutants = []
    for k in range(n_source):
        name, data, _, extra, files = rng.choice(compiled)
        # One in ten with a step limit that stops most runs part way (alarm NCC7204).
        steps = "5" if k % 10 == 9 else MAX_STEPS
        mutants.append(Mutant(f"source#{k} from {name} (--max-steps {steps})",
                              {"prog.nc": mutate_source(rng, data), **files}, "prog.nc", extra,
                              steps))
    for k in range(n_ncb):
        name, _, data, extra, files = rng.choice(compiled)
        mutated = mutate_bytes(rng, data)
        sealed = k % 2 == 0
        if sealed:
            mutated = seal(mutated)
        mutants.append(Mutant(f"ncb#{k} from {name}.ncb{' (sealed)' if sealed else ''}",
                              {"prog.ncb": mutated, **files}, "prog.ncb", extra))
    for k in range(COUNT - n_source - n_ncb):
        name, machine, program, extra = rng.choice(machines)
        mutants.append(Mutant(f"machine#{k} from {name}",
                              {"prog.nc": program, "m.toml": mutate_machine(rng, machine)},
                              "prog.nc", ["--machine", "m.toml", *extra]))
    return mutants


def run_mutant(mutant, workdir):
    """Returns a list of failure descriptions (empty: the mutant behaved)."""
    base = tempfile.mkdtemp(dir=workdir)
    for name, data in mutant.files.items():
        with open(os.path.join(base, name), "wb") as f:
            f.write(data)
    failures = []
    codes = {}
    for mode in MODES:
        outdir = os.path.join(base, "out-" + mode)
        os.mkdir(outdir)
        out = os.path.join(outdir, OUTPUT[mode])
        # 1,000 jumps back instead of 10,000: a mutant that loops (M99 in the main program) still
        # reaches the limit (NCC2419), in a tenth of the time, which matters under ASan.
        args = [NCC, "run", mutant.input, f"--emit={mode}", "-o", out, "--max-steps", mutant.max_steps,
                "--max-time", MAX_SIMULATED_SECONDS, "--max-back-jumps", "1000", *mutant.extra]
        try:
            proc = subprocess.run(args, cwd=base, capture_output=True, timeout=TIMEOUT)
        except subprocess.TimeoutExpired:
            failures.append(f"{mutant.name}: --emit={mode} did not end within {TIMEOUT} s")
            codes[mode] = "timeout"
            continue
        codes[mode] = proc.returncode
        stderr = proc.stderr.decode("utf-8", "replace").strip().splitlines()
        first = stderr[0] if stderr else ""
        # Under the sanitizer build (CI) a finding may still exit with 1: look for its report.
        sanitizer = [l for l in stderr if "Sanitizer" in l or ": runtime error:" in l]
        if sanitizer:
            failures.append(f"{mutant.name}: --emit={mode}: {sanitizer[0]}")
        if proc.returncode not in (0, 1, 2, 3):
            failures.append(f"{mutant.name}: --emit={mode} exit code {proc.returncode} "
                            f"(a crash?) {first}")
        left = os.listdir(outdir)
        # An alarm (exit 3) is a verdict of a run that took place: the summary, the trace and
        # the moves up to it stay (docs/cli.md, "Output files"), the moves ending with the alarm
        # record; vars has no end state to write. Any other failure leaves nothing at all, and
        # no run leaves a temporary file.
        kept = {OUTPUT[mode]} if proc.returncode == 3 and mode != "vars" else set()
        if proc.returncode != 0 and set(left) - kept:
            failures.append(f"{mutant.name}: --emit={mode} failed (exit {proc.returncode}) and "
                            f"left {left}: {first}")
        if proc.returncode == 3 and mode == "moves" and OUTPUT[mode] in left:
            with open(os.path.join(outdir, OUTPUT[mode]), "rb") as f:
                lines = f.read().splitlines()
            if not lines or b'"kind": "alarm"' not in lines[-1]:
                failures.append(f"{mutant.name}: --emit=moves alarm without the alarm record")
        if proc.returncode == 0 and OUTPUT[mode] not in left:
            failures.append(f"{mutant.name}: --emit={mode} succeeded without writing -o")
    distinct = set(codes.values())
    if len(distinct) > 1:
        failures.append(f"{mutant.name}: exit codes differ between modes: {codes}")
    if not failures:
        shutil.rmtree(base, ignore_errors=True)
    elif os.environ.get("NCC_FUZZ_CLI_KEEP"):
        failures = [f + f"  [files in {base}]" for f in failures]
    return failures, codes


class FuzzCliTest(unittest.TestCase):
    def test_mutants_behave_in_every_mode(self):
        keep = os.environ.get("NCC_FUZZ_CLI_KEEP")  # a folder: failing mutants stay there
        workdir = keep or tempfile.mkdtemp(prefix="ncc-fuzz-cli-")
        os.makedirs(workdir, exist_ok=True)
        try:
            mutants = make_mutants(workdir)
            self.assertEqual(len(mutants), COUNT)
            started = time.monotonic()
            failures = []
            histogram = {}
            with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
                for found, codes in pool.map(lambda m: run_mutant(m, workdir), mutants):
                    failures.extend(found)
                    for key in codes.values():
                        histogram[key] = histogram.get(key, 0) + 1
            elapsed = time.monotonic() - started
            print(f"\n{len(mutants)} mutants x {len(MODES)} modes in {elapsed:.1f} s (seed {SEED}); "
                  f"exit codes of all runs: {histogram}", file=sys.stderr)
            # The mutants must reach every outcome, or the test checks less than it seems.
            for code in (0, 1, 2, 3):
                self.assertIn(code, histogram, f"no run ended with exit code {code}")
            if failures:
                self.fail(f"{len(failures)} failures (NCC_FUZZ_CLI_KEEP=DIR keeps the mutants):\n"
                          + "\n".join(failures))
        finally:
            if not keep:
                shutil.rmtree(workdir, ignore_errors=True)


if __name__ == "__main__":
    NCC = os.path.abspath(sys.argv.pop(1))
    unittest.main(verbosity=2)
