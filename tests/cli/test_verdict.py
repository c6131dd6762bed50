#!/usr/bin/env python3
"""`ncc run` gives one verdict whatever it emits; outputs never replace inputs or leave debris;
the command line's stdin/stdout, --version, error codes and progress display (issue 21).

Run by ctest as: test_verdict.py NCC_BINARY
"""
import concurrent.futures
import glob
import json
import os
import pty
import re
import select
import signal
import subprocess
import sys
import tempfile
import time
import unittest

from cli_harness import ScratchDirTest

NCC = None
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "tests", "conformance"))

GOOD = "N10 G90 G00 X10. Y5.\nN20 G01 Z-2. F100.\nN30 G02 X20. Y5. R5.\nN40 G04 X1.5\nN50 M30\n"
# G95 with the spindle stopped: the executor alone accepts it, the planner raises NCC7207.
G95 = "G21 G90 G17\nG01 X5. F600.\nG95 G01 X10. F0.1\nM30\n"
# 6 mm of following error at F6000 without feed-forward: over a 0.5 mm CONTOUR_TOL (25050).
SERVO_PROGRAM = "G21 G90 G17\nG01 Y100. F6000.\nG01 Y0.\nM30\n"
SERVO_MACHINE = """[machine]
axes = ["X", "Y", "Z"]
[machine.axis.Y]
ffw_mode = "none"
contour_tol = 0.5
[start]
position = { X = 0.0, Y = 0.0, Z = 0.0 }
"""
# 200 mm at 1 mm/min: 200 minutes of program time, a few seconds of simulation.
LONG = "G21 G90 G17 G94\nG01 X200. F1.\nM30\n"

ERROR_CODE_RE = re.compile(r"error\[([^\]]+)\]")
MODES = ("summary", "trace", "moves", "vars")


def ncc(*args, cwd=None, stdin=None, text=True, timeout=120):
    return subprocess.run([NCC, *args], capture_output=True, text=text, timeout=timeout, cwd=cwd,
                          input=stdin)


def first_error_code(stderr):
    match = ERROR_CODE_RE.search(stderr)
    return match.group(1) if match else None


def read_jsonl(path):
    with open(path, "rb") as f:
        return [json.loads(line.decode("utf-8")) for line in f.read().splitlines()]


def leftovers(folder, keep):
    """Files in `folder` other than those named in `keep` (temporary outputs left behind)."""
    return sorted(set(os.listdir(folder)) - set(keep))


# --- every golden and conformance program in every mode -------------------------------------

def golden_programs():
    """(name, program, extra args) of every example program the golden tests run."""
    found = []
    for program in sorted(glob.glob(os.path.join(ROOT, "examples", "*.nc"))):
        name = os.path.splitext(os.path.basename(program))[0]
        args = []
        args_file = os.path.join(ROOT, "tests", "golden", name + ".args")
        if os.path.exists(args_file):
            with open(args_file) as f:
                args += f.read().split()
        machine = os.path.splitext(program)[0] + ".toml"
        if os.path.exists(machine):
            args += ["--machine", machine]
        found.append((f"golden/{name}", program, args))
    return found


def conformance_programs(machine_dir):
    """(name, program, extra args) of every conformance case, its machine file written out."""
    from runner import case as case_module, run as run_module
    found = []
    for folder in case_module.find_cases(os.path.join(ROOT, "tests", "conformance")):
        case = case_module.load(folder)
        machine = os.path.join(machine_dir, case.name.replace("/", "__") + ".toml")
        with open(machine, "w") as f:
            f.write(run_module.machine_file_text(case))
        found.append((case.name, str(case.program),
                      ["--dialect", case.dialect, "--machine", machine, "--program-dir", str(case.folder)]))
    return found


# In the instrumented CI stage (.ci/run sets NCC_TEST_SANITIZED) every third golden and
# conformance program, each in every mode; the release stage runs them all.
SAMPLE = 3 if os.environ.get("NCC_TEST_SANITIZED") else 1


def verdicts(name, program, args, out_dir):
    """Exit code and first error code of the program in each output mode, and what each wrote."""
    base = os.path.join(out_dir, name.replace("/", "__"))
    outputs = {"summary": None, "trace": base + ".csv", "moves": base + ".jsonl", "vars": base + ".json"}
    results = {}
    for mode in MODES:
        command = ["run", program, f"--emit={mode}", *args]
        if outputs[mode]:
            command += ["-o", outputs[mode]]
        proc = subprocess.run([NCC, *command], capture_output=True, text=True, errors="replace",
                              timeout=120)
        results[mode] = (proc.returncode, first_error_code(proc.stderr) if proc.returncode else None)
    return name, results, outputs


