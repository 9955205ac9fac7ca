#!/usr/bin/env python3
"""Writes examples/sun-sky.pfm: a small equirectangular sky (glint's convention: the image centre looks
along -z, the top row is +y) with a bright sun, for the environment-image example. Linear radiance.

  python3 scripts/make_sun_sky_pfm.py [out.pfm]
"""
import math
import os
import struct
import sys

WIDTH, HEIGHT = 128, 64
SUN = (math.radians(35), math.radians(40))  # elevation, azimuth from -z towards +x
SUN_RADIUS = math.radians(2.5)
SUN_RADIANCE = (900.0, 800.0, 650.0)


def direction(u, v):
    phi, theta = 2 * math.pi * (u - 0.5), math.pi * v
    return (math.sin(theta) * math.sin(phi), math.cos(theta), -math.sin(theta) * math.cos(phi))


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "examples", "sun-sky.pfm")
    elevation, azimuth = SUN
    sun = (math.cos(elevation) * math.sin(azimuth), math.sin(elevation), -math.cos(elevation) * math.cos(azimuth))
    rows = []
    for y in range(HEIGHT):
        row = []
        for x in range(WIDTH):
            d = direction((x + 0.5) / WIDTH, (y + 0.5) / HEIGHT)
            if d[1] < 0:  # ground: dim brown
                rgb = (0.12, 0.1, 0.08)
            else:  # sky: deeper blue towards the zenith
                t = d[1]
                rgb = (0.9 - 0.6 * t, 0.95 - 0.45 * t, 1.0 - 0.1 * t)
            cos_to_sun = sum(a * b for a, b in zip(d, sun))
            if cos_to_sun > math.cos(SUN_RADIUS):
                rgb = SUN_RADIANCE
            row.append(rgb)
        rows.append(row)
    with open(out, "wb") as f:
        f.write(b"PF\n%d %d\n-1.0\n" % (WIDTH, HEIGHT))
        for row in reversed(rows):  # PFM stores the bottom row first
            for rgb in row:
                f.write(struct.pack("<3f", *rgb))
    print("wrote", out)


if __name__ == "__main__":
    main()
