#!/usr/bin/env python3
"""Golden test of one example program.

  run_golden.py --ncc NCC --example examples/NAME.nc --golden-dir tests/golden

Moves: `ncc run` with --emit=moves is compared with NAME.moves.jsonl object by object (same keys,
same strings and booleans, numbers within 1e-6). Diagnostics: for NAME.diag, `ncc check` must fail
with exactly the listed `file:line:col: severity[CODE]` prefixes, in order, each followed by the
listed message when the .diag line carries one after the prefix.
Disassembly: NAME.dis is compared line by line with `ncc dis` of the compiled example.
IR: NAME.after-PASS.ir is compared line by line with `ncc compile NAME --emit=ir
--print-after=PASS`, NAME.check-after-PASS.ir with `ncc check NAME --print-after=PASS` (a pass
only `ncc check` runs, e.g. travel-check); both must exit 0. Each file is the command's exact
output: to write one, run that command (docs/testing.md, "IR golden files").
Every compile and check here runs with --verify-each (the IR verifier after every pass), and
an example with moves is also compiled so, so a pass that breaks an IR invariant fails here.
ncc runs in the example's folder with the file's bare name, so recorded paths are stable.
Extra command-line arguments for ncc (e.g. --dialect mazak-m) come from NAME.args when present;
a machine file NAME.toml beside the example is passed as --machine.
"""
import argparse
import glob
import json
import os
import re
import subprocess
import sys
import tempfile

TOLERANCE = 1e-6
DIAG_RE = re.compile(r"^(?P<file>[^:\s]+):(?P<line>\d+):(?P<col>\d+): (?P<sev>error|warning)\[(?P<code>[^\]]+)\]: (?P<msg>.*)$")


def same(expected, actual, path):
    if isinstance(expected, dict):
        if not isinstance(actual, dict) or set(expected) != set(actual):
            return f"{path}: keys {sorted(expected) if isinstance(expected, dict) else expected} != {sorted(actual) if isinstance(actual, dict) else actual}"
        for key in expected:
            problem = same(expected[key], actual[key], f"{path}.{key}")
            if problem:
                return problem
        return None
    if isinstance(expected, bool) or isinstance(actual, bool) or isinstance(expected, str):
        return None if expected == actual else f"{path}: expected {expected!r}, got {actual!r}"
    if isinstance(expected, (int, float)) and isinstance(actual, (int, float)):
        return None if abs(expected - actual) <= TOLERANCE else f"{path}: expected {expected}, got {actual}"
    return None if expected == actual else f"{path}: expected {expected!r}, got {actual!r}"


def ncc_args(example, golden_dir):
    name = os.path.splitext(os.path.basename(example))[0]
    args = []
    args_file = os.path.join(golden_dir, name + ".args")
    if os.path.exists(args_file):
        args += open(args_file).read().split()
    machine = os.path.splitext(example)[0] + ".toml"
    if os.path.exists(machine):
        args += ["--machine", machine]
    return name, args


def run_ncc(ncc, args, example):
    """Runs ncc in the example's folder, naming the example by its bare file name."""
    args = [os.path.basename(example) if a == example else a for a in args]
    return subprocess.run([ncc] + args, capture_output=True, text=True, timeout=120,
                          cwd=os.path.dirname(os.path.abspath(example)))


def check_moves(ncc, example, golden, extra):
    with tempfile.TemporaryDirectory() as tmp:
        proc = run_ncc(ncc, ["compile", example, "--verify-each", "-o", os.path.join(tmp, "p.ncb")] + extra,
                       example)
        if proc.returncode != 0:
            return f"ncc compile --verify-each exited {proc.returncode}:\n{proc.stderr}"
        out = os.path.join(tmp, "moves.jsonl")
        proc = run_ncc(ncc, ["run", example, "--emit=moves", "-o", out] + extra, example)
        if proc.returncode != 0:
            return f"ncc run exited {proc.returncode}:\n{proc.stderr}"
        actual = [json.loads(l) for l in open(out) if l.strip()]
    expected = [json.loads(l) for l in open(golden) if l.strip()]
    for i, (e, a) in enumerate(zip(expected, actual)):
        problem = same(e, a, f"move {i + 1}")
        if problem:
            return f"{problem}\n  expected: {json.dumps(e)}\n  actual:   {json.dumps(a)}"
    if len(expected) != len(actual):
        return f"expected {len(expected)} moves, got {len(actual)}"
    return None