class OneVerdictTest(unittest.TestCase):
    def test_every_golden_and_conformance_program_gives_one_verdict_in_every_mode(self):
        with tempfile.TemporaryDirectory() as tmp:
            programs = golden_programs() + conformance_programs(tmp)
            self.assertGreater(len(programs), 100)
            programs = programs[::SAMPLE]
            # The golden and conformance programs stop at compile time or not at all; the two
            # reproducers of issue 21 add the run-time alarms (planner and servo).
            for name, text, machine in (("g95", G95, None), ("servo", SERVO_PROGRAM, SERVO_MACHINE)):
                program = os.path.join(tmp, name + ".nc")
                with open(program, "w") as f:
                    f.write(text)
                args = []
                if machine:
                    args = ["--machine", os.path.join(tmp, name + ".toml")]
                    with open(args[1], "w") as f:
                        f.write(machine)
                programs.append((f"issue21/{name}", program, args))
            alarms = compile_errors = 0
            with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
                jobs = [pool.submit(verdicts, name, program, args, tmp) for name, program, args in programs]
                for job in jobs:
                    name, results, outputs = job.result()
                    first = results["summary"]
                    for mode in MODES:
                        self.assertEqual(results[mode], first, f"{name}: {mode} {results[mode]} but summary {first}")
                        self.assertGreaterEqual(results[mode][0], 0, f"{name}: {mode} crashed")
                    code, alarm = first
                    if code == 3:
                        alarms += 1
                        records = read_jsonl(outputs["moves"])
                        self.assertEqual(records[-1]["kind"], "alarm", name)
                        self.assertEqual(records[-1]["code"], alarm, name)
                        self.assertTrue(all(r["kind"] != "alarm" for r in records[:-1]), name)
                        self.assertFalse(os.path.exists(outputs["vars"]), name)
                        self.assertTrue(os.path.exists(outputs["trace"]), name)
                    elif code == 1:
                        compile_errors += 1
                    elif code == 0:
                        self.assertTrue(all(r["kind"] != "alarm" for r in read_jsonl(outputs["moves"])), name)
                        with open(outputs["vars"]) as f:
                            self.assertIsInstance(json.load(f), dict)
                    for path in outputs.values():
                        if path and os.path.exists(path):
                            os.remove(path)
            self.assertGreaterEqual(alarms, 2)
            self.assertGreater(compile_errors, 0)
            inputs = [n for n in os.listdir(tmp) if n.endswith((".toml", ".nc"))]
            self.assertEqual(leftovers(tmp, inputs), [])


