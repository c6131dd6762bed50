#!/usr/bin/env python3
"""The documentation cannot drift: every `ncc` command shown in README.md and docs/*.md is run
and its output compared.

Run by ctest as: test_docs.py NCC_BINARY REPO_ROOT

Conventions (docs/testing.md, "Documentation tests"):
- A fenced block tagged `console` is a transcript. A line `$ COMMAND` is run by bash in a
  scratch folder that holds a copy of the repository's `examples/` (so `examples/x.nc` works),
  with `ncc` on PATH. The lines up to the next `$` line are its expected output, stdout and
  stderr together (the test accepts stderr before or after stdout, since they are separate
  streams). A line `...` matches any number of lines. The command must exit 0 unless it ends
  with a comment `# exit N`.
- Every other line of a fenced block that starts with `ncc ` is a synopsis: each `--option` in
  it must be an option of that command (`ncc COMMAND --help`).
- Every `--option` named anywhere in docs/cli.md must be an option of some command.
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile
import unittest

NCC = None
ROOT = None
COMMANDS = ("compile", "check", "dis", "run", "trace", "plot")

FENCE = re.compile(r"^```(\S*)\s*$")
EXIT_COMMENT = re.compile(r"\s+#\s*exit\s+(\d+)\s*$")
OPTION = re.compile(r"(?<![\w-])(--[a-z][a-z0-9-]*)")


def doc_files():
    files = [os.path.join(ROOT, "README.md")]
    docs = os.path.join(ROOT, "docs")
    files += sorted(os.path.join(docs, f) for f in os.listdir(docs) if f.endswith(".md"))
    return files


def fenced_blocks(path):
    """(info string, first line number, lines) of every fenced block of a Markdown file."""
    blocks, info, start, lines = [], None, 0, []
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            line = line.rstrip("\n")
            match = FENCE.match(line)
            if info is None and match:
                info, start, lines = match.group(1), number + 1, []
            elif info is not None and line.strip() == "```":
                blocks.append((info, start, lines))
                info = None
            elif info is not None:
                lines.append(line)
    return blocks


def transcript_steps(lines):
    """[(command, expected exit code, expected output lines)] of a console block."""
    steps = []
    for line in lines:
        if line.startswith("$ "):
            command = line[2:]
            code = 0
            match = EXIT_COMMENT.search(command)
            if match:
                code = int(match.group(1))
                command = command[: match.start()]
            steps.append((command, code, []))
        elif steps:
            steps[-1][2].append(line)
    return steps


def matches(expected, actual):
    """Line-wise comparison where a line `...` in `expected` matches any run of lines."""
    if not expected:
        return not actual
    if expected[0] == "...":
        return any(matches(expected[1:], actual[i:]) for i in range(len(actual) + 1))
    return bool(actual) and expected[0] == actual[0] and matches(expected[1:], actual[1:])


def lines_of(text):
    return [line.rstrip() for line in text.rstrip("\n").split("\n")] if text.strip() else []


_help_cache = {}


def help_options(command):
    """The options `ncc COMMAND --help` lists ("" for ncc itself: --version)."""
    if command not in _help_cache:
        args = [NCC, command, "--help"] if command else [NCC, "--help"]
        proc = subprocess.run(args, capture_output=True, text=True, timeout=30)
        _help_cache[command] = set(OPTION.findall(proc.stdout)) | {"--help"}
    return _help_cache[command]


class DocsTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        shutil.copytree(os.path.join(ROOT, "examples"), os.path.join(self.tmp.name, "examples"))
        self.env = dict(os.environ)
        self.env["PATH"] = os.path.dirname(os.path.abspath(NCC)) + os.pathsep + self.env["PATH"]

    def tearDown(self):
        self.tmp.cleanup()

    def test_transcripts(self):
        ran = 0
        for path in doc_files():
            name = os.path.relpath(path, ROOT)
            for info, start, lines in fenced_blocks(path):
                if info != "console":
                    continue
                for command, code, expected in transcript_steps(lines):
                    with self.subTest(doc=name, line=start, command=command):
                        proc = subprocess.run(["bash", "-c", command], cwd=self.tmp.name,
                                              env=self.env, capture_output=True, text=True,
                                              timeout=300)
                        out, err = lines_of(proc.stdout), lines_of(proc.stderr)
                        self.assertEqual(proc.returncode, code, f"{name}:{start}: {command}\n{proc.stderr}")
                        self.assertTrue(matches(expected, err + out) or matches(expected, out + err),
                                        f"{name}:{start}: `{command}` printed\n"
                                        + "\n".join(out + err) + "\n--- documented:\n"
                                        + "\n".join(expected))
                    ran += 1
        self.assertGreater(ran, 5, "the docs show fewer transcripts than expected")

    def test_synopsis_options_exist(self):
        for path in doc_files():
            name = os.path.relpath(path, ROOT)
            for info, start, lines in fenced_blocks(path):
                if info == "console":
                    continue
                for offset, line in enumerate(lines):
                    words = line.split()
                    if len(words) < 2 or words[0] != "ncc":
                        continue
                    command = words[1] if words[1] in COMMANDS else ""
                    known = help_options(command)
                    for option in OPTION.findall(line):
                        self.assertIn(option, known,
                                      f"{name}:{start + offset}: {option} is not an option of ncc {words[1]}")

    def test_every_option_in_cli_md_exists(self):
        known = set()
        for command in ("",) + COMMANDS:
            known |= help_options(command)
        with open(os.path.join(ROOT, "docs", "cli.md"), encoding="utf-8") as f:
            text = f.read()
        for option in sorted(set(OPTION.findall(text))):
            self.assertIn(option, known, f"docs/cli.md names {option}, which no ncc command has")


if __name__ == "__main__":
    NCC = sys.argv.pop(1)
    ROOT = sys.argv.pop(1)
    unittest.main()
