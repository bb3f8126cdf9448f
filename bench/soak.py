#!/usr/bin/env python3
"""Soak: does nprgl's resident memory stay flat over a long run?

Runs the character demo offscreen under nprgl (default style unless --style) for --frames
frames with `--rss-every N`, so the demo itself prints its VmRSS (from /proc/self/status)
every N frames: the samples are taken by frame number, never by time. Reports the first,
last and largest sample, and the least-squares slope of RSS over frames after the warm-up
(KiB per 1,000 frames), the frame of the last new high and the slope over the second half.
Target: flat after warm-up.

  bench/soak.py [--build DIR] [--frames N] [--every N] [--warmup N] [--model FILE]
                [--size WxH] [--style S | --native] [--tolerance KIB] [--json FILE]
                [--reanalyse JSON] [-- DEMO ARGS...]

Default: 100,000 frames at 128x128 (a per-frame leak shows at any frame size, and a small
frame keeps the run to minutes on a software rasteriser), a sample every 1,000, the first
10% of the frames ignored as warm-up. For a quick check: `bench/soak.py --frames 5000
--every 100`. Exit status 0 whatever the slope (a benchmark reports), 1 if the run failed.
Python 3 standard library only.
"""

from __future__ import annotations

import argparse
import json
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from benchlib import clean_env  # noqa: E402

SAMPLE_RE = re.compile(r"^demo_character: frame=(\d+) vmrss_kib=(\d+)\s*$")
DEFAULT_MODEL = "/usr/share/assimp/models/X/Testwuson.X"


def least_squares(points: list[tuple[int, int]]) -> tuple[float, float]:
    """Slope and intercept of the line through (frame, kib) points, by least squares."""
    n = len(points)
    mx = sum(x for x, _ in points) / n
    my = sum(y for _, y in points) / n
    sxx = sum((x - mx) ** 2 for x, _ in points)
    sxy = sum((x - mx) * (y - my) for x, y in points)
    slope = sxy / sxx if sxx > 0 else 0.0
    return slope, my - slope * mx


def command(args: argparse.Namespace) -> list[str]:
    b = os.path.join(args.build, "bin")
    demo = [f"{b}/demo_character", "--offscreen", "--frames", str(args.frames),
            "--rss-every", str(args.every), "--size", args.size]
    if args.model:
        demo += ["--model", args.model]
    demo += args.demo_args
    if args.native:
        return demo
    nprgl = [f"{b}/nprgl"]
    if args.style:
        nprgl += ["--style", args.style]
    return nprgl + ["--"] + demo


def run(cmd: list[str], quiet: bool) -> tuple[list[tuple[int, int]], int, str]:
    """Runs cmd; returns the (frame, kib) samples, the exit code and the other stderr lines."""
    samples: list[tuple[int, int]] = []
    other: list[str] = []
    with subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                          env=clean_env()) as proc:
        assert proc.stderr is not None
        for line in proc.stderr:
            m = SAMPLE_RE.match(line)
            if not m:
                other.append(line)
                continue
            samples.append((int(m.group(1)), int(m.group(2))))
            if not quiet and len(samples) % 10 == 0:
                print(f"  frame {samples[-1][0]}: {samples[-1][1]} KiB", flush=True)
        code = proc.wait()
    return samples, code, "".join(other[-40:])


