"""Running one case through `ncc run` and judging it against the case's expectations."""
import subprocess
import tempfile
from dataclasses import dataclass
from pathlib import Path

from . import compare, ncc_output, toml_emit

TIMEOUT_SECONDS = 60
STDERR_LINES_SHOWN = 12


@dataclass
class Result:
    passed: bool
    report: str = ""  # the first difference (empty when passed)


@dataclass
class Invocation:
    command: list
    exit_code: int
    stderr: str
    output: str | None  # the -o file's text, None if ncc did not write it


def machine_file_text(case):
    return toml_emit.dumps({"machine": case.machine, "start": case.start})


def invoke(ncc, case, machine_path, emit, out_path, timeout=TIMEOUT_SECONDS):
    command = [str(ncc), "run", str(case.program), "--dialect", case.dialect, "--machine", str(machine_path),
               "--program-dir", str(case.folder), f"--emit={emit}", "-o", str(out_path)]
    try:
        proc = subprocess.run(command, capture_output=True, text=True, errors="replace", timeout=timeout)
    except subprocess.TimeoutExpired:
        return Invocation(command, None, f"timed out after {timeout} s", None)
    out = Path(out_path)
    return Invocation(command, proc.returncode, proc.stderr, out.read_text() if out.is_file() else None)


def _stderr_excerpt(stderr):
    lines = stderr.rstrip().splitlines()
    shown = "\n    ".join(lines[:STDERR_LINES_SHOWN])
    more = f"\n    ... ({len(lines) - STDERR_LINES_SHOWN} more lines)" if len(lines) > STDERR_LINES_SHOWN else ""
    return f"\n  ncc stderr:\n    {shown}{more}" if lines else ""


def _failed_run(inv, what):
    if inv.exit_code is None:
        return f"ncc {what}: {inv.stderr}\n  command: {' '.join(inv.command)}"
    if inv.exit_code < 0:
        state = f"was killed by signal {-inv.exit_code} (crash)"
    elif inv.exit_code in (1, 3):
        stage = "compile time" if inv.exit_code == 1 else "run time"
        state = f"rejected the program at {stage} (exit {inv.exit_code})"
    else:
        state = f"exited with {inv.exit_code}"
    return f"ncc {what} {state}{_stderr_excerpt(inv.stderr)}\n  command: {' '.join(inv.command)}"


def judge(ncc, case, timeout=TIMEOUT_SECONDS):
    """Runs the case and compares every expectation it states; the first difference wins."""
    expect = case.expect
    with tempfile.TemporaryDirectory(prefix="ncc-conf-") as tmp:
        tmp = Path(tmp)
        machine = tmp / "machine.toml"
        machine.write_text(machine_file_text(case))
        moves_run = invoke(ncc, case, machine, "moves", tmp / "moves.jsonl", timeout)

        if "alarm" in expect:
            if moves_run.exit_code is None:
                return Result(False, _failed_run(moves_run, "run"))
            diags = ncc_output.parse_diagnostics(moves_run.stderr)
            diff = compare.compare_alarm(expect["alarm"], moves_run.exit_code, diags)
            if diff and not diags:  # the diagnostics are already quoted in the report otherwise
                diff += _stderr_excerpt(moves_run.stderr)
            return Result(diff is None, diff or "")

        if moves_run.exit_code != 0:
            return Result(False, _failed_run(moves_run, "run --emit=moves"))
        if moves_run.output is None:
            return Result(False, f"ncc exited 0 but wrote no move file\n  command: {' '.join(moves_run.command)}")
        try:
            actual = ncc_output.parse_moves(moves_run.output, "moves.jsonl")
        except ncc_output.OutputError as e:
            return Result(False, f"malformed --emit=moves output: {e}")

        start, tol = case.start_position, case.tolerance
        if "moves" in expect:
            diff = compare.compare_moves(expect["moves"], actual, start, tol, bool(expect.get("moves_subset", False)))
            if diff:
                return Result(False, diff)
        if "final" in expect:
            diff = compare.compare_final(expect["final"], actual, start, tol)
            if diff:
                return Result(False, diff)
        if "vars" in expect:
            vars_run = invoke(ncc, case, machine, "vars", tmp / "vars.json", timeout)
            if vars_run.exit_code != 0 or vars_run.output is None:
                return Result(False, _failed_run(vars_run, "run --emit=vars"))
            try:
                actual_vars = ncc_output.parse_vars(vars_run.output, "vars.json")
            except ncc_output.OutputError as e:
                return Result(False, f"malformed --emit=vars output: {e}")
            diff = compare.compare_vars(expect["vars"], actual_vars, tol)
            if diff:
                return Result(False, diff)
    return Result(True)


@dataclass
class Verdict:
    status: str  # PASS, XFAIL, FAIL, XPASS (listed as expected to fail but passed: a failure)
    report: str = ""

    @property
    def ok(self):
        return self.status in ("PASS", "XFAIL")


def verdict(result, xfail_reason):
    if xfail_reason is None:
        return Verdict("PASS") if result.passed else Verdict("FAIL", result.report)
    if result.passed:
        return Verdict("XPASS", "unexpected pass: remove it from expected_failures.txt "
                                f"(listed as: {xfail_reason})")
    return Verdict("XFAIL", f"{xfail_reason}\n  first difference: {result.report}")
