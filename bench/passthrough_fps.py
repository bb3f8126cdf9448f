#!/usr/bin/env python3
"""Passthrough overhead: frames per second native vs `nprgl --style none`.

For each case (the immediate-mode demo at about 1M vertices per frame, the display-list
demo) and each surface mode (GLX window, OSMesa offscreen), the script runs the demo natively
(A) and under `nprgl run --style none` (B) alternately, A B A B ..., so that both share the
machine's drift and noise. The fps figures are the demos' own `--report` lines, which time
the frame loop only (start-up and context creation are excluded).

It prints, per case: native median fps (min-max), nprgl median fps (min-max), the ratio of
the medians (nprgl / native) and whether that ratio meets the target (0.97).

A benchmark reports; it does not judge noise. The exit status is 0 whatever the ratios are,
1 if a run failed (non-zero exit, no --report line, fewer frames than asked), 2 on bad usage.

Python 3 standard library only.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import platform
import re
import shutil
import statistics
import subprocess
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from benchlib import RunFailed, clean_env, report_fps  # noqa: E402

TARGET_RATIO = 0.97
REPO_ROOT = Path(__file__).resolve().parent.parent


@dataclass
class Case:
    name: str
    program: str
    extra_args: list[str]
    calibration_frames: int  # short native run used to pick the frame count
    min_frames: int


CASES = [
    # --detail 275 gives 1,002,450 vertices per frame (the demo prints the exact count).
    Case("immediate", "demo_immediate", ["--detail", "275"], calibration_frames=6, min_frames=3),
    Case("displaylist", "demo_displaylist", [], calibration_frames=300, min_frames=50),
]


@dataclass
class Result:
    case: str
    mode: str
    frames: int
    native_fps: list[float] = field(default_factory=list)
    nprgl_fps: list[float] = field(default_factory=list)

    @property
    def label(self) -> str:
        return f"{self.case} ({self.mode})"

    def ratio(self) -> float:
        return statistics.median(self.nprgl_fps) / statistics.median(self.native_fps)

    def paired_ratio(self) -> float:
        return statistics.median(b / a for a, b in zip(self.native_fps, self.nprgl_fps))

    def as_dict(self) -> dict:
        ratio = self.ratio()
        return {
            "case": self.case,
            "mode": self.mode,
            "frames": self.frames,
            "native_fps": self.native_fps,
            "nprgl_fps": self.nprgl_fps,
            "native_median": statistics.median(self.native_fps),
            "nprgl_median": statistics.median(self.nprgl_fps),
            "ratio_of_medians": ratio,
            "median_of_paired_ratios": self.paired_ratio(),
            "target": TARGET_RATIO,
            "meets_target": ratio >= TARGET_RATIO,
        }




def run_env(mode: str) -> dict[str, str]:
    """The environment for both variants; offscreen runs must not depend on an X server."""
    env = clean_env()
    if mode == "offscreen":
        env.pop("DISPLAY", None)
    return env


def demo_command(bin_dir: Path, case: Case, frames: int, size: str, mode: str) -> list[str]:
    cmd = [str(bin_dir / case.program), *case.extra_args, "--frames", str(frames),
           "--size", size, "--report"]
    if mode == "offscreen":
        cmd.append("--offscreen")
    return cmd


def run_once(cmd: list[str], env: dict[str, str], frames: int, hang_guard: float) -> float:
    """Runs one command and returns the fps from its --report line."""
    try:
        proc = subprocess.run(cmd, env=env, stdin=subprocess.DEVNULL, capture_output=True,
                              text=True, timeout=hang_guard)
    except subprocess.TimeoutExpired as exc:
        # A hang guard, not a performance check: the bound is many times the expected time.
        raise RunFailed(f"no exit after {hang_guard:.0f} s (hung?): {' '.join(cmd)}") from exc
    except OSError as exc:
        raise RunFailed(f"cannot run {cmd[0]}: {exc}") from exc
    if proc.returncode != 0:
        raise RunFailed(f"exit status {proc.returncode}: {' '.join(cmd)}\n"
                        f"{proc.stderr.strip()}")
    return report_fps(cmd, proc.stdout, proc.stderr, frames)


def fmt_fps(values: list[float]) -> str:
    def f(v: float) -> str:
        return f"{v:.1f}" if v >= 100 else f"{v:.2f}"
    return f"{f(statistics.median(values))} ({f(min(values))}-{f(max(values))})"


def print_table(results: list[Result], runs: int, out=sys.stdout) -> None:
    headers = ["case", "frames", f"native fps, median (min-max) of {runs}",
               "nprgl --style none fps", "ratio", f">= {TARGET_RATIO}"]
    rows = [[r.label, str(r.frames), fmt_fps(r.native_fps), fmt_fps(r.nprgl_fps),
             f"{r.ratio():.3f}", "yes" if r.ratio() >= TARGET_RATIO else "NO"]
            for r in results]
    widths = [max(len(h), *(len(row[i]) for row in rows)) for i, h in enumerate(headers)]
    line = "  ".join(h.ljust(w) for h, w in zip(headers, widths))
    print(line, file=out)
    print("  ".join("-" * w for w in widths), file=out)
    for row in rows:
        print("  ".join(c.ljust(w) for c, w in zip(row, widths)), file=out)


def machine_info(modes: list[str]) -> dict:
    info: dict = {
        "cpus": os.cpu_count(),
        "platform": platform.platform(),
        "python": platform.python_version(),
    }
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                info["cpu_model"] = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    glxinfo = shutil.which("glxinfo")
    if "window" in modes and glxinfo and os.environ.get("DISPLAY"):
        try:
            out = subprocess.run([glxinfo, "-B"], capture_output=True, text=True,
                                 timeout=30).stdout
            for key in ("OpenGL renderer string", "OpenGL version string"):
                m = re.search(rf"^{key}: (.*)$", out, re.M)
                if m:
                    info[key.replace(" ", "_").lower()] = m.group(1).strip()
        except (OSError, subprocess.TimeoutExpired):
            pass
    return info


def parse_args(argv: list[str]) -> argparse.Namespace:
    parser = argparse.ArgumentParser(
        description="Frames per second of the demo apps, native vs `nprgl --style none`, "
                    "run alternately; prints the ratio (target >= %.2f)." % TARGET_RATIO)
    parser.add_argument("--build-dir", type=Path, default=REPO_ROOT / "build",
                        help="the CMake build directory (default: %(default)s)")
    parser.add_argument("--runs", type=int, default=None,
                        help="measured runs of each variant per case (default 5; --quick 2)")
    mode = parser.add_mutually_exclusive_group()
    mode.add_argument("--mode", choices=["window", "offscreen", "both"], default=None,
                      help="surface: GLX window, OSMesa offscreen, or both "
                           "(default: window if DISPLAY is set, else offscreen)")
    mode.add_argument("--window", dest="mode", action="store_const", const="window",
                      help="same as --mode window")
    mode.add_argument("--offscreen", dest="mode", action="store_const", const="offscreen",
                      help="same as --mode offscreen")
    parser.add_argument("--seconds", type=float, default=None,
                        help="approximate length of one run, used to pick the frame count "
                             "(default 3; --quick 0.3)")
    parser.add_argument("--size", default="512x512", help="surface size (default %(default)s)")
    parser.add_argument("--case", action="append", choices=[c.name for c in CASES],
                        help="run only this case (repeatable; default: all)")
    parser.add_argument("--quick", action="store_true",
                        help="short smoke run: 2 runs of about 0.3 s each")
    parser.add_argument("--json", type=Path, metavar="FILE", help="also write the results here")
    args = parser.parse_args(argv)

    if args.runs is None:
        args.runs = 2 if args.quick else 5
    if args.seconds is None:
        args.seconds = 0.3 if args.quick else 3.0
    if args.runs < 1:
        parser.error("--runs must be at least 1")
    if args.seconds <= 0:
        parser.error("--seconds must be positive")
    if not re.fullmatch(r"\d+x\d+", args.size):
        parser.error("--size must be WxH")
    if args.mode is None:
        args.mode = "window" if os.environ.get("DISPLAY") else "offscreen"
    args.modes = ["window", "offscreen"] if args.mode == "both" else [args.mode]
    if "window" in args.modes and not os.environ.get("DISPLAY"):
        parser.error("window mode needs DISPLAY (e.g. Xvfb :99; DISPLAY=:99), or use --offscreen")
    return args


def main(argv: list[str]) -> int:
    args = parse_args(argv)
    build_dir = args.build_dir.resolve()
    bin_dir = build_dir / "bin"
    nprgl = bin_dir / "nprgl"
    cases = [c for c in CASES if not args.case or c.name in args.case]
    missing = [p for p in [nprgl, *(bin_dir / c.program for c in cases)] if not p.is_file()]
    if missing:
        print("passthrough_fps: missing (build first): " + ", ".join(map(str, missing)),
              file=sys.stderr)
        return 1

    results: list[Result] = []
    try:
        for mode in args.modes:
            env = run_env(mode)
            for case in cases:
                # Calibration: one short native run picks the frame count for ~--seconds. It is
                # also the warm-up (page cache, shader cache); one untimed nprgl run follows.
                calib = demo_command(bin_dir, case, case.calibration_frames, args.size, mode)
                calib_fps = run_once(calib, env, case.calibration_frames, hang_guard=600)
                frames = max(case.min_frames, math.ceil(calib_fps * args.seconds))
                native = demo_command(bin_dir, case, frames, args.size, mode)
                wrapped = [str(nprgl), "run", "--style", "none", "--", *native]
                hang_guard = max(120.0, 20.0 * args.seconds)
                run_once([str(nprgl), "run", "--style", "none", "--", *calib], env,
                         case.calibration_frames, hang_guard=600)

                result = Result(case.name, mode, frames)
                print(f"{result.label}: {frames} frames per run, {args.runs} runs of each, "
                      f"alternating native / nprgl", file=sys.stderr, flush=True)
                for i in range(args.runs):
                    result.native_fps.append(run_once(native, env, frames, hang_guard))
                    result.nprgl_fps.append(run_once(wrapped, env, frames, hang_guard))
                    print(f"  run {i + 1}/{args.runs}: native {result.native_fps[-1]:.2f} fps, "
                          f"nprgl {result.nprgl_fps[-1]:.2f} fps", file=sys.stderr, flush=True)
                results.append(result)
    except RunFailed as exc:
        print(f"passthrough_fps: run failed: {exc}", file=sys.stderr)
        if results:
            print_table(results, args.runs)
        return 1

    print()
    print(f"Passthrough overhead, fps native vs `nprgl --style none` (size {args.size}, "
          f"ratio = nprgl median / native median, target >= {TARGET_RATIO})")
    print_table(results, args.runs)

    if args.json:
        doc = {
            "benchmark": "passthrough_fps",
            "date_utc": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()),
            "command": [Path(sys.argv[0]).name, *argv],
            "runs": args.runs,
            "seconds_per_run": args.seconds,
            "size": args.size,
            "target_ratio": TARGET_RATIO,
            "machine": machine_info(args.modes),
            "results": [r.as_dict() for r in results],
        }
        args.json.parent.mkdir(parents=True, exist_ok=True)
        args.json.write_text(json.dumps(doc, indent=2) + "\n")
        print(f"wrote {args.json}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
