#!/usr/bin/env python3
"""Recording and replay: nprgl vs apitrace, side by side in one run.

For each case (a demo app with fixed arguments and a fixed frame count, GLX window mode under
DISPLAY, one surface size for all) the script runs, alternately and RUNS times each:

  native     the demo on its own
  nprgl      `nprgl record -o FILE.nprgl -- DEMO ...`
  apitrace   `apitrace trace --api gl -o FILE.trace DEMO ...`

and reads the fps from the demo's own `--report` line (the frame loop only: start-up, context
creation and whatever a tool does at exit are excluded; the whole-process wall time of each
run is kept in the JSON too). It reports the median fps of each, the ratio recording fps /
native fps for both tools (overhead = 1 - ratio) and the bytes per frame of each file (file
size / frames).

Then it replays the files recorded from the same program and frames, alternately, RUNS times
each: `nprgl replay FILE.nprgl -o DIR --frames N` (OSMesa, headless; --frames N writes the PNG
of the last frame only, every frame is still executed) against `glretrace -b FILE.trace` (GLX
window on DISPLAY) and `glretrace -b --headless FILE.trace`. Replay fps = frames / wall seconds
of the whole process (start-up, reading and decompressing the file, context creation and one
PNG for nprgl included).

Targets (capture issue, item 8), reported, never enforced:
  - nprgl's recording overhead at most half of apitrace's;
  - nprgl's files at most a quarter of apitrace's size on the immediate-mode demo;
  - nprgl replay at least as fast as `glretrace -b`.

The binaries are copied into a temporary directory first, so that a rebuild during the run
cannot mix two builds; every file goes there and the directory is removed at exit (--keep
leaves it). The exit status is 0 whatever the figures are, 1 if a run failed (non-zero exit,
no --report line, fewer frames than asked, a missing file), 2 on bad usage.

Python 3 standard library only.
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from benchlib import RunFailed, clean_env, report_fps  # noqa: E402

GLRETRACE_RE = re.compile(r"Rendered (\d+) frames in ([0-9.eE+-]+) secs")
INFO_FRAMES_RE = re.compile(r"^frames:\s+(\d+)", re.M)
INFO_CALL_RE = re.compile(r"^\s+(\d+)\s+(gl\w+)\s*$", re.M)
REPO_ROOT = Path(__file__).resolve().parent.parent

OVERHEAD_SHARE_TARGET = 0.5  # nprgl overhead <= this * apitrace overhead
SIZE_RATIO_TARGET = 0.25     # nprgl bytes <= this * apitrace bytes (immediate-mode demo)
REPLAY_RATIO_TARGET = 1.0    # nprgl replay fps >= this * glretrace -b fps


@dataclass
class Case:
    name: str
    program: str
    extra_args: list[str]
    frames: int  # fixed: a few seconds natively on a 2-core llvmpipe machine
    immediate: bool  # the size target is stated for the immediate-mode demo


CASES = [
    Case("immediate-1", "demo_immediate", ["--detail", "1"], 1000, True),        # ~3.8k vertices
    Case("immediate-275", "demo_immediate", ["--detail", "275"], 20, True),      # ~1M vertices
    Case("displaylist", "demo_displaylist", [], 3000, False),
    Case("arrays", "demo_arrays", [], 300, False),  # apitrace: ~7 MB per frame
]

REC_VARIANTS = ["native", "nprgl", "apitrace"]
REPLAY_VARIANTS = ["nprgl replay", "glretrace -b", "glretrace -b --headless"]


@dataclass
class Result:
    case: Case
    frames: int
    fps: dict[str, list[float]] = field(default_factory=lambda: {v: [] for v in REC_VARIANTS})
    wall: dict[str, list[float]] = field(default_factory=lambda: {v: [] for v in REC_VARIANTS})
    sizes: dict[str, list[int]] = field(default_factory=lambda: {"nprgl": [], "apitrace": []})
    replay_wall: dict[str, list[float]] = field(
        default_factory=lambda: {v: [] for v in REPLAY_VARIANTS})
    glretrace_inner_fps: dict[str, list[float]] = field(
        default_factory=lambda: {v: [] for v in REPLAY_VARIANTS[1:]})
    nprgl_calls: dict[str, int] = field(default_factory=dict)

    def med_fps(self, variant: str) -> float:
        return statistics.median(self.fps[variant])

    def ratio(self, tool: str) -> float:
        return self.med_fps(tool) / self.med_fps("native")

    def overhead(self, tool: str) -> float:
        return 1.0 - self.ratio(tool)

    def paired_ratio(self, tool: str) -> float:
        return statistics.median(t / n for n, t in zip(self.fps["native"], self.fps[tool]))

    def bytes_per_frame(self, tool: str) -> float:
        return statistics.median(self.sizes[tool]) / self.frames

    def size_ratio(self) -> float:
        return self.bytes_per_frame("nprgl") / self.bytes_per_frame("apitrace")

    def replay_fps(self, variant: str) -> list[float]:
        return [self.frames / w for w in self.replay_wall[variant]]

    def med_replay_fps(self, variant: str) -> float:
        return statistics.median(self.replay_fps(variant))

    def replay_ratio(self, variant: str = "glretrace -b") -> float:
        return self.med_replay_fps("nprgl replay") / self.med_replay_fps(variant)

    def overhead_met(self) -> bool:
        return self.overhead("nprgl") <= OVERHEAD_SHARE_TARGET * self.overhead("apitrace")

    def size_met(self) -> bool:
        return self.size_ratio() <= SIZE_RATIO_TARGET

    def replay_met(self) -> bool:
        return self.replay_ratio() >= REPLAY_RATIO_TARGET

    def as_dict(self) -> dict:
        d = {
            "case": self.case.name,
            "command": [self.case.program, *self.case.extra_args],
            "frames": self.frames,
            "record_fps": self.fps,
            "record_wall_seconds": self.wall,
            "record_fps_median": {v: self.med_fps(v) for v in REC_VARIANTS},
            "file_bytes": self.sizes,
            "bytes_per_frame": {t: self.bytes_per_frame(t) for t in ("nprgl", "apitrace")},
            "size_ratio_nprgl_over_apitrace": self.size_ratio(),
            "replay_wall_seconds": self.replay_wall,
            "replay_fps": {v: self.replay_fps(v) for v in REPLAY_VARIANTS},
            "replay_fps_median": {v: self.med_replay_fps(v) for v in REPLAY_VARIANTS},
            "glretrace_own_fps": self.glretrace_inner_fps,
            "nprgl_calls_by_name": self.nprgl_calls,
            "targets": {
                "overhead_nprgl_at_most_half_of_apitrace": self.overhead_met(),
                "size_at_most_quarter": self.size_met(),
                "size_target_applies": self.case.immediate,
                "replay_at_least_glretrace_b": self.replay_met(),
            },
        }
        for tool in ("nprgl", "apitrace"):
            d[f"{tool}_ratio_of_medians"] = self.ratio(tool)
            d[f"{tool}_median_of_paired_ratios"] = self.paired_ratio(tool)
            d[f"{tool}_overhead"] = self.overhead(tool)
        d["replay_ratio_nprgl_over_glretrace_b"] = self.replay_ratio("glretrace -b")
        d["replay_ratio_nprgl_over_glretrace_b_headless"] = self.replay_ratio(
            "glretrace -b --headless")
        return d




# A shared X server sometimes refuses a connection for a moment (other clients' tests); such a
# run has not started and is repeated, at most DISPLAY_ATTEMPTS times in all.
DISPLAY_REFUSED_RE = re.compile(r"(unable to|cannot|can't) open (X )?display", re.I)
DISPLAY_ATTEMPTS = 3
display_retries = 0


def run(cmd: list[str], env: dict[str, str], hang_guard: float) -> tuple[float, str, str]:
    """Runs cmd; returns (wall seconds, stdout, stderr). Raises RunFailed on failure."""
    global display_retries
    for attempt in range(1, DISPLAY_ATTEMPTS + 1):
        start = time.monotonic()
        try:
            proc = subprocess.run(cmd, env=env, stdin=subprocess.DEVNULL, capture_output=True,
                                  text=True, errors="replace", timeout=hang_guard)
        except subprocess.TimeoutExpired as exc:
            # A hang guard, not a performance check: the bound is many times the expected time.
            raise RunFailed(f"no exit after {hang_guard:.0f} s (hung?): {' '.join(cmd)}") \
                from exc
        except OSError as exc:
            raise RunFailed(f"cannot run {cmd[0]}: {exc}") from exc
        wall = time.monotonic() - start
        if (proc.returncode != 0 and attempt < DISPLAY_ATTEMPTS
                and DISPLAY_REFUSED_RE.search(proc.stderr)):
            display_retries += 1
            print(f"  (the X server refused a connection; running again: {' '.join(cmd)})",
                  file=sys.stderr, flush=True)
            time.sleep(1.0)
            continue
        break
    if proc.returncode != 0:
        raise RunFailed(f"exit status {proc.returncode}: {' '.join(cmd)}\n"
                        f"{proc.stderr.strip()[-2000:]}")
    return wall, proc.stdout, proc.stderr


def file_size(path: Path, cmd: list[str]) -> int:
    try:
        size = path.stat().st_size
    except OSError as exc:
        raise RunFailed(f"no file {path} after: {' '.join(cmd)}") from exc
    if size == 0:
        raise RunFailed(f"empty file {path} after: {' '.join(cmd)}")
    return size


def copy_binaries(build_dir: Path, dest: Path, programs: list[str]) -> Path:
    """Copies nprgl, libnprgl.so and the demos to dest/{bin,lib}; returns dest/bin."""
    (dest / "bin").mkdir(parents=True)
    (dest / "lib").mkdir()
    for name in ["nprgl", *programs]:
        shutil.copy2(build_dir / "bin" / name, dest / "bin" / name)
    shutil.copy2(build_dir / "lib" / "libnprgl.so", dest / "lib" / "libnprgl.so")
    return dest / "bin"


def fmt_fps(v: float) -> str:
    return f"{v:.0f}" if v >= 1000 else f"{v:.1f}" if v >= 100 else f"{v:.2f}"


def fmt_range(values: list[float]) -> str:
    return (f"{fmt_fps(statistics.median(values))} "
            f"({fmt_fps(min(values))}-{fmt_fps(max(values))})")


def fmt_bytes(v: float) -> str:
    for unit, scale in (("MB", 1e6), ("kB", 1e3)):
        if v >= scale:
            return f"{v / scale:.2f} {unit}" if v < 100 * scale else f"{v / scale:.0f} {unit}"
    return f"{v:.0f} B"


def yes_no(ok: bool) -> str:
    return "yes" if ok else "NO"


def print_table(headers: list[str], rows: list[list[str]], out=sys.stdout) -> None:
    widths = [max(len(h), *(len(row[i]) for row in rows)) for i, h in enumerate(headers)]
    print("  ".join(h.ljust(w) for h, w in zip(headers, widths)).rstrip(), file=out)
    print("  ".join("-" * w for w in widths), file=out)
    for row in rows:
        print("  ".join(c.ljust(w) for c, w in zip(row, widths)).rstrip(), file=out)


def print_results(results: list[Result], runs: int, size: str, out=sys.stdout) -> None:
    print(f"Recording (GLX window, {size}): fps from the demo's --report line, median "
          f"(min-max) of {runs}; ratio = tool median / native median; overhead = 1 - ratio; "
          f"target: nprgl overhead <= {OVERHEAD_SHARE_TARGET} x apitrace overhead", file=out)
    print_table(
        ["case", "frames", "native fps", "nprgl record fps", "apitrace trace fps",
         "nprgl ratio", "apitrace ratio", "nprgl overhead", "apitrace overhead", "target met"],
        [[r.case.name, str(r.frames), fmt_range(r.fps["native"]), fmt_range(r.fps["nprgl"]),
          fmt_range(r.fps["apitrace"]), f"{r.ratio('nprgl'):.3f}",
          f"{r.ratio('apitrace'):.3f}", f"{r.overhead('nprgl'):.1%}",
          f"{r.overhead('apitrace'):.1%}", yes_no(r.overhead_met())] for r in results],
        out)
    print(file=out)
    print(f"File size: bytes per frame = file size / frames; target (immediate-mode demo): "
          f"nprgl <= {SIZE_RATIO_TARGET} x apitrace", file=out)
    print_table(
        ["case", "frames", "nprgl bytes/frame", "apitrace bytes/frame", "nprgl / apitrace",
         "target met"],
        [[r.case.name, str(r.frames), fmt_bytes(r.bytes_per_frame("nprgl")),
          fmt_bytes(r.bytes_per_frame("apitrace")), f"{r.size_ratio():.3f}",
          yes_no(r.size_met()) if r.case.immediate else f"({yes_no(r.size_met())}, n/a)"]
         for r in results],
        out)
    print(file=out)
    print(f"Replay: fps = frames / wall seconds of the whole process (start-up, file reading "
          f"and context creation included; nprgl replay writes one PNG, the last frame), "
          f"median (min-max) of {runs}; target: nprgl >= glretrace -b", file=out)
    print_table(
        ["case", "frames", "nprgl replay fps", "glretrace -b fps", "glretrace -b --headless fps",
         "nprgl / glretrace -b", "nprgl / --headless", "target met"],
        [[r.case.name, str(r.frames), fmt_range(r.replay_fps("nprgl replay")),
          fmt_range(r.replay_fps("glretrace -b")),
          fmt_range(r.replay_fps("glretrace -b --headless")),
          f"{r.replay_ratio('glretrace -b'):.2f}",
          f"{r.replay_ratio('glretrace -b --headless'):.2f}", yes_no(r.replay_met())]
         for r in results],
        out)


def tool_version(cmd: list[str]) -> str | None:
    try:
        out = subprocess.run(cmd, capture_output=True, text=True, timeout=30).stdout.strip()
        return out or None
    except (OSError, subprocess.TimeoutExpired):
        return None


def machine_info() -> dict:
    info: dict = {
        "cpus": os.cpu_count(),
        "platform": platform.platform(),
        "python": platform.python_version(),
        "apitrace_package": tool_version(["dpkg-query", "-W", "-f=${Version}", "apitrace"]),
    }
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                info["cpu_model"] = line.split(":", 1)[1].strip()
                break
        info["loadavg_at_end"] = Path("/proc/loadavg").read_text().split()[:3]
    except OSError:
        pass
    glxinfo = shutil.which("glxinfo")
    if glxinfo:
        out = tool_version([glxinfo, "-B"]) or ""
        for key in ("OpenGL renderer string", "OpenGL version string"):
            m = re.search(rf"^{key}: (.*)$", out, re.M)
            if m:
                info[key.replace(" ", "_").lower()] = m.group(1).strip()
    return info


def parse_args(argv: list[str]) -> argparse.Namespace:
    parser = argparse.ArgumentParser(
        description="Recording overhead, bytes per frame and replay speed: nprgl record / "
                    "replay vs apitrace trace / glretrace -b on the demo apps, run alternately.")
    parser.add_argument("--build-dir", type=Path, default=REPO_ROOT / "build",
                        help="the CMake build directory (default: %(default)s)")
    parser.add_argument("--runs", type=int, default=3,
                        help="measured runs of each variant per case (default %(default)s)")
    parser.add_argument("--size", default="512x512", help="window size (default %(default)s)")
    parser.add_argument("--case", action="append", choices=[c.name for c in CASES],
                        help="run only this case (repeatable; default: all)")
    parser.add_argument("--frames-scale", type=float, default=1.0,
                        help="multiply every case's frame count (default 1; e.g. 0.1 for a "
                             "smoke run)")
    parser.add_argument("--quick", action="store_true",
                        help="smoke run: 1 run of each, a tenth of the frames")
    parser.add_argument("--json", type=Path, metavar="FILE", help="also write the results here")
    parser.add_argument("--keep", action="store_true",
                        help="keep the temporary directory (captures, traces) and print it")
    args = parser.parse_args(argv)
    if args.quick:
        args.runs = 1
        args.frames_scale = 0.1
    if args.runs < 1:
        parser.error("--runs must be at least 1")
    if args.frames_scale <= 0:
        parser.error("--frames-scale must be positive")
    if not re.fullmatch(r"\d+x\d+", args.size):
        parser.error("--size must be WxH")
    if not os.environ.get("DISPLAY"):
        parser.error("needs DISPLAY (window mode for both tools), e.g. Xvfb :99 and DISPLAY=:99")
    return args


def measure_case(case: Case, frames: int, args, bins: Path, work: Path,
                 env: dict[str, str]) -> Result:
    nprgl = str(bins / "nprgl")
    demo = [str(bins / case.program), *case.extra_args, "--size", args.size, "--report"]
    nprgl_file = work / f"{case.name}.nprgl"
    trace_file = work / f"{case.name}.trace"
    png_dir = work / f"{case.name}.png"

    def native(n: int) -> list[str]:
        return [*demo, "--frames", str(n)]

    # Style none on both sides: apitrace records and glretrace replays the program's own
    # picture, so that is what is compared (the default style would add its rendering).
    def record(n: int) -> list[str]:
        return [nprgl, "record", "--style", "none", "-o", str(nprgl_file), "--", *native(n)]

    def trace(n: int) -> list[str]:
        return ["apitrace", "trace", "--api", "gl", "-o", str(trace_file), *native(n)]

    result = Result(case, frames)
    commands = {"native": native(frames), "nprgl": record(frames), "apitrace": trace(frames)}
    guard = 3600.0  # hang guard only

    # Warm-up, untimed: page cache, shader cache, first-run costs of each tool.
    warm = max(2, frames // 10)
    for cmd in (native(warm), record(warm), trace(warm)):
        _, out, err = run(cmd, env, guard)
        report_fps(cmd, out, err, warm)

    print(f"{case.name}: {frames} frames per run, {args.runs} runs of each, alternating "
          f"native / nprgl record / apitrace trace", file=sys.stderr, flush=True)
    for i in range(args.runs):
        for variant in REC_VARIANTS:
            cmd = commands[variant]
            wall, out, err = run(cmd, env, guard)
            result.fps[variant].append(report_fps(cmd, out, err, frames))
            result.wall[variant].append(wall)
            if variant == "nprgl":
                result.sizes["nprgl"].append(file_size(nprgl_file, cmd))
            elif variant == "apitrace":
                result.sizes["apitrace"].append(file_size(trace_file, cmd))
        print(f"  run {i + 1}/{args.runs}: native {fmt_fps(result.fps['native'][-1])}, "
              f"nprgl {fmt_fps(result.fps['nprgl'][-1])}, "
              f"apitrace {fmt_fps(result.fps['apitrace'][-1])} fps; "
              f"{result.sizes['nprgl'][-1]} / {result.sizes['apitrace'][-1]} bytes",
              file=sys.stderr, flush=True)

    # The capture of the last run: check it holds every frame, keep its calls by name.
    info_cmd = [nprgl, "info", str(nprgl_file)]
    _, out, _ = run(info_cmd, env, guard)
    m = INFO_FRAMES_RE.search(out)
    if not m or int(m.group(1)) != frames:
        raise RunFailed(f"{nprgl_file}: `nprgl info` shows {m.group(1) if m else 'no'} frames, "
                        f"{frames} recorded")
    result.nprgl_calls = {name: int(n) for n, name in INFO_CALL_RE.findall(out)}

    replay_cmds = {
        "nprgl replay": [nprgl, "replay", "--style", "none", str(nprgl_file), "-o",
                         str(png_dir), "--frames", str(frames)],
        "glretrace -b": ["glretrace", "-b", str(trace_file)],
        "glretrace -b --headless": ["glretrace", "-b", "--headless", str(trace_file)],
    }
    for cmd in replay_cmds.values():  # warm-up: the files into the page cache
        run(cmd, env, guard)
    print(f"{case.name}: replay, {args.runs} runs of each, alternating nprgl replay / "
          f"glretrace -b / glretrace -b --headless", file=sys.stderr, flush=True)
    for i in range(args.runs):
        for variant, cmd in replay_cmds.items():
            wall, out, err = run(cmd, env, guard)
            result.replay_wall[variant].append(wall)
            if variant == "nprgl replay":
                pngs = list(png_dir.glob("frame_*.png"))
                if len(pngs) != 1:
                    raise RunFailed(f"{len(pngs)} PNGs in {png_dir} after: {' '.join(cmd)}")
            else:
                m = GLRETRACE_RE.search(out + err)
                if not m or int(m.group(1)) < frames:
                    raise RunFailed(f"glretrace rendered {m.group(1) if m else 'no'} frames, "
                                    f"{frames} traced: {' '.join(cmd)}")
                result.glretrace_inner_fps[variant].append(int(m.group(1)) /
                                                           float(m.group(2)))
        print(f"  run {i + 1}/{args.runs}: " + ", ".join(
            f"{v} {fmt_fps(frames / result.replay_wall[v][-1])}" for v in REPLAY_VARIANTS)
            + " fps", file=sys.stderr, flush=True)

    # Free the disk space (a 1M-vertex trace is hundreds of MB) unless asked to keep it.
    if not args.keep:
        for path in (nprgl_file, trace_file):
            path.unlink(missing_ok=True)
        shutil.rmtree(png_dir, ignore_errors=True)
    return result


def main(argv: list[str]) -> int:
    args = parse_args(argv)
    build_dir = args.build_dir.resolve()
    cases = [c for c in CASES if not args.case or c.name in args.case]
    programs = sorted({c.program for c in cases})
    missing = [p for p in [build_dir / "bin" / "nprgl", build_dir / "lib" / "libnprgl.so",
                           *(build_dir / "bin" / p for p in programs)] if not p.is_file()]
    missing += [tool for tool in ("apitrace", "glretrace") if not shutil.which(tool)]
    if missing:
        print("capture_bench: missing (build first; apitrace: apt-get install apitrace): "
              + ", ".join(map(str, missing)), file=sys.stderr)
        return 1

    tmp = Path(tempfile.mkdtemp(prefix="nprgl-capture-bench-"))
    results: list[Result] = []
    status = 0
    try:
        bins = copy_binaries(build_dir, tmp / "snapshot", programs)
        work = tmp / "files"
        work.mkdir()
        env = clean_env()
        for case in cases:
            frames = max(2, round(case.frames * args.frames_scale))
            results.append(measure_case(case, frames, args, bins, work, env))
    except RunFailed as exc:
        print(f"capture_bench: run failed: {exc}", file=sys.stderr)
        status = 1
    except KeyboardInterrupt:
        print("capture_bench: interrupted", file=sys.stderr)
        status = 130
    finally:
        if args.keep:
            print(f"capture_bench: kept {tmp}", file=sys.stderr)
        else:
            shutil.rmtree(tmp, ignore_errors=True)

    if results:
        print()
        print_results(results, args.runs, args.size)
    if args.json and results:
        doc = {
            "benchmark": "capture_bench",
            "date_utc": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()),
            "command": [Path(sys.argv[0]).name, *argv],
            "complete": status == 0,
            "display_retries": display_retries,
            "runs": args.runs,
            "size": args.size,
            "mode": "window",
            "targets": {
                "nprgl_overhead_at_most_share_of_apitrace": OVERHEAD_SHARE_TARGET,
                "size_ratio_at_most": SIZE_RATIO_TARGET,
                "replay_ratio_at_least": REPLAY_RATIO_TARGET,
            },
            "machine": machine_info(),
            "results": [r.as_dict() for r in results],
        }
        args.json.parent.mkdir(parents=True, exist_ok=True)
        args.json.write_text(json.dumps(doc, indent=2) + "\n")
        print(f"wrote {args.json}", file=sys.stderr)
    return status


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
