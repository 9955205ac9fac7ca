#!/usr/bin/env python3
"""Writes the seed corpora of fuzz/corpus/ and the scene assets of fuzz/assets/.

Every file is made here, from nothing (no third-party file is copied), so the seeds can be read and
remade: run `fuzz/make_seeds.py` from anywhere; it rewrites the files it owns and leaves the others
(the JPEG and EXR seeds come from fuzz/make_image_seeds.cpp, which uses glint's own libraries; the
scene seeds also take the repository's examples/). Keep every seed small: the whole corpus folder
stays well under 1 MB and a seed runs in milliseconds.

Seeds that crash glint today are NOT put here (the corpus is what the fuzzer starts from, and a
crashing seed would stop it at once): such inputs go to fuzz/regressions/<harness>/.
"""
import json
import math
import os
import re
import struct
import sys
import zlib

import yaml  # python3-yaml, only to turn the YAML seeds into JSON ones

FUZZ = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(FUZZ)


def write(relative, data):
    path = os.path.join(FUZZ, relative)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    if isinstance(data, str):
        data = data.encode()
    with open(path, "wb") as f:
        f.write(data)


def pattern(w, h):
    """A small test picture: (r, g, b) in [0, 1] for every pixel, row by row from the top."""
    return [[((x + 0.5) / w, (y + 0.5) / h, 0.5 + 0.5 * math.sin(x * 1.7 + y * 0.9)) for x in range(w)]
            for y in range(h)]


def to8(v):
    return max(0, min(255, int(round(v * 255))))


# ---------------------------------------------------------------------------------------------- PNG

def png_chunk(kind, body):
    return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body) & 0xffffffff)


def pack_bits(samples, depth):
    """Packs samples of `depth` bits (1, 2, 4, 8 or 16) into bytes, most significant first."""
    if depth == 8:
        return bytes(samples)
    if depth == 16:
        return b"".join(struct.pack(">H", s) for s in samples)
    out, acc, n = bytearray(), 0, 0
    for s in samples:
        acc = (acc << depth) | s
        n += depth
        if n == 8:
            out.append(acc)
            acc, n = 0, 0
    if n:
        out.append(acc << (8 - n))
    return bytes(out)


def png(w, h, color_type, depth, sample, plte=None, trns=None, interlace=False, filters=(0,), extra=()):
    """`sample(x, y)` gives the list of channel values of a pixel at `depth` bits."""
    def scanlines(xs, ys):
        raw = bytearray()
        for row, y in enumerate(ys):
            raw.append(filters[row % len(filters)] if depth >= 8 else 0)
            line = pack_bits([c for x in xs for c in sample(x, y)], depth)
            raw += apply_filter(filters[row % len(filters)] if depth >= 8 else 0, line, prev_line(raw, row),
                                max(1, len(sample(0, 0)) * depth // 8))
        return raw

    rows_written = []

    def prev_line(raw, row):
        return rows_written[-1] if rows_written and row > 0 else None

    def apply_filter(kind, line, prev, bpp):
        prev = prev or bytes(len(line))
        rows_written.append(line)
        out = bytearray(len(line))
        for i, v in enumerate(line):
            a = line[i - bpp] if i >= bpp else 0
            b = prev[i]
            c = prev[i - bpp] if i >= bpp else 0
            if kind == 0:
                p = 0
            elif kind == 1:
                p = a
            elif kind == 2:
                p = b
            elif kind == 3:
                p = (a + b) // 2
            else:
                pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                p = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
            out[i] = (v - p) & 0xff
        return bytes(out)

    if interlace:
        raw = bytearray()
        passes = [(0, 0, 8, 8), (4, 0, 8, 8), (0, 4, 4, 8), (2, 0, 4, 4), (0, 2, 2, 4), (1, 0, 2, 2), (0, 1, 1, 2)]
        for x0, y0, dx, dy in passes:
            xs, ys = list(range(x0, w, dx)), list(range(y0, h, dy))
            if xs and ys:
                rows_written.clear()
                raw += scanlines(xs, ys)
    else:
        raw = scanlines(list(range(w)), list(range(h)))
    out = b"\x89PNG\r\n\x1a\n"
    out += png_chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, depth, color_type, 0, 0, 1 if interlace else 0))
    for kind, body in extra:
        out += png_chunk(kind, body)
    if plte:
        out += png_chunk(b"PLTE", bytes(c for rgb in plte for c in rgb))
    if trns is not None:
        out += png_chunk(b"tRNS", trns)
    data = zlib.compress(bytes(raw), 9)
    half = len(data) // 2
    out += png_chunk(b"IDAT", data[:half]) + png_chunk(b"IDAT", data[half:])  # split: a second IDAT
    out += png_chunk(b"IEND", b"")
    return out


def png_seeds():
    p = pattern(8, 8)
    rgb8 = lambda x, y: [to8(c) for c in p[y][x]]
    write("corpus/image_png/rgb8.png", png(8, 8, 2, 8, rgb8, filters=(0, 1, 2, 3, 4)))
    write("corpus/image_png/rgba8.png", png(8, 8, 6, 8, lambda x, y: rgb8(x, y) + [255 - 16 * x]))
    write("corpus/image_png/gray8.png", png(8, 8, 0, 8, lambda x, y: [rgb8(x, y)[0]], filters=(1, 4)))
    write("corpus/image_png/gray-alpha8.png", png(5, 3, 4, 8, lambda x, y: [40 * x, 80 * y]))
    write("corpus/image_png/rgb16.png", png(4, 4, 2, 16, lambda x, y: [c * 257 for c in rgb8(x, y)]))
    write("corpus/image_png/gray16.png", png(4, 3, 0, 16, lambda x, y: [x * 16000 + y]))
    write("corpus/image_png/gray1.png", png(9, 3, 0, 1, lambda x, y: [(x + y) & 1]))
    write("corpus/image_png/gray4.png", png(5, 2, 0, 4, lambda x, y: [(3 * x + y) & 15]))
    palette = [(255, 0, 0), (0, 255, 0), (0, 0, 255), (255, 255, 255)]
    write("corpus/image_png/palette2.png",
          png(6, 4, 3, 2, lambda x, y: [(x + y) % 4], plte=palette, trns=b"\x00\xff"))
    write("corpus/image_png/palette8.png", png(4, 4, 3, 8, lambda x, y: [(x * y) % 4], plte=palette))
    write("corpus/image_png/rgb8-trns.png", png(3, 3, 2, 8, rgb8, trns=struct.pack(">HHH", 0, 0, 128)))
    write("corpus/image_png/interlaced.png", png(10, 9, 2, 8, lambda x, y: [to8(c) for c in pattern(10, 9)[y][x]],
                                                 interlace=True))
    write("corpus/image_png/ancillary.png",
          png(2, 2, 2, 8, lambda x, y: [x * 200, y * 200, 100],
              extra=[(b"gAMA", struct.pack(">I", 45455)), (b"tEXt", b"Comment\x00glint fuzz seed"),
                     (b"sRGB", b"\x00")]))


# ---------------------------------------------------------------------------------------------- BMP

def bmp(w, h, bits, pixels_bottom_up, palette=None, compression=0, masks=None, top_down=False, header=40):
    """`pixels_bottom_up`: the pixel array exactly as stored (rows padded to 4 bytes by the caller)."""
    extra = b""
    if masks:
        extra = struct.pack("<III", *masks[:3])
        if header >= 56:
            extra += struct.pack("<I", masks[3] if len(masks) > 3 else 0)
    pal = b"".join(struct.pack("<BBBB", b, g, r, 0) for r, g, b in (palette or []))
    info = struct.pack("<IiiHHIIiiII", header, w, -h if top_down else h, 1, bits, compression,
                       len(pixels_bottom_up), 2835, 2835, len(palette or []), 0)
    if header > 40:
        info += extra + bytes(header - 40 - len(extra))
        extra = b""
    offset = 14 + len(info) + len(extra) + len(pal)
    return b"BM" + struct.pack("<IHHI", offset + len(pixels_bottom_up), 0, 0, offset) + info + extra + pal + \
        pixels_bottom_up


