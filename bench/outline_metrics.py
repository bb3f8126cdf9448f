#!/usr/bin/env python3
"""Outline metrics: accuracy against an analytic truth, and temporal flicker.

Outline pixels of a rendered frame are found in one of three ways:
  --ink-threshold L     pixels whose luma (0.299 R + 0.587 G + 0.114 B, 0-255) is below L
                        (the default, with L = 64: dark ink on a lighter picture)
  --ink-colour R,G,B    pixels within --tolerance of that colour in every channel
  --reference PNG...    pixels that differ from a reference frame (the same frame rendered
                        with the shading style alone) by more than --tolerance in any channel
A truth silhouette PNG (demo_shapes --truth) marks silhouette pixels white on black.

accuracy FRAME TRUTH [FRAME TRUTH ...]
    precision = share of outline pixels within --radius (default 1.5 px, i.e. the 8
    neighbours) of a truth silhouette pixel; recall = share of truth silhouette pixels within
    --radius of an outline pixel. Pooled over all pairs as well as per pair.

flicker FRAME FRAME [FRAME ...]
    For consecutive frames t, t+1: appeared = outline pixels of t+1 with no outline pixel of t
    within --radius (the motion bound, default 2 px), vanished = outline pixels of t with none
    of t+1 within --radius; flicker = (appeared + vanished) / (outline pixels of t + of t+1).
    Reports every pair, and the mean and max over the sequence.

The result is one JSON object on stdout; ratios with an empty denominator are null.
Examples:
    outline_metrics.py accuracy out/shapes_5.png truth/shapes_5_truth.png --ink-threshold 60
    outline_metrics.py accuracy toon+edges/shapes_5.png truth/shapes_5_truth.png \\
        --reference toon/shapes_5.png --tolerance 24
    outline_metrics.py flicker out/shapes_{1..30}.png --radius 2

Needs only Python 3's standard library; uses Pillow for faster PNG decoding when present.
"""

import argparse
import json
import math
import struct
import sys
import zlib

try:
    from PIL import Image  # optional: about 50x faster decoding than the fallback below
except ImportError:  # pragma: no cover - depends on the interpreter
    Image = None


class PngError(Exception):
    pass


def _paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    if pa <= pb and pa <= pc:
        return a
    return b if pb <= pc else c


