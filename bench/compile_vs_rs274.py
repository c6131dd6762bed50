#!/usr/bin/env python3
"""Whole-program compile time and memory of `ncc compile`, next to LinuxCNC's rs274 interpreter
measured in the same run on the same files.

    python3 bench/compile_vs_rs274.py --ncc build/tools/ncc/ncc [--blocks 1000000] [--repeat 3]

Inputs: the corpus's largest real toolpath (cam-iso/camotics-tiger_tiger.nc, 67k lines) and a
generated CAM finishing toolpath of --blocks blocks (G1 X Y Z F rows joined by G2/G3 I J
turnarounds, no macros), plus the same generator at a tenth of the size to show how ncc's peak
memory grows with program length (streaming: it should not); and a macro loop of --loops turns
(a move, a SIN, two assignments a turn), a FANUC `WHILE [...] DO1` for ncc and the same loop as
an o-word `while` for rs274.

Figures: wall time (best of --repeat runs) and peak resident memory of each process (GNU time's
%M when /usr/bin/time exists, else VmHWM sampled from /proc), and the ratios ncc / rs274. Printed, never judged: the script fails only
when a program does not compile. rs274 (Debian linuxcnc-uspace) runs as
`rs274 -t TOOL.tbl -g IN OUT.canon < /dev/null`, i.e. batch mode writing its canonical-command
log; when it is absent the table says "peer unavailable" and still gives ncc's figures.
"""
import argparse
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

HERE = Path(__file__).resolve().parent
DEFAULT_CORPUS = HERE.parent / "tests" / "corpus"
TIGER = "cam-iso/camotics-tiger_tiger.nc"
TOOL_TABLE = "T1 P1 D6.0 Z+0.0 ;6 mm end mill\n"


def generate_program(path, blocks):
    """A raster finishing pass over z = f(x, y): rows of G1 X Y Z moves, each row joined to the
    next by a half-circle G3 / G2 in XY (I0 J = step/2, exact at 3 decimals). Deterministic."""
    step, seg, row_len = 0.5, 0.5, 100  # mm between rows, mm per segment, segments a row
    header = ["%", "(generated CAM finishing toolpath)", "G17 G21 G90 G94 G40 G49 G54",
              "S12000 M3", "G0 Z5.", "G0 X0. Y0.", "G1 Z-1. F600."]
    footer = ["G0 Z5.", "M5", "M30", "%"]
    body = blocks - len(header) - len(footer)
    with open(path, "w", buffering=1 << 20) as f:
        f.write("\n".join(header) + "\n")
        written, row, x, y = 0, 0, 0.0, 0.0
        while written < body:
            direction = 1 if row % 2 == 0 else -1
            for i in range(row_len):
                if written >= body:
                    break
                x += direction * seg
                z = -1.0 - 0.5 * math.sin(x / 7.0) * math.cos(y / 11.0)
                feed = " F1200." if i == 0 else ""
                f.write(f"G1 X{x:.3f} Y{y:.3f} Z{z:.3f}{feed}\n")
                written += 1
            if written >= body:
                break
            # Turn around: counter-clockwise at the +X end, clockwise at the start end.
            y += step
            f.write(f"{'G3' if direction > 0 else 'G2'} X{x:.3f} Y{y:.3f} I0. J{step / 2:.3f}\n")
            written += 1
            row += 1
        f.write("\n".join(footer) + "\n")


def generate_loop(path, turns, dialect):
    """A macro loop of `turns` turns, each a G1 move, a SIN and two assignments: FANUC Macro B
    (`fanuc`) or LinuxCNC's o-word while (`rs274`), the same arithmetic either way."""
    head = ["%", "G17 G21 G90 G94 G40 G49 G54", "G0 X0. Y0. Z5.", "G1 Z-1. F600.", "#1=0", "#2=0"]
    if dialect == "fanuc":
        body = [f"WHILE[#1LT{turns}]DO1", "#2=SIN[#1*0.36]*10.", "G1 X[#1*0.001] Y#2 F1200.",
                "#1=#1+1", "END1"]
    else:
        body = [f"o100 while [#1 LT {turns}]", "#2=[SIN[#1*0.36]*10.]", "G1 X[#1*0.001] Y#2 F1200.",
                "#1=[#1+1]", "o100 endwhile"]
    path.write_text("\n".join(head + body + ["G0 Z5.", "M30", "%"]) + "\n")