def rows_padded(rows):
    return b"".join(r + bytes((-len(r)) % 4) for r in rows)


def bmp_seeds():
    w, h = 5, 4
    p = pattern(w, h)
    rows24 = [bytes(c for x in range(w) for c in reversed([to8(v) for v in p[y][x]])) for y in reversed(range(h))]
    write("corpus/image_bmp/rgb24.bmp", bmp(w, h, 24, rows_padded(rows24)))
    rows24_top = list(reversed(rows24))
    write("corpus/image_bmp/rgb24-top-down.bmp", bmp(w, h, 24, rows_padded(rows24_top), top_down=True))
    rows32 = [bytes(c for x in range(w) for c in [to8(v) for v in reversed(p[y][x])] + [255]) for y in reversed(range(h))]
    write("corpus/image_bmp/rgba32-bitfields.bmp",
          bmp(w, h, 32, rows_padded(rows32), compression=3, masks=(0xff0000, 0xff00, 0xff, 0xff000000), header=108))
    rows16 = [b"".join(struct.pack("<H", (x * 6 << 11) | (y * 15 << 5) | 20) for x in range(w)) for y in range(h)]
    write("corpus/image_bmp/rgb565.bmp", bmp(w, h, 16, rows_padded(rows16), compression=3,
                                              masks=(0xf800, 0x07e0, 0x001f)))
    rows555 = [b"".join(struct.pack("<H", (x * 6 << 10) | (y * 7 << 5) | 9) for x in range(w)) for y in range(h)]
    write("corpus/image_bmp/rgb555.bmp", bmp(w, h, 16, rows_padded(rows555)))
    palette = [(0, 0, 0), (255, 0, 0), (0, 255, 0), (0, 0, 255)]
    rows8 = [bytes((x + y) % 4 for x in range(w)) for y in range(h)]
    write("corpus/image_bmp/palette8.bmp", bmp(w, h, 8, rows_padded(rows8), palette=palette))
    rows4 = [bytes(((2 * i) % 4) << 4 | ((2 * i + 1 + y) % 4) for i in range(3)) for y in range(h)]
    write("corpus/image_bmp/palette4.bmp", bmp(w, h, 4, rows_padded(rows4), palette=palette))
    rows1 = [bytes([0b10101000 >> y]) for y in range(h)]
    write("corpus/image_bmp/mono1.bmp", bmp(w, h, 1, rows_padded(rows1), palette=palette[:2]))
    # RLE8: a run of 3, an absolute run of 3 (padded to a word), end of line; a delta; end of bitmap.
    rle8 = bytes([3, 1, 0, 3, 2, 3, 1, 0, 0, 0]) + bytes([2, 2, 0, 2, 1, 1, 0, 0]) + bytes([5, 3, 0, 0, 0, 1])
    write("corpus/image_bmp/rle8.bmp", bmp(6, 3, 8, rle8, palette=palette, compression=1))
    core_rows = rows_padded([b"\x00\x00\xff\x00\xff\x00", b"\xff\x00\x00\xff\xff\xff"])
    write("corpus/image_bmp/core-header.bmp",  # the OS/2 12-byte header
          b"BM" + struct.pack("<IHHI", 26 + len(core_rows), 0, 0, 26) + struct.pack("<IHHHH", 12, 2, 2, 1, 24) +
          core_rows)


# ---------------------------------------------------------------------------------------------- TGA

def tga(w, h, image_type, depth, body, cmap=None, descriptor=0, ident=b""):
    cmap_type, first, length, entry = (1, 0, len(cmap) // 3, 24) if cmap else (0, 0, 0, 0)
    header = struct.pack("<BBBHHBHHHHBB", len(ident), cmap_type, image_type, first, length, entry, 0, 0, w, h,
                         depth, descriptor)
    return header + ident + (cmap or b"") + body


def tga_rle(pixels, bpp):
    """Alternates runs and raw packets so that both kinds appear."""
    out, i, toggle = bytearray(), 0, True
    while i < len(pixels):
        n = min(3, len(pixels) - i)
        if toggle:
            out.append(0x80 | (n - 1))
            out += pixels[i]
        else:
            out.append(n - 1)
            for k in range(n):
                out += pixels[i + k]
        i += n
        toggle = not toggle
    return bytes(out)


def tga_seeds():
    w, h = 6, 4
    p = pattern(w, h)
    bgr = [bytes(reversed([to8(v) for v in p[y][x]])) for y in range(h) for x in range(w)]
    write("corpus/image_tga/rgb24.tga", tga(w, h, 2, 24, b"".join(bgr), ident=b"glint"))
    write("corpus/image_tga/rgba32-top-left.tga", tga(w, h, 2, 32, b"".join(c + b"\x80" for c in bgr), descriptor=0x28))
    write("corpus/image_tga/rgb24-rle.tga", tga(w, h, 10, 24, tga_rle(bgr, 3)))
    gray = [bytes([to8(p[y][x][0])]) for y in range(h) for x in range(w)]
    write("corpus/image_tga/gray8.tga", tga(w, h, 3, 8, b"".join(gray)))
    write("corpus/image_tga/gray8-rle.tga", tga(w, h, 11, 8, tga_rle(gray, 1)))
    cmap = bytes([0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255])
    write("corpus/image_tga/colormap.tga", tga(w, h, 1, 8, bytes((x + y) % 4 for y in range(h) for x in range(w)), cmap=cmap))
    rgb16 = [struct.pack("<H", (x * 5 << 10) | (y * 7 << 5) | 12) for y in range(h) for x in range(w)]
    write("corpus/image_tga/rgb16.tga", tga(w, h, 2, 16, b"".join(rgb16)))


# ---------------------------------------------------------------------------------------------- PNM

def pnm_seeds():
    # Only 8-bit (maxval 255 or less): a 16-bit PGM crashes glint today (fuzz/regressions/image_pnm).
    w, h = 4, 3
    p = pattern(w, h)
    write("corpus/image_pnm/rgb.ppm", b"P6\n4 3\n255\n" + bytes(to8(c) for row in p for px in row for c in px))
    write("corpus/image_pnm/gray.pgm", b"P5\n# a comment\n4 3\n255\n" + bytes(to8(px[1]) for row in p for px in row))
    write("corpus/image_pnm/maxval-100.ppm", b"P6 2 2 100 " + bytes([0, 50, 100, 100, 0, 50, 25, 25, 25, 99, 1, 2]))


# ---------------------------------------------------------------------------------------------- HDR

def rgbe(r, g, b):
    m = max(r, g, b)
    if m < 1e-32:
        return bytes(4)
    e = math.frexp(m)[1]
    scale = math.ldexp(1.0, -e) * 256
    return bytes([int(r * scale), int(g * scale), int(b * scale), e + 128])


def hdr_rle_line(pixels):
    out = bytearray([2, 2, len(pixels) >> 8, len(pixels) & 0xff])
    for channel in range(4):
        values = [px[channel] for px in pixels]
        i = 0
        while i < len(values):
            run = 1
            while i + run < len(values) and values[i + run] == values[i] and run < 127:
                run += 1
            if run >= 3:
                out += bytes([128 + run, values[i]])
                i += run
            else:
                n = min(len(values) - i, 4)
                out += bytes([n]) + bytes(values[i:i + n])
                i += n
    return bytes(out)


def hdr_seeds():
    w, h = 12, 3
    p = pattern(w, h)
    header = b"#?RADIANCE\n# glint fuzz seed\nFORMAT=32-bit_rle_rgbe\nEXPOSURE=1.0\n\n"
    pixels = [[rgbe(*(4 * c if x < 4 else c for c in p[y][x])) for x in range(w)] for y in range(h)]
    write("corpus/image_hdr/rle.hdr", header + b"-Y 3 +X 12\n" + b"".join(hdr_rle_line(row) for row in pixels))
    write("corpus/image_hdr/flat.hdr", header + b"-Y 3 +X 12\n" + b"".join(px for row in pixels for px in row))
    small = [[rgbe(0.5, 2.0, 8.0 * x) for x in range(4)] for _ in range(2)]
    write("corpus/image_hdr/narrow.hdr", b"#?RGBE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 4\n" +
          b"".join(px for row in small for px in row))


# ---------------------------------------------------------------------------------------------- PFM

def pfm(w, h, rows_bottom_up, little=True, magic=b"PF", channels=3):
    scale = b"-1.0" if little else b"1.0"
    fmt = ("<" if little else ">") + "f" * (w * channels)
    return magic + b"\n%d %d\n" % (w, h) + scale + b"\n" + b"".join(struct.pack(fmt, *row) for row in rows_bottom_up)


def pfm_seeds():
    w, h = 4, 3
    p = pattern(w, h)
    rows = [[c for px in p[y] for c in px] for y in reversed(range(h))]
    write("corpus/image_pfm/little-endian.pfm", pfm(w, h, rows))
    write("corpus/image_pfm/big-endian.pfm", pfm(w, h, rows, little=False))
    write("corpus/image_pfm/gray.pfm", pfm(w, h, [[px[0] for px in p[y]] for y in reversed(range(h))], magic=b"Pf",
                                          channels=1))
    write("corpus/image_pfm/hdr-values.pfm", pfm(2, 1, [[1e30, 0.0, -1.0, float("inf"), float("nan"), 65504.0]]))


# ---------------------------------------------------------------------------------------- OBJ / PLY

OBJ_SEEDS = {
    "triangle.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
    "quad-fan.obj": "# a quad and a pentagon, split into fans\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv -0.5 0.5 0\n"
                    "f 1 2 3 4\nf 1 4 5 2 3\n",
    "negative-indices.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\nv 0 0 1\nf -4 -3 -1\n",
    "normals-texcoords.obj": "o thing\ng group1\nusemtl red\ns 1\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
                             "vn 0 0 1\nvn 0 0 1\nvn 0 0 1\nf 1/1/1 2/2/2 3/3/3\nf 1//1 3//3 2//2\nf 1/1 2/2 3/3\n",
    "crlf-tabs.obj": "v\t0 0 0\r\nv 1\t0 0\r\nv 0 1 0   \r\n\r\n# comment\r\nf 1 2 3\r\n",
    "zero-area.obj": "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 4\n",
    "numbers.obj": "v -1.5e-3 +2.0E+2 .5\nv 1. -0 1e-300\nv 3 4 5 1.0\nvn 0 0 0\nvn 0 1e-300 0\nvn 1 0 0\n"
                   "f 1//1 2//2 3//3\n",
    "only-vertices.obj": "v 0 0 0\nv 1 1 1\nmtllib none.mtl\nl 1 2\np 1\n",
}


def ply_ascii(vertices, faces, normals=None, extra_header="", face_list="uchar int"):
    props = "property float x\nproperty float y\nproperty float z\n"
    if normals:
        props += "property float nx\nproperty float ny\nproperty float nz\n"
    body = ""
    for i, v in enumerate(vertices):
        body += " ".join(repr(c) for c in v + (normals[i] if normals else ())) + "\n"
    for f in faces:
        body += " ".join(str(c) for c in (len(f),) + tuple(f)) + "\n"
    return ("ply\nformat ascii 1.0\ncomment made by fuzz/make_seeds.py\n" + extra_header +
            "element vertex %d\n%s" % (len(vertices), props) +
            "element face %d\nproperty list %s vertex_indices\nend_header\n" % (len(faces), face_list) + body)


TETRA_V = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)]
TETRA_F = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]