def _read_png_stdlib(path):
    """Decodes a non-interlaced PNG into (width, height, rgb bytes) with zlib alone."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise PngError(f"{path}: not a PNG file")
    pos, idat, palette = 8, [], None
    width = height = depth = colour_type = None
    while pos + 8 <= len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if len(body) != length:
            raise PngError(f"{path}: truncated chunk at offset {pos}")
        if kind == b"IHDR":
            width, height, depth, colour_type, _, _, interlace = struct.unpack(">IIBBBBB", body)
            if interlace:
                raise PngError(f"{path}: interlaced PNGs are not supported without Pillow")
        elif kind == b"PLTE":
            palette = body
        elif kind == b"IDAT":
            idat.append(body)
        elif kind == b"IEND":
            break
        pos += 12 + length
    if width is None:
        raise PngError(f"{path}: no IHDR chunk")
    channels = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}.get(colour_type)
    if channels is None or depth not in (8, 16) and not (colour_type == 3 and depth == 8):
        raise PngError(f"{path}: colour type {colour_type} depth {depth} is not supported")
    bpp = channels * depth // 8
    stride = width * bpp
    raw = zlib.decompress(b"".join(idat))
    if len(raw) < (stride + 1) * height:
        raise PngError(f"{path}: image data is truncated")
    previous = bytearray(stride)
    rows = []
    for y in range(height):
        start = y * (stride + 1)
        kind = raw[start]
        row = bytearray(raw[start + 1:start + 1 + stride])
        if kind == 1:
            for i in range(bpp, stride):
                row[i] = (row[i] + row[i - bpp]) & 0xFF
        elif kind == 2:
            row = bytearray((a + b) & 0xFF for a, b in zip(row, previous))
        elif kind == 3:
            for i in range(stride):
                left = row[i - bpp] if i >= bpp else 0
                row[i] = (row[i] + ((left + previous[i]) >> 1)) & 0xFF
        elif kind == 4:
            for i in range(stride):
                left = row[i - bpp] if i >= bpp else 0
                upper_left = previous[i - bpp] if i >= bpp else 0
                row[i] = (row[i] + _paeth(left, previous[i], upper_left)) & 0xFF
        elif kind != 0:
            raise PngError(f"{path}: bad filter type {kind} in row {y}")
        rows.append(row)
        previous = row
    pixels = b"".join(rows)
    if depth == 16:
        pixels = pixels[0::2]  # keep the high byte of each sample
    if colour_type == 3:
        if palette is None:
            raise PngError(f"{path}: palette image without PLTE")
        return width, height, b"".join(palette[3 * i:3 * i + 3] for i in pixels)
    if channels == 3:
        return width, height, bytes(pixels)
    out = bytearray(width * height * 3)
    if channels == 4:
        for c in range(3):
            out[c::3] = pixels[c::4]
    else:  # grey or grey + alpha
        grey = pixels[0::channels]
        for c in range(3):
            out[c::3] = grey
    return width, height, bytes(out)


def read_rgb(path):
    """Returns (width, height, rgb bytes, top row first)."""
    if Image is not None:
        try:
            with Image.open(path) as image:
                rgb = image.convert("RGB")
                return rgb.width, rgb.height, rgb.tobytes()
        except OSError as error:
            raise PngError(f"{path}: {error}") from error
    try:
        return _read_png_stdlib(path)
    except (OSError, zlib.error, struct.error) as error:
        raise PngError(f"{path}: {error}") from error


class Mask:
    """A set of marked pixels: a flat bytearray for lookups and the list of marked indices."""

    def __init__(self, width, height, flags):
        self.width, self.height, self.flags = width, height, flags
        self.indices = [i for i, v in enumerate(flags) if v]

    def __len__(self):
        return len(self.indices)


def luma_mask(width, height, rgb, predicate):
    r, g, b = rgb[0::3], rgb[1::3], rgb[2::3]
    flags = bytearray(predicate(0.299 * x + 0.587 * y + 0.114 * z) for x, y, z in zip(r, g, b))
    return Mask(width, height, flags)


def outline_mask(path, args, reference=None):
    width, height, rgb = read_rgb(path)
    if reference is not None:
        rw, rh, ref = read_rgb(reference)
        if (rw, rh) != (width, height):
            raise PngError(f"{reference}: {rw}x{rh}, but {path} is {width}x{height}")
        tolerance = args.tolerance
        differs = bytearray(abs(a - b) > tolerance for a, b in zip(rgb, ref))
        flags = bytearray(x | y | z for x, y, z in zip(differs[0::3], differs[1::3],
                                                      differs[2::3]))
        return Mask(width, height, flags)
    if args.ink_colour is not None:
        ink, tolerance = args.ink_colour, args.tolerance
        near = [bytearray(abs(v - ink[c]) <= tolerance for v in rgb[c::3]) for c in range(3)]
        flags = bytearray(x & y & z for x, y, z in zip(*near))
        return Mask(width, height, flags)
    threshold = args.ink_threshold
    return luma_mask(width, height, rgb, lambda luma: luma < threshold)


def truth_mask(path):
    width, height, rgb = read_rgb(path)
    return luma_mask(width, height, rgb, lambda luma: luma > 127.5)


def disc_offsets(radius):
    reach = int(math.floor(radius))
    return [(dx, dy) for dy in range(-reach, reach + 1) for dx in range(-reach, reach + 1)
            if dx * dx + dy * dy <= radius * radius + 1e-9]


def count_near(points, target, offsets):
    """How many pixels of points have a pixel of target within the disc of offsets."""
    width, height, flags = target.width, target.height, target.flags
    found = 0
    for index in points.indices:
        y, x = divmod(index, width)
        for dx, dy in offsets:
            nx, ny = x + dx, y + dy
            if 0 <= nx < width and 0 <= ny < height and flags[ny * width + nx]:
                found += 1
                break
    return found


def ratio(numerator, denominator):
    return numerator / denominator if denominator else None


def check_same_size(a, b, name_a, name_b):
    if (a.width, a.height) != (b.width, b.height):
        raise PngError(f"{name_a} is {a.width}x{a.height} but {name_b} is {b.width}x{b.height}")


def references_for(args, count):
    if not args.reference:
        return [None] * count
    if len(args.reference) != count:
        raise PngError(f"{len(args.reference)} reference(s) given for {count} frame(s)")
    return args.reference


def accuracy(args):
    if len(args.images) % 2:
        raise PngError("accuracy takes FRAME TRUTH pairs")
    frames, truths = args.images[0::2], args.images[1::2]
    offsets = disc_offsets(args.radius)
    results, totals = [], [0, 0, 0, 0]
    for frame, truth_path, reference in zip(frames, truths, references_for(args, len(frames))):
        outline = outline_mask(frame, args, reference)
        truth = truth_mask(truth_path)
        check_same_size(outline, truth, frame, truth_path)
        near_truth = count_near(outline, truth, offsets)
        covered = count_near(truth, outline, offsets)
        for i, v in enumerate((near_truth, len(outline), covered, len(truth))):
            totals[i] += v
        results.append({"frame": frame, "truth": truth_path, "outline_pixels": len(outline),
                        "truth_pixels": len(truth),
                        "precision": ratio(near_truth, len(outline)),
                        "recall": ratio(covered, len(truth))})
    precision, recall = ratio(totals[0], totals[1]), ratio(totals[2], totals[3])
    f1 = None
    if precision is not None and recall is not None and precision + recall > 0:
        f1 = 2 * precision * recall / (precision + recall)
    return {"metric": "accuracy", "radius": args.radius, "precision": precision,
            "recall": recall, "f1": f1, "frames": results}


def flicker(args):
    if len(args.images) < 2:
        raise PngError("flicker needs at least two consecutive frames")
    offsets = disc_offsets(args.radius)
    masks = [outline_mask(frame, args, reference)
             for frame, reference in zip(args.images, references_for(args, len(args.images)))]
    pairs = []
    for t in range(len(masks) - 1):
        a, b = masks[t], masks[t + 1]
        check_same_size(a, b, args.images[t], args.images[t + 1])
        appeared = len(b) - count_near(b, a, offsets)
        vanished = len(a) - count_near(a, b, offsets)
        total = len(a) + len(b)
        pairs.append({"from": args.images[t], "to": args.images[t + 1], "appeared": appeared,
                      "vanished": vanished, "outline_pixels": total,
                      "flicker": (appeared + vanished) / total if total else 0.0})
    values = [p["flicker"] for p in pairs]
    return {"metric": "flicker", "radius": args.radius, "pairs": pairs,
            "mean": sum(values) / len(values), "max": max(values)}


def parse_colour(text):
    try:
        parts = [int(p) for p in text.split(",")]
    except ValueError:
        parts = []
    if len(parts) != 3 or not all(0 <= p <= 255 for p in parts):
        raise argparse.ArgumentTypeError(f"expected R,G,B with 0-255 each, got '{text}'")
    return parts


def main(argv=None):
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("metric", choices=["accuracy", "flicker"])
    parser.add_argument("images", nargs="+",
                        help="accuracy: FRAME TRUTH pairs; flicker: consecutive frames")
    way = parser.add_mutually_exclusive_group()
    way.add_argument("--ink-threshold", type=float, default=64.0, metavar="L",
                     help="outline = luma below L (0-255, default 64)")
    way.add_argument("--ink-colour", type=parse_colour, metavar="R,G,B",
                     help="outline = within --tolerance of this colour")
    way.add_argument("--reference", nargs="+", metavar="PNG",
                     help="outline = differs from this reference by more than --tolerance; "
                          "one per frame")
    parser.add_argument("--tolerance", type=int, default=24,
                        help="per-channel tolerance for --reference/--ink-colour (default 24)")
    parser.add_argument("--radius", type=float, default=None,
                        help="match radius in pixels (accuracy 1.5, flicker 2)")
    args = parser.parse_args(argv)
    if args.radius is None:
        args.radius = 1.5 if args.metric == "accuracy" else 2.0
    try:
        result = accuracy(args) if args.metric == "accuracy" else flicker(args)
    except PngError as error:
        print(f"outline_metrics: {error}", file=sys.stderr)
        return 1
    json.dump(result, sys.stdout, indent=2)
    print()
    return 0


if __name__ == "__main__":
    sys.exit(main())
