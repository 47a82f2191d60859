#!/usr/bin/env python3
"""Writes the tangent-space normal map of scenes/examples/normal_map.json: a grid of round studs
(spherical caps) on a flat ground, as an 8-bit RGB PNG in OpenGL's convention (docs/scene-format.md,
*Normal maps*: red along +u, green along +v, blue out of the surface; (128, 128, 255) is flat).

    python3 tools/make_normal_map.py scenes/textures/studs_normal.png [--size 256] [--cells 4]

The normals are those of the height field h(u, v), a cap of radius 0.38 cells and height 0.16
cells in each cell, from its exact gradient: n = normalize(-dh/du, -dh/dv, 1). Standard library
only, so that the file can be made again anywhere.
"""
import argparse
import math
import struct
import zlib


def cap_normal(x, y, radius, height):
    """The normal at (x, y) from the centre of a cell, in cells: a spherical cap of the given
    base radius and height, flat ground around it."""
    r2 = x * x + y * y
    if r2 >= radius * radius:
        return 0.0, 0.0, 1.0
    sphere = (radius * radius + height * height) / (2 * height)  # the cap's sphere's radius
    z = math.sqrt(sphere * sphere - r2)  # above the sphere's centre, which lies below the ground
    return x / sphere, y / sphere, z / sphere


def png(width, height, rows):
    def chunk(kind, data):
        return (struct.pack('>I', len(data)) + kind + data +
                struct.pack('>I', zlib.crc32(kind + data) & 0xffffffff))
    raw = b''.join(b'\x00' + bytes(row) for row in rows)
    return (b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', width, height, 8, 2, 0, 0, 0))
            + chunk(b'IDAT', zlib.compress(raw, 9)) + chunk(b'IEND', b''))


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('out')
    ap.add_argument('--size', type=int, default=256)
    ap.add_argument('--cells', type=int, default=4)
    a = ap.parse_args()
    rows = []
    for j in range(a.size):  # from the image's top row, where v = 1
        row = []
        v = 1.0 - (j + 0.5) / a.size
        for i in range(a.size):
            u = (i + 0.5) / a.size
            x = (u * a.cells) % 1.0 - 0.5
            y = (v * a.cells) % 1.0 - 0.5
            n = cap_normal(x, y, 0.38, 0.16)
            row += [max(0, min(255, round((c * 0.5 + 0.5) * 255))) for c in n]
        rows.append(row)
    with open(a.out, 'wb') as f:
        f.write(png(a.size, a.size, rows))
    return 0


if __name__ == '__main__':
    raise SystemExit(main())
