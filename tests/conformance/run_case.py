#!/usr/bin/env python3
"""Runs conformance cases through `ncc run` and compares with what the manuals state.

    run_case.py --ncc build/tools/ncc/ncc --case tests/conformance/mazak-m/g43-length-offset-absolute \
                --expected-failures tests/conformance/expected_failures.txt
    run_case.py --ncc ... --all tests/conformance --summary     # every case, counts per dialect

Per case it prints PASS, XFAIL (listed in expected_failures.txt and failing: the reason and
the first difference), FAIL (the first difference) or XPASS (listed but passing, which fails:
remove the entry). Exit status: 0 when every case is PASS or XFAIL, 1 otherwise, 2 when a case
or the expected-failures file is malformed. With --summary the exit status is 0 unless a case
crashed ncc or is malformed, or an expected-failures entry names no case: the per-case ctests
carry the verdicts; the summary is the overview.
"""
import argparse
import collections
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from runner import case as case_mod  # noqa: E402
from runner import expected_failures, run  # noqa: E402
from runner.compare import CaseError  # noqa: E402


def parse_args(argv):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--ncc", required=True, help="path of the ncc executable")
    p.add_argument("--case", action="append", default=[], help="a case folder (repeatable)")
    p.add_argument("--all", metavar="ROOT", help="every <dialect>/<id>/case.toml under ROOT")
    p.add_argument("--expected-failures", metavar="FILE", help="expected_failures.txt")
    p.add_argument("--summary", action="store_true", help="print pass/xfail/fail counts per dialect")
    p.add_argument("--timeout", type=float, default=run.TIMEOUT_SECONDS, help="seconds per ncc run")
    p.add_argument("--jobs", type=int, default=1, help="cases run in parallel")
    args = p.parse_args(argv)
    if not args.case and not args.all:
        p.error("give --case DIR or --all ROOT")
    return args


def judge_one(args, folder, xfails):
    case = case_mod.load(folder)
    return case, run.verdict(run.judge(args.ncc, case, args.timeout), xfails.get(case.name))


def print_summary(results, xfails, out):
    counts = collections.defaultdict(collections.Counter)
    for case, v in results:
        counts[case.dialect][v.status] += 1
    statuses = ("PASS", "XFAIL", "FAIL", "XPASS")
    out.write("\nconformance summary\n")
    out.write(f"  {'dialect':<15}" + "".join(f"{s:>7}" for s in statuses) + f"{'total':>7}\n")
    total = collections.Counter()
    for dialect in sorted(counts):
        c = counts[dialect]
        total.update(c)
        out.write(f"  {dialect:<15}" + "".join(f"{c[s]:>7}" for s in statuses) + f"{sum(c.values()):>7}\n")
    out.write(f"  {'all':<15}" + "".join(f"{total[s]:>7}" for s in statuses) + f"{sum(total.values()):>7}\n")
    failing = [(case.name, v) for case, v in results if not v.ok]
    if failing:
        out.write("\nnot passing (first line of each report):\n")
        for name, v in failing:
            out.write(f"  {v.status:<6}{name}: {v.report.splitlines()[0] if v.report else ''}\n")


def main(argv):
    args = parse_args(argv)
    try:
        xfails = expected_failures.load(args.expected_failures)
        folders = [Path(c) for c in args.case]
        if args.all:
            folders += case_mod.find_cases(args.all)
        with ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
            results = list(pool.map(lambda f: judge_one(args, f, xfails), folders))
    except (CaseError, OSError) as e:
        print(f"error: {e}", file=sys.stderr)
        return 2

    for case, v in results:
        if not args.summary or not v.ok:
            print(f"{v.status}: conformance/{case.name}" + (f"\n  {v.report}" if v.report else ""))

    if not args.summary:
        return 0 if all(v.ok for _, v in results) else 1

    print_summary(results, xfails, sys.stdout)
    status = 0
    if args.all:
        stale = sorted(set(xfails) - {case.name for case, _ in results})
        for name in stale:
            print(f"error: expected_failures.txt lists {name}, which is no case", file=sys.stderr)
            status = 1
    crashed = [case.name for case, v in results if "killed by signal" in v.report or "timed out" in v.report]
    for name in crashed:
        print(f"error: ncc crashed or hung on {name}", file=sys.stderr)
        status = 1
    return status


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
