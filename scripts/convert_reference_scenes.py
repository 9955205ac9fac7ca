#!/usr/bin/env python3
"""Converts the scene data of two reference renderers into glint scenes, exactly.

  python3 scripts/convert_reference_scenes.py [--shared ../shared] [--out examples]

reads   <shared>/data/scenes/rtiow-book1-final.json   (Ray Tracing in One Weekend, book 1, final scene)
        <shared>/data/scenes/smallpt.json             (Kevin Beason's smallpt)
writes  <out>/rtiow-final.yaml and <out>/smallpt.yaml

Every number is copied at full precision (repr of the float); what cannot be the same is said in the
header comment each file gets. The glint names used for the reference materials are in MATERIALS.
"""
import argparse
import json
import math
import os


def num(x):
    """A number as YAML: integers without a fraction, floats at full precision."""
    x = float(x)
    return str(int(x)) if x.is_integer() and abs(x) < 1e15 else repr(x)


def vec(v):
    return "[" + ", ".join(num(c) for c in v) + "]"


# The reference materials as glint materials (docs/scene-format.md, "materials").
MATERIALS = {
    "lambertian": lambda m: f"{{type: matte, albedo: {vec(m['albedo'])}}}",
    # The book's own lobes: its metal is glint's fuzzy-metal (mirror direction + fuzz × a random point
    # in the unit ball, no Fresnel), its dielectric chooses reflection with Schlick's approximation.
    "metal": lambda m: f"{{type: fuzzy-metal, albedo: {vec(m['albedo'])}, fuzz: {num(m['fuzz'])}}}",
    "dielectric": lambda m: f"{{type: dielectric, ior: {num(m['ir'])}, fresnel: schlick}}",
}


def convert_rtiow(data, defocus=True):
    cam = data["camera"]
    width, height = cam["image_width"], cam["image_height"]
    # RTIOW's defocus disk radius is focus_dist · tan(defocus_angle / 2).
    lens_radius = cam["focus_dist"] * math.tan(math.radians(cam["defocus_angle"] / 2))
    out = [
        "# The final scene of Ray Tracing in One Weekend (book 1), converted exactly by",
        "# scripts/convert_reference_scenes.py from ../shared/data/scenes/rtiow-book1-final.json (the spheres",
        "# its reference code generates with glibc rand() unseeded).",
        "# Camera: vfov 20°, thin lens of radius focus_dist · tan(defocus_angle / 2) focused at 10. Light: the",
        "# book's sky, white at the nadir to (0.5, 0.7, 1) at the zenith, lerped by 0.5 (dir.y + 1), as an",
        "# environment light (so it also lights the scene, as in the book). Materials: lambertian → matte,",
        "# metal (albedo, fuzz) → fuzzy-metal (the book's lobe: the mirror direction plus fuzz × a random",
        "# point in the unit ball, absorbed below the surface), dielectric → dielectric with `fresnel: schlick` (the",
        "# book's reflect/refract choice). The book's integrator is a path tracer without light sampling;",
        "# so is glint's here: it spends no shadow ray on a gradient sky, which BSDF sampling follows as well",
        "# (fuzzy-metal and glass are sampled like the book, as delta lobes). It ends dim paths by Russian",
        "# roulette, unbiased, where the book runs every path to max_depth. Not the book's:",
        "# its t_min = 0.001 (glint offsets ray origins by the hit's error bound) and its gamma-2 output.",
        "# Full quality (the book's settings):",
        f"#   glint render examples/rtiow-final.yaml --width {width} --height {height} --spp {cam['samples_per_pixel']}"
        f" --max-depth {cam['max_depth'] - 1} -o rtiow-final.png",
        "# Pixels: box pixels, as the book's uniform offsets in the pixel square; glint's default sampler",
        "# (sobol) stratifies them, which converges to the same image with less noise (`--sampler random`",
        "# draws them independently, as the book does).",
        f"# Depth: the book's max_depth {cam['max_depth']} returns black for the ray after {cam['max_depth'] - 1} bounces;"
        f" glint's max_depth counts",
        f"# bounces (1 = direct light only), so the book's {cam['max_depth']} is glint's {cam['max_depth'] - 1}.",
        f"render: {{width: 200, height: 113, samples: 4, integrator: path,"
        f" max_depth: {cam['max_depth'] - 1}}}",
        f"camera: {{type: thin-lens, eye: {vec(cam['lookfrom'])}, look_at: {vec(cam['lookat'])}, up: {vec(cam['vup'])},"
        f" fov: {num(cam['vfov'])}, lens_radius: {num(lens_radius)}, focus_distance: {num(cam['focus_dist'])}}}"
        if defocus else
        f"camera: {{type: pinhole, eye: {vec(cam['lookfrom'])}, look_at: {vec(cam['lookat'])}, up: {vec(cam['vup'])},"
        f" fov: {num(cam['vfov'])}}}  # --no-defocus: the book's lens (radius {num(lens_radius)}, focus 10) left out",
        "lights:",
        "  - {type: environment, radiance: {type: gradient, bottom: [1, 1, 1], top: [0.5, 0.7, 1.0]}}",
        "objects:",
    ]
    for s in data["spheres"]:
        m = s["material"]
        out.append(f"  - {{type: sphere, center: {vec(s['center'])}, radius: {num(s['radius'])},"
                   f" material: {MATERIALS[m['type']](m)}}}")
    return "\n".join(out) + "\n"


