#!/usr/bin/env python3
"""Holds candela's roughness textures against Mitsuba 3's textured `alpha` on a plane
(docs/scene-format.md, *Roughness textures*; the plane of tools/mitsuba_plane.py): a rough gold
conductor and a rough glass, their roughness given by 64 x 64 float maps, seen from above and from
the side under a directional light, both renderers at 1024 samples a pixel over a box filter (the
light is direct: the only noise is where in a pixel a sample falls). Mitsuba's `roughconductor`
and `roughdielectric` take alpha = roughness^2: their map holds each texel's square, a bilinear
`bitmap` read raw and turned upside down (its v runs down the image, candela's up). candela
interpolates the roughness and squares it, Mitsuba interpolates the squares: on these smooth maps
the two differ by under 1e-4 in alpha. The maps: roughness rising along u from 0.1 to 0.7, and a
curved field, 0.35 + 0.15 sin(2 pi u) + 0.15 cos(4 pi v).

    /tmp/mi/bin/python tools/mitsuba_roughness_map.py [--candela build/candela]

Prints, per material, map and view, the median and the 5th and 95th percentiles of candela /
Mitsuba over the pixels both see the plane in.
"""
import os
import tempfile

import mitsuba as mi
import numpy as np

import mitsuba_plane as plane

SPP = 1024


def roughness_maps(size=64):
    """Each map as its rows from the top (candela's v = 1)."""
    u, v, zero = plane.texel_grid(size)
    return {'rise along u': zero + 0.1 + 0.6 * u[None, :],
            'curved': 0.35 + 0.15 * np.sin(2 * np.pi * u)[None, :] +
                      0.15 * np.cos(4 * np.pi * v)[:, None]}


def materials(candela_map, mitsuba_map):
    """(name, candela material, Mitsuba BSDF) of each material."""
    alpha = {'type': 'bitmap', 'raw': True, 'filter_type': 'bilinear', 'filename': mitsuba_map}
    texture = {'texture': candela_map}
    return [('gold', {'type': 'conductor', 'metal': 'Au', 'roughness': texture},
             {'type': 'roughconductor', 'material': 'Au', 'distribution': 'ggx',
              'sample_visible': True, 'alpha': alpha}),
            ('glass', {'type': 'glass', 'ior': 1.5, 'roughness': texture},
             {'type': 'roughdielectric', 'int_ior': 1.5, 'ext_ior': 1.0, 'distribution': 'ggx',
              'sample_visible': True, 'alpha': alpha})]


def main():
    a = plane.parse_args(__doc__)
    with tempfile.TemporaryDirectory() as work:
        plane.write_obj(work)
        candela_map, mitsuba_map = os.path.join(work, 'r.exr'), os.path.join(work, 'a_mi.exr')
        for map_name, r in roughness_maps().items():
            rgb = np.repeat(r[:, :, None], 3, axis=2).astype(np.float32)
            mi.Bitmap(rgb).write(candela_map)
            mi.Bitmap(np.ascontiguousarray((rgb * rgb)[::-1])).write(mitsuba_map)
            for name, material, bsdf in materials(candela_map, mitsuba_map):
                plane.compare_views(a.candela, work, f'{name}, {map_name}', material, bsdf, SPP)
    return 0


if __name__ == '__main__':
    raise SystemExit(main())
