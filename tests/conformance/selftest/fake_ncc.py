#!/usr/bin/env python3
"""A stand-in for `ncc run` and `ncc check`, for testing the conformance runner and the corpus
check.

It answers from a JSON script named by $FAKE_NCC_SCRIPT:
  {"moves": [ {...}, ... ],  # objects written as JSON Lines for --emit=moves
   "moves_text": "...",      # or raw text (malformed output tests)
   "vars": {"#100": 3.0},    # written for --emit=vars
   "stderr": "...", "exit": 0, "signal": 11, "sleep": 5}
and appends its argv and the machine file it was given to $FAKE_NCC_LOG (JSON Lines), so
tests can check how the runner called it.
"""
import json
import os
import signal
import sys
import time


def option(argv, name):
    for i, a in enumerate(argv):
        if a == name and i + 1 < len(argv):
            return argv[i + 1]
        if a.startswith(name + "="):
            return a.split("=", 1)[1]
    return None


def main(argv):
    with open(os.environ["FAKE_NCC_SCRIPT"], encoding="utf-8") as f:
        script = json.load(f)
    machine = option(argv, "--machine")
    if "FAKE_NCC_LOG" in os.environ:
        with open(os.environ["FAKE_NCC_LOG"], "a", encoding="utf-8") as log:
            text = open(machine, encoding="utf-8").read() if machine else None
            log.write(json.dumps({"argv": argv, "machine": text}) + "\n")
    command = argv[:1]
    if command not in (["run"], ["check"]) or option(argv, "--dialect") is None or \
            (command == ["run"] and option(argv, "-o") is None):
        sys.stderr.write("fake ncc: usage: run PROGRAM --dialect D ... --emit=E -o OUT | check PROGRAM --dialect D\n")
        return 2
    time.sleep(script.get("sleep", 0))
    if "signal" in script:
        os.kill(os.getpid(), script["signal"])
    if command == ["check"]:
        sys.stderr.write(script.get("stderr", ""))
        return script.get("exit", 0)
    emit, out = option(argv, "--emit"), option(argv, "-o")
    with open(out, "w", encoding="utf-8") as f:
        if emit == "moves":
            f.write(script.get("moves_text", "".join(json.dumps(m) + "\n" for m in script.get("moves", []))))
        elif emit == "vars":
            json.dump(script.get("vars", {}), f)
    sys.stderr.write(script.get("stderr", ""))
    return script.get("exit", 0)


if __name__ == "__main__":
    signal.signal(signal.SIGINT, signal.SIG_DFL)
    sys.exit(main(sys.argv[1:]))
