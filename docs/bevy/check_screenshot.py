#!/usr/bin/env python3
"""Checks that a screenshot of the vibrating_conveyor example is not blank.

    python3 docs/bevy/check_screenshot.py PATH [MIN_WIDTH MIN_HEIGHT]

Decodes the PNG with the standard library only (8-bit RGB/RGBA, all five row filters) and
requires: the window's size; many distinct colours; most pixels not the background; and
coloured, lit geometry (saturated pixels: the parts in their regime colours, the blue
troughs), which a clear colour with text over it does not have. Exit code 1 on failure.
"""
import struct
import sys
import zlib
from collections import Counter


def decode(path):
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("not a PNG")
    pos, idat, header = 8, [], None
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat.append(body)
        pos += 12 + n
    width, height, depth, ctype, _, _, interlace = header
    if depth != 8 or ctype not in (2, 6) or interlace != 0:
        raise ValueError(f"unsupported PNG: depth {depth}, colour type {ctype}, interlace {interlace}")
    bpp = 3 if ctype == 2 else 4
    raw = zlib.decompress(b"".join(idat))
    stride = width * bpp
    rows, prev = [], bytearray(stride)
    for y in range(height):
        f = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b = prev[i]
            c = prev[i - bpp] if i >= bpp else 0
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + b) & 255
            elif f == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                pred = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                line[i] = (line[i] + pred) & 255
        rows.append(line)
        prev = line
    pixels = [tuple(r[x * bpp:x * bpp + 3]) for r in rows for x in range(width)]
    return width, height, pixels


def main():
    path = sys.argv[1]
    min_w, min_h = (int(sys.argv[2]), int(sys.argv[3])) if len(sys.argv) > 3 else (640, 360)
    width, height, pixels = decode(path)
    colours = Counter((r >> 4, g >> 4, b >> 4) for r, g, b in pixels)
    background, count = colours.most_common(1)[0]
    not_background = 1.0 - count / len(pixels)
    saturated = sum(1 for r, g, b in pixels if max(r, g, b) - min(r, g, b) > 60) / len(pixels)
    print(
        f"{path}: {width}x{height}, {len(colours)} colours (4 bits/channel), "
        f"{100 * not_background:.1f} % not background, {100 * saturated:.1f} % saturated"
    )
    failures = []
    if width < min_w or height < min_h:
        failures.append(f"smaller than {min_w}x{min_h}")
    if len(colours) < 50:
        failures.append("too few colours: blank or flat")
    if not_background < 0.2:
        failures.append("mostly background")
    if saturated < 0.01:
        failures.append("no coloured geometry: the 3D scene did not render")
    if failures:
        print("screenshot check FAILED: " + "; ".join(failures))
        sys.exit(1)
    print("screenshot check passed")


if __name__ == "__main__":
    main()
