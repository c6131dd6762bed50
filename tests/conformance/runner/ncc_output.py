"""Reading what `ncc` writes: the JSON Lines move list, the variable dump and diagnostics."""
import json
import re
from dataclasses import dataclass, field

# `file:line:col: error[CODE]: message` (the file name may itself contain ':').
DIAGNOSTIC = re.compile(r"^(?P<file>.+):(?P<line>\d+):(?P<col>\d+): error\[(?P<code>[^\]]+)\]: (?P<msg>.*)$")


class OutputError(Exception):
    """ncc's output is not in the documented format."""


@dataclass
class Move:
    kind: str
    to: dict = field(default_factory=dict)
    center: dict = field(default_factory=dict)
    cw: bool | None = None
    feed: float | None = None
    feed_per_rev: bool = False
    seconds: float | None = None
    file: str = ""
    line: int = 0

    def where(self):
        return f"{self.file}:{self.line}" if self.file else f"line {self.line}"

    def describe(self):
        parts = [self.kind]
        if self.to:
            parts.append("to " + axes_text(self.to))
        if self.center:
            parts.append("center " + axes_text(self.center))
        if self.cw is not None:
            parts.append("cw" if self.cw else "ccw")
        if self.feed is not None:
            parts.append(f"F{fmt(self.feed)}" + ("/rev" if self.feed_per_rev else ""))
        if self.seconds is not None:
            parts.append(f"{fmt(self.seconds)} s")
        return " ".join(parts)


@dataclass
class Diagnostic:
    file: str
    line: int
    col: int
    code: str
    message: str

    def __str__(self):
        return f"{self.file}:{self.line}:{self.col}: error[{self.code}]: {self.message}"


def fmt(x):
    return f"{x:.6g}" if isinstance(x, float) else str(x)


def axes_text(axes):
    return "{" + ", ".join(f"{k}={fmt(v)}" for k, v in axes.items()) + "}"


def _number(obj, key, where):
    v = obj[key]
    if isinstance(v, bool) or not isinstance(v, (int, float)):
        raise OutputError(f"{where}: '{key}' is not a number: {v!r}")
    return float(v)


def _axes(obj, key, where):
    v = obj.get(key, {})
    if not isinstance(v, dict):
        raise OutputError(f"{where}: '{key}' is not an object")
    return {axis: _number(v, axis, f"{where} {key}") for axis in v}


def parse_move(obj, where):
    if not isinstance(obj, dict) or not isinstance(obj.get("kind"), str):
        raise OutputError(f"{where}: not a move object with a 'kind': {obj!r}")
    move = Move(kind=obj["kind"], file=str(obj.get("file", "")))
    if "line" in obj:
        move.line = int(_number(obj, "line", where))
    move.to = _axes(obj, "to", where)
    move.center = _axes(obj, "center", where)
    if "cw" in obj:
        if not isinstance(obj["cw"], bool):
            raise OutputError(f"{where}: 'cw' is not a boolean")
        move.cw = obj["cw"]
    if "feed" in obj:
        move.feed = _number(obj, "feed", where)
    move.feed_per_rev = obj.get("feed_per_rev") is True
    if "seconds" in obj:
        move.seconds = _number(obj, "seconds", where)
    return move


def parse_moves(text, name="moves"):
    """The move list of `--emit=moves`: one JSON object a line; blank lines are ignored."""
    moves = []
    for number, line in enumerate(text.splitlines(), 1):
        if not line.strip():
            continue
        try:
            obj = json.loads(line)
        except json.JSONDecodeError as e:
            raise OutputError(f"{name}:{number}: not JSON: {e}") from None
        moves.append(parse_move(obj, f"{name}:{number}"))
    return moves


def parse_vars(text, name="vars"):
    """The variable dump of `--emit=vars`: one JSON object, name -> number."""
    try:
        obj = json.loads(text)
    except json.JSONDecodeError as e:
        raise OutputError(f"{name}: not JSON: {e}") from None
    if not isinstance(obj, dict):
        raise OutputError(f"{name}: not a JSON object")
    return {k: _number(obj, k, name) for k in obj}


def parse_diagnostics(stderr):
    """Every `file:line:col: error[CODE]: message` line (quoted source lines are skipped)."""
    out = []
    for line in stderr.splitlines():
        m = DIAGNOSTIC.match(line)
        if m:
            out.append(Diagnostic(m["file"], int(m["line"]), int(m["col"]), m["code"], m["msg"]))
    return out
