#!/usr/bin/env python3
"""Frame time per style against passthrough, measured side by side in one run.

Cases: each demo app offscreen (OSMesa, 512x512; the character demo with Testwuson.X), timed
by its own `--report` line (the frame loop only), and a glxgears capture replayed headless
(`nprgl replay`, whole process). For every case the styles run in rounds, each round all
styles one after the other (so drift and noise hit all of them alike); the figure per style
is the median over the rounds and the ratio is style frame time / `none` frame time (lower
is better). Targets (issue 6): toon and halftone at most 1.5. The style `native` runs the demo
without nprgl (no preload) in the same rounds, so every style also has a ratio to the
program alone (issue 13: toon at most 1.3x native); a capture's replay has no native run.

  bench/style_bench.py [--build DIR] [--rounds N] [--styles native,none,a,b,...] [--json]

A benchmark reports; it does not judge noise. Exit status 0 whatever the ratios, 1 if a run
failed. Python 3 standard library only.
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from benchlib import RunFailed, clean_env, report_fps  # noqa: E402

DEFAULT_STYLES = ["none", "toon", "textured", "halftone", "toon+edges", "toon+wireframe",
                  "toon+perpixel", "toon+strokes"]
MODELS = "/usr/share/assimp/models"


def demo_cases(build: str) -> list[tuple[str, list[str], int]]:
    b = os.path.join(build, "bin")
    return [
        ("immediate (~1M vertices)", [f"{b}/demo_immediate", "--detail", "275"], 30),
        ("immediate (3.7k vertices)", [f"{b}/demo_immediate"], 300),
        ("arrays", [f"{b}/demo_arrays"], 200),
        ("display lists", [f"{b}/demo_displaylist"], 300),
        ("textured", [f"{b}/demo_textured"], 300),
        ("overlay", [f"{b}/demo_overlay"], 300),
        ("character (skinned)",
         [f"{b}/demo_character", "--model", f"{MODELS}/X/Testwuson.X"], 200),
    ]


def run_demo(build: str, style: str, argv: list[str], frames: int) -> float:
    nprgl = [] if style == "native" else [os.path.join(build, "bin", "nprgl"), "--style", style,
                                          "--"]
    cmd = [*nprgl, *argv, "--offscreen", "--size", "512x512", "--frames", str(frames),
           "--report"]
    p = subprocess.run(cmd, capture_output=True, text=True, env=clean_env(), timeout=600)
    if p.returncode != 0:
        raise RunFailed(f"exit {p.returncode}: {' '.join(cmd)}\n{p.stderr[-2000:]}")
    return 1000.0 / report_fps(cmd, p.stdout, p.stderr, frames)  # ms per frame


def record_glxgears(build: str, path: str) -> int:
    nprgl = os.path.join(build, "bin", "nprgl")
    script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts",
                          "with-display.sh")
    subprocess.run([script, "timeout", "4", nprgl, "record", "-o", path, "--frames", "1-300",
                    "--style", "none", "--", "glxgears"], capture_output=True,
                   env=clean_env(), timeout=120)
    info = subprocess.run([nprgl, "info", path], capture_output=True, text=True,
                          env=clean_env())
    for line in info.stdout.splitlines():
        if line.startswith("frames:"):
            return int(line.split()[1])
    raise RunFailed(f"could not record glxgears: {info.stderr[-500:]}")


def run_replay(build: str, style: str, capture: str, out: str) -> float:
    cmd = [os.path.join(build, "bin", "nprgl"), "replay", capture, "-o", out, "--style", style,
           "--frames", "1000000000"]  # writes no PNG: only the replay is timed
    start = time.perf_counter()
    p = subprocess.run(cmd, capture_output=True, text=True, env=clean_env(), timeout=600)
    elapsed = time.perf_counter() - start
    if p.returncode != 0:
        raise RunFailed(f"exit {p.returncode}: {' '.join(cmd)}\n{p.stderr[-2000:]}")
    return elapsed * 1000.0


def main() -> int:
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", default=os.path.join(here, "..", "build"))
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--styles", default=",".join(DEFAULT_STYLES))
    ap.add_argument("--json", action="store_true")
    args = ap.parse_args()
    styles = args.styles.split(",")
    if "none" not in styles:
        styles.insert(0, "none")
    results = []
    try:
        cases = [(name, argv, frames, None) for name, argv, frames in demo_cases(args.build)]
        tmp = tempfile.mkdtemp()
        capture = os.path.join(tmp, "glxgears.nprgl")
        gears_frames = record_glxgears(args.build, capture)
        cases.append((f"glxgears capture ({gears_frames} frames, replay)", None, gears_frames,
                      capture))
        for name, argv, frames, cap in cases:
            times: dict[str, list[float]] = {s: [] for s in styles}
            for _ in range(args.rounds):
                for style in styles:
                    if cap and style == "native":
                        continue
                    if cap:
                        times[style].append(run_replay(args.build, style, cap, tmp + "/out"))
                    else:
                        times[style].append(run_demo(args.build, style, argv, frames))
            base = statistics.median(times["none"])
            native = statistics.median(times["native"]) if times.get("native") else None
            row = {"case": name, "unit": "ms per frame" if not cap else "ms per replay",
                   "none": base, "native": native, "styles": {}}
            for style in styles:
                if style == "none" or not times[style]:
                    continue
                med = statistics.median(times[style])
                row["styles"][style] = {"median": med, "min": min(times[style]),
                                        "max": max(times[style]), "ratio": med / base,
                                        "native_ratio": med / native if native else None}
            results.append(row)
            if not args.json:
                print(f"{name}: none {base:.3f} {row['unit']}")
                for style, r in row["styles"].items():
                    vs_native = (f"  x native {r['native_ratio']:.2f}"
                                 if r["native_ratio"] else "")
                    print(f"    {style:16s} {r['median']:9.3f}  ratio {r['ratio']:.2f}"
                          f"{vs_native}  ({r['min']:.3f}-{r['max']:.3f})")
                sys.stdout.flush()
    except RunFailed as e:
        print(f"style_bench: {e}", file=sys.stderr)
        return 1
    if args.json:
        print(json.dumps(results, indent=2))
    return 0


if __name__ == "__main__":
    sys.exit(main())