def check_diagnostics(ncc, example, golden, extra):
    proc = run_ncc(ncc, ["check", example, "--verify-each"] + extra, example)
    if proc.returncode != 1:
        return f"ncc check exited {proc.returncode}, expected 1 (errors in the program):\n{proc.stderr}"
    actual = []
    for line in proc.stderr.splitlines():
        m = DIAG_RE.match(line)
        if m:
            actual.append((f"{os.path.basename(m['file'])}:{m['line']}:{m['col']}: {m['sev']}[{m['code']}]", m["msg"]))
    expected = [l.rstrip("\n") for l in open(golden) if l.strip() and not l.startswith("#")]
    if len(expected) != len(actual):
        return f"expected {len(expected)} diagnostics, got {len(actual)}:\n{proc.stderr}"
    for e, (prefix, msg) in zip(expected, actual):
        want_prefix, _, want_msg = e.partition("]: ")
        want_prefix += "]" if not want_prefix.endswith("]") else ""
        if want_prefix != prefix:
            return f"expected '{want_prefix}', got '{prefix}'\n{proc.stderr}"
        if want_msg and want_msg != msg:
            return f"{prefix}: expected message '{want_msg}', got '{msg}'"
    return None


def check_disassembly(ncc, example, golden, extra):
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "program.ncb")
        proc = run_ncc(ncc, ["compile", example, "--verify-each", "-o", out] + extra, example)
        if proc.returncode != 0:
            return f"ncc compile exited {proc.returncode}:\n{proc.stderr}"
        proc = run_ncc(ncc, ["dis", out] + extra, example)
        if proc.returncode != 0:
            return f"ncc dis exited {proc.returncode}:\n{proc.stderr}"
    actual = proc.stdout.splitlines()
    expected = open(golden).read().splitlines()
    for i, (e, a) in enumerate(zip(expected, actual)):
        if e != a:
            return f"disassembly line {i + 1}:\n  expected: {e}\n  actual:   {a}"
    if len(expected) != len(actual):
        return f"expected {len(expected)} disassembly lines, got {len(actual)}"
    return None


IR_GOLDEN_RE = re.compile(r"^(?P<command>after|check-after)-(?P<pass>[a-z0-9-]+)\.ir$")


def check_ir(ncc, example, golden, m, extra):
    """NAME.after-PASS.ir / NAME.check-after-PASS.ir (`m`: its match of IR_GOLDEN_RE): the IR
    printed after PASS, exactly."""
    if m["command"] == "after":
        command = ["compile", example, "--emit=ir", "-o", "-"]
    else:
        command = ["check", example]
    command += [f"--print-after={m['pass']}", "--verify-each"]
    proc = run_ncc(ncc, command + extra, example)
    label = f"ncc {' '.join(command[:1] + command[2:])}"
    if proc.returncode != 0:
        return f"{label} exited {proc.returncode}:\n{proc.stderr}"
    actual = proc.stdout.splitlines()
    expected = open(golden).read().splitlines()
    for i, (e, a) in enumerate(zip(expected, actual)):
        if e != a:
            return f"{os.path.basename(golden)} line {i + 1}:\n  expected: {e}\n  actual:   {a}"
    if len(expected) != len(actual):
        return f"{os.path.basename(golden)}: expected {len(expected)} lines, got {len(actual)}"
    return None


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--ncc", required=True)
    parser.add_argument("--example", required=True)
    parser.add_argument("--golden-dir", required=True)
    opts = parser.parse_args()
    name, extra = ncc_args(opts.example, opts.golden_dir)
    moves = os.path.join(opts.golden_dir, name + ".moves.jsonl")
    diag = os.path.join(opts.golden_dir, name + ".diag")
    dis = os.path.join(opts.golden_dir, name + ".dis")
    irs = []
    for f in sorted(glob.glob(os.path.join(glob.escape(opts.golden_dir), glob.escape(name) + ".*.ir"))):
        m = IR_GOLDEN_RE.match(os.path.basename(f)[len(name) + 1:])
        if m:
            irs.append((f, m))
    problems = []
    for ir, m in irs:
        problems.append(check_ir(opts.ncc, opts.example, ir, m, extra))
    if os.path.exists(dis):
        problems.append(check_disassembly(opts.ncc, opts.example, dis, extra))
    if os.path.exists(moves):
        problems.append(check_moves(opts.ncc, opts.example, moves, extra))
    if os.path.exists(diag):
        problems.append(check_diagnostics(opts.ncc, opts.example, diag, extra))
    if not irs and not any(os.path.exists(f) for f in (moves, diag, dis)):
        problems.append(f"no golden file for {name} (expected {moves}, {diag}, {dis} or NAME.after-PASS.ir)")
    problems = [p for p in problems if p]
    if problems:
        print(f"FAIL {name}\n" + "\n".join(problems))
        return 1
    print(f"PASS {name}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
