"""One conformance case folder: `<dialect>/<id>/case.toml` plus its program (FORMAT.md)."""
import tomllib
from dataclasses import dataclass
from pathlib import Path

from .compare import CaseError

PROGRAM_NAMES = ("program.nc", "program.mpf")
DIALECTS = ("fanuc-m", "fanuc-t", "mazak-m", "siemens-iso-m", "siemens-din")


@dataclass
class Case:
    folder: Path
    name: str       # "<dialect>/<id>", the key of expected_failures.txt and of the ctest
    dialect: str
    program: Path
    machine: dict   # the [machine] table
    start: dict     # the [start] table
    expect: dict    # the [expect] table

    @property
    def start_position(self):
        return {k: float(v) for k, v in self.start.get("position", {}).items()}

    @property
    def tolerance(self):
        return float(self.expect.get("tolerance", 0.001))


def load(folder):
    folder = Path(folder).resolve()
    path = folder / "case.toml"
    try:
        with open(path, "rb") as f:
            data = tomllib.load(f)
    except (OSError, tomllib.TOMLDecodeError) as e:
        raise CaseError(f"{path}: {e}") from None
    for key in ("dialect", "machine", "start", "expect"):
        if key not in data:
            raise CaseError(f"{path}: no '{key}'")
    dialect = data["dialect"]
    if dialect not in DIALECTS:
        raise CaseError(f"{path}: unknown dialect {dialect!r}")
    if folder.parent.name != dialect:
        raise CaseError(f"{path}: dialect {dialect!r} but the case sits in {folder.parent.name}/")
    programs = [folder / n for n in PROGRAM_NAMES if (folder / n).is_file()]
    if len(programs) != 1:
        raise CaseError(f"{folder}: needs exactly one of {', '.join(PROGRAM_NAMES)}")
    expect = data["expect"]
    if not any(k in expect for k in ("moves", "final", "vars", "alarm")):
        raise CaseError(f"{path}: [expect] states nothing to compare")
    return Case(folder=folder, name=f"{dialect}/{folder.name}", dialect=dialect, program=programs[0],
                machine=data["machine"], start=data["start"], expect=expect)


def find_cases(root):
    """Every case folder under `root`, sorted by name."""
    return sorted(p.parent for p in Path(root).glob("*/*/case.toml"))
