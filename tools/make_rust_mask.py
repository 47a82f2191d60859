#!/usr/bin/env python3
"""Writes the mask of scenes/examples/mix.json: blotches of rust (or worn-off paint) as an 8-bit
grey PNG, white where the second material of a mix shows, black where the first does, with soft
edges between (docs/scene-format.md, *Mix*: a mix's `weight` may be a texture, read linearly).

    python3 tools/make_rust_mask.py scenes/textures/rust_mask.png [--size 256] [--seed 7]

Fractal value noise that tiles (it wraps at the image's edges, as a sphere's u does), pushed
through a smooth step so that most texels are 0 or 1. Standard library only, so that the file can
be made again anywhere.
"""
import argparse
import math
import random

from png8 import png8

OCTAVES = 5
COVER = 0.4   # the share of the surface the blotches cover
EDGE = 0.03   # half the width of the step, in noise values


def lattice(cells, rng):
    return [[rng.random() for _ in range(cells)] for _ in range(cells)]


def value_noise(grid, x, y):
    """Smoothly interpolated lattice values at (x, y) in cells, wrapping around the grid."""
    n = len(grid)
    x0, y0 = int(math.floor(x)), int(math.floor(y))
    fx, fy = x - x0, y - y0
    sx, sy = fx * fx * (3 - 2 * fx), fy * fy * (3 - 2 * fy)

    def at(i, j):
        return grid[j % n][i % n]
    top = at(x0, y0) * (1 - sx) + at(x0 + 1, y0) * sx
    bottom = at(x0, y0 + 1) * (1 - sx) + at(x0 + 1, y0 + 1) * sx
    return top * (1 - sy) + bottom * sy


def smoothstep(a, b, v):
    t = min(max((v - a) / (b - a), 0.0), 1.0)
    return t * t * (3 - 2 * t)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('output')
    parser.add_argument('--size', type=int, default=256)
    parser.add_argument('--seed', type=int, default=7)
    args = parser.parse_args()
    rng = random.Random(args.seed)
    grids = [lattice(4 << k, rng) for k in range(OCTAVES)]
    size = args.size
    values = []
    for y in range(size):
        for x in range(size):
            v, amplitude, total = 0.0, 1.0, 0.0
            for grid in grids:
                cells = len(grid)
                v += amplitude * value_noise(grid, x * cells / size, y * cells / size)
                total += amplitude
                amplitude *= 0.5
            values.append(v / total)
    # The threshold that leaves COVER of the texels above it.
    threshold = sorted(values)[int((1 - COVER) * len(values))]
    rows = [[round(255 * smoothstep(threshold - EDGE, threshold + EDGE, values[y * size + x]))
             for x in range(size)] for y in range(size)]
    with open(args.output, 'wb') as f:
        f.write(png8(size, size, rows, channels=1))


if __name__ == '__main__':
    main()
