#!/usr/bin/env python3
"""Writes examples/assets/trefoil-knot.ply: a tube around the trefoil knot, made here from its formula
(so the file is the project's own, under its licence), for examples/knot.yaml and the tests of meshes.

The curve is c(t) = (sin t + 2 sin 2t, cos t - 2 cos 2t, -sin 3t), t in [0, 2 pi); the tube has radius
0.35, with RINGS rings of SIDES vertices each, joined into 2 * RINGS * SIDES triangles. Each ring lies in
the plane normal to the curve, spanned by a frame carried along the curve by parallel transport (no
twist), and the frame's small mismatch after one turn is spread over the rings so the tube closes.
Binary little-endian PLY: float x, y, z and the tube's exact normal nx, ny, nz (for smooth shading), and
uchar-counted int vertex_indices lists.

    python3 scripts/make_knot_mesh.py            # rewrites the file
"""
import math
import os
import struct

RINGS, SIDES, RADIUS = 256, 24, 0.35


def curve(t):
    return (math.sin(t) + 2 * math.sin(2 * t), math.cos(t) - 2 * math.cos(2 * t), -math.sin(3 * t))


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def normalize(a):
    n = math.sqrt(dot(a, a))
    return tuple(x / n for x in a)


def tangent(t, h=1e-5):
    return normalize(sub(curve(t + h), curve(t - h)))


def main():
    ts = [2 * math.pi * i / RINGS for i in range(RINGS)]
    tangents = [tangent(t) for t in ts]
    # Parallel transport of a normal: project the previous normal onto the next ring's plane.
    normal = normalize(cross(tangents[0], (0.0, 0.0, 1.0)))
    normals = []
    for tan in tangents:
        normal = normalize(sub(normal, tuple(dot(normal, tan) * x for x in tan)))
        normals.append(normal)
    # After a full turn the transported normal is rotated by some angle against the first: undo it
    # gradually so the last ring meets the first without a seam.
    last = normalize(sub(normals[-1], tuple(dot(normals[-1], tangents[0]) * x for x in tangents[0])))
    twist = math.atan2(dot(cross(normals[0], last), tangents[0]), dot(normals[0], last))
    vertices = []
    for i, (t, tan, n) in enumerate(zip(ts, tangents, normals)):
        b = cross(tan, n)
        correction = -twist * i / RINGS
        for j in range(SIDES):
            a = 2 * math.pi * j / SIDES + correction
            c = curve(t)
            out = tuple(math.cos(a) * n[k] + math.sin(a) * b[k] for k in range(3))  # the tube's normal
            vertices.append(tuple(c[k] + RADIUS * out[k] for k in range(3)) + out)
    faces = []
    for i in range(RINGS):
        for j in range(SIDES):
            a = i * SIDES + j
            b = i * SIDES + (j + 1) % SIDES
            c = ((i + 1) % RINGS) * SIDES + (j + 1) % SIDES
            d = ((i + 1) % RINGS) * SIDES + j
            faces += [(a, b, c), (a, c, d)]
    out = os.path.join(os.path.dirname(__file__), "..", "examples", "assets", "trefoil-knot.ply")
    header = (
        "ply\nformat binary_little_endian 1.0\n"
        "comment trefoil knot tube, made by scripts/make_knot_mesh.py (glint, MIT licence)\n"
        f"element vertex {len(vertices)}\nproperty float x\nproperty float y\nproperty float z\n"
        "property float nx\nproperty float ny\nproperty float nz\n"
        f"element face {len(faces)}\nproperty list uchar int vertex_indices\nend_header\n"
    )
    with open(out, "wb") as f:
        f.write(header.encode("ascii"))
        for v in vertices:
            f.write(struct.pack("<6f", *v))
        for face in faces:
            f.write(struct.pack("<B3i", 3, *face))
    print(f"{out}: {len(vertices)} vertices, {len(faces)} triangles")


if __name__ == "__main__":
    main()
