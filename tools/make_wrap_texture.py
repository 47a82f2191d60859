#!/usr/bin/env python3
"""Writes the texture of scenes/examples/texture_wrap.json: an 8 x 8 pixel-art arrow pointing to
the top right, with a teal left column and a gold bottom row, so that each wrap mode shows what it
does beyond the image's edges (docs/scene-format.md, *Textures*: `wrap` and `filter`): repeated
copies, edge texels held (teal and gold streaks), or every other copy mirrored (arrows that point
the other way).

    python3 tools/make_wrap_texture.py scenes/textures/wrap_arrow.png

Standard library only, so that the file can be made again anywhere.
"""
import argparse

from png8 import png8

ART = ['T...RRRR',
       'T.....RR',
       'T....R.R',
       'T...R..R',
       'T..R....',
       'T.R.....',
       'TR......',
       'GGGGGGGG']
COLOURS = {'.': (236, 226, 200), 'R': (170, 36, 40), 'T': (36, 128, 150), 'G': (232, 178, 36)}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('output')
    args = parser.parse_args()
    rows = [[value for texel in line for value in COLOURS[texel]] for line in ART]
    with open(args.output, 'wb') as f:
        f.write(png8(len(ART[0]), len(ART), rows))


if __name__ == '__main__':
    main()
