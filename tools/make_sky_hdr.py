#!/usr/bin/env python3
"""Writes assets/environments/sky.hdr: an analytic sky for shadelab's image-based lighting.

A 256x128 equirectangular Radiance RGBE file (run-length encoded scanlines) with a blue gradient from the
horizon to the zenith, a warm sun disk (radiance 60, 2.5 degrees across its radius) with a glow around it,
and a dim brown ground below the horizon. Pure Python, no randomness: running it again reproduces the
file byte for byte (ctest: sky_hdr_reproducible). The mapping is shadelab's (src/shading/prefilter.h):
row 0 looks up (+y), the centre column looks along -z, u grows toward +x.

Usage: tools/make_sky_hdr.py [--output PATH]   (default: assets/environments/sky.hdr)
"""
import argparse
import math
import os
import sys

WIDTH, HEIGHT = 256, 128
SUN = (0.45, 0.55, -0.70)  # direction toward the sun, normalised below
SUN_RADIUS_DEG = 2.5
SUN_RADIANCE = (60.0, 56.0, 48.0)
ZENITH = (0.18, 0.34, 0.80)
HORIZON = (0.80, 0.86, 0.95)
GROUND = (0.16, 0.13, 0.10)


def normalise(v):
    n = math.sqrt(sum(c * c for c in v))
    return tuple(c / n for c in v)


def direction(u, v):
    """shadelab's equirectDirection: u, v in [0, 1]."""
    phi = (u - 0.5) * 2.0 * math.pi
    theta = v * math.pi
    return (math.sin(theta) * math.sin(phi), math.cos(theta), -math.sin(theta) * math.cos(phi))


def radiance(d, sun):
    y = d[1]
    if y >= 0.0:
        t = (1.0 - y) ** 4  # 1 at the horizon, 0 at the zenith
        sky = tuple(z + (h - z) * t for z, h in zip(ZENITH, HORIZON))
    else:
        t = min(1.0, -y * 8.0)  # a short blend from the horizon haze into the ground
        sky = tuple(h * 0.5 * (1.0 - t) + g * t for h, g in zip(HORIZON, GROUND))
    c = sum(a * b for a, b in zip(d, sun))
    glow = 1.5 * math.exp((c - 1.0) * 60.0)
    sky = (sky[0] + glow, sky[1] + 0.8 * glow, sky[2] + 0.55 * glow)
    if c >= math.cos(math.radians(SUN_RADIUS_DEG)):
        sky = SUN_RADIANCE
    return sky


def rgbe(r, g, b):
    """Ward's float2rgbe."""
    v = max(r, g, b)
    if v < 1e-32:
        return (0, 0, 0, 0)
    m, e = math.frexp(v)
    scale = m * 256.0 / v
    return (int(r * scale), int(g * scale), int(b * scale), e + 128)


def rle_plane(values):
    """New-style Radiance run-length encoding of one channel of a scanline."""
    out = bytearray()
    i, n = 0, len(values)
    while i < n:
        run = 1
        while i + run < n and run < 127 and values[i + run] == values[i]:
            run += 1
        if run >= 4:
            out += bytes((128 + run, values[i]))
            i += run
            continue
        start = i
        while i < n and i - start < 128:
            if i + 3 < n and values[i] == values[i + 1] == values[i + 2] == values[i + 3]:
                break
            i += 1
        out.append(i - start)
        out += bytes(values[start:i])
    return bytes(out)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    parser.add_argument("--output", default=os.path.join(root, "assets", "environments", "sky.hdr"))
    args = parser.parse_args()
    sun = normalise(SUN)
    data = bytearray(b"#?RADIANCE\n# tools/make_sky_hdr.py: an analytic sky for shadelab\n"
                     b"FORMAT=32-bit_rle_rgbe\n\n")
    data += ("-Y %d +X %d\n" % (HEIGHT, WIDTH)).encode()
    for row in range(HEIGHT):
        pixels = [rgbe(*radiance(direction((x + 0.5) / WIDTH, (row + 0.5) / HEIGHT), sun)) for x in range(WIDTH)]
        data += bytes((2, 2, WIDTH >> 8, WIDTH & 255))
        for c in range(4):
            data += rle_plane([p[c] for p in pixels])
    tmp = args.output + ".tmp"
    with open(tmp, "wb") as f:
        f.write(data)
    os.replace(tmp, args.output)
    return 0


if __name__ == "__main__":
    sys.exit(main())