def convert_smallpt(data):
    cam = data["camera"]
    width, height = cam["image_width"], cam["image_height"]
    d = cam["direction_unnormalized"]
    d_len = math.sqrt(sum(c * c for c in d))
    # smallpt normalises cam.d before it builds cx and cy, so the view plane is at distance 1, where cy
    # (length .5135) spans the image height: tan(fov / 2) = .5135 / 2.
    fov = 2 * math.degrees(math.atan(0.5135 / 2))
    look_at = [cam["origin"][i] + d[i] / d_len * 100 for i in range(3)]
    # Its primary ray is Ray(cam.o + d*140, d.norm()), d = cx·(..) + cy·(..) + cam.d; Vec::norm()
    # normalises d in place, and C++ leaves the order of the two arguments unspecified. g++ (which
    # builds the peer and smallpt's published image) evaluates d.norm() first: the rays start 140 along
    # themselves, on a sphere about cam.o. (clang goes left to right: the plane at 140 along the view.)
    near = 140
    out = [
        "# smallpt's scene (Kevin Beason, 2008), converted exactly by scripts/convert_reference_scenes.py from",
        "# ../shared/data/scenes/smallpt.json: nine spheres, the walls being spheres of radius 1e5.",
        "# Camera: smallpt's primary ray is Ray(cam.o + d*140, d.norm()), d = cx·(..) + cy·(..) + cam.d.",
        "# norm() normalises d in place and C++ leaves the order of the two arguments unspecified: g++,",
        f"# which builds smallpt, normalises first, so the rays start {near} along themselves (`near: {near},",
        "# near_shape: sphere`); clang would start them on the plane at 140 along the view (near_shape:",
        "# plane), which reaches above the ceiling in the top rows and shows the light there. Either way the",
        "# black front wall 'Frnt' lies nearer and is never seen, but it stays in the scene: the walls are",
        "# spheres of radius 1e5 that continue past the room, and without Frnt light leaving the room",
        "# through its place comes back off them (about +3 % overall, up to +19 % on the near ceiling).",
        f"# fov = 2 atan(.5135 / 2) = {fov:.4f}° (cam.d is normalised before cx and cy are built); pixels are",
        "# square (cx = w · .5135 / h).",
        "# Materials: DIFF → matte, SPEC → mirror, REFR → dielectric of index 1.5 with `fresnel:",
        "# schlick-outside` (smallpt's Schlick reflectance, its cosine taken in the air; smallpt traces both",
        "# lobes up to depth 2 and then picks one with P = .25 + .5 Re, weighted Re/P or Tr/(1 − P): the same",
        "# expectation as glint's choice with probability Re), and the light 'Lite' (emission 12, colour 0)",
        "# → an area light on its sphere, which the ceiling mostly covers.",
        "# Pixels: smallpt splits each into 2×2 sub-pixels and draws, per sub-pixel and axis, a tent of",
        "# radius one sub-pixel about its centre; `filter: {type: tent, radius: 0.5, subpixels: 2}` draws the",
        "# same footprint (per axis a trapezoid over [−0.25, 1.25] of the pixel). The sample pattern picks",
        "# the sub-pixels: jittered with 4, 16, 64, … samples puts as many in each, as smallpt does.",
        "# Not reproduced: smallpt's per-sub-pixel clamping to [0, 1] (a clamp of a noisy mean: its expected",
        "# value depends on the sample count, so no unbiased renderer converges to it; compare with",
        "# smallpt_lin's CLAMP 0), the 0.999 colour of its glass (glint's dielectric is clear: 0.1 % more",
        "# light per crossing), and its unbounded depth (glint stops at max_depth 50, after Russian",
        "# roulette). tests/e2e/smallpt_test.cpp checks that both converge to the same image.",
        "# Full quality (smallpt's size; `./smallpt 64` takes 64 spp):",
        f"#   glint render examples/smallpt.yaml --width {width} --height {height} --spp 64 -o smallpt.png",
        "render: {width: 256, height: 192, samples: 4, integrator: path, max_depth: 50,"
        " filter: {type: tent, radius: 0.5, subpixels: 2}}",
        f"camera: {{type: pinhole, eye: {vec(cam['origin'])}, look_at: {vec(look_at)}, up: [0, 1, 0], fov: {num(fov)},"
        f" near: {near}, near_shape: sphere}}",
        "objects:",
    ]
    lights = []
    for s in data["spheres"]:
        name = s["name"]
        shape = f"{{type: sphere, center: {vec(s['center'])}, radius: {num(s['radius'])}}}"
        if any(s["emission"]):
            assert not any(s["color"]), "an emitter that also reflects needs an emissive + matte material"
            lights.append(f"  - {{type: area, radiance: {vec(s['emission'])}, shape: {shape}}}  # {name}")
            continue
        kind = s["material"]
        if kind == "DIFF":
            material = f"{{type: matte, albedo: {vec(s['color'])}}}"
        elif kind == "SPEC":
            material = f"{{type: mirror, reflectance: {vec(s['color'])}}}"
        elif kind == "REFR":
            # smallpt multiplies light through glass by its colour (0.999) at each hit; glint's
            # dielectric is clear (said in the header).
            material = f"{{type: dielectric, ior: {num(s['ior'])}, fresnel: schlick-outside}}"
        else:
            raise ValueError(f"unknown smallpt material {kind}")
        out.append(f"  - {{type: sphere, center: {vec(s['center'])}, radius: {num(s['radius'])},"
                   f" material: {material}}}  # {name}")
    out.append("lights:")
    out.extend(lights)
    return "\n".join(out) + "\n"


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--shared", default=os.path.join(here, "..", "..", "shared"))
    parser.add_argument("--out", default=os.path.join(here, "..", "examples"))
    parser.add_argument("--no-defocus", action="store_true",
                        help="a pinhole camera for RTIOW, for builds without the thin-lens camera")
    args = parser.parse_args()
    scenes = os.path.join(args.shared, "data", "scenes")
    with open(os.path.join(scenes, "rtiow-book1-final.json")) as f:
        rtiow = convert_rtiow(json.load(f), defocus=not args.no_defocus)
    with open(os.path.join(scenes, "smallpt.json")) as f:
        smallpt = convert_smallpt(json.load(f))
    for name, text in (("rtiow-final.yaml", rtiow), ("smallpt.yaml", smallpt)):
        with open(os.path.join(args.out, name), "w") as f:
            f.write(text)
        print("wrote", os.path.join(args.out, name))


if __name__ == "__main__":
    main()
