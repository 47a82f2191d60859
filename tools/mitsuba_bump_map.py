#!/usr/bin/env python3
"""Holds candela's bump maps against Mitsuba 3's `bumpmap` BSDF on a plane (docs/scene-format.md,
*Bump maps*; the plane of tools/mitsuba_plane.py): bumped by 64 x 64 float maps of heights at a
height of 2, seen from above and from the side, both renderers at 1024 samples a pixel over a box
filter (the light is direct: the only noise is where in a pixel a sample falls). Mitsuba's map is
a bilinear `bitmap` read raw, turned upside down (its v runs down the image, candela's up). The
maps: heights rising along u, and along v (slopes constant away from where the map repeats);
then a curved field, 0.5 + 0.25 sin(2 pi u) + 0.25 cos(4 pi v).

    /tmp/mi/bin/python tools/mitsuba_bump_map.py [--candela build/candela]

Prints, per map and view, the median and the 5th and 95th percentiles of candela / Mitsuba over
the pixels both see the plane in.
"""
import os
import tempfile

import mitsuba as mi
import numpy as np

import mitsuba_plane as plane

HEIGHT = 2.0
SPP = 1024


def heights(size=64):
    """Each map as its rows from the top (candela's v = 1)."""
    u, v, zero = plane.texel_grid(size)
    return {'gentle rise along u': zero + 0.3 + 0.3 * u[None, :],
            'steep rise along u': zero + 0.3 + 3.0 * u[None, :],
            'steep rise along v': zero + 0.3 + 3.0 * v[:, None],
            'curved': 0.5 + 0.25 * np.sin(2 * np.pi * u)[None, :] +
                      0.25 * np.cos(4 * np.pi * v)[:, None]}


def main():
    a = plane.parse_args(__doc__)
    with tempfile.TemporaryDirectory() as work:
        plane.write_obj(work)
        candela_map, mitsuba_map = os.path.join(work, 'h.exr'), os.path.join(work, 'h_mi.exr')
        material = {'type': 'diffuse', 'color': 0.6,
                    'bump_map': {'texture': candela_map, 'height': HEIGHT}}
        bsdf = {'type': 'bumpmap', 'scale': HEIGHT,
                'texture': {'type': 'bitmap', 'raw': True, 'filter_type': 'bilinear',
                            'filename': mitsuba_map},
                'bsdf': {'type': 'diffuse', 'reflectance': {'type': 'rgb', 'value': [0.6] * 3}}}
        for map_name, h in heights().items():
            rgb = np.repeat(h[:, :, None], 3, axis=2).astype(np.float32)
            mi.Bitmap(rgb).write(candela_map)
            mi.Bitmap(np.ascontiguousarray(rgb[::-1])).write(mitsuba_map)
            plane.compare_views(a.candela, work, map_name, material, bsdf, SPP)
    return 0


if __name__ == '__main__':
    raise SystemExit(main())
