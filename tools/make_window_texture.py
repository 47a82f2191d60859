#!/usr/bin/env python3
"""Writes the texture of scenes/examples/textured_light.json: a stained-glass window of 3 x 4
coloured panes in dark lead came, as an 8-bit RGB PNG (docs/scene-format.md, *Rectangle lights*:
a rectangle light's `color` may be a texture, shown upright from in front of it).

    python3 tools/make_window_texture.py scenes/textures/window.png [--size 96]

The image is `size` texels wide and 4/3 of that high. Standard library only, so that the file can
be made again anywhere.
"""
import argparse

from png8 import png8

COLUMNS, ROWS = 3, 4
CAME = 0.06  # the lead's width, in panes
# sRGB colours of the panes, by row from the top.
PANES = [[(230, 60, 50), (250, 210, 80), (60, 110, 220)],
         [(70, 170, 90), (240, 240, 230), (200, 90, 180)],
         [(60, 110, 220), (250, 150, 60), (70, 170, 90)],
         [(250, 210, 80), (230, 60, 50), (240, 240, 230)]]
LEAD = (25, 22, 20)


def colour(x, y):
    """The colour at (x, y) in panes from the top left."""
    fx, fy = x % 1.0, y % 1.0
    if min(fx, 1.0 - fx, fy, 1.0 - fy) < CAME / 2:
        return LEAD
    return PANES[min(int(y), ROWS - 1)][min(int(x), COLUMNS - 1)]


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('out')
    ap.add_argument('--size', type=int, default=96)
    a = ap.parse_args()
    width, height = a.size, a.size * ROWS // COLUMNS
    rows = []
    for j in range(height):
        row = []
        for i in range(width):
            row.extend(colour((i + 0.5) / width * COLUMNS, (j + 0.5) / height * ROWS))
        rows.append(row)
    with open(a.out, 'wb') as f:
        f.write(png8(width, height, rows))
    return 0


if __name__ == '__main__':
    raise SystemExit(main())
