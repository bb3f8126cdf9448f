#!/usr/bin/env python3
"""Two builds side by side on one capture: CPU time of their headless replays, pair ratios.

Each pair replays CAPTURE with build A, then build B (`nprgl replay CAPTURE -o DIR --frames N`,
the style's default unless --style), with LP_NUM_THREADS=0 so llvmpipe draws on the calling
thread and the process's user + system time is all of the drawing; the pairs alternate after
nothing else, so drift on a shared machine hits both alike. Prints each pair's CPU seconds
and B/A, then the median ratio and its range. This is how docs/benchmarks.md measures a
change against the build before it ("headless on one core").

  bench/replay_ab.py --a BUILD_A --b BUILD_B CAPTURE FRAMES [--pairs 3] [--style S] [--set k=v]

A benchmark reports; it does not judge noise. Exit status 0 whatever the ratios, 1 if a run
failed. Python 3 standard library only.
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from benchlib import RunFailed, clean_env  # noqa: E402


def cpu_seconds(build: str, capture: str, frames: int, extra: list[str], out: str) -> float:
    cmd = [os.path.join(build, "bin", "nprgl"), "replay", capture, "-o", out, "--frames",
           str(frames), *extra]
    env = clean_env()
    env["LP_NUM_THREADS"] = "0"
    # The log to a file, not a pipe: a full pipe would stall the replay while we wait.
    with tempfile.TemporaryFile() as log:
        p = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=log, env=env)
        _, status, usage = os.wait4(p.pid, 0)
        log.seek(0)
        err = log.read().decode(errors="replace")
    if os.waitstatus_to_exitcode(status) != 0:
        raise RunFailed(f"exit {os.waitstatus_to_exitcode(status)}: {' '.join(cmd)}\n"
                        f"{err[-2000:]}")
    return usage.ru_utime + usage.ru_stime


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--a", required=True, help="build directory A (the one before)")
    ap.add_argument("--b", required=True, help="build directory B")
    ap.add_argument("capture")
    ap.add_argument("frames", type=int, help="replay frames 1..FRAMES, write the last")
    ap.add_argument("--pairs", type=int, default=3)
    ap.add_argument("--style", help="style chain (default: the default style)")
    ap.add_argument("--set", action="append", default=[], help="style.param=value")
    args = ap.parse_args()
    extra = (["--style", args.style] if args.style else [])
    for kv in args.set:
        extra += ["--set", kv]
    for build in (args.a, args.b):
        if not os.access(os.path.join(build, "bin", "nprgl"), os.X_OK):
            print(f"replay_ab: no {build}/bin/nprgl (build it first)", file=sys.stderr)
            return 1
    if not os.path.isfile(args.capture):
        print(f"replay_ab: no capture {args.capture}", file=sys.stderr)
        return 1
    ratios = []
    with tempfile.TemporaryDirectory() as out:
        try:
            for i in range(args.pairs):
                a = cpu_seconds(args.a, args.capture, args.frames, extra, out)
                b = cpu_seconds(args.b, args.capture, args.frames, extra, out)
                ratios.append(b / a)
                print(f"pair {i + 1}: A {a:.2f} s, B {b:.2f} s, B/A {b / a:.3f}", flush=True)
        except RunFailed as e:
            print(e, file=sys.stderr)
            return 1
    print(f"B/A median {statistics.median(ratios):.3f} ({min(ratios):.3f}-{max(ratios):.3f}), "
          f"{len(ratios)} pairs")
    return 0


if __name__ == "__main__":
    sys.exit(main())
