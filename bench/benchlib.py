"""What the benchmark scripts share: reading a demo app's --report line."""
from __future__ import annotations

import os
import re

REPORT_RE = re.compile(r"^frames=(\d+) seconds=([0-9.eE+-]+) fps=([0-9.eE+-]+)\s*$", re.M)


class RunFailed(Exception):
    """A benchmark run that did not produce a usable figure."""


def report_fps(cmd: list[str], stdout: str, stderr: str, frames: int) -> float:
    """The fps of a demo's `frames=N seconds=S fps=F` line, checked against the frames asked."""
    matches = REPORT_RE.findall(stdout)
    if not matches:
        raise RunFailed(f"no 'frames=N seconds=S fps=F' line: {' '.join(cmd)}\n"
                        f"stdout: {stdout.strip()[-1000:]}\nstderr: {stderr.strip()[-1000:]}")
    done, seconds, fps = matches[-1]
    if int(done) != frames:
        raise RunFailed(f"{done} frames rendered, {frames} asked: {' '.join(cmd)}")
    if float(fps) <= 0.0:
        raise RunFailed(f"fps={fps} (seconds={seconds}): {' '.join(cmd)}")
    return float(fps)


def clean_env() -> dict[str, str]:
    """The environment for benchmark runs: no nprgl settings, no stray libnprgl preload."""
    env = {k: v for k, v in os.environ.items() if not k.startswith("NPRGL_")}
    preload = [p for p in re.split(r"[: ]+", env.get("LD_PRELOAD", "")) if p]
    preload = [p for p in preload if "libnprgl" not in os.path.basename(p)]
    if preload:
        env["LD_PRELOAD"] = ":".join(preload)
    else:
        env.pop("LD_PRELOAD", None)
    return env