def ply_binary(little, vertex_types=("float",) * 3, count_type="uchar", index_type="int", normals=False,
               extra_vertex=(), extra_element=None):
    e = "<" if little else ">"
    codes = {"char": "b", "uchar": "B", "short": "h", "ushort": "H", "int": "i", "uint": "I", "float": "f",
             "double": "d", "int8": "b", "uint8": "B", "int16": "h", "uint16": "H", "int32": "i", "uint32": "I",
             "float32": "f", "float64": "d"}
    header = "ply\nformat binary_%s_endian 1.0\n" % ("little" if little else "big")
    header += "element vertex %d\n" % len(TETRA_V)
    names = ["x", "y", "z"] + (["nx", "ny", "nz"] if normals else [])
    types = list(vertex_types) + (["float"] * 3 if normals else [])
    for t, n in zip(types, names):
        header += "property %s %s\n" % (t, n)
    for t, n in extra_vertex:
        header += "property %s %s\n" % (t, n)
    header += "element face %d\nproperty list %s %s vertex_indices\n" % (len(TETRA_F), count_type, index_type)
    if extra_element:
        header += extra_element[0]
    header += "end_header\n"
    body = b""
    for v in TETRA_V:
        values = list(v) + ([0.0, 0.0, 1.0] if normals else [])
        body += struct.pack(e + "".join(codes[t] for t in types), *values)
        for t, _ in extra_vertex:
            body += struct.pack(e + codes[t], 7)
    for f in TETRA_F:
        body += struct.pack(e + codes[count_type], 3) + struct.pack(e + codes[index_type] * 3, *f)
    if extra_element:
        body += extra_element[1]
    return header.encode() + body


