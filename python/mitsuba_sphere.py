"""A sphere with a patch's exported BSDF, rendered by Mitsuba 3 under a small round light and a dim constant sky.

    python3 python/mitsuba_sphere.py table.json -o sphere.png [--size 160] [--spp 64] [--exposure 1000]

The sphere's shading frame is Mitsuba's (x along dp/du, the longitude); the sphere is turned so that its poles lie on
the world's y axis, so the patch's columns run round it horizontally, as on diffract's own sphere with its tangent
projected from x (docs/measurements/mitsuba-figure.sh renders both).
The PNG is sRGB-encoded at the exposure, clipped; the specular highlight saturates so that the orders show.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import mitsuba as mi  # noqa: E402

mi.set_variant("scalar_rgb")
import diffract_mitsuba  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("table")
    parser.add_argument("-o", "--output", required=True)
    parser.add_argument("--size", type=int, default=160)
    parser.add_argument("--spp", type=int, default=256)
    parser.add_argument("--exposure", type=float, default=1000.0)
    args = parser.parse_args()
    diffract_mitsuba.register()
    scene = mi.load_dict({
        "type": "scene",
        "integrator": {"type": "direct"},
        "sensor": {
            "type": "perspective", "fov": 30,
            "to_world": mi.ScalarTransform4f().look_at(origin=[0, 0, 4.2], target=[0, 0, 0], up=[0, 1, 0]),
            "film": {"type": "hdrfilm", "width": args.size, "height": args.size, "rfilter": {"type": "box"}},
            "sampler": {"type": "independent", "sample_count": args.spp},
        },
        # poles on the world's y axis: the longitude (dp/du, the patch's x) runs horizontally across the view
        "sphere": {"type": "sphere", "to_world": mi.ScalarTransform4f().rotate(axis=[1, 0, 0], angle=-90),
                   "bsdf": {"type": "diffract", "filename": args.table, "mode": "relative", "scale": args.exposure}},
        # a small round light (1.4 degrees in radius, irradiance pi) above and behind the camera's right: a light of
        # finite size widens the orders from lines thinner than a pixel into bands
        "sun": {"type": "sphere", "center": [9, 12, 13.2], "radius": 0.5,
                "emitter": {"type": "area", "radiance": {"type": "rgb", "value": 1600.0}}},
        "sky": {"type": "constant", "radiance": {"type": "rgb", "value": 0.02}},
    })
    image = mi.render(scene)
    bitmap = mi.Bitmap(image).convert(mi.Bitmap.PixelFormat.RGB, mi.Struct.Type.UInt8, srgb_gamma=True)
    bitmap.write(args.output)
    print(f"wrote {args.output} ({args.size}x{args.size}, {args.spp} spp)")


if __name__ == "__main__":
    main()
