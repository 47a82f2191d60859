#!/usr/bin/env python3
"""Writes the height map of scenes/examples/bump_map.json: a running bond of bricks, each a raised
block with bevelled edges, in mortar joints, as a 16-bit grey PNG (docs/scene-format.md, *Bump
maps*: a texel's value is its height over the map's `height`; 16 bits, as 8 would step the
bevels' slopes).

    python3 tools/make_height_map.py scenes/textures/bricks_height.png [--size 256]

One repeat of the map holds four courses of two bricks (each course shifted half a brick from the
last). Heights: 1 on a brick's face, falling linearly to 0 across a bevel of 0.06 brick heights,
0 in the joints. Standard library only, so that the file can be made again anywhere.
"""
import argparse
import struct
import zlib

COURSES, BRICKS = 4, 2
JOINT, BEVEL = 0.05, 0.06  # in brick heights (a course is one brick height)


def height(u, v):
    """The height at (u, v) in [0, 1)^2, u along the courses."""
    y = v * COURSES
    course = int(y)
    x = u * BRICKS + (0.5 if course % 2 else 0.0)
    # Distances to the brick's edges, in brick heights (a brick is COURSES / BRICKS heights long).
    across = min(y - course, course + 1 - y)
    along = min(x % 1.0, 1.0 - x % 1.0) * COURSES / BRICKS
    edge = min(across, along) - JOINT / 2
    return 0.0 if edge <= 0 else min(1.0, edge / BEVEL)


def png16(width, height_, rows):
    def chunk(kind, data):
        return (struct.pack('>I', len(data)) + kind + data +
                struct.pack('>I', zlib.crc32(kind + data) & 0xffffffff))
    raw = b''.join(b'\x00' + struct.pack(f'>{len(row)}H', *row) for row in rows)
    return (b'\x89PNG\r\n\x1a\n' +
            chunk(b'IHDR', struct.pack('>IIBBBBB', width, height_, 16, 0, 0, 0, 0)) +
            chunk(b'IDAT', zlib.compress(raw, 9)) + chunk(b'IEND', b''))


def write_map(path, size, value):
    """A size x size 16-bit grey PNG of value(u, v) in [0, 1] at each texel's centre."""
    rows = []
    for j in range(size):  # from the image's top row, where v = 1
        v = 1.0 - (j + 0.5) / size
        rows.append([round(65535 * value((i + 0.5) / size, v)) for i in range(size)])
    with open(path, 'wb') as f:
        f.write(png16(size, size, rows))


def command_line(doc, value, default_size):
    """A map maker's command line (`doc` its help): writes value's map to the file it names, at
    --size texels square."""
    ap = argparse.ArgumentParser(description=doc,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('out')
    ap.add_argument('--size', type=int, default=default_size)
    a = ap.parse_args()
    write_map(a.out, a.size, value)
    return 0


def main():
    return command_line(__doc__, height, 256)


if __name__ == '__main__':
    raise SystemExit(main())
