#!/usr/bin/env python3
"""Corpus check: real programs through `ncc check` must compile, or be rejected with at least
one `file:line:col: error[CODE]:` diagnostic, and never crash or hang.

    corpus_check.py --ncc build/tools/ncc/ncc --file tests/corpus/cam-iso/pygcode-Clamp.nc
    corpus_check.py --ncc build/tools/ncc/ncc --all tests/corpus --summary

Exit status for --file: 0 compiled (exit 0) or rejected with diagnostics (exit 1); 77 (a ctest
SKIP) when ncc answers that the folder's dialect is not supported yet (exit 2 saying "not
supported"); 1 on a crash (signal), a hang (timeout), another exit code, or exit 1 without a
diagnostic. For --summary: counts per folder and the most frequent first-error codes; exit 1
only if something crashed or hung.
"""
import argparse
import collections
import re
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from pathlib import Path

# The dialect each corpus folder is written in (tests/corpus/README.md).
FOLDER_DIALECT = {"cam-iso": "fanuc-m", "fanuc-m": "fanuc-m", "fanuc-t": "fanuc-t", "siemens-din": "siemens-din"}
# The machine a folder's programs are written for, when it is not the default 3-axis one
# (machines/, the project's own).
FOLDER_MACHINE = {"siemens-din": "cead-din.toml"}
MACHINES = Path(__file__).resolve().parent / "machines"
DIAGNOSTIC = re.compile(r"^.+:\d+:\d+: error\[(?P<code>[^\]]+)\]: ")
TIMEOUT_SECONDS = 60
SKIP = 77


@dataclass
class Outcome:
    status: str           # clean, rejected, unsupported, crash
    detail: str = ""
    first_code: str = ""  # code of the first error diagnostic (rejected)
    errors: int = 0

    @property
    def ok(self):
        return self.status != "crash"


def check(ncc, program, timeout=TIMEOUT_SECONDS):
    program = Path(program)
    dialect = FOLDER_DIALECT.get(program.parent.name)
    if dialect is None:
        return Outcome("crash", f"{program.parent.name}/ has no dialect in FOLDER_DIALECT")
    command = [str(ncc), "check", str(program), "--dialect", dialect]
    if program.parent.name in FOLDER_MACHINE:
        command += ["--machine", str(MACHINES / FOLDER_MACHINE[program.parent.name])]
    try:
        proc = subprocess.run(command, capture_output=True, text=True, errors="replace", timeout=timeout)
    except subprocess.TimeoutExpired:
        return Outcome("crash", f"hang: no answer within {timeout} s ({' '.join(command)})")
    codes = [m["code"] for m in map(DIAGNOSTIC.match, proc.stderr.splitlines()) if m]
    head = "\n    ".join(proc.stderr.strip().splitlines()[:6])
    if proc.returncode == 0:
        return Outcome("clean")
    if proc.returncode == 1:
        if not codes:
            return Outcome("crash", f"exit 1 without a `file:line:col: error[CODE]:` line:\n    {head}")
        return Outcome("rejected", head, codes[0], len(codes))
    if proc.returncode == 2 and "not supported" in proc.stderr.lower():
        return Outcome("unsupported", head)
    if proc.returncode < 0:
        return Outcome("crash", f"killed by signal {-proc.returncode}:\n    {head}")
    return Outcome("crash", f"exit {proc.returncode} ({' '.join(command)}):\n    {head}")


def programs_under(root):
    return sorted(p for p in Path(root).glob("*/*") if p.is_file() and p.parent.name in FOLDER_DIALECT)


def run_one(args):
    outcome = check(args.ncc, args.file, args.timeout)
    name = f"{Path(args.file).parent.name}/{Path(args.file).name}"
    if outcome.status == "clean":
        print(f"OK: {name} compiles cleanly")
        return 0
    if outcome.status == "rejected":
        print(f"OK: {name} rejected with {outcome.errors} diagnostic(s), first [{outcome.first_code}]:\n    {outcome.detail}")
        return 0
    if outcome.status == "unsupported":
        print(f"NOT SUPPORTED: {name}: {outcome.detail}")
        return SKIP
    print(f"FAIL: {name}: {outcome.detail}")
    return 1


def run_summary(args):
    programs = programs_under(args.all)
    with ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        outcomes = list(pool.map(lambda p: check(args.ncc, p, args.timeout), programs))
    per_folder = collections.defaultdict(collections.Counter)
    codes = collections.defaultdict(collections.Counter)
    for program, o in zip(programs, outcomes):
        per_folder[program.parent.name][o.status] += 1
        if o.first_code:
            codes[program.parent.name][o.first_code] += 1
    statuses = ("clean", "rejected", "unsupported", "crash")
    print("corpus summary (ncc check)")
    print(f"  {'folder':<13}" + "".join(f"{s:>13}" for s in statuses) + f"{'total':>8}")
    for folder in sorted(per_folder):
        c = per_folder[folder]
        print(f"  {folder:<13}" + "".join(f"{c[s]:>13}" for s in statuses) + f"{sum(c.values()):>8}")
    for folder in sorted(codes):
        common = ", ".join(f"{code} x{n}" for code, n in codes[folder].most_common(5))
        print(f"  most frequent first errors in {folder}: {common}")
    crashed = [(p, o) for p, o in zip(programs, outcomes) if not o.ok]
    for program, o in crashed:
        print(f"CRASH: {program.parent.name}/{program.name}: {o.detail}")
    return 1 if crashed else 0


def main(argv):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--ncc", required=True)
    p.add_argument("--file", help="one corpus program")
    p.add_argument("--all", metavar="ROOT", help="every program under ROOT/<folder>/")
    p.add_argument("--summary", action="store_true")
    p.add_argument("--timeout", type=float, default=TIMEOUT_SECONDS)
    p.add_argument("--jobs", type=int, default=2)
    args = p.parse_args(argv)
    if args.file:
        return run_one(args)
    if args.all:
        return run_summary(args)
    p.error("give --file PROGRAM or --all ROOT --summary")


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