def mesh_seeds():
    for name, text in OBJ_SEEDS.items():
        write("corpus/obj/" + name, text)
    write("corpus/ply/ascii.ply", ply_ascii(TETRA_V, TETRA_F))
    write("corpus/ply/ascii-normals-quad.ply",
          ply_ascii([(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (1.0, 1.0, 0.0), (0.0, 1.0, 0.0)], [(0, 1, 2, 3)],
                    normals=[(0.0, 0.0, 1.0)] * 4, extra_header="obj_info generated\n", face_list="uint8 uint32"))
    write("corpus/ply/binary-little.ply", ply_binary(True))
    write("corpus/ply/binary-big.ply", ply_binary(False))
    write("corpus/ply/binary-double-ushort.ply", ply_binary(True, vertex_types=("double",) * 3, count_type="ushort",
                                                            index_type="uint", normals=True))
    write("corpus/ply/binary-extra-props.ply",
          ply_binary(True, vertex_types=("float32",) * 3, count_type="uint8", index_type="int32",
                     extra_vertex=(("uchar", "red"), ("short", "s"), ("double", "u")),
                     extra_element=("element material 1\nproperty uchar ambient_red\n", b"\x09")))
    tristrips = ("ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
                 "element tristrips 1\nproperty list int int vertex_indices\nend_header\n"
                 "0 0 0\n1 0 0\n0 1 0\n1 1 0\n2 1 0\n6 0 1 2 3 -1 4\n")
    write("corpus/ply/tristrips.ply", tristrips)


MTL_SEEDS = {  # one material library of each kind the OBJ importer maps (docs/importers.md)
    "matte.mtl": "newmtl clay\nKd 0.5 0.25 0.125\n",
    "kinds.mtl": "# one material of each kind\nnewmtl shiny\nKd 0.5 0.5 0.5\nKs 0.25 0.25 0.25\nNs 100\n"
                 "illum 2\nnewmtl lamp\nKe 10 9 8\nnewmtl water\nillum 7\nNi 1.33\nd 0.5\nnewmtl chrome\n"
                 "Kd 0 0 0\nKs 0.9 0.9 0.9\nillum 3\n",
    "textured.mtl": "newmtl wood\nKa 0.1 0.1 0.1\nKd 1 1 1\nmap_Kd -s 2 2 1 checker.png\nmap_Bump bump.png\n"
                    "Tr 0.25\nTf 1 0.5 0.5\nd -halo 0.5\n",
}


def mtl_seeds():
    for name, text in MTL_SEEDS.items():
        write("corpus/mtl/" + name, text)


# --------------------------------------------------------------------------------------- scene assets

def asset_seeds():
    write("assets/tetrahedron.obj", "# made by fuzz/make_seeds.py\n" +
          "".join("v %g %g %g\n" % v for v in TETRA_V) + "".join("f %d %d %d\n" % tuple(i + 1 for i in f)
                                                                 for f in TETRA_F))
    write("assets/tetrahedron.ply", ply_binary(True, normals=True))
    p = pattern(8, 4)
    write("assets/sky.pfm", pfm(8, 4, [[4 * c if (x, y) == (2, 1) else c for x, px in enumerate(p[y]) for c in px]
                                       for y in reversed(range(4))]))
    checker = lambda x, y: [230, 40, 40] if (x + y) % 2 else [240, 240, 240]
    write("assets/checker.png", png(4, 4, 2, 8, checker))


# --------------------------------------------------------------------------------------------- scenes

FEATURE_SCENES = {
    "cameras-thin-lens.yaml": """render: {width: 16, height: 12, samples: 4, sampler: halton}
camera: {type: thin-lens, eye: [0, 1, 5], look_at: [0, 0.5, 0], fov: 40, f_stop: 2.8, focal_length: 0.05,
         focus_distance: 5}
objects:
  - {type: sphere, center: [0, 0.5, 0], radius: 0.5}
lights:
  - {type: point, position: [2, 4, 3], intensity: 40}
""",
    "cameras-orthographic.yaml": """camera: {type: orthographic, eye: [0, 0, 5], look_at: [0, 0, 0], height: 3}
objects: [{type: box, min: [-1, -1, -1], max: [1, 1, 1], transform: {rotate: {axis: [1, 1, 0], angle: 30}}}]
lights: [{type: directional, direction: [-1, -2, -1], irradiance: 2}]
""",
    "cameras-spherical.yaml": """render: {width: 16, height: 8, sampler: sobol, samples: 2}
camera: {type: equirectangular, eye: [0, 1, 0], look_at: [0, 1, -1]}
objects: [{type: plane, normal: [0, 1, 0]}, {type: torus, center: [0, 1, -3], major_radius: 1, minor_radius: 0.3}]
lights: [{type: ambient, radiance: 0.5}]
""",
    "cameras-fisheye.yaml": """camera: {type: fisheye, fov: 360, eye: [0, 0, 0], look_at: [1, 0, 0], up: [0, 0, 1]}
render: {sampler: multi-jittered, samples: 8}
objects: [{type: cylinder, base: [2, 0, -1], top: [2, 0, 1], radius: 0.5, capped: false},
          {type: cone, base: [-2, 0, 0], apex: [-2, 1, 0], radius: 0.5}]
lights: [{type: spot, position: [0, 0, 3], look_at: [2, 0, 0], angle: 40, falloff_angle: 20}]
""",
    "materials-path.yaml": """render: {integrator: path, max_depth: 6, samples: 4, sampler: random, seed: 7}
camera: {eye: [0, 1, 6], look_at: [0, 1, 0], view_distance: 300, zoom: 1.5}
materials:
  glass: {type: dielectric, ior: 1.5, absorption: [0.2, 0.1, 0], fresnel: schlick}
  water: {type: dielectric, ior: 1.333, fresnel: schlick-outside}
  gold: {type: metal, reflectance: [1, 0.8, 0.3], roughness: 0.2}
  old: {type: glossy, albedo: 0.7, fuzz: 0.5}
  book: {type: fuzzy-metal, albedo: 0.8, fuzz: 0.3}
  shiny: {type: phong, diffuse: [0.4, 0.2, 0.1], specular: 0.3, exponent: 100}
  coat: {type: plastic, diffuse: 0.5, ior: 1.6}
  mirror: {type: mirror, reflectance: 0.9}
  lamp: {type: emissive, radiance: [8, 8, 6], two_sided: true}
objects:
  - {type: sphere, center: [-1, 1, 0], radius: 0.5, material: glass}
  - {type: sphere, center: [0, 1, 0], radius: 0.5, material: gold}
  - {type: sphere, center: [1, 1, 0], radius: 0.5, material: shiny}
  - {type: disk, center: [0, 0.01, 1], radius: 0.4, material: coat}
  - {type: annulus, center: [0, 0.02, -1], inner_radius: 0.2, outer_radius: 0.5, material: mirror}
  - {type: rectangle, corner: [-1, 3, -1], edge1: [2, 0, 0], edge2: [0, 0, 2], material: lamp}
  - {type: box, min: [2, 0, 0], max: [2.5, 0.5, 0.5], material: old}
  - {type: sphere, center: [-2, 0.5, 0], radius: 0.4, material: water}
  - {type: sphere, center: [2, 1.5, 0], radius: 0.3, material: book}
  - {type: plane, normal: [0, 1, 0], material: {type: matte, albedo: 0.5}}
lights:
  - {type: environment, radiance: {type: gradient, bottom: 1, top: [0.5, 0.7, 1]}}
""",
    "whitted-area.yaml": """render: {integrator: whitted, max_depth: 4, samples: 1}
materials:
  glass: {type: dielectric, ior: 1.5}
objects:
  - {type: sphere, center: [0, 1, 0], radius: 1, material: glass}
  - {type: plane, normal: [0, 1, 0]}
lights:
  - {type: area, radiance: [17, 12, 4], samples: 4, two_sided: true,
     shape: {type: rectangle, corner: [-1, 3, -1], edge1: [2, 0, 0], edge2: [0, 0, 2]}}
  - {type: area, radiance: 2, shape: {type: sphere, center: [3, 3, 0], radius: 0.2}}
  - {type: ambient-occlusion, radiance: 0.2, samples: 2, distance: 5}
""",
    "textures.yaml": """materials:
  floor: {type: matte, albedo: {type: checker, scale: 4, even: 0.9, odd: {type: noise, scale: 3, octaves: 4,
          color_a: [0.1, 0, 0], color_b: 0.9}, space: solid}}
  picture: {type: matte, albedo: {type: image, file: checker.png}}
  flat: {type: matte, albedo: {type: constant, value: [0.2, 0.3, 0.4]}}
  uv: {type: phong, diffuse: {type: checker, space: uv}, specular: 0.1}
objects:
  - {type: plane, normal: [0, 1, 0], material: floor}
  - {type: rectangle, corner: [-1, 0, -2], edge1: [2, 0, 0], edge2: [0, 2, 0], material: picture}
  - {type: sphere, center: [1.5, 0.5, 0], radius: 0.5, material: uv}
  - {type: box, min: [-2, 0, 0], max: [-1.5, 0.5, 0.5], material: flat}
lights: [{type: ambient, radiance: 1}]
""",
    "meshes-transforms.yaml": """render: {accelerator: list}
objects:
  - {type: mesh, file: tetrahedron.obj, transform: {scale: [2, 1, 0.5], rotate: {axis: [0, 1, 0], angle: 30},
     translate: [0, 1, 0]}}
  - {type: mesh, file: tetrahedron.ply,
     transform: [{translate: [2, 0, 0]}, {rotate: {axis: [0, 0, 1], angle: 45}}, {scale: -1}]}
  - {type: sphere, radius: 1, transform: {matrix: [1, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1, -3]}}
  - {type: sphere, radius: 1, transform: {matrix: [1, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]}}
lights: [{type: point, position: [0, 5, 5], intensity: [10, 20, 30], scale: 2}]
""",
    "environment-image.yaml": """render: {integrator: path, max_depth: 2, accelerator: embree}
objects: [{type: sphere, center: [0, 0, 0], radius: 1, material: {type: mirror}}]
lights: [{type: environment, image: sky.pfm, rotation: 90, scale: 0.5}]
""",
    "samplers.yaml": """render: {sampler: regular, samples: 9, seed: 0}
objects: [{type: sphere, radius: 1}]
""",
    "samplers-n-rooks.yaml": """render: {sampler: n-rooks, samples: 5}
objects: [{type: sphere, radius: 2}]
lights: [{type: ambient}]
""",
    "samplers-hammersley.yaml": """{render: {sampler: hammersley, samples: 3, seed: 12345678901}, background: 0.5}
""",
    "anchors-flow.yaml": """# anchors, aliases and flow/block mixes (the loader sees plain trees)
materials:
  a: &grey {type: matte, albedo: 0.5}
  b: *grey
  c: {type: matte, albedo: [0.1, 0.2, 0.3]}
objects:
- type: sphere
  center: &origin [0, 0, 0]
  radius: 1
  material: a
- type: sphere
  center: [0, 2, 0]
  radius: "0.5"
  material: c
lights:
- {type: point, position: *origin}
""",
    "empty.yaml": "{}\n",
    "comments-only.yaml": "# nothing but a comment\n---\n{}\n...\n",
    "errors-typo.yaml": "objects:\n  - {type: sphere, radious: 1}\n",
    "errors-not-a-map.yaml": "- 1\n- 2\n",
    "errors-syntax.yaml": "objects: [ {type: sphere\n",
    "errors-unknown-type.yaml": "camera: {type: pinhol}\nlights: [{type: laser}]\n",
    "block-scalars.yaml": "render:\n  sampler: >-\n    jittered\n  integrator: |-\n    raycast\n",
}


def scene_seeds():
    examples = os.path.join(ROOT, "examples")
    renames = {"sun-sky.pfm": "sky.pfm", "../../shared/data/meshes/stanford-bunny.obj": "tetrahedron.obj",
               "assets/icosahedron.obj": "tetrahedron.obj"}
    yaml_seeds = {}
    for name in sorted(os.listdir(examples)):
        if not name.endswith(".yaml"):
            continue
        text = open(os.path.join(examples, name)).read()
        if len(text) > 20000:
            continue  # rtiow-final.yaml: hundreds of spheres, too big for a seed
        for old, new in renames.items():
            text = text.replace(old, new)
        yaml_seeds["example-" + name] = text
    yaml_seeds.update(FEATURE_SCENES)
    for name, text in yaml_seeds.items():
        write("corpus/scene_yaml/" + name, text)
        if name.startswith("errors-syntax"):
            continue
        tree = yaml.safe_load(text)
        if tree is None:
            continue
        stem = name[:-len(".yaml")]
        write("corpus/scene_json/" + stem + ".json", json.dumps(tree, indent=1) + "\n")
        if name.startswith("example-shapes") or name.startswith("materials"):
            write("corpus/scene_json/" + stem + "-compact.json", json.dumps(tree, separators=(",", ":")))
    write("corpus/scene_json/errors-syntax.json", '{"objects": [{"type": "sphere", "radius": 1,}]}')
    write("corpus/scene_json/errors-duplicate-key.json", '{"camera": {}, "camera": {"fov": 30}}')
    write("corpus/scene_json/unicode-escape.json", '{"materials": {"r\\u00e9d": {"type": "matte"}}, '
                                                   '"objects": [{"type": "sphere", "radius": 1, "material": "r\\u00e9d"}]}')


EDIT_SEEDS = {
    "camera-fov.json": {"path": ["camera", "fov"], "value": 20},
    "many.json": {"edits": [
        {"path": ["camera", "fov"], "value": 20},
        {"path": ["camera", "lens_radius"], "value": 0.05},
        {"path": ["camera", "type"], "value": "thin-lens"},
        {"path": ["materials", "steel", "roughness"], "value": 0.05},
        {"path": ["render", "sampler"], "value": "sobol"},
        {"path": ["background"], "value": [0, 0, 0]},
        {"path": ["camera", "up"], "value": None},
        {"path": ["render", "nothing", "here"], "value": None}]},
    "render.json": {"edits": [{"path": ["render", "width"], "value": 4096},
                              {"path": ["render", "height"], "value": 2},
                              {"path": ["render", "samples"], "value": 1.5e2},
                              {"path": ["render", "integrator"], "value": "whitted"},
                              {"path": ["render", "max_depth"], "value": 8},
                              {"path": ["render", "seed"], "value": 3}]},
    "materials.json": {"edits": [{"path": ["materials", "glass", "ior"], "value": 2.417},
                                 {"path": ["materials", "glass", "fresnel"], "value": "schlick"},
                                 {"path": ["materials", "lamp", "two_sided"], "value": True},
                                 {"path": ["materials", "coat", "diffuse"], "value": [1, 0.5, 1e-7]},
                                 {"path": ["materials", "floor", "albedo", "even"], "value": 0.1},
                                 {"path": ["materials", "shiny", "exponent"], "value": None}]},
    "material-type.json": {"edits": [{"path": ["materials", "shiny", "type"], "value": "mirror"},
                                     {"path": ["materials", "shiny", "diffuse"], "value": None},
                                     {"path": ["materials", "shiny", "specular"], "value": None},
                                     {"path": ["materials", "shiny", "exponent"], "value": None}]},
    "camera-type.json": {"edits": [{"path": ["camera", "type"], "value": "fisheye"},
                                   {"path": ["camera", "fov"], "value": 360}]},
    "refused-section.json": {"path": ["objects", "0", "radius"], "value": 2},
    "refused-path-value.json": {"path": ["materials", "floor", "albedo"], "value": "../../etc/passwd"},
    "refused-object-value.json": {"path": ["camera", "eye"], "value": {"x": 1}},
    "unknown-material.json": {"path": ["materials", "nothing", "albedo"], "value": 0.5},
    "inline-material.json": {"edits": [{"path": ["objects", 8, "material", "albedo", "even"], "value": 0.3},
                                        {"path": ["objects", "8", "material", "type"], "value": "matte"}]},
    "lights.json": {"edits": [{"path": ["lights", 1, "intensity"], "value": 45},
                              {"path": ["lights", 2, "angle"], "value": 60},
                              {"path": ["lights", 0, "radiance"], "value": [0.1, 0.2, 0.3]}]},
    "refused-positions.json": {"edits": [{"path": ["lights", 3, "intensity"], "value": 1},
                                         {"path": ["objects", -1, "material", "albedo"], "value": 1},
                                         {"path": ["objects", 0, "material", "albedo"], "value": 1},
                                         {"path": ["lights", "1e3", "position"], "value": [0, 0, 0]}]},
    "big-numbers.json": {"edits": [{"path": ["camera", "fov"], "value": 1e308},
                                   {"path": ["render", "width"], "value": 9223372036854775807},
                                   {"path": ["background"], "value": [-0.0, 5e-324, 18446744073709551615]}]},
}


def edit_seeds():
    for name, request in EDIT_SEEDS.items():
        write("corpus/scene_edit/" + name, json.dumps(request) + "\n")
    write("corpus/scene_edit/not-an-object.json", "[1, 2, 3]")
    write("corpus/scene_edit/empty-edits.json", '{"edits": []}')


def gltf_seeds():
    """Small glTF 2.0 models, text and binary: a square placed by a node hierarchy, a camera, a punctual
    light, a metallic-roughness material with a texture, an emissive one, a triangle strip."""
    import base64
    import json
    import struct
    geometry = struct.pack("<12f", 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0) + struct.pack("<6H", 0, 1, 2, 0, 2, 3)

    def model(buffer_uri):
        m = {
            "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 2, 3]}],
            "nodes": [{"translation": [0, 0, -3], "rotation": [0, 0.7071067811865476, 0, 0.7071067811865476],
                       "children": [1]},
                      {"mesh": 0, "scale": [2, 2, 2]},
                      {"camera": 0, "translation": [4, 1, -4], "rotation": [0, 0.7071067811865476, 0,
                                                                             0.7071067811865476]},
                      {"translation": [1, 2, 3], "extensions": {"KHR_lights_punctual": {"light": 0}}}],
            "cameras": [{"name": "side", "type": "perspective", "perspective": {"yfov": 0.5, "znear": 0.1}}],
            "extensionsUsed": ["KHR_lights_punctual"],
            "extensions": {"KHR_lights_punctual": {"lights": [{"type": "spot", "color": [1, 0.5, 0.25],
                                                               "intensity": 8, "spot": {"outerConeAngle": 0.5}}]}},
            "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0},
                                       {"attributes": {"POSITION": 0}, "mode": 5, "material": 1}]}],
            "materials": [{"name": "red", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.1, 0.1, 1],
                                                                   "metallicFactor": 0.25, "roughnessFactor": 0.5,
                                                                   "baseColorTexture": {"index": 0}}},
                          {"name": "lamp", "emissiveFactor": [1, 1, 1]}],
            "textures": [{"source": 0}],
            "images": [{"uri": "data:image/png;base64," +
                        base64.b64encode(png(2, 2, 2, 8, lambda x, y: [255 * x, 255 * y, 128])).decode()}],
            "buffers": [{"byteLength": len(geometry)}],
            "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                            {"buffer": 0, "byteOffset": 48, "byteLength": 12}],
            "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
                           "min": [0, 0, 0], "max": [1, 1, 0]},
                          {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"}]}
        if buffer_uri:
            m["buffers"][0]["uri"] = buffer_uri
        return m

    uri = "data:application/octet-stream;base64," + base64.b64encode(geometry).decode()
    write("corpus/gltf/square.gltf", json.dumps(model(uri)))
    text = json.dumps(model(None)).encode()
    text += b" " * (-len(text) % 4)
    binary = geometry + b"\0" * (-len(geometry) % 4)
    glb = (b"glTF" + struct.pack("<II", 2, 12 + 8 + len(text) + 8 + len(binary)) +
           struct.pack("<I", len(text)) + b"JSON" + text + struct.pack("<I", len(binary)) + b"BIN\0" + binary)
    write("corpus/gltf/square.glb", glb)

    # The same square with uvs, normals and tangents, and a material with every map glTF's
    # metallic-roughness model has: base colour, metallic-roughness, normal (scaled), emissive, occlusion.
    mapped = (geometry + struct.pack("<8f", 0, 0, 1, 0, 1, 1, 0, 1) + struct.pack("<12f", *([0, 0, 1] * 4)) +
              struct.pack("<16f", *([1, 0, 0, 1] * 4)))
    tiny_png = "data:image/png;base64," + base64.b64encode(png(2, 2, 2, 8, lambda x, y: [128, 128 + 100 * x, 255])).decode()
    maps = {
        "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 2, "NORMAL": 3, "TANGENT": 4},
                                    "indices": 1, "material": 0}]}],
        "materials": [{"name": "mapped",
                       "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}, "metallicFactor": 0.5,
                                                "metallicRoughnessTexture": {"index": 0}},
                       "normalTexture": {"index": 0, "scale": 0.5}, "occlusionTexture": {"index": 0},
                       "emissiveTexture": {"index": 0}, "emissiveFactor": [0.1, 0.2, 0.3]}],
        "textures": [{"source": 0}], "images": [{"uri": tiny_png}],
        "buffers": [{"byteLength": len(mapped),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(mapped).decode()}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                        {"buffer": 0, "byteOffset": 48, "byteLength": 12},
                        {"buffer": 0, "byteOffset": 60, "byteLength": 32},
                        {"buffer": 0, "byteOffset": 92, "byteLength": 48},
                        {"buffer": 0, "byteOffset": 140, "byteLength": 64}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
                       "min": [0, 0, 0], "max": [1, 1, 0]},
                      {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"},
                      {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"},
                      {"bufferView": 3, "componentType": 5126, "count": 4, "type": "VEC3"},
                      {"bufferView": 4, "componentType": 5126, "count": 4, "type": "VEC4"}]}
    write("corpus/gltf/square-with-every-map.gltf", json.dumps(maps))