@dataclass
class Figure:
    seconds: float = math.nan  # best wall time
    peak_mb: float = math.nan  # largest peak RSS over the runs
    error: str = ""


def gnu_time():
    """GNU time's path, if installed. It reports the peak RSS of the process it forks itself;
    a child forked from this Python process would inherit Python's own high-water mark (the
    kernel keeps it across fork and exec), hiding anything smaller."""
    path = Path("/usr/bin/time")
    if not path.is_file():
        return None
    probe = subprocess.run([str(path), "-f", "%M", "true"], capture_output=True, text=True)
    return str(path) if probe.returncode == 0 and probe.stderr.strip().isdigit() else None


def peak_rss_by_polling(pid, stop):
    """VmHWM of `pid` sampled every 2 ms until `stop()` (fallback without GNU time)."""
    peak = 0
    while not stop():
        try:
            with open(f"/proc/{pid}/status") as f:
                for line in f:
                    if line.startswith("VmHWM:"):
                        peak = max(peak, int(line.split()[1]))
        except (OSError, ValueError):
            pass
        time.sleep(0.002)
    return peak


def measure(command, repeat, timer):
    """Runs `command` `repeat` times: best wall time, largest peak RSS."""
    fig = Figure(seconds=math.inf, peak_mb=0.0)
    for _ in range(repeat):
        with tempfile.TemporaryDirectory() as tmp:
            rss_file, err_file = Path(tmp, "rss"), Path(tmp, "err")
            wrapped = [timer, "-f", "%M", "-o", str(rss_file), *command] if timer else command
            with open(err_file, "wb") as err:
                start = time.perf_counter()
                proc = subprocess.Popen(wrapped, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=err)
                if timer:
                    proc.wait()
                    peak_kb = int(rss_file.read_text().split()[-1]) if proc.returncode == 0 else 0
                else:
                    peak_kb = peak_rss_by_polling(proc.pid, lambda: proc.poll() is not None)
                elapsed = time.perf_counter() - start
            if proc.returncode != 0:
                text = err_file.read_text(errors="replace").strip().splitlines()
                return Figure(error=f"exit {proc.returncode}: " + " | ".join(text[:3]))
        fig.seconds = min(fig.seconds, elapsed)
        fig.peak_mb = max(fig.peak_mb, peak_kb / 1024.0)
    return fig


def count_blocks(path):
    with open(path, "rb") as f:
        return sum(1 for line in f if line.strip())


def ratio(a, b):
    return f"{a / b:.2f}x" if b and not (math.isnan(a) or math.isnan(b)) else "n/a"


def cell(fig, value):
    if fig is None:
        return "peer unavailable"
    return fig.error and "failed" or value


