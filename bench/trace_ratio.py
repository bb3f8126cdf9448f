#!/usr/bin/env python3
"""A game's apitrace trace replayed with glretrace: nprgl in a style against native.

    bench/trace_ratio.py TRACE [--style S] [--pairs N] [--build DIR]
    bench/trace_ratio.py --make-openarena-trace TRACE    (needs openarena and apitrace)

Runs `nprgl --style S -- glretrace -b TRACE` (A) and `glretrace -b TRACE` (B) alternately,
A B A B ... after one warm-up pair, so that both share the machine's drift, and prints per
side the median wall time and peak resident memory (the replay process's own, from wait4),
and the median of the pair-by-pair wall ratios A/B with its range. Needs a display (or run it
under scripts/with-display.sh).

A benchmark reports; it does not judge. Exit status 0 whatever the ratio, 1 if a run failed,
2 on bad usage. Python 3 standard library only.
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from benchlib import RunFailed, clean_env  # noqa: E402

REPO_ROOT = Path(__file__).resolve().parent.parent
OPENARENA = ["/usr/games/openarena", "+set", "r_mode", "-1", "+set", "r_customwidth", "640",
             "+set", "r_customheight", "480", "+set", "r_fullscreen", "0",
             "+set", "cl_renderer", "opengl1", "+set", "s_initsound", "0",
             "+devmap", "oa_dm1", "+wait", "800", "+quit"]


def run(cmd: list[str]) -> tuple[float, float]:
    """Wall seconds and peak resident MiB of one run."""
    with tempfile.TemporaryFile() as err:
        start = time.monotonic()
        proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=err, env=clean_env())
        _, status, usage = os.wait4(proc.pid, 0)
        wall = time.monotonic() - start
        proc.returncode = code = os.waitstatus_to_exitcode(status)
        if code != 0:
            err.seek(0)
            text = err.read().decode(errors="replace")
            raise RunFailed(f"{' '.join(cmd)}: exit {code}\n{text[-2000:]}")
    return wall, usage.ru_maxrss / 1024.0


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("trace", help="the .trace file (written with --make-openarena-trace)")
    parser.add_argument("--style", default="toon+paper+edges")
    parser.add_argument("--pairs", type=int, default=3)
    parser.add_argument("--build", default=str(REPO_ROOT / "build"))
    parser.add_argument("--make-openarena-trace", action="store_true",
                        help="trace openarena into its map (oa_dm1) into TRACE first")
    args = parser.parse_args()
    if args.pairs < 1:
        parser.error("--pairs must be at least 1")
    if "DISPLAY" not in os.environ:
        parser.error("needs DISPLAY (run it under scripts/with-display.sh)")
    try:
        if args.make_openarena_trace:
            run(["apitrace", "trace", "--api", "gl", "-o", args.trace] + OPENARENA)
        if not Path(args.trace).is_file():
            parser.error(f"no trace at {args.trace}")
        styled = [str(Path(args.build) / "bin" / "nprgl"), "--style", args.style, "--",
                  "glretrace", "-b", args.trace]
        native = ["glretrace", "-b", args.trace]
        run(styled)
        run(native)
        a, b = [], []
        for _ in range(args.pairs):
            a.append(run(styled))
            b.append(run(native))
    except RunFailed as failure:
        print(f"trace_ratio: {failure}", file=sys.stderr)
        return 1
    ratios = [x[0] / y[0] for x, y in zip(a, b)]
    for name, runs in ((f"nprgl --style {args.style}", a), ("native", b)):
        print(f"{name:32s} wall {statistics.median(r[0] for r in runs):7.2f} s  "
              f"peak {statistics.median(r[1] for r in runs):7.1f} MiB")
    print(f"wall ratio (median of {args.pairs} pairs): {statistics.median(ratios):.2f} "
          f"({min(ratios):.2f}-{max(ratios):.2f})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