def pbrt_seeds():
    """Small pbrt-v4 scenes: every directive family the importer reads, and the files it names are the
    assets (tetrahedron.ply, checker.png)."""
    camera = ('LookAt 0 1 -4  0 0 0  0 1 0\nCamera "perspective" "float fov" 45\n'
              'Film "rgb" "integer xresolution" 8 "integer yresolution" 8 "string filename" "x.exr"\n'
              'Sampler "halton" "integer pixelsamples" 2\nIntegrator "volpath" "integer maxdepth" 3\n')
    write("corpus/pbrt/spheres.pbrt", camera +
          'WorldBegin\nLightSource "infinite" "rgb L" [0.4 0.5 0.6]\n'
          'AttributeBegin\n  Material "diffuse" "rgb reflectance" [0.8 0.2 0.1]\n  Translate -1 0 0\n'
          '  Shape "sphere" "float radius" 0.5 "float zmax" 0.2\nAttributeEnd\n'
          'AttributeBegin\n  Material "dielectric" "spectrum eta" "glass-BK7"\n  Translate 1 0 0\n'
          '  Shape "sphere" "float radius" 0.5\nAttributeEnd\n')
    write("corpus/pbrt/materials.pbrt", "Scale -1 1 1\n" + camera +
          'PixelFilter "triangle" "float xradius" 1\nWorldBegin\n'
          'Texture "checks" "spectrum" "checkerboard" "float uscale" 4 "float vscale" 4 "rgb tex1" [1 0 0]\n'
          'Texture "img" "spectrum" "imagemap" "string filename" "checker.png"\n'
          'Texture "rough" "float" "constant" "float value" 0.1\n'
          'MakeNamedMaterial "gold" "string type" "conductor" "spectrum eta" "metal-Au-eta" '
          '"spectrum k" "metal-Au-k" "texture roughness" "rough"\n'
          'MakeNamedMaterial "coat" "string type" "coateddiffuse" "texture reflectance" "checks"\n'
          'MakeNamedMaterial "mixed" "string type" "mix" "string materials" ["gold" "coat"] "float amount" 0.3\n'
          'NamedMaterial "mixed"\nShape "disk" "float radius" 2 "float innerradius" 0.5\n'
          'Material "diffuse" "texture reflectance" "img"\nShape "cylinder" "float zmin" 0 "float zmax" 1\n'
          'Material "interface"\nShape "sphere"\n')
    write("corpus/pbrt/meshes-lights.pbrt", camera +
          'WorldBegin\nLightSource "spot" "point3 from" [0 3 0] "point3 to" [0 0 0] "blackbody I" 4000\n'
          'LightSource "distant" "point3 from" [1 1 1] "rgb L" [1 1 1]\n'
          'LightSource "point" "spectrum I" [400 1 500 2 600 3 700 4]\n'
          'AttributeBegin\n  AreaLightSource "diffuse" "rgb L" [4 4 4] "bool twosided" true\n'
          '  ReverseOrientation\n  Translate 0 2 0\n'
          '  Shape "bilinearmesh" "point3 P" [-1 0 -1 1 0 -1 -1 0 1 1 0 1]\nAttributeEnd\n'
          'ObjectBegin "tet"\n  Shape "plymesh" "string filename" "tetrahedron.ply"\n'
          '  Shape "loopsubdiv" "integer levels" 2 "integer indices" [0 1 2 0 3 1 0 2 3 1 3 2] '
          '"point3 P" [1 1 1 1 -1 -1 -1 1 -1 -1 -1 1]\nObjectEnd\n'
          'ObjectInstance "tet"\nTransformBegin\n  Translate 2 0 0\n  ObjectInstance "tet"\nTransformEnd\n'
          'CoordSysTransform "camera"\nShape "trianglemesh" "point3 P" [0 0 1 1 0 1 0 1 1] '
          '"integer indices" [0 1 2] "normal N" [0 0 -1 0 0 -1 0 0 -1] "point2 uv" [0 0 1 0 0 1]\n')
    write("corpus/pbrt/orthographic.pbrt",
          'Transform [1 0 0 0  0 1 0 0  0 0 1 0  0 0 5 1]\n'
          'Camera "orthographic" "float screenwindow" [-2 2 -2 2]\nWorldBegin\n'
          'ConcatTransform [1 0 0 0  0 1 0 0  0 0 1 0  0 0 0 1]\nRotate 30 0 1 0\nShape "sphere"\n')


