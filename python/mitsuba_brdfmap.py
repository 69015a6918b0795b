"""A BRDF map of an exported table as Mitsuba 3 evaluates it: the counterpart of `diffract brdfmap --pfm`.

    python3 python/mitsuba_brdfmap.py table.json --theta-i 30 --phi-i 90 --size 64 -o map.pfm

Pixel (i, j) of the S x S map is the viewing direction (x, y, sqrt(1 - x^2 - y^2)), x = 2 (i + 0.5) / S - 1,
y = 1 - 2 (j + 0.5) / S (diffract.optics.BrdfMap), black outside the unit disk; each pixel averages K x K directions
over its square (brdfmap's pixel box). The value is the BSDF's eval (f cos(theta_light), Mitsuba's convention) divided
by cos(theta_light) in the plugin's "relative" mode times pi: the relative BRDF in linear sRGB, as brdfmap writes it.
"""
import argparse
import math
import os
import struct
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import mitsuba as mi  # noqa: E402

mi.set_variant("scalar_rgb")
import diffract_mitsuba  # noqa: E402


def write_pfm(path, pixels, size):
    """PFM, colour, little-endian, rows from the bottom (pixels: rows from the top, RGB per pixel)."""
    with open(path, "wb") as f:
        f.write(f"PF\n{size} {size}\n-1.0\n".encode("ascii"))
        for j in range(size - 1, -1, -1):
            row = pixels[j * size * 3:(j + 1) * size * 3]
            f.write(struct.pack("<%df" % len(row), *row))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("table")
    parser.add_argument("--theta-i", type=float, required=True)
    parser.add_argument("--phi-i", type=float, default=0.0)
    parser.add_argument("--size", type=int, default=64)
    parser.add_argument("--subsamples", type=int, default=4, help="K: K x K directions per pixel")
    parser.add_argument("-o", "--output", required=True)
    args = parser.parse_args()
    diffract_mitsuba.register()
    bsdf = mi.load_dict({"type": "diffract", "filename": args.table, "mode": "relative", "clip": False})
    t, p = math.radians(args.theta_i), math.radians(args.phi_i)
    light = mi.Vector3f(math.sin(t) * math.cos(p), math.sin(t) * math.sin(p), math.cos(t))
    ctx = mi.BSDFContext()
    si = mi.SurfaceInteraction3f()
    si.n = mi.Normal3f(0, 0, 1)
    si.sh_frame = mi.Frame3f(si.n)
    size, k = args.size, args.subsamples
    out = [0.0] * (size * size * 3)
    for j in range(size):
        for i in range(size):
            xc = 2.0 * (i + 0.5) / size - 1.0
            yc = 1.0 - 2.0 * (j + 0.5) / size
            if xc * xc + yc * yc >= 1.0:
                continue
            total = [0.0, 0.0, 0.0]
            count = 0
            for b in range(k):
                for a in range(k):
                    x = xc + 2.0 / size * ((a + 0.5) / k - 0.5)
                    y = yc + 2.0 / size * ((b + 0.5) / k - 0.5)
                    r2 = x * x + y * y
                    if r2 >= 1.0:
                        continue  # the part of an edge pixel beyond the horizon reflects nothing
                    si.wi = mi.Vector3f(x, y, math.sqrt(1.0 - r2))
                    value = bsdf.eval(ctx, si, light)
                    for c in range(3):
                        total[c] += value[c]
                    count += 1
            scale = math.pi / (light.z * k * k)
            for c in range(3):
                out[3 * (j * size + i) + c] = total[c] * scale
    write_pfm(args.output, out, size)
    print(f"wrote {args.output} ({size}x{size}, {args.subsamples}x{args.subsamples} directions per pixel)")


if __name__ == "__main__":
    main()
