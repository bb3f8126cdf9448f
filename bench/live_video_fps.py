#!/usr/bin/env python3
"""What `nprgl run --video` costs the program: its fps with and without the video.

The display-list demo runs in a GLX window under `nprgl run` in one style, without (A) and
with `--video` (B), alternately A B A B ..., so that both share the machine's drift. The fps
figures are the demo's own `--report` lines (the frame loop only). Per size it prints both
medians (min-max), the ratio B/A of the medians, and from nprgl's summary lines how many of
the program's frames the video took and how many it left while the one before was still on
its way (the program never waits for the encoder).

A benchmark reports; it does not judge. Exit status 0 whatever the figures, 1 when a run
failed, 2 on bad usage. It writes only inside a temporary directory of its own. Python 3
standard library only.
"""

from __future__ import annotations

import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from benchlib import RunFailed, clean_env, report_fps  # noqa: E402

SUMMARY_RE = re.compile(r"video \S+: .* from (\d+) frames? of process \d+ \(frames \d+ to \d+\)"
                        r"(?:; (\d+) not taken)?")


def run(cmd: list[str], frames: int, env: dict[str, str]) -> tuple[float, int, int]:
    done = subprocess.run(cmd, env=env, capture_output=True, text=True, timeout=600)
    if done.returncode != 0:
        raise RunFailed(f"exit {done.returncode}: {' '.join(cmd)}\n{done.stderr[-2000:]}")
    fps = report_fps(cmd, done.stdout, done.stderr, frames)
    taken = dropped = 0
    for match in SUMMARY_RE.finditer(done.stderr):
        taken += int(match.group(1))
        dropped += int(match.group(2) or 0)
    return fps, taken, dropped


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", default=str(Path(__file__).resolve().parent.parent / "build"))
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--frames", type=int, default=300)
    parser.add_argument("--style", default="toon+paper+edges")
    parser.add_argument("--sizes", default="512x512,1280x720")
    args = parser.parse_args()
    if args.runs < 1 or args.frames < 1:
        parser.error("--runs and --frames must be at least 1")
    if "DISPLAY" not in os.environ:
        parser.error("needs an X display (scripts/with-display.sh)")
    nprgl = str(Path(args.build) / "bin" / "nprgl")
    demo = str(Path(args.build) / "bin" / "demo_displaylist")
    env = clean_env()
    env["NPRGL_CONFIG_FILE"] = ""
    try:
        with tempfile.TemporaryDirectory(prefix="nprgl-video-bench-") as tmp:
            for size in args.sizes.split(","):
                program = ["--", demo, "--frames", str(args.frames), "--size", size, "--report"]
                plain = [nprgl, "run", "--style", args.style] + program
                video = [nprgl, "run", "--style", args.style, "--video",
                         f"{tmp}/bench.mp4"] + program
                a, b, taken, dropped = [], [], 0, 0
                for _ in range(args.runs):
                    a.append(run(plain, args.frames, env)[0])
                    fps, t, d = run(video, args.frames, env)
                    b.append(fps)
                    taken += t
                    dropped += d
                ma, mb = statistics.median(a), statistics.median(b)
                print(f"{size}: without video {ma:.1f} fps ({min(a):.1f}-{max(a):.1f}), "
                      f"with --video {mb:.1f} fps ({min(b):.1f}-{max(b):.1f}), "
                      f"ratio {mb / ma:.3f}; the video took {taken} of "
                      f"{args.frames * args.runs} frames ({dropped} left while the one before "
                      f"was on its way)")
    except RunFailed as failure:
        print(failure, file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