# ----------------------------------------------------------------------------------------- dictionaries

def dict_entry(token):
    """One libFuzzer dictionary line: the token quoted, with \\ " and non-printable bytes escaped."""
    if isinstance(token, str):
        token = token.encode("latin-1")  # "\xff" is the byte 0xff
    out = ""
    for b in token:
        out += "\\x%02x" % b if b < 0x20 or b >= 0x7f or b in (0x22, 0x5c) else chr(b)
    return '"%s"' % out


def write_dict(name, comment, tokens):
    seen, lines = set(), ["# %s" % line for line in comment.strip().splitlines()]
    for t in tokens:
        if t not in seen:
            seen.add(t)
            lines.append(dict_entry(t))
    write("dict/" + name, "\n".join(lines) + "\n")


SCENE_WORDS = [  # type names and keys the docs' tables name without backticks
    "sphere", "plane", "disk", "annulus", "rectangle", "box", "cylinder", "cone", "torus", "mesh", "matte", "phong",
    "plastic", "mirror", "metal", "dielectric", "emissive", "checker", "image", "noise", "constant", "gradient",
    "bottom", "spot", "directional", "area", "point", "true", "false", "null", "~", "1e308", "-1", "0", "0.5",
    "1e-300", "nan", ".inf", "-.inf", ".nan", "32768", "1048576", "65536", "4294967296", "tetrahedron.obj",
    "tetrahedron.ply", "sky.pfm", "checker.png", "/dev/null"]


