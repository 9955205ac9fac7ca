#!/usr/bin/env python3
"""glint from Python, notebook style: render a scene, look at its numbers, save them.

    PYTHONPATH=build/release/python python3 examples/python/render.py [SCENE] [-o OUT.npy] [--spp N]

Each `# %%` block is a cell (VS Code, Jupytext and Spyder read them so). The saved .npy holds exactly the film:
float32 linear radiance, (height, width, 3), top row first; the .ppm beside it is for looking at.
"""
import argparse
import pathlib
import time

import numpy as np

import glint

REPO = pathlib.Path(__file__).resolve().parents[2]

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("scene", nargs="?", default=str(REPO / "examples" / "cornell-box.yaml"))
parser.add_argument("-o", "--output", default="render.npy", help="the film as .npy (a .ppm is written beside it)")
parser.add_argument("--spp", type=int, default=16)
parser.add_argument("--size", type=int, default=128, help="width and height in pixels")
args = parser.parse_args()

# %% Render: a path (or the scene's YAML text, or nothing for the built-in scene); keywords as glint's flags.
start = time.perf_counter()
image = glint.render(args.scene, spp=args.spp, width=args.size, height=args.size, seed=1)
seconds = time.perf_counter() - start
print(f"glint {glint.__version__}: {args.scene}")
print(f"{image.shape[1]} x {image.shape[0]} pixels, {args.spp} spp, {image.dtype}, {seconds:.2f} s")

# %% Statistics of the linear radiance
print("mean radiance (r, g, b):", " ".join(f"{v:.6f}" for v in image.mean(axis=(0, 1))))
luminance = image @ np.array([0.2126, 0.7152, 0.0722], dtype=np.float32)  # Rec. 709
y, x = np.unravel_index(np.argmax(luminance), luminance.shape)
print(f"brightest pixel: ({x}, {y}), luminance {luminance[y, x]:.4f}")
print(f"black pixels: {np.count_nonzero(luminance == 0)} of {luminance.size}")

# %% Noise: two renders that differ only in the seed; their difference is noise alone (its variance is twice
# that of one render's)
other = glint.render(args.scene, spp=args.spp, width=args.size, height=args.size, seed=2)
noise = np.std(luminance - other @ np.array([0.2126, 0.7152, 0.0722], dtype=np.float32)) / np.sqrt(2)
print(f"noise (standard deviation of a pixel's luminance): {noise:.4f}")

# %% Save: the film as it is, and an 8-bit sRGB picture (values clamped to [0, 1]) as a binary PPM
output = pathlib.Path(args.output)
np.save(output, image)
clamped = np.clip(image, 0.0, 1.0)
srgb = np.where(clamped <= 0.0031308, 12.92 * clamped, 1.055 * np.power(clamped, 1 / 2.4) - 0.055)
picture = np.round(srgb * 255).astype(np.uint8)
with open(output.with_suffix(".ppm"), "wb") as ppm:
    ppm.write(b"P6\n%d %d\n255\n" % (picture.shape[1], picture.shape[0]))
    ppm.write(picture.tobytes())
print(f"wrote {output} and {output.with_suffix('.ppm')}")
