#!/usr/bin/env python3
"""Holds candela's normal maps against Mitsuba 3's `normalmap` BSDF on a plane (docs/scene-format.md,
*Normal maps*): a diffuse square of side 8 under a directional light, its uvs running along +x and
-z, a constant tangent-space normal map, seen from above (the map's normal faces the camera) and
from low on the side it tilts away from (its tilt is mirrored). Mitsuba's plane is its `rectangle`,
turned so that its uvs run the same way, with `use_shadowing_function` off (candela does not apply
that smoothing of the shadow terminator) and `flip_invalid_normals` at its default, on.

    /tmp/mi/bin/python tools/mitsuba_normal_map.py [--candela build/candela]

Prints, per view, the median and the 5th and 95th percentiles of candela / Mitsuba over the pixels
both see the plane in (the plane's edge pixels differ: candela samples pixel centres here, Mitsuba
its box filter's whole pixel).
"""
import os
import tempfile

import mitsuba as mi
import numpy as np

import mitsuba_plane as plane

TEXEL = [230, 128, 170]  # the map's normal tilts 67 degrees towards +u
SUN = plane.SUN
VIEWS = {'above': ([0, 5, 0.001], [0, 0, 0], [0, 0, -1]),
         'low, tilted away': ([-5, 2.5, 0], [0, 0, 0], [0, 1, 0])}


def write_png(path, rgb, size=4):
    import struct
    import zlib

    def chunk(kind, data):
        return (struct.pack('>I', len(data)) + kind + data +
                struct.pack('>I', zlib.crc32(kind + data) & 0xffffffff))
    raw = b''.join(b'\x00' + bytes(rgb * size) for _ in range(size))
    with open(path, 'wb') as f:
        f.write(b'\x89PNG\r\n\x1a\n' +
                chunk(b'IHDR', struct.pack('>IIBBBBB', size, size, 8, 2, 0, 0, 0)) +
                chunk(b'IDAT', zlib.compress(raw)) + chunk(b'IEND', b''))


def diffuse(reflectance):
    return {'type': 'diffuse', 'reflectance': {'type': 'rgb', 'value': [reflectance] * 3}}


def main():
    a = plane.parse_args(__doc__)
    with tempfile.TemporaryDirectory() as work:
        plane.write_obj(work)
        write_png(os.path.join(work, 'n.png'), TEXEL)
        texel = np.array(TEXEL, dtype=np.float32) / 255
        mi.Bitmap(np.tile(texel, (4, 4, 1))).write(os.path.join(work, 'n.exr'))
        material = {'type': 'diffuse', 'color': 0.6,
                    'normal_map': {'texture': os.path.join(work, 'n.png')}}
        bsdf = {'type': 'normalmap', 'use_shadowing_function': False,
                'normalmap': {'type': 'bitmap', 'raw': True, 'filter_type': 'nearest',
                              'filename': os.path.join(work, 'n.exr')},
                'bsdf': diffuse(0.6)}
        for name, view in VIEWS.items():
            c = plane.candela(a.candela, work, view, material, SUN, 4, False)
            print(plane.report(name, c, plane.mitsuba(view, bsdf, SUN, 64)))
    return 0


if __name__ == '__main__':
    raise SystemExit(main())