def dictionaries():
    docs = open(os.path.join(ROOT, "docs", "scene-format.md")).read()
    doc_words = sorted(set(re.findall(r"`([a-z_][a-z0-9_-]*)`", docs)))
    yaml_syntax = [": ", "- ", "{", "}", "[", "]", ", ", "&a ", "*a", "<<: ", "!!str ", "!!int ", "!!map", "---\n",
                   "...\n", "'", '"', "|\n", ">-\n", "# ", "%YAML 1.2\n", "? ", "\t", "\r\n", "\\u0000", "\xef\xbb\xbf"]
    write_dict("scene_yaml.dict", "Scene keys and names (from docs/scene-format.md, made by fuzz/make_seeds.py) and YAML syntax.",
               doc_words + SCENE_WORDS + yaml_syntax)
    json_syntax = ['"%s"' % w for w in doc_words + SCENE_WORDS[:22]] + [
        '": ', "{", "}", "[", "]", ",", "true", "false", "null", "1e308", "-0", "\\u00e9", "\\ud800", '\\"']
    write_dict("scene_json.dict", "Scene keys and names as JSON strings (made by fuzz/make_seeds.py), JSON syntax.",
               json_syntax)
    edit_words = ['"edits"', '"path"', '"value"', '"render"', '"camera"', '"background"', '"materials"', "null",
                  '"objects"', '"lights"', '"material"', "0", "8", "-1", '"2"',
                  "true", "false", "[]", "{}", "1e400", "-1e-400", "9223372036854775808", '"a-b_c"'] + [
        '"%s"' % w for w in doc_words + SCENE_WORDS[:22]] + ['"floor"', '"shiny"', '"coat"', '"steel"', '"rtiow"',
                                                             '"glass"', '"lamp"', '"chrome"']
    write_dict("scene_edit.dict", "Edit requests of glint serve (made by fuzz/make_seeds.py): keys, sections, the "
               "loaded scene's materials.", edit_words)
    write_dict("obj.dict", "OBJ statements and number forms (made by fuzz/make_seeds.py).",
               ["v ", "vn ", "vt ", "vp ", "f ", "l ", "p ", "o ", "g ", "s ", "usemtl ", "mtllib ", "#", "\n", "\r\n",
                "/", "//", "-1", "-2147483648", "4294967296", "1e38", "1e-45", "nan", "inf", "-0", ".5", "1.", "+"])
    write_dict("gltf.dict", "glTF 2.0 keys and values (made by fuzz/make_seeds.py).",
               ['"asset"', '"version"', '"2.0"', '"scene"', '"scenes"', '"nodes"', '"children"', '"mesh"',
                '"meshes"', '"primitives"', '"attributes"', '"POSITION"', '"NORMAL"', '"TEXCOORD_0"', '"indices"',
                '"mode"', '"material"', '"materials"', '"pbrMetallicRoughness"', '"baseColorFactor"',
                '"baseColorTexture"', '"metallicFactor"', '"roughnessFactor"', '"emissiveFactor"', '"textures"',
                '"source"', '"images"', '"uri"', '"buffers"', '"byteLength"', '"bufferViews"', '"buffer"',
                '"byteOffset"', '"byteStride"', '"accessors"', '"bufferView"', '"componentType"', '"count"',
                '"type"', '"VEC3"', '"VEC2"', '"SCALAR"', '"MAT4"', '"matrix"', '"translation"', '"rotation"',
                '"scale"', '"camera"', '"cameras"', '"perspective"', '"orthographic"', '"yfov"', '"ymag"',
                '"KHR_lights_punctual"', '"lights"', '"light"', '"spot"', '"point"', '"directional"',
                '"intensity"', '"sparse"', '"skin"', "5120", "5121", "5122", "5123", "5125", "5126", "4294967295",
                "-1", "1e308", "glTF", "JSON", "BIN\x00", "data:application/octet-stream;base64,"])
    write_dict("mtl.dict", "MTL statements and number forms (made by fuzz/make_seeds.py).",
               ["newmtl ", "Ka ", "Kd ", "Ks ", "Ke ", "Tf ", "Ns ", "Ni ", "d ", "Tr ", "illum ", "map_Kd ",
                "map_Ks ", "map_Bump ", "bump ", "-halo ", "-s ", "-o ", "-bm ", "spectral ", "xyz ", "checker.png",
                "sky.pfm", "tetrahedron.obj", "#", "\n", "\r\n", "0", "1", "2.5", "-1", "1e308", "nan", "inf",
                "+", "10", "11"])
    write_dict("ply.dict", "PLY header words and types (made by fuzz/make_seeds.py).",
               ["ply\n", "format ", "ascii 1.0\n", "binary_little_endian 1.0\n", "binary_big_endian 1.0\n",
                "element ", "property ", "list ", "comment ", "obj_info ", "end_header\n", "vertex ", "face ",
                "tristrips ", "vertex_indices", "vertex_index", " x\n", " y\n", " z\n", " nx\n", " ny\n", " nz\n",
                "char ", "uchar ", "short ", "ushort ", "int ", "uint ", "float ", "double ", "int8 ", "uint8 ",
                "int16 ", "uint16 ", "int32 ", "uint32 ", "float32 ", "float64 ", "4294967295", "2147483647",
                "\xff\xff\xff\xff", "\x00\x00\x80\x7f", "\x00\x00\xc0\x7f"])
    write_dict("pbrt.dict", "pbrt-v4 directives, parameter types and names (made by fuzz/make_seeds.py).",
               ["AttributeBegin\n", "AttributeEnd\n", "TransformBegin\n", "TransformEnd\n", "WorldBegin\n",
                "ObjectBegin ", "ObjectEnd\n", "ObjectInstance ", "Include ", "Import ", "LookAt ", "Translate ",
                "Scale ", "Rotate ", "Transform ", "ConcatTransform ", "CoordinateSystem ", "CoordSysTransform ",
                "ActiveTransform ", "ReverseOrientation\n", "Camera ", "Film ", "Sampler ", "Integrator ",
                "PixelFilter ", "Shape ", "Material ", "MakeNamedMaterial ", "NamedMaterial ", "Texture ",
                "LightSource ", "AreaLightSource ", "\"integer ", "\"float ", "\"point2 ", "\"point3 ",
                "\"normal ", "\"rgb ", "\"spectrum ", "\"blackbody ", "\"bool ", "\"string ", "\"texture ",
                "\"sphere\"", "\"disk\"", "\"cylinder\"", "\"trianglemesh\"", "\"plymesh\"",
                "\"bilinearmesh\"", "\"loopsubdiv\"", "\"diffuse\"", "\"conductor\"", "\"dielectric\"",
                "\"coateddiffuse\"", "\"mix\"", "\"interface\"", "\"imagemap\"", "\"checkerboard\"",
                "\"scale\"", "\"infinite\"", "\"point\"", "\"spot\"", "\"distant\"", "\"perspective\"",
                "\"orthographic\"", "\"metal-Au-eta\"", "\"glass-BK7\"", "\"tetrahedron.ply\"",
                "\"checker.png\"", "[", "]", "#", "\\", "true", "false", "1e38", "-0", "nan"])
    write_dict("image_png.dict", "PNG signature and chunk names (made by fuzz/make_seeds.py).",
               ["\x89PNG\r\n\x1a\n", "IHDR", "PLTE", "IDAT", "IEND", "tRNS", "gAMA", "sRGB", "iCCP", "tEXt", "zTXt",
                "CgBI", "\x00\x00\x00\x0d", "\x7f\xff\xff\xff", "\x08\x02", "\x10\x06", "\x08\x03", "\x78\x9c"])
    write_dict("image_jpeg.dict", "JPEG markers (made by fuzz/make_seeds.py).",
               ["\xff\xd8", "\xff\xd9", "\xff\xc0", "\xff\xc1", "\xff\xc2", "\xff\xc4", "\xff\xdb", "\xff\xda",
                "\xff\xdd", "\xff\xe0", "\xff\xe1", "\xff\xee", "\xff\xfe", "\xff\xd0", "JFIF\x00", "Adobe",
                "\x11\x00", "\x22\x00", "\xff\xff"])
    write_dict("image_bmp.dict", "BMP header words (made by fuzz/make_seeds.py).",
               ["BM", "\x28\x00\x00\x00", "\x6c\x00\x00\x00", "\x7c\x00\x00\x00", "\x0c\x00\x00\x00", "\x01\x00",
                "\x18\x00", "\x20\x00", "\x10\x00", "\x08\x00", "\x04\x00", "\x03\x00\x00\x00", "\x01\x00\x00\x00",
                "\x02\x00\x00\x00", "\xff\xff\xff\x7f", "\x00\x00\x00\x80", "\x00\x00\xff\x00"])
    write_dict("image_tga.dict", "TGA header values (made by fuzz/make_seeds.py).",
               ["\x00\x00\x02", "\x00\x00\x0a", "\x00\x01\x01", "\x00\x00\x03", "\x00\x00\x0b", "\x18", "\x20",
                "\x10", "\x0f", "\x08", "\xff\xff", "\x00\x80", "TRUEVISION-XFILE.\x00"])
    write_dict("image_pnm.dict", "PNM headers (made by fuzz/make_seeds.py).",
               ["P5", "P6", "P2", "P3", "P1", "P4", "P7", "#", "\n", " ", "255", "65535", "65536", "0", "1",
                "2147483647", "4294967296"])
    write_dict("image_hdr.dict", "Radiance HDR header (made by fuzz/make_seeds.py).",
               ["#?RADIANCE\n", "#?RGBE\n", "FORMAT=32-bit_rle_rgbe\n", "FORMAT=32-bit_rle_xyze\n", "EXPOSURE=",
                "\n\n", "-Y ", "+Y ", " +X ", " -X ", "32767", "65536", "\x02\x02", "\x80", "\xff"])
    write_dict("image_pfm.dict", "PFM headers (made by fuzz/make_seeds.py).",
               ["PF\n", "Pf\n", "-1.0\n", "1.0\n", "0\n", "2147483647", "-2147483648", "1e308", "nan", "inf",
                " ", "\n", "\x00\x00\x80\x7f", "\x00\x00\xc0\x7f"])
    write_dict("image_exr.dict", "OpenEXR magic, attribute names and types (made by fuzz/make_seeds.py).",
               ["\x76\x2f\x31\x01", "\x02\x00\x00\x00", "\x02\x02\x00\x00", "channels\x00", "chlist\x00",
                "compression\x00", "dataWindow\x00", "displayWindow\x00", "box2i\x00", "lineOrder\x00",
                "pixelAspectRatio\x00", "screenWindowCenter\x00", "screenWindowWidth\x00", "tiles\x00",
                "tiledesc\x00", "v2f\x00", "float\x00", "int\x00", "compression\x00", "lineOrder\x00", "B\x00",
                "G\x00", "R\x00", "A\x00", "Y\x00", "\x01\x00\x00\x00", "\xff\xff\xff\x7f", "\x00\x00\x00\x80"])


