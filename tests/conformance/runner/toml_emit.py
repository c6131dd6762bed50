"""A small TOML writer for the value types conformance cases use.

The runner hands `ncc run` a machine file made of a case's [machine] and [start] tables.
tomllib only reads TOML, so this writes it back: strings, integers, floats, booleans, arrays,
inline tables and nested tables. Integers stay integers and floats stay floats (toml++ keeps
the distinction), so `tomllib.loads(dumps(d)) == d` for every case (a unit test checks it).
"""
import json
import math
import re

_BARE_KEY = re.compile(r"^[A-Za-z0-9_-]+$")


def _key(key):
    return key if _BARE_KEY.match(key) else json.dumps(key, ensure_ascii=False)


def _float(value):
    if math.isnan(value):
        return "nan"
    if math.isinf(value):
        return "inf" if value > 0 else "-inf"
    # repr gives the shortest text that reads back as the same double; "1e-05" is valid TOML.
    text = repr(value)
    return text if any(c in text for c in ".eEn") else text + ".0"


def value(v):
    """One TOML value, written inline."""
    if isinstance(v, bool):  # before int: bool is an int in Python
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        return _float(v)
    if isinstance(v, str):
        # JSON string escapes (\" \\ \n \t \uXXXX) are all valid TOML basic-string escapes.
        return json.dumps(v, ensure_ascii=False)
    if isinstance(v, list):
        return "[" + ", ".join(value(x) for x in v) + "]"
    if isinstance(v, dict):
        if not v:
            return "{}"
        return "{ " + ", ".join(f"{_key(k)} = {value(x)}" for k, x in v.items()) + " }"
    raise TypeError(f"cannot write a {type(v).__name__} as TOML: {v!r}")


def _table(path, table, out):
    """A [section] with its plain keys; dict children become [path.child] sub-sections."""
    out.append("[" + ".".join(_key(p) for p in path) + "]")
    children = []
    for k, v in table.items():
        if isinstance(v, dict) and len(path) == 1:
            children.append((k, v))
        else:
            out.append(f"{_key(k)} = {value(v)}")
    for k, v in children:
        _table(path + [k], v, out)


def dumps(tables):
    """A TOML document of top-level tables: {"machine": {...}, "start": {...}}.

    Tables directly below a top-level table are written as sub-sections ([machine.offsets]),
    deeper ones inline, as the cases themselves write them.
    """
    out = []
    for name, table in tables.items():
        if not isinstance(table, dict):
            raise TypeError(f"top-level entry {name!r} is not a table")
        _table([name], table, out)
        out.append("")
    return "\n".join(out)