class VerdictTest(ScratchDirTest):
    def test_g95_without_spindle_is_the_same_alarm_in_every_mode(self):
        prog = self.write("g95.nc", G95)
        out = os.path.join(self.dir, "m.jsonl")
        proc = ncc("run", prog, "--emit=moves", "-o", out)
        self.assertEqual(proc.returncode, 3, proc.stderr)
        self.assertIn("g95.nc:3:1: error[NCC7207]", proc.stderr)
        records = read_jsonl(out)
        # The move before the alarm stays; the file ends with the alarm.
        self.assertEqual([r["kind"] for r in records], ["line", "alarm"])
        self.assertEqual(records[0]["to"]["X"], 5.0)
        self.assertEqual(records[1]["code"], "NCC7207")
        self.assertEqual(records[1]["line"], 3)
        self.assertEqual(records[1]["file"], "g95.nc")
        self.assertIn("spindle stopped", records[1]["message"])
        self.assertEqual(set(records[1]), {"kind", "code", "line", "file", "message"})
        for args in (["--emit=summary"], ["--emit=trace", "-o", os.path.join(self.dir, "t.csv")],
                     ["--emit=vars", "-o", os.path.join(self.dir, "v.json")], ["--emit=moves"]):
            proc = ncc("run", prog, *args)
            self.assertEqual(proc.returncode, 3, args)
            self.assertEqual(first_error_code(proc.stderr), "NCC7207", args)
        self.assertFalse(os.path.exists(os.path.join(self.dir, "v.json")))
        self.assertTrue(os.path.exists(os.path.join(self.dir, "t.csv")))
        self.assertEqual(leftovers(self.dir, ["g95.nc", "m.jsonl", "t.csv"]), [])

    def test_servo_alarm_is_raised_in_moves_and_vars_too(self):
        prog = self.write("servo.nc", SERVO_PROGRAM)
        machine = self.write("servo.toml", SERVO_MACHINE)
        for mode in MODES:
            out = os.path.join(self.dir, "out." + ("csv" if mode == "trace" else "txt"))
            proc = ncc("run", prog, "--machine", machine, f"--emit={mode}", "-o", out)
            self.assertEqual(proc.returncode, 3, f"{mode}: {proc.stderr}")
            self.assertIn("servo.nc:2:1: error[25050]", proc.stderr, mode)
            if mode == "moves":
                records = read_jsonl(out)
                self.assertEqual(records[0]["kind"], "line")
                self.assertEqual(records[-1]["kind"], "alarm")
                self.assertEqual(records[-1]["code"], "25050")
                self.assertEqual(records[-1]["line"], 2)
            if mode == "summary":
                with open(out) as f:
                    self.assertIn("status             alarm 25050", f.read())
            if os.path.exists(out):
                os.remove(out)

    def test_moves_to_stdout_end_with_the_alarm_record(self):
        prog = self.write("g95.nc", G95)
        proc = ncc("run", prog, "--emit=moves")
        self.assertEqual(proc.returncode, 3)
        last = json.loads(proc.stdout.splitlines()[-1])
        self.assertEqual(last["kind"], "alarm")
        self.assertEqual(last["code"], "NCC7207")

    # --- nothing lost ---------------------------------------------------------------------

    def test_output_never_replaces_the_program(self):
        prog = self.write("good.nc", GOOD)
        for args in (["run", prog, "--emit=moves", "-o", prog],
                     ["run", prog, "-o", prog],
                     ["compile", prog, "--emit=ir", "-o", prog],
                     ["compile", prog, "-o", prog]):
            proc = ncc(*args)
            self.assertEqual(proc.returncode, 2, args)
            self.assertIn("error[NCC0005]", proc.stderr, args)
            with open(prog) as f:
                self.assertEqual(f.read(), GOOD, args)
        self.assertEqual(leftovers(self.dir, ["good.nc"]), [])

    def test_output_is_compared_by_identity_not_by_name(self):
        prog = self.write("good.nc", GOOD)
        link = os.path.join(self.dir, "alias.nc")
        os.link(prog, link)
        sym = os.path.join(self.dir, "sym.jsonl")
        os.symlink(prog, sym)
        sub = os.path.join(self.dir, "sub")
        os.mkdir(sub)
        for out in (link, sym, os.path.join(sub, "..", "good.nc")):
            proc = ncc("run", prog, "--emit=moves", "-o", out)
            self.assertEqual(proc.returncode, 2, out)
            self.assertIn("error[NCC0005]", proc.stderr)
            with open(prog) as f:
                self.assertEqual(f.read(), GOOD)

    def test_output_never_replaces_the_bytecode_or_the_machine_file(self):
        prog = self.write("good.nc", GOOD)
        ncb = os.path.join(self.dir, "good.ncb")
        self.assertEqual(ncc("compile", prog, "-o", ncb).returncode, 0)
        with open(ncb, "rb") as f:
            before = f.read()
        proc = ncc("run", ncb, "--emit=moves", "-o", ncb)
        self.assertEqual(proc.returncode, 2)
        self.assertIn("error[NCC0005]", proc.stderr)
        with open(ncb, "rb") as f:
            self.assertEqual(f.read(), before)
        machine = self.write("m.toml", SERVO_MACHINE)
        for args in (["run", prog, "--machine", machine, "--emit=vars", "-o", machine],
                     ["compile", prog, "--machine", machine, "-o", machine]):
            proc = ncc(*args)
            self.assertEqual(proc.returncode, 2, args)
            self.assertIn("error[NCC0005]", proc.stderr)
            with open(machine) as f:
                self.assertEqual(f.read(), SERVO_MACHINE)

    def test_a_users_tmp_file_is_never_touched(self):
        prog = self.write("good.nc", GOOD)
        mine = self.write("OUT.jsonl.tmp", "my notes\n")
        ncb_tmp = self.write("good.ncb.tmp", "more notes\n")
        self.assertEqual(ncc("run", prog, "--emit=moves", "-o", os.path.join(self.dir, "OUT.jsonl")).returncode, 0)
        self.assertEqual(ncc("compile", prog).returncode, 0)
        bad = self.write("bad.nc", "G01 X1. Q@\n")
        self.assertEqual(ncc("compile", bad, "-o", os.path.join(self.dir, "good.ncb")).returncode, 1)
        with open(mine) as f:
            self.assertEqual(f.read(), "my notes\n")
        with open(ncb_tmp) as f:
            self.assertEqual(f.read(), "more notes\n")
        self.assertEqual(leftovers(self.dir, ["good.nc", "bad.nc", "OUT.jsonl", "OUT.jsonl.tmp", "good.ncb",
                                              "good.ncb.tmp"]), [])

    def test_a_new_output_gets_the_usual_permissions(self):
        prog = self.write("good.nc", GOOD)
        out = os.path.join(self.dir, "m.jsonl")
        self.assertEqual(ncc("run", prog, "--emit=moves", "-o", out).returncode, 0)
        mask = os.umask(0)
        os.umask(mask)
        self.assertEqual(os.stat(out).st_mode & 0o777, 0o666 & ~mask)

    def interrupted_run(self, sig):
        prog = self.write("long.nc", LONG)
        out = os.path.join(self.dir, "m.jsonl")
        proc = subprocess.Popen([NCC, "run", prog, "--emit=moves", "-o", out],
                                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        deadline = time.monotonic() + 30
        while not leftovers(self.dir, ["long.nc"]) and time.monotonic() < deadline and proc.poll() is None:
            time.sleep(0.01)
        temps = leftovers(self.dir, ["long.nc"])
        self.assertEqual(len(temps), 1, "the run made no temporary file")
        self.assertTrue(temps[0].startswith(".m.jsonl."), temps)
        self.assertIsNone(proc.poll(), "the run ended before the signal")
        proc.send_signal(sig)
        proc.wait(timeout=30)
        self.assertEqual(proc.returncode, -sig)
        self.assertEqual(leftovers(self.dir, ["long.nc"]), [])

    def test_sigint_removes_the_temporary_output(self):
        self.interrupted_run(signal.SIGINT)

    def test_sigterm_removes_the_temporary_output(self):
        self.interrupted_run(signal.SIGTERM)

    def test_an_ignored_hangup_stays_ignored(self):
        # nohup: a SIGHUP the caller ignores must not end the run.
        prog = self.write("long.nc", LONG)
        out = os.path.join(self.dir, "m.jsonl")
        proc = subprocess.Popen([NCC, "run", prog, "--emit=moves", "-o", out], stdout=subprocess.DEVNULL,
                                stderr=subprocess.DEVNULL,
                                preexec_fn=lambda: signal.signal(signal.SIGHUP, signal.SIG_IGN))
        deadline = time.monotonic() + 30
        while not leftovers(self.dir, ["long.nc"]) and time.monotonic() < deadline and proc.poll() is None:
            time.sleep(0.01)
        self.assertIsNone(proc.poll(), "the run ended before the signal")
        proc.send_signal(signal.SIGHUP)
        time.sleep(0.3)
        self.assertIsNone(proc.poll(), "an ignored SIGHUP ended the run")
        proc.send_signal(signal.SIGTERM)
        proc.wait(timeout=30)
        self.assertEqual(proc.returncode, -signal.SIGTERM)
        self.assertEqual(leftovers(self.dir, ["long.nc"]), [])

    def test_json_stays_valid_for_any_file_name(self):
        name = b'q"b\\s\x01t\x7f\xff\xc3(\xe2\x82\xac.nc'
        path = os.path.join(self.dir.encode(), name)
        with open(path, "wb") as f:
            f.write(GOOD.encode())
        out = os.path.join(self.dir, "m.jsonl")
        proc = subprocess.run([NCC.encode(), b"run", path, b"--emit=moves", b"-o", out.encode()],
                              capture_output=True)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        records = read_jsonl(out)  # strict UTF-8 and JSON
        self.assertEqual(len(records), 4)
        self.assertEqual(records[0]["file"], 'q"b\\s\x01t\x7f\ufffd\ufffd(\u20ac.nc')
        g95 = os.path.join(self.dir.encode(), b"\xfe\x01.nc")
        with open(g95, "wb") as f:
            f.write(G95.encode())
        proc = subprocess.run([NCC.encode(), b"run", g95, b"--emit=moves", b"-o", out.encode()],
                              capture_output=True)
        self.assertEqual(proc.returncode, 3)
        self.assertEqual(read_jsonl(out)[-1]["file"], "\ufffd\x01.nc")

    # --- the command line a user expects ----------------------------------------------------

    def test_version(self):
        proc = ncc("--version")
        self.assertEqual(proc.returncode, 0)
        self.assertRegex(proc.stdout.strip(), r"^ncc \d+\.\d+\.\d+$")

    def test_program_from_stdin_and_output_to_stdout(self):
        proc = ncc("run", "-", "--emit=moves", "-o", "-", stdin=GOOD)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        records = [json.loads(line) for line in proc.stdout.splitlines()]
        self.assertEqual(len(records), 4)
        self.assertEqual(records[0]["file"], "<stdin>")
        proc = ncc("check", "-", stdin="G01 X1. Q@\n")
        self.assertEqual(proc.returncode, 1)
        self.assertIn("<stdin>:1:", proc.stderr)
        # Bytecode through a pipe: compile to stdout, run from stdin.
        compiled = subprocess.run([NCC, "compile", "-", "-o", "-"], input=GOOD.encode(), capture_output=True)
        self.assertEqual(compiled.returncode, 0, compiled.stderr)
        self.assertTrue(compiled.stdout.startswith(b"NCCB"))
        proc = subprocess.run([NCC, "run", "-", "--emit=moves"], input=compiled.stdout, capture_output=True)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual(len(proc.stdout.splitlines()), 4)
        proc = ncc("compile", "-", stdin=GOOD)
        self.assertEqual(proc.returncode, 2)
        self.assertIn("error[NCC0008]", proc.stderr)
        self.assertEqual(os.listdir(self.dir), [])

    def test_unreadable_input_exits_two_with_a_driver_code(self):
        proc = ncc("run", self.dir)
        self.assertEqual(proc.returncode, 2)
        self.assertIn(f"ncc: error[NCC0001]: cannot read '{self.dir}': not a regular file", proc.stderr)
        proc = ncc("run", os.path.join(self.dir, "missing.nc"))
        self.assertEqual(proc.returncode, 2)
        self.assertIn("error[NCC0001]", proc.stderr)

    def test_input_without_read_permission_exits_two(self):
        # Root reads any file: then ncc runs as nobody (setpriv), in a folder nobody may enter.
        as_user = []
        if os.geteuid() == 0:
            if not os.path.exists("/usr/bin/setpriv"):
                self.skipTest("root, and no setpriv to drop the privileges")
            as_user = ["/usr/bin/setpriv", "--reuid=65534", "--regid=65534", "--clear-groups"]
            os.chmod(self.dir, 0o755)
        prog = self.write("secret.nc", GOOD)
        os.chmod(prog, 0)
        for command in ("run", "check", "compile"):
            proc = subprocess.run([*as_user, NCC, command, prog], capture_output=True, text=True, timeout=60)
            self.assertEqual(proc.returncode, 2, (command, proc.stderr))
            self.assertIn(f"ncc: error[NCC0001]: cannot read '{prog}': Permission denied", proc.stderr)
            self.assertNotIn("NCC1000", proc.stderr)
        if as_user:
            locked = os.path.join(self.dir, "locked")
            os.mkdir(locked, 0o700)
            inside = os.path.join(locked, "part.nc")
            with open(inside, "w") as f:
                f.write(GOOD)
            proc = subprocess.run([*as_user, NCC, "run", inside], capture_output=True, text=True, timeout=60)
            self.assertEqual(proc.returncode, 2, proc.stderr)
            self.assertIn(f"ncc: error[NCC0001]: cannot read '{inside}': Permission denied", proc.stderr)

    def test_every_driver_error_has_its_code(self):
        prog = self.write("good.nc", GOOD)
        cases = [
            (["check", prog, "--dialect", "heidenhain"], "NCC0002"),
            (["check", prog, "--dialect", "fanuc-t"], "NCC0002"),
            (["check", prog, "--machine", os.path.join(self.dir, "none.toml")], "NCC0003"),
            (["check", prog, "--machine", self.write("bad.toml", "[machine]\naxes = 3\n")], "NCC0003"),
            (["run", prog, "-o", os.path.join(self.dir, "no", "such", "dir.txt")], "NCC0004"),
            (["run", prog, "-o", self.dir], "NCC0004"),
            (["run", prog, "--feed-hold-at", "x"], "NCC0006"),
            (["dis", prog], "NCC0007"),
            (["run", prog, "--bogus"], "NCC0010"),
            (["frobnicate"], "NCC0010"),
        ]
        for args, code in cases:
            proc = ncc(*args)
            self.assertEqual(proc.returncode, 2, args)
            lines = [l for l in proc.stderr.splitlines() if l.startswith("ncc: error")]
            self.assertTrue(lines, f"{args}: {proc.stderr}")
            for line in lines:
                self.assertRegex(line, r"^ncc: error\[NCC00\d\d\]: ", args)
            self.assertIn(f"ncc: error[{code}]: ", proc.stderr, args)

    # --- progress on a terminal -------------------------------------------------------------

    def run_on_pty(self, args, stdout_too=False):
        """Runs ncc with stderr (and stdout if asked) on a pseudo-terminal; returns (exit code,
        what the terminal got)."""
        master, slave = pty.openpty()
        proc = subprocess.Popen([NCC, *args], stdout=slave if stdout_too else subprocess.DEVNULL, stderr=slave,
                                stdin=subprocess.DEVNULL)
        os.close(slave)
        seen = b""
        while True:
            ready, _, _ = select.select([master], [], [], 60)
            if not ready:
                break
            try:
                chunk = os.read(master, 4096)
            except OSError:  # the child closed the terminal
                break
            if not chunk:
                break
            seen += chunk
        proc.wait(timeout=60)
        os.close(master)
        return proc.returncode, seen.decode("utf-8", "replace")

    def test_progress_on_a_terminal_never_in_a_pipe(self):
        prog = self.write("long.nc", LONG)
        out = os.path.join(self.dir, "m.jsonl")
        code, seen = self.run_on_pty(["run", prog, "--emit=moves", "-o", out])
        self.assertEqual(code, 0, seen)
        self.assertRegex(seen, r"ncc: running: \d+ blocks, [\d.]+ s simulated, line \d+ \(\d+ % of the file\)")
        self.assertTrue(seen.endswith("\r\x1b[K"), repr(seen[-40:]))  # the line is erased at the end
        proc = ncc("run", prog, "--emit=moves", "-o", out)
        self.assertEqual(proc.returncode, 0)
        self.assertNotIn("ncc: running", proc.stderr)
        self.assertEqual(proc.stderr, "")
        # Moves streaming to the same terminal: no progress line between them.
        code, seen = self.run_on_pty(["run", prog, "--emit=moves"], stdout_too=True)
        self.assertEqual(code, 0, seen)
        self.assertIn('"kind": "line"', seen)
        self.assertNotIn("ncc: running", seen)
        # A short run shows nothing even on a terminal.
        code, seen = self.run_on_pty(["run", self.write("good.nc", GOOD), "-o", out])
        self.assertEqual((code, seen), (0, ""))

    def test_compile_progress_on_a_terminal(self):
        # A program long enough to compile for 2 s here (the line appears after about 1 s).
        out = os.path.join(self.dir, "big.ncb")
        blocks = 250000
        while True:
            lines = ["G21 G90 G17 G94"] + [f"G01 X{i % 100 * 0.5:.1f} Y{i % 37 * 0.3:.1f} F3000." for i in range(blocks)]
            prog = self.write("big.nc", "\n".join(lines + ["M30"]) + "\n")
            start = time.monotonic()
            proc = ncc("compile", prog, "-o", out)
            took = time.monotonic() - start
            self.assertEqual((proc.returncode, proc.stderr), (0, ""))
            if took >= 2.0:
                break
            if blocks >= 2000000:
                self.skipTest(f"{blocks} blocks compile in {took:.1f} s here: too fast for the progress line")
            blocks *= 2
        code, seen = self.run_on_pty(["compile", prog, "-o", out])
        self.assertEqual(code, 0, seen)
        self.assertRegex(seen, r"ncc: compiling: \d+ blocks, line \d+ \(\d+ % of the file\)")
        self.assertTrue(seen.endswith("\r\x1b[K"))

if __name__ == "__main__":
    NCC = os.path.abspath(sys.argv.pop(1))
    unittest.main()