def checkpoint_seeds():
    # The format of src/glint/render/checkpoint.hpp: magic, version, fingerprint, width, height, samples
    # done and asked, then per pixel four doubles (the sums of r, g, b and of Y²) and a count.
    def checkpoint(width, height, done, asked, pixel):
        header = b"GLINTCKP" + struct.pack("<IQIIII", 1, 0x0123456789abcdef, width, height, done, asked)
        return header + b"".join(struct.pack("<ddddQ", *pixel(x, y)) for y in range(height) for x in range(width))
    write("corpus/checkpoint/one-pixel.ckpt", checkpoint(1, 1, 1, 4, lambda x, y: (0.5, 0.25, 1.0, 0.1, 1)))
    write("corpus/checkpoint/gradient.ckpt",
          checkpoint(4, 3, 3, 16, lambda x, y: (x * 0.75, y * 1.5, 0.125, x * y * 0.5, 3 if x < 3 else 2)))
    write("corpus/checkpoint/cropped.ckpt",
          checkpoint(3, 3, 7, 8, lambda x, y: (1.0, 2.0, 3.0, 1.5, 7) if (x, y) == (1, 1) else (0.0, 0.0, 0.0, 0.0, 0)))
    write("corpus/checkpoint/header-only.ckpt", checkpoint(2, 2, 1, 2, lambda x, y: (0, 0, 0, 0, 0))[:36])


def main():
    checkpoint_seeds()
    png_seeds()
    bmp_seeds()
    tga_seeds()
    pnm_seeds()
    hdr_seeds()
    pfm_seeds()
    mesh_seeds()
    mtl_seeds()
    gltf_seeds()
    asset_seeds()
    scene_seeds()
    edit_seeds()
    pbrt_seeds()
    dictionaries()
    total = 0
    for folder, _, files in os.walk(os.path.join(FUZZ, "corpus")):
        total += sum(os.path.getsize(os.path.join(folder, f)) for f in files)
    print("fuzz/corpus: %d bytes" % total, file=sys.stderr)


if __name__ == "__main__":
    main()
