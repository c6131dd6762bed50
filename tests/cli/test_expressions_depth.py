#!/usr/bin/env python3
"""Hostile expression depth (issue 31, case 1) through the ncc CLI: a 20,000-term chain of
`+`, `*` or `EQ` (in an assignment or an IF condition) and 20,000 nested brackets are refused
by every command with a program error at file:line:column (NCC1017: deeper than 256 levels,
docs/macro.md "Expression depth"; NCC1016 for brackets, 64 levels), never a crash, and
`ncc compile` leaves no temporary file behind. A chain exactly 256 deep is read and computed.

Run by ctest as: test_expressions_depth.py NCC_BINARY
"""
import json
import os
import re
import sys
import unittest

from cli_harness import ScratchDirTest, run_ncc

NCC = None
LIMIT = 256  # ast::kMaxExprDepth
HOSTILE = 20000
DIAGNOSTIC = re.compile(r"^(?P<file>.+):(?P<line>\d+):(?P<col>\d+): error\[(?P<code>[^\]]+)\]: (?P<message>.*)$")
DEPTH_MESSAGE = (f"expression nested deeper than {LIMIT} levels "
                 "(each operator, sign, bracket and function is one)")


def ncc(*args, cwd=None):
    return run_ncc(NCC, args, cwd=cwd, timeout=120)


def chain(terms, op, term="1"):
    return op.join([term] * terms)


# name: (line 2 of the program, column where it is refused, code, message)
CASES = {
    # '#1=' is columns 1-3: the k-th '+' is at 3 + 2k; the 256th makes the tree 257 deep.
    "plus": ("#1=" + chain(HOSTILE, "+"), 3 + 2 * LIMIT, "NCC1017", DEPTH_MESSAGE),
    "star": ("#1=" + chain(HOSTILE, "*"), 3 + 2 * LIMIT, "NCC1017", DEPTH_MESSAGE),
    "eq": ("#1=" + chain(HOSTILE, "EQ"), 2 + 3 * LIMIT, "NCC1017", DEPTH_MESSAGE),
    "if": ("IF[" + chain(HOSTILE, "EQ") + "]GOTO5", 2 + 3 * LIMIT, "NCC1017", DEPTH_MESSAGE),
    # Brackets are refused before parsing at the 65th '['.
    "brackets": ("G0X" + "[" * HOSTILE + "1" + "]" * HOSTILE, 3 + 65, "NCC1016",
                 "brackets nested deeper than 64 levels"),
}


class ExpressionDepthTest(ScratchDirTest):
    def program(self, name, line):
        return self.write(name, f"G90\n{line}\nN5 M30\n")

    def assert_refused(self, proc, name, prog, col, code, message):
        what = f"{name}: exit {proc.returncode}\n{proc.stderr[:2000]}"
        self.assertGreaterEqual(proc.returncode, 0, "killed by a signal: " + what)
        self.assertEqual(proc.returncode, 1, what)
        found = [m.groupdict() for m in map(DIAGNOSTIC.match, proc.stderr.splitlines()) if m]
        self.assertTrue(found, what)
        first = found[0]
        self.assertEqual((os.path.basename(first["file"]), first["line"], first["col"], first["code"]),
                         (os.path.basename(prog), "2", str(col), code), what)
        self.assertEqual(first["message"], message, what)
        self.assertLess(len(proc.stderr), 5000, "the diagnostic quotes a cut line")

    def assert_no_temporaries(self):
        left = [f for f in os.listdir(self.dir) if ".ncb." in f or f.endswith(".ncb")]
        self.assertEqual(left, [], "compile left files behind")

    def test_hostile_depth_is_refused_by_every_command(self):
        for name, (line, col, code, message) in CASES.items():
            with self.subTest(name):
                prog = self.program(f"{name}.nc", line)
                self.assert_refused(ncc("check", prog), name, prog, col, code, message)
                self.assert_refused(ncc("compile", prog, "-o", self.path(f"{name}.ncb")),
                                    name, prog, col, code, message)
                self.assert_no_temporaries()
                self.assert_refused(ncc("compile", prog), name, prog, col, code, message)
                self.assert_no_temporaries()
                self.assert_refused(ncc("compile", prog, "--emit=ast", "-o", self.path("ast.txt")),
                                    name, prog, col, code, message)
                self.assertFalse(os.path.exists(self.path("ast.txt")))
                self.assert_refused(ncc("run", prog), name, prog, col, code, message)
                self.assert_refused(ncc("run", prog, "--emit=vars"), name, prog, col, code, message)
                os.remove(prog)

    def test_a_chain_at_the_limit_is_computed(self):
        # Left to right as written: 1000-1-1-... is 1000 - 255, not an alternating sum.
        prog = self.write("limit.nc", "\n".join([
            "#100=" + chain(LIMIT, "+"),
            "#101=3" + "*1" * (LIMIT - 1),
            "#102=1000" + "-1" * (LIMIT - 1),
            "#103=" + chain(LIMIT, "EQ"),
            "#104=0",
            "IF[" + chain(LIMIT, "EQ") + "]THEN#104=7",
            "#105=[[" + chain(LIMIT - 2, "+", "0.5") + "]]",
            "M30", ""]))
        out = self.path("vars.json")
        proc = ncc("run", prog, "--emit=vars", "-o", out)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        with open(out) as f:
            got = json.load(f)
        self.assertEqual(got, {"#100": float(LIMIT), "#101": 3.0, "#102": 1000.0 - (LIMIT - 1),
                               "#103": 1.0, "#104": 7.0, "#105": 0.5 * (LIMIT - 2)})
        # Deferred, the blocks travel in the block store (nested 257 deep with the statement)
        # and the VM evaluates them: the same values.
        proc = ncc("run", prog, "--defer", "--emit=vars")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual(json.loads(proc.stdout), got)
        for command in (["check", prog], ["compile", prog, "-o", self.path("limit.ncb")]):
            proc = ncc(*command)
            self.assertEqual(proc.returncode, 0, proc.stderr)
        proc = ncc("compile", prog, "--emit=ast")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertIn("#100=" + "[" * (LIMIT - 1) + "1+1]+1]", proc.stdout)
        # One term more is refused at its last operator.
        over = self.write("over.nc", "G90\n#100=" + chain(LIMIT + 1, "+") + "\nM30\n")
        self.assert_refused(ncc("check", over), "over", over, 5 + 2 * LIMIT, "NCC1017", DEPTH_MESSAGE)


if __name__ == "__main__":
    NCC = sys.argv.pop(1)
    unittest.main(verbosity=2)
