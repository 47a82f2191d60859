#!/usr/bin/env python3
"""Writes the mesh of scenes/examples/vertex_colors.json: a trefoil knot's tube painted by its
vertices (docs/scene-format.md, *Vertex colours*), its hue running once round the knot and a
darker band round the tube, as a binary little-endian PLY with uchar red, green and blue, the
form scanners and MeshLab write.

    python3 tools/make_vertex_colour_example.py scenes/meshes/painted_knot.ply

Standard library only, so that the file can be made again anywhere.
"""
import colorsys
import math
import struct
import sys

SEGMENTS, SIDES = 180, 12  # along the knot, round the tube
TUBE = 0.28


def knot(t):
    """A trefoil knot's point at t in [0, 2 pi), about 2.4 units across."""
    return (math.sin(t) + 2 * math.sin(2 * t), math.cos(t) - 2 * math.cos(2 * t), -math.sin(3 * t))


def unit(v):
    n = math.sqrt(sum(c * c for c in v))
    return tuple(c / n for c in v)


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def main(path):
    vertices, faces = [], []
    for i in range(SEGMENTS):
        t = 2 * math.pi * i / SEGMENTS
        p = knot(t)
        ahead = knot(t + 1e-4)
        tangent = unit(tuple(a - b for a, b in zip(ahead, p)))
        side = unit(cross(tangent, (0.0, 0.0, 1.0)))
        up = cross(side, tangent)
        hue = i / SEGMENTS
        for j in range(SIDES):
            a = 2 * math.pi * j / SIDES
            offset = tuple(TUBE * (math.cos(a) * s + math.sin(a) * u) for s, u in zip(side, up))
            shade = 0.45 if j in (0, 1) else 0.9  # a darker band along one side of the tube
            rgb = colorsys.hsv_to_rgb(hue, 0.75, shade)
            vertices.append((tuple(0.6 * (c + o) for c, o in zip(p, offset)),
                             tuple(round(255 * c) for c in rgb)))
    for i in range(SEGMENTS):
        for j in range(SIDES):
            a = i * SIDES + j
            b = i * SIDES + (j + 1) % SIDES
            c = ((i + 1) % SEGMENTS) * SIDES + (j + 1) % SIDES
            d = ((i + 1) % SEGMENTS) * SIDES + j
            faces += [(a, d, c), (a, c, b)]
    header = ("ply\nformat binary_little_endian 1.0\ncomment candela tools/make_vertex_colour_"
              "example.py\nelement vertex %d\nproperty float x\nproperty float y\nproperty float z\n"
              "property uchar red\nproperty uchar green\nproperty uchar blue\nelement face %d\n"
              "property list uchar uint vertex_indices\nend_header\n" % (len(vertices), len(faces)))
    with open(path, 'wb') as f:
        f.write(header.encode())
        for (x, y, z), (r, g, b) in vertices:
            f.write(struct.pack('<fffBBB', x, y, z, r, g, b))
        for face in faces:
            f.write(struct.pack('<BIII', 3, *face))


if __name__ == '__main__':
    main(sys.argv[1])
