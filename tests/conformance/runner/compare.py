"""Comparing what ncc did with what a conformance case expects (FORMAT.md).

Each function returns None when the expectation holds, else a report of the first difference,
precise enough to act on: which move, which source line ncc attributed it to, which field, the
expected and the actual value.
"""
from .ncc_output import Move, axes_text, fmt

MOVE_KEYS = {"kind", "to", "center", "cw", "feed", "seconds"}
MOVE_KINDS = {"rapid", "line", "arc", "dwell"}


class CaseError(Exception):
    """The case itself is malformed (a bug in the case, not in ncc)."""


def expected_move(spec, index):
    """A case's move table as a Move; unknown keys or kinds are case errors."""
    if not isinstance(spec, dict):
        raise CaseError(f"expect.moves[{index}] is not a table")
    unknown = set(spec) - MOVE_KEYS
    if unknown:
        raise CaseError(f"expect.moves[{index}] has unknown keys {sorted(unknown)}")
    if spec.get("kind") not in MOVE_KINDS:
        raise CaseError(f"expect.moves[{index}] has kind {spec.get('kind')!r}")
    return Move(kind=spec["kind"], to=dict(spec.get("to", {})), center=dict(spec.get("center", {})),
                cw=spec.get("cw"), feed=spec.get("feed"), seconds=spec.get("seconds"))


def positions_before(actual, start):
    """The commanded position before each actual move: the start, then each move's `to`."""
    before = []
    pos = dict(start)
    for move in actual:
        before.append(dict(pos))
        pos.update(move.to)
    return before


def _close(a, b, tol):
    return abs(a - b) <= tol


def move_differences(exp, act, prev, tol):
    """Every way `act` (which started at `prev`) differs from the expected move `exp`."""
    if exp.kind != act.kind:
        return [f"kind: expected {exp.kind}, got {act.kind}"]
    diffs = []
    for axis, want in exp.to.items():
        if axis not in act.to:
            diffs.append(f"to.{axis}: expected {fmt(want)}, ncc reported no {axis} axis")
        elif not _close(act.to[axis], want, tol):
            diffs.append(f"to.{axis}: expected {fmt(want)}, got {fmt(act.to[axis])}")
    for axis, got in act.to.items():
        if axis in exp.to or axis not in prev:
            continue
        if not _close(got, prev[axis], tol):
            diffs.append(f"to.{axis}: moved from {fmt(prev[axis])} to {fmt(got)}, but the case does not "
                         f"list {axis} (an unlisted axis must not move)")
    for axis, want in exp.center.items():
        if axis not in act.center:
            diffs.append(f"center.{axis}: expected {fmt(want)}, ncc reported none")
        elif not _close(act.center[axis], want, tol):
            diffs.append(f"center.{axis}: expected {fmt(want)}, got {fmt(act.center[axis])}")
    if exp.cw is not None and act.cw != exp.cw:
        diffs.append(f"cw: expected {str(exp.cw).lower()}, got {'none' if act.cw is None else str(act.cw).lower()}")
    if exp.feed is not None:
        if act.feed is None:
            diffs.append(f"feed: expected {fmt(exp.feed)}, ncc reported none")
        elif not _close(act.feed, exp.feed, tol):
            diffs.append(f"feed: expected {fmt(exp.feed)}, got {fmt(act.feed)}")
    if exp.seconds is not None:
        if act.seconds is None:
            diffs.append(f"seconds: expected {fmt(exp.seconds)}, ncc reported none")
        elif not _close(act.seconds, exp.seconds, tol):
            diffs.append(f"seconds: expected {fmt(exp.seconds)}, got {fmt(act.seconds)}")
    return diffs


def _at(moves, i):
    return f"ncc move #{i + 1} ({moves[i].where()})"


