"""What the CLI tests share: a scratch folder per test, and files written into it.

Each test script is run by ctest as `test_x.py NCC_BINARY [...]` and keeps its own `ncc()`
(timeouts and text mode differ); this module holds only the folder handling.
"""
import os
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
