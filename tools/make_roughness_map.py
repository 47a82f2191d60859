#!/usr/bin/env python3
"""Writes the roughness map of scenes/examples/roughness_map.json: a checker of polished and honed
tiles, each polished tile crossed by a wiped smear, as a 16-bit grey PNG (docs/scene-format.md,
*Roughness textures*: a texel's value is the roughness there).

    python3 tools/make_roughness_map.py scenes/textures/tiles_roughness.png [--size 128]

One repeat of the map holds 2 x 2 tiles. Roughness: 0.06 on a polished tile, 0.5 on a honed one,
blended over a twentieth of a tile at their edges; a smear of roughness 0.3 runs diagonally
across each polished tile, fading out over its width. Standard library only, like
make_height_map.py, whose map writer it shares.
"""
import math

from make_height_map import command_line

TILES = 2
POLISHED, HONED, SMEAR = 0.06, 0.5, 0.3
EDGE = 0.05  # the blend between tiles, in tile widths
SMEAR_WIDTH = 0.12  # in tile widths


def smoothstep(x):
    x = min(1.0, max(0.0, x))
    return x * x * (3 - 2 * x)


def roughness(u, v):
    """The roughness at (u, v) in [0, 1)^2."""
    x, y = u * TILES, v * TILES
    fx, fy = x % 1.0, y % 1.0
    # How far into its tile the point is, 0 at an edge: the checker's blend weight.
    inside = smoothstep(min(fx, 1 - fx, fy, 1 - fy) / EDGE * 2)
    polished = (int(x) + int(y)) % 2 == 0
    # Each tile's colour faded to the mean of both at its edges, so that neighbours meet there.
    mean = (POLISHED + HONED) / 2
    if not polished:
        return mean + (HONED - mean) * inside
    across = abs(fx - fy) / math.sqrt(2)  # distance from the tile's diagonal
    smear = 1 - smoothstep(across / SMEAR_WIDTH)
    tile = POLISHED + (SMEAR - POLISHED) * smear
    return mean + (tile - mean) * inside


def main():
    return command_line(__doc__, roughness, 128)


if __name__ == '__main__':
    raise SystemExit(main())