def main(argv):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--ncc", required=True, help="path of the ncc executable")
    p.add_argument("--rs274", default=shutil.which("rs274") or "/usr/bin/rs274", help="LinuxCNC rs274")
    p.add_argument("--corpus", type=Path, default=DEFAULT_CORPUS, help="tests/corpus")
    p.add_argument("--blocks", type=int, default=1_000_000, help="size of the generated program")
    p.add_argument("--loops", type=int, default=200_000, help="turns of the macro loop")
    p.add_argument("--repeat", type=int, default=3, help="runs per figure (best time is kept)")
    args = p.parse_args(argv)

    have_peer = Path(args.rs274).is_file() and os.access(args.rs274, os.X_OK)
    timer = gnu_time()
    with tempfile.TemporaryDirectory(prefix="ncc-bench-") as tmp:
        tmp = Path(tmp)
        tool_table = tmp / "tool.tbl"
        tool_table.write_text(TOOL_TABLE)
        small, big = tmp / f"generated_{args.blocks // 10}.nc", tmp / f"generated_{args.blocks}.nc"
        generate_program(small, args.blocks // 10)
        generate_program(big, args.blocks)
        loop, loop_peer = tmp / "loop.nc", tmp / "loop.ngc"
        generate_loop(loop, args.loops, "fanuc")
        generate_loop(loop_peer, args.loops, "rs274")
        # (label, ncc's input, rs274's input)
        inputs = [("tiger.nc (corpus)", args.corpus / TIGER, None),
                  (f"generated {args.blocks // 10:,}", small, None),
                  (f"generated {args.blocks:,}", big, None),
                  (f"loop {args.loops:,} turns", loop, loop_peer)]

        rows, failed = [], False
        for label, path, peer_path in inputs:
            if not path.is_file():
                print(f"{label}: {path} not found, skipped")
                continue
            # A loop's blocks are the turns it runs: 5 blocks a turn.
            blocks = 5 * args.loops if peer_path else count_blocks(path)
            # The loop runs 200,000 turns: older builds stopped it at 10,000 jumps back unless told.
            loop_args = ["--max-back-jumps", "1000000000"] if peer_path else []
            ncc = measure([args.ncc, "compile", str(path), "--dialect", "fanuc-m", "-o", str(tmp / "out.ncb"),
                           *loop_args], args.repeat, timer)
            peer = None
            if have_peer:
                peer = measure([args.rs274, "-t", str(tool_table), "-g", str(peer_path or path),
                                str(tmp / "out.canon")],
                               args.repeat, timer)
            failed |= bool(ncc.error)
            rows.append((label, blocks, ncc, peer))
            for who, fig in (("ncc", ncc), ("rs274", peer)):
                if fig is not None and fig.error:
                    print(f"{label}: {who} failed: {fig.error}")

    print(f"\nCompile time and peak memory, best of {args.repeat} (ncc compile vs LinuxCNC rs274 -g)"
          + ("" if have_peer else ": rs274 peer unavailable")
          + ("; peak RSS from GNU time" if timer else "; peak RSS sampled from /proc every 2 ms"))
    head = f"{'input':<22}{'blocks':>10}{'ncc s':>9}{'rs274 s':>18}{'time ratio':>12}{'speed-up':>10}" \
           f"{'ncc MB':>9}{'rs274 MB':>18}{'mem ratio':>11}{'ncc blocks/s':>14}"
    print(head)
    print("-" * len(head))
    for label, blocks, ncc, peer in rows:
        rate = f"{blocks / ncc.seconds:,.0f}" if not ncc.error else "failed"
        print(f"{label:<22}{blocks:>10,}{cell(ncc, f'{ncc.seconds:.3f}'):>9}"
              f"{cell(peer, peer and f'{peer.seconds:.3f}'):>18}"
              f"{ratio(ncc.seconds, peer.seconds) if peer else 'n/a':>12}"
              f"{ratio(peer.seconds, ncc.seconds) if peer else 'n/a':>10}"
              f"{cell(ncc, f'{ncc.peak_mb:.1f}'):>9}{cell(peer, peer and f'{peer.peak_mb:.1f}'):>18}"
              f"{ratio(ncc.peak_mb, peer.peak_mb) if peer else 'n/a':>11}{rate:>14}")
    gen = [r for r in rows if r[0].startswith("generated")]
    if len(gen) == 2:
        (_, b1, n1, p1), (_, b2, n2, p2) = gen
        print(f"\nMemory growth from {b1:,} to {b2:,} blocks (x{b2 / b1:.0f} input): ncc peak RSS "
              f"{n1.peak_mb:.1f} -> {n2.peak_mb:.1f} MB ({ratio(n2.peak_mb, n1.peak_mb)})"
              + (f", rs274 {p1.peak_mb:.1f} -> {p2.peak_mb:.1f} MB ({ratio(p2.peak_mb, p1.peak_mb)})" if p1 else ""))
    print("ratios: ncc / rs274 (below 1.00x: ncc is faster or smaller); speed-up: rs274 s / ncc s "
          "(the target is 5x on the CAM inputs and the loop). Figures only, not a pass/fail test.")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