def main() -> int:
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=os.path.join(root, "build"))
    parser.add_argument("--frames", type=int, default=100_000)
    parser.add_argument("--every", type=int, default=1000, help="frames between samples")
    parser.add_argument("--warmup", type=int, default=None,
                        help="frames left out of the slope (default: 10%% of --frames)")
    parser.add_argument("--model", default=DEFAULT_MODEL,
                        help="model file ('' for the demo's built-in default)")
    parser.add_argument("--size", default="128x128", help="demo frame size (default 128x128)")
    parser.add_argument("--style", default="", help="nprgl style (default: nprgl's default)")
    parser.add_argument("--native", action="store_true", help="run the demo without nprgl")
    parser.add_argument("--tolerance", type=float, default=1.0,
                        help="largest slope called flat, KiB per 1,000 frames (default 1)")
    parser.add_argument("--json", help="also write the figures and samples here")
    parser.add_argument("--quiet", action="store_true", help="no progress lines")
    parser.add_argument("--reanalyse", metavar="JSON",
                        help="report on the samples a previous --json run wrote, without running")
    parser.add_argument("demo_args", nargs="*", help="more demo_character arguments")
    args = parser.parse_args()
    if args.frames < 1 or args.every < 1:
        parser.error("--frames and --every must be positive")
    warmup = args.warmup if args.warmup is not None else args.frames // 10

    if args.reanalyse:
        with open(args.reanalyse, encoding="utf-8") as f:
            old = json.load(f)
        cmd = old["command"]
        samples = [(int(frame), int(k)) for frame, k in old["samples_kib"]]
        args.frames, args.every = old["frames"], old["every"]
        warmup = args.warmup if args.warmup is not None else args.frames // 10
        print("soak (from " + args.reanalyse + "): " + " ".join(cmd))
    else:
        cmd = command(args)
        print("soak: " + " ".join(cmd), flush=True)
        samples, code, stderr = run(cmd, args.quiet)
        expected = args.frames // args.every
        if code != 0 or len(samples) != expected:
            print(f"soak: run failed (exit {code}, {len(samples)} of {expected} samples)\n"
                  f"{stderr}", file=sys.stderr)
            return 1
    steady = [s for s in samples if s[0] > warmup]
    if len(steady) < 2:
        print(f"soak: fewer than 2 samples after the warm-up of {warmup} frames",
              file=sys.stderr)
        return 1

    slope, _ = least_squares(steady)
    per_kframe = slope * 1000.0
    span = steady[-1][0] - steady[0][0]
    kib = [k for _, k in samples]
    at_max = max(samples, key=lambda s: s[1])
    flat = per_kframe <= args.tolerance
    # A step (an allocator arena or a reused buffer reaching a new high-water mark) tilts the
    # fit without being a leak: say when RSS last reached a new high, and fit the second half
    # of the samples after the warm-up alone.
    last_high = samples[0]
    for frame, k in samples[1:]:
        if k > last_high[1]:
            last_high = (frame, k)
    tail = steady[len(steady) // 2:]
    tail_per_kframe = least_squares(tail)[0] * 1000.0 if len(tail) >= 2 else 0.0
    if flat:
        verdict = "flat"
    elif tail_per_kframe <= args.tolerance and last_high[0] <= tail[0][0]:
        verdict = (f"bounded: grew in steps until frame {last_high[0]}, no new high in the "
                   f"{steady[-1][0] - last_high[0]} frames since")
    else:
        verdict = "GROWING"
    figures = {
        "command": cmd,
        "frames": args.frames,
        "every": args.every,
        "warmup_frames": warmup,
        "samples": len(samples),
        "samples_after_warmup": len(steady),
        "first_kib": kib[0],
        "warmup_end_kib": steady[0][1],
        "last_kib": kib[-1],
        "max_kib": at_max[1],
        "max_frame": at_max[0],
        "min_after_warmup_kib": min(k for _, k in steady),
        "max_after_warmup_kib": max(k for _, k in steady),
        "slope_kib_per_1000_frames": per_kframe,
        "fitted_growth_after_warmup_kib": slope * span,
        "tolerance_kib_per_1000_frames": args.tolerance,
        "last_new_high_frame": last_high[0],
        "second_half_slope_kib_per_1000_frames": tail_per_kframe,
        "flat": flat,
        "verdict": verdict,
    }
    print(f"frames {args.frames}, a sample every {args.every} ({len(samples)} samples), "
          f"warm-up {warmup} frames")
    print(f"VmRSS first {kib[0]} KiB (frame {samples[0][0]}), at end of warm-up "
          f"{steady[0][1]} KiB (frame {steady[0][0]}), last {kib[-1]} KiB, max {at_max[1]} KiB "
          f"(frame {at_max[0]})")
    print(f"after warm-up: min {figures['min_after_warmup_kib']} KiB, max "
          f"{figures['max_after_warmup_kib']} KiB; least-squares slope {per_kframe:.3f} KiB "
          f"per 1,000 frames ({slope * span:.0f} KiB over {span} frames)")
    print(f"last new high at frame {last_high[0]}; slope over the second half after the "
          f"warm-up (frames {tail[0][0]}-{tail[-1][0]}): {tail_per_kframe:.3f} KiB per 1,000 "
          f"frames")
    print(f"verdict: {verdict} (tolerance {args.tolerance} KiB per 1,000 frames)")
    if args.json:
        figures["samples_kib"] = samples
        with open(args.json, "w", encoding="utf-8") as f:
            json.dump(figures, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
