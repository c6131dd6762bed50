#!/usr/bin/env python3
"""Checks that an imported copy of a shared/ folder is identical to its source.

    sync_check.py --copy tests/conformance --shared ../shared/conformance \
                  --own CMakeLists.txt run_case.py sync_check.py expected_failures.txt runner selftest

Every file under --shared must exist in --copy with the same bytes, and the copy must hold no
other file except the project's own top-level entries named by --own (scripts, CMake files;
a named folder is skipped whole). Exit 0 in sync, 1 with the list of differences and the
command that re-imports, 77 (ctest SKIP) when --shared does not exist (a checkout without
shared/ beside it).
"""
import argparse
import filecmp
import sys
from pathlib import Path

SKIP = 77
IGNORED_NAMES = {"__pycache__", ".DS_Store"}


def files_under(root, own=()):
    out = set()
    for p in root.rglob("*"):
        rel = p.relative_to(root)
        if rel.parts[0] in own or IGNORED_NAMES.intersection(rel.parts) or not p.is_file():
            continue
        out.add(rel.as_posix())
    return out


def main(argv):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--copy", required=True, type=Path)
    p.add_argument("--shared", required=True, type=Path)
    p.add_argument("--own", nargs="*", default=[], help="top-level entries of the copy that are the project's")
    args = p.parse_args(argv)

    if not args.shared.is_dir():
        print(f"SKIP: {args.shared} does not exist (no shared/ beside this checkout); nothing to compare")
        return SKIP
    shared = files_under(args.shared)
    copy = files_under(args.copy, set(args.own))
    missing = sorted(shared - copy)
    extra = sorted(copy - shared)
    changed = sorted(f for f in shared & copy if not filecmp.cmp(args.shared / f, args.copy / f, shallow=False))
    if not (missing or extra or changed):
        print(f"in sync: {len(shared)} files of {args.shared} match {args.copy}")
        return 0
    for label, names in (("missing from the copy", missing), ("only in the copy", extra), ("differ", changed)):
        for name in names:
            print(f"{label}: {name}")
    print(f"\n{args.copy} is out of sync with {args.shared} "
          f"({len(missing)} missing, {len(extra)} extra, {len(changed)} changed). Re-import: "
          f"cp -r {args.shared}/. {args.copy}/ and delete the files only in the copy.")
    return 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
