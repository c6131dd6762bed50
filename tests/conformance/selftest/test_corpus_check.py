"""Unit tests of tests/corpus/corpus_check.py against the fake ncc: what counts as compiled,
rejected, not supported, and as a crash."""
import io
import json
import os
import signal
import sys
import tempfile
import unittest
from contextlib import redirect_stdout
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parents[1] / "corpus"))

import corpus_check  # noqa: E402

FAKE_NCC = HERE / "fake_ncc.py"
DIAG = "part.nc:3:1: error[NCC1002]: LinuxCNC O-words are not supported in fanuc-m\n  o100 sub\n  ^\n"


class CorpusCheckTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.root = Path(self.tmp.name)
        for folder in ("cam-iso", "fanuc-t"):
            (self.root / folder).mkdir()
        self.program = self.root / "cam-iso" / "part.nc"
        self.program.write_text("G0 X1\nM30\n")
        (self.root / "fanuc-t" / "lathe.nc").write_text("G0 X1\nM30\n")
        self.log = self.root / "log.jsonl"
        os.environ["FAKE_NCC_LOG"] = str(self.log)

    def tearDown(self):
        os.environ.pop("FAKE_NCC_SCRIPT", None)
        os.environ.pop("FAKE_NCC_LOG", None)
        self.tmp.cleanup()

    def script(self, **script):
        path = self.root / "script.json"
        path.write_text(json.dumps(script))
        os.environ["FAKE_NCC_SCRIPT"] = str(path)

    def check(self, **script):
        self.script(**script)
        return corpus_check.check(FAKE_NCC, self.program, timeout=20)

    def test_clean(self):
        self.assertEqual(self.check(exit=0).status, "clean")
        argv = json.loads(self.log.read_text())["argv"]
        self.assertEqual(argv, ["check", str(self.program), "--dialect", "fanuc-m"])

    def test_rejected_with_diagnostic(self):
        o = self.check(exit=1, stderr=DIAG + DIAG)
        self.assertEqual((o.status, o.first_code, o.errors), ("rejected", "NCC1002", 2))

    def test_exit_1_without_diagnostic_is_a_failure(self):
        o = self.check(exit=1, stderr="ncc: internal error\n")
        self.assertEqual(o.status, "crash")
        self.assertIn("without a `file:line:col: error[CODE]:` line", o.detail)

    def test_signal_is_a_crash(self):
        o = self.check(signal=signal.SIGABRT)
        self.assertEqual(o.status, "crash")
        self.assertIn(f"killed by signal {int(signal.SIGABRT)}", o.detail)

    def test_hang_is_a_failure(self):
        self.script(sleep=10)
        o = corpus_check.check(FAKE_NCC, self.program, timeout=0.5)
        self.assertEqual(o.status, "crash")
        self.assertIn("hang", o.detail)

    def test_dialect_not_supported(self):
        o = self.check(exit=2, stderr="ncc: error: dialect fanuc-t is not supported yet\n")
        self.assertEqual(o.status, "unsupported")

    def test_other_usage_error_is_a_failure(self):
        self.assertEqual(self.check(exit=2, stderr="ncc: error: unknown option --x\n").status, "crash")

    def test_exit_status_and_summary(self):
        self.script(exit=1, stderr=DIAG)
        with redirect_stdout(io.StringIO()) as out:
            status = corpus_check.main(["--ncc", str(FAKE_NCC), "--file", str(self.program)])
        self.assertEqual(status, 0)
        self.assertIn("rejected with 1 diagnostic(s), first [NCC1002]", out.getvalue())
        self.script(exit=2, stderr="dialect not supported yet\n")
        with redirect_stdout(io.StringIO()):
            self.assertEqual(corpus_check.main(["--ncc", str(FAKE_NCC), "--file", str(self.program)]), 77)
        self.script(signal=signal.SIGSEGV)
        with redirect_stdout(io.StringIO()) as out:
            status = corpus_check.main(["--ncc", str(FAKE_NCC), "--all", str(self.root), "--summary"])
        self.assertEqual(status, 1)
        self.assertIn("CRASH: cam-iso/part.nc", out.getvalue())
        row = next(line for line in out.getvalue().splitlines() if line.strip().startswith("fanuc-t"))
        self.assertEqual(row.split(), ["fanuc-t", "0", "0", "0", "1", "1"])


if __name__ == "__main__":
    unittest.main()