def _exact(expected, actual, before, tol):
    for i, (exp, act) in enumerate(zip(expected, actual)):
        diffs = move_differences(exp, act, before[i], tol)
        if diffs:
            return (f"move #{i + 1} differs, {_at(actual, i)}:\n  expected: {exp.describe()}\n"
                    f"  got:      {act.describe()}\n  - " + "\n  - ".join(diffs))
    if len(actual) > len(expected):
        i = len(expected)
        return (f"ncc emitted {len(actual)} moves, the case lists {len(expected)}; first extra move is "
                f"{_at(actual, i)}: {actual[i].describe()}")
    if len(actual) < len(expected):
        i = len(actual)
        return (f"ncc emitted {len(actual)} moves, the case lists {len(expected)}; first missing move is "
                f"#{i + 1}: {expected[i].describe()}")
    return None


def _subset(expected, actual, before, tol):
    # Greedy earliest match is complete for "appear in this order": whether an actual move
    # matches depends only on that move and the one before it in ncc's stream.
    j = 0
    for k, exp in enumerate(expected):
        start = j
        while j < len(actual) and move_differences(exp, actual[j], before[j], tol):
            j += 1
        if j == len(actual):
            return _subset_miss(exp, k, start, actual, before, tol)
        j += 1
    return None


def _subset_miss(exp, k, start, actual, before, tol):
    report = f"listed move #{k + 1} ({exp.describe()}) not found in order (moves_subset = true): "
    if start >= len(actual):
        return report + (f"ncc emitted no move after the one matching listed move #{k}" if k else "ncc emitted no move")
    report += f"searched ncc moves #{start + 1}..#{len(actual)}"
    for i in range(start, len(actual)):
        if actual[i].kind == exp.kind:
            diffs = move_differences(exp, actual[i], before[i], tol)
            return (report + f"\n  nearest {exp.kind} is {_at(actual, i)}: {actual[i].describe()}\n  - "
                    + "\n  - ".join(diffs))
    return report + f"\n  ncc emitted no {exp.kind} move there"


def compare_moves(expected_specs, actual, start, tol, subset):
    expected = [expected_move(s, i) for i, s in enumerate(expected_specs)]
    before = positions_before(actual, start)
    return (_subset if subset else _exact)(expected, actual, before, tol)


def final_position(actual, start):
    """The last commanded machine position: the last move's `to`, else the start position."""
    pos = dict(start)
    for move in actual:
        pos.update(move.to)
    return pos


def compare_final(expected, actual, start, tol):
    pos = final_position(actual, start)
    for axis, want in expected.items():
        if axis not in pos:
            return f"final.{axis}: expected {fmt(want)}, ncc has no {axis} axis"
        if not _close(pos[axis], want, tol):
            last = f" (last move: {actual[-1].where()})" if actual else " (no move was emitted)"
            return f"final.{axis}: expected {fmt(want)}, got {fmt(pos[axis])}; final position {axes_text(pos)}{last}"
    return None


def compare_vars(expected, actual, tol):
    for name, want in expected.items():
        if name not in actual:
            return f"vars {name}: expected {fmt(float(want))}, ncc reports it vacant (absent from --emit=vars)"
        if not _close(actual[name], want, tol):
            return f"vars {name}: expected {fmt(float(want))}, got {fmt(actual[name])}"
    return None


def compare_alarm(expected, exit_code, diagnostics):
    """The program must be rejected (exit 1 at compile time, 3 at run time) with a diagnostic
    whose code is exactly the case's code (FORMAT.md: the code as the manual numbers it) at the
    case's line."""
    code, line = str(expected["code"]), int(expected["line"])
    want = f"alarm {code} at line {line}"
    if exit_code == 0:
        return f"expected {want}, but ncc ran the program to the end (exit 0)"
    if exit_code not in (1, 3):
        return f"expected {want}, but ncc exited with {exit_code} (an alarm is exit 1 or 3)"
    for d in diagnostics:
        if d.code == code and d.line == line:
            return None
    if not diagnostics:
        return f"expected {want}; ncc exited with {exit_code} but printed no `file:line:col: error[CODE]:` line"
    same_code = [d for d in diagnostics if d.code == code]
    hint = f" (code {code} was reported at line {same_code[0].line})" if same_code else ""
    shown = "\n  ".join(str(d) for d in diagnostics[:5])
    return f"expected {want}{hint}; ncc reported:\n  {shown}"
