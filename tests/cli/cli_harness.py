"""What the CLI tests share: a scratch folder per test, files written into it, and running
a command both ways, ahead of time and with --defer (`run_ncc`, NCC_TEST_DEFER=1).

Each test script is run by ctest as `test_x.py NCC_BINARY [...]` and keeps its own `ncc()`
(timeouts and text mode differ); the macro and subprogram tests' `ncc()` call `run_ncc`.
"""
import json
import os
import re
import subprocess
import tempfile
import unittest


class ScratchDirTest(unittest.TestCase):
    """A test case with a fresh temporary folder, `self.dir`, removed after each test."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name

    def tearDown(self):
        self.tmp.cleanup()

    def path(self, name):
        return os.path.join(self.dir, name)

    def write(self, name, data, mode=None):
        """Writes `data` (text, or bytes) to `name` in the scratch folder; returns its path."""
        path = self.path(name)
        with open(path, mode or ("wb" if isinstance(data, (bytes, bytearray)) else "w")) as f:
            f.write(data)
        return path


# ---- both ways: ahead of time and with --defer ------------------------------------------------
#
# With NCC_TEST_DEFER=1 in the environment, run_ncc() runs every command a second time with
# --defer (the VM prepares every block while the program runs, docs/runtime.md) and requires
# the same result; it returns the plain run, so a test's own assertions are unchanged. ctest
# runs the macro and subprogram test files once plainly and once so (cli_*_deferred).

DEFER_ENV = "NCC_TEST_DEFER"

# Diagnostic header lines. Notes (note[NCC0023]: where the VM takes over) are left out of the
# comparison: a deferred run prints none.
_DIAGNOSTIC = re.compile(r"^(?:.+:\d+:\d+|ncc): (?P<severity>error|warning|note)\[(?P<code>[^\]]+)\]: ")
# The output option of run/compile/check.
_OUTPUT_OPTIONS = ("-o", "--output")


def deferred_both_ways():
    return os.environ.get(DEFER_ENV) == "1"


def diagnostic_lines(stderr):
    """stderr without note diagnostics (their header and the source line and caret quoted under
    them): the errors, warnings and alarms, each with its quoted line."""
    kept, in_note = [], False
    for line in stderr.splitlines():
        m = _DIAGNOSTIC.match(line)
        if m:
            in_note = m["severity"] == "note"
        elif not line.startswith(" "):
            in_note = False
        if not in_note:
            kept.append(line)
    return kept


def _option_value(args, names):
    """(index of the value, value) of the last -o/--output in args, or (None, None)."""
    found = (None, None)
    for i, a in enumerate(args):
        if a in names and i + 1 < len(args):
            found = (i + 1, args[i + 1])
        for n in names:
            if n.startswith("--") and a.startswith(n + "="):
                found = (i, a[len(n) + 1:])
    return found


def _with_value(args, index, value):
    """args with the option value at `index` (a separate argument or `--opt=value`) replaced."""
    args = list(args)
    if "=" in args[index] and args[index].startswith("--"):
        args[index] = args[index].split("=", 1)[0] + "=" + value
    else:
        args[index] = value
    return args


def _read(path):
    try:
        with open(path, "rb") as f:
            return f.read()
    except OSError:
        return None


def _restore(path, data):
    if data is None:
        if os.path.exists(path):
            os.remove(path)
    else:
        with open(path, "wb") as f:
            f.write(data)


def _mismatch(what, args, plain, deferred, extra=""):
    return AssertionError(
        f"--defer changes {what} of `ncc {' '.join(args)}`{extra}\n"
        f"--- plain: exit {plain.returncode}\nstdout:\n{plain.stdout}\nstderr:\n{plain.stderr}\n"
        f"--- with --defer: exit {deferred.returncode}\nstdout:\n{deferred.stdout}\n"
        f"stderr:\n{deferred.stderr}")


def move_list(stdout):
    """The moves of `ncc run --emit=moves` output (one JSON object per line)."""
    return [json.loads(line) for line in stdout.splitlines() if line.strip()]


def run_ncc(ncc_path, args, cwd=None, timeout=120, stdin=None):
    """Runs `ncc ARGS` (text mode) and returns the CompletedProcess; with NCC_TEST_DEFER=1 also
    checks the command gives the same with --defer (raises AssertionError with both outputs):
      - run of a source program (not a .ncb): the same exit code, stdout, -o file and errors
        and warnings on stderr; a --vars file ends as the plain run left it;
      - compile/check that succeed: they succeed with --defer, check with the same stdout
        (unless it prints the IR, --print-after: deferred, that is PREPARE and the store).
    """
    def call(argv):
        return subprocess.run([ncc_path, *argv], capture_output=True, text=True, errors="replace",
                              timeout=timeout, cwd=cwd, input=stdin)

    def at(path):
        return path if cwd is None or os.path.isabs(path) else os.path.join(cwd, path)

    args = [str(a) for a in args]
    command = args[0] if args else ""
    if not deferred_both_ways() or "--defer" in args or command not in ("run", "compile", "check"):
        return call(args)
    out_index, out = _option_value(args, _OUTPUT_OPTIONS)
    if command == "run" and any(a.lower().endswith(".ncb") for i, a in enumerate(args) if i != out_index):
        return call(args)  # a bytecode file: nothing is prepared from source
    vars_index, vars_file = _option_value(args, ("--vars",))
    vars_before = _read(at(vars_file)) if vars_file else None

    plain = call(args)
    if command != "run" and plain.returncode != 0:
        return plain

    # The deferred run writes its -o file into a folder of its own (same name: the extension
    # chooses the format) and starts from the --vars file as the plain run found it.
    with tempfile.TemporaryDirectory(prefix="ncc-defer-") as tmp:
        deferred_args = list(args)
        deferred_out = None
        if out not in (None, "-"):
            deferred_out = os.path.join(tmp, os.path.basename(out) or "out")
            deferred_args = _with_value(deferred_args, out_index, deferred_out)
        elif out is None and command == "compile":
            deferred_args += ["-o", os.path.join(tmp, "deferred.ncb")]  # not over IN.ncb
        vars_after = None
        if vars_file:
            vars_after = _read(at(vars_file))
            _restore(at(vars_file), vars_before)
        # Right after the command: after the input, a repeatable option before it (--probe
        # Z=-8 IN) would take IN as its value once a flag follows.
        deferred = call(deferred_args[:1] + ["--defer"] + deferred_args[1:])
        if vars_file:
            vars_deferred = _read(at(vars_file))
            _restore(at(vars_file), vars_after)

        if command in ("compile", "check"):
            if deferred.returncode != 0:
                raise _mismatch("the exit code", args, plain, deferred)
            # The IR (--print-after) differs by design: deferred, it is PREPARE and the store.
            prints_ir = any(a.startswith("--print-after") for a in args)
            if command == "check" and not prints_ir and deferred.stdout != plain.stdout:
                raise _mismatch("stdout", args, plain, deferred)
            return plain
        if deferred.returncode != plain.returncode:
            raise _mismatch("the exit code", args, plain, deferred)
        if deferred.stdout != plain.stdout:
            raise _mismatch("stdout", args, plain, deferred)
        if diagnostic_lines(deferred.stderr) != diagnostic_lines(plain.stderr):
            raise _mismatch("the diagnostics", args, plain, deferred)
        if deferred_out is not None and _read(deferred_out) != _read(at(out)):
            raise _mismatch(f"the -o file {out}", args, plain, deferred,
                            f"\n--- plain {out}:\n{_read(at(out))!r}\n--- deferred:\n{_read(deferred_out)!r}")
        if vars_file and vars_deferred != vars_after:
            raise _mismatch(f"the --vars file {vars_file}", args, plain, deferred,
                            f"\n--- plain:\n{vars_after!r}\n--- deferred:\n{vars_deferred!r}")
    return plain
