#!/usr/bin/env python3
"""Outline quality per outline style: accuracy against analytic silhouettes, and flicker.

Each outline style runs alone over two animations, offscreen (OSMesa) at 512x512:
  shapes     demo_shapes turning by --step degrees a frame, with its ray-cast truth
  character  demo_character walking (Testwuson.X, skinned)
The program's own shading stays under an outline-only chain, so outline pixels are the pixels
that differ from the same frame rendered natively by more than --tolerance in any channel.
The figures come from bench/outline_metrics.py (imported as a module):
  precision, recall  shapes only, pooled over all frames: share of outline pixels within
                     1.5 px of a truth silhouette pixel, and of truth pixels within 1.5 px of
                     an outline pixel
  flicker            per pair of consecutive frames, outline pixels with no outline pixel of
                     the other frame within 2 px (the motion bound), over the outline pixels
                     of both; mean and max over the sequence
A first row, "motion baseline", is the flicker that the motion alone gives: of the truth
silhouettes (shapes) and of the object's boundary against the clear colour in the native
frames (character, whose limbs move more than 2 px a frame).
Styles: wireframe, perpixel, edges, strokes with visibility=depth and visibility=query,
pencil (its outlines: fill off, measured against pencil with outlines off, whose page is the
same paper) and blueprint (its lines alone, then with its grid and dimension lines, which
count as outline pixels that match no silhouette) when `nprgl styles` lists them.

  bench/outline_quality.py [--build DIR] [--frames N] [--step DEG] [--styles a,b,...]
                           [--keep DIR] [--json]

--styles takes case names (wireframe, perpixel, edges, strokes-depth, strokes-query, pencil,
blueprint-lines, blueprint);
--keep DIR keeps the rendered frames there. Python 3 standard library only; with 30 frames
the decoding dominates (a few minutes without Pillow). Exit status 0, or 1 if a run failed.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
from types import SimpleNamespace

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import outline_metrics as metrics  # noqa: E402
from benchlib import RunFailed, clean_env  # noqa: E402

MODEL = "/usr/share/assimp/models/X/Testwuson.X"
# Case name, style, --set values, and the reference: None for the native frames, else the
# --set values that render the same style without its outlines (for styles that also change
# the page or the surfaces, whose outline pixels are those the outlines alone change).
CASES = [
    ("wireframe", "wireframe", [], None),
    ("perpixel", "perpixel", [], None),
    ("edges", "edges", [], None),
    ("strokes-depth", "strokes", ["strokes.visibility=depth"], None),
    ("strokes-query", "strokes", ["strokes.visibility=query"], None),
    ("pencil", "pencil", ["pencil.fill=off"], ["pencil.fill=off", "pencil.outlines=off"]),
    ("blueprint-lines", "blueprint", ["blueprint.grid=0", "blueprint.dimensions=0"], None),
    ("blueprint", "blueprint", [], None),
]


def available(listing: str, style: str, settings: list[str]) -> bool:
    """Whether `nprgl styles` lists the style and every value the settings need."""
    if f"\n{style} [" not in listing:
        return False
    for setting in settings:
        key, value = setting.split("=", 1)
        lines = [line for line in listing.splitlines() if line.strip().startswith(key + " ")]
        if not lines or value not in lines[0]:
            return False
    return True


def run(cmd: list[str]) -> None:
    p = subprocess.run(cmd, capture_output=True, text=True, env=clean_env(), timeout=900)
    if p.returncode != 0:
        raise RunFailed(f"exit {p.returncode}: {' '.join(cmd)}\n{p.stderr[-2000:]}")


def app_args(build: str, app: str, frames: int, step: float, out: str) -> list[str]:
    bin_dir = os.path.join(build, "bin")
    common = ["--offscreen", "--size", "512x512", "--frames", str(frames), "--save-dir", out,
              "--save-frames", f"1-{frames}"]
    if app == "shapes":
        return [f"{bin_dir}/demo_shapes", "--step", str(step), *common]
    return [f"{bin_dir}/demo_character", "--model", MODEL, *common]


def frame_paths(directory: str, app: str, frames: int, suffix: str = "") -> list[str]:
    return [os.path.join(directory, f"{app}_{f}{suffix}.png") for f in range(1, frames + 1)]


def object_boundary(path: str, tolerance: int) -> "metrics.Mask":
    """Object pixels next to the clear colour (the top left pixel): the native silhouette."""
    width, height, rgb = metrics.read_rgb(path)
    background = rgb[0:3]
    fg = bytearray(max(abs(rgb[3 * i + c] - background[c]) for c in range(3)) > tolerance
                   for i in range(width * height))
    flags = bytearray(width * height)
    for i in range(width * height):
        if not fg[i]:
            continue
        y, x = divmod(i, width)
        flags[i] = any(0 <= nx < width and 0 <= ny < height and not fg[ny * width + nx]
                       for nx, ny in ((x - 1, y), (x + 1, y), (x, y - 1), (x, y + 1)))
    return metrics.Mask(width, height, flags)


def flicker(masks: list, radius: float = 2.0) -> tuple[float, float]:
    """Mean and max flicker over consecutive frames, as outline_metrics.py flicker."""
    offsets = metrics.disc_offsets(radius)
    values = []
    for a, b in zip(masks, masks[1:]):
        appeared = len(b) - metrics.count_near(b, a, offsets)
        vanished = len(a) - metrics.count_near(a, b, offsets)
        total = len(a) + len(b)
        values.append((appeared + vanished) / total if total else 0.0)
    return sum(values) / len(values), max(values)


def accuracy(masks: list, truths: list, radius: float = 1.5) -> tuple[float, float]:
    """Pooled precision and recall, as outline_metrics.py accuracy."""
    offsets = metrics.disc_offsets(radius)
    near, outline, covered, truth = 0, 0, 0, 0
    for m, t in zip(masks, truths):
        near += metrics.count_near(m, t, offsets)
        covered += metrics.count_near(t, m, offsets)
        outline += len(m)
        truth += len(t)
    return metrics.ratio(near, outline), metrics.ratio(covered, truth)


def measure(args, work: str, cases: list) -> list[dict]:
    options = SimpleNamespace(tolerance=args.tolerance, ink_colour=None, ink_threshold=64.0)
    nprgl = os.path.join(args.build, "bin", "nprgl")
    native, truths = {}, None
    for app in ("shapes", "character"):
        out = os.path.join(work, f"native_{app}")
        cmd = app_args(args.build, app, args.frames, args.step, out)
        run(cmd + (["--truth", out] if app == "shapes" else []))
        native[app] = frame_paths(out, app, args.frames)
        if app == "shapes":
            truths = [metrics.truth_mask(p) for p in frame_paths(out, app, args.frames, "_truth")]
    # What the motion alone gives: the analytic silhouettes of shapes, the object's outer
    # boundary in the native character frames.
    baseline = {"case": "motion baseline", "style": "", "settings": [], "precision": None,
                "recall": None}
    boundaries = [object_boundary(p, args.tolerance) for p in native["character"]]
    for app, masks in (("shapes", truths), ("character", boundaries)):
        baseline[f"{app}_outline_pixels"] = sum(len(m) for m in masks) / len(masks)
        baseline[f"{app}_flicker_mean"], baseline[f"{app}_flicker_max"] = flicker(masks)
    rows = [baseline]
    def styled(out: str, app: str, style: str, settings: list[str]) -> list[str]:
        cmd = [nprgl, "--style", style]
        for setting in settings:
            cmd += ["--set", setting]
        run(cmd + ["--", *app_args(args.build, app, args.frames, args.step, out)])
        return frame_paths(out, app, args.frames)

    for name, style, settings, reference in cases:
        row = {"case": name, "style": style, "settings": settings}
        for app in ("shapes", "character"):
            frames = styled(os.path.join(work, f"{name}_{app}"), app, style, settings)
            refs = native[app] if reference is None else \
                styled(os.path.join(work, f"{name}_{app}_reference"), app, style, reference)
            masks = [metrics.outline_mask(p, options, ref) for p, ref in zip(frames, refs)]
            row[f"{app}_outline_pixels"] = sum(len(m) for m in masks) / len(masks)
            row[f"{app}_flicker_mean"], row[f"{app}_flicker_max"] = flicker(masks)
            if app == "shapes":
                row["precision"], row["recall"] = accuracy(masks, truths)
        print(f"outline_quality: {name} done", file=sys.stderr)
        rows.append(row)
    return rows


def fmt(value) -> str:
    return "-" if value is None else f"{value:.3f}"


def main() -> int:
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", default=os.path.join(here, "..", "build"))
    ap.add_argument("--frames", type=int, default=30)
    ap.add_argument("--step", type=float, default=0.5, help="shapes: degrees per frame")
    ap.add_argument("--tolerance", type=int, default=24)
    ap.add_argument("--styles", default=",".join(c[0] for c in CASES))
    ap.add_argument("--keep", metavar="DIR", help="keep the rendered frames in DIR")
    ap.add_argument("--json", action="store_true")
    args = ap.parse_args()
    if args.frames < 2:
        ap.error("--frames must be at least 2")

    listing = subprocess.run([os.path.join(args.build, "bin", "nprgl"), "styles"],
                             capture_output=True, text=True).stdout
    wanted = args.styles.split(",")
    cases, missing = [], []
    for case in CASES:
        if case[0] not in wanted:
            continue
        (cases if available(listing, case[1], case[2]) else missing).append(case)
    for name, *_ in missing:
        print(f"outline_quality: {name} is not available in this build, skipped",
              file=sys.stderr)

    try:
        if args.keep:
            os.makedirs(args.keep, exist_ok=True)
            rows = measure(args, args.keep, cases)
        else:
            with tempfile.TemporaryDirectory(prefix="outline_quality-") as work:
                rows = measure(args, work, cases)
    except (RunFailed, metrics.PngError, subprocess.TimeoutExpired) as error:
        print(f"outline_quality: {error}", file=sys.stderr)
        return 1

    if args.json:
        json.dump(rows, sys.stdout, indent=2)
        print()
        return 0
    print(f"{args.frames} frames at 512x512; shapes step {args.step} deg; character "
          f"{os.path.basename(MODEL)}; tolerance {args.tolerance}; accuracy radius 1.5 px, "
          "flicker radius 2 px")
    print("| style | precision | recall | shapes flicker mean | shapes flicker max "
          "| character flicker mean | character flicker max |")
    print("|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['case']} | {fmt(r['precision'])} | {fmt(r['recall'])} "
              f"| {fmt(r['shapes_flicker_mean'])} | {fmt(r['shapes_flicker_max'])} "
              f"| {fmt(r['character_flicker_mean'])} | {fmt(r['character_flicker_max'])} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
