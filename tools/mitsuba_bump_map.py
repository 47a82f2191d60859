#!/usr/bin/env python3
"""Holds candela's bump maps against Mitsuba 3's `bumpmap` BSDF on a plane (docs/scene-format.md,
*Bump maps*): a diffuse square of side 8 under a directional light, its uvs running along +x and
-z, bumped by a 64 x 64 float map of heights 0.5 + 0.25 sin(2 pi u) + 0.25 cos(4 pi v) (the same
under v -> 1 - v, so the two renderers' conventions for v cannot part them) at a height of 2,
seen from above and from the side. Mitsuba's plane is its `rectangle`, turned so that its uvs run
the same way; its map a bilinear `bitmap` read raw.

    /tmp/mi/bin/python tools/mitsuba_bump_map.py [--candela build/candela]

Prints, per view, the median and the 5th and 95th percentiles of candela / Mitsuba over the pixels
both see the plane in, both at 64 samples a pixel over a box filter (the light is direct and the
only noise is where in a pixel a sample falls, so the plane's edge pixels part most).
"""
import argparse
import json
import os
import subprocess
import tempfile

import mitsuba as mi
import numpy as np

SUN = [0.2, -1.0, 0.4]
HEIGHT = 2.0
VIEWS = {'above': ([0, 5, 0.001], [0, 0, 0], [0, 0, -1]),
         'from the side': ([-4, 3, 1], [0, 0, 0], [0, 1, 0])}


def heights(size=64):
    u = (np.arange(size) + 0.5) / size
    v = 1 - (np.arange(size) + 0.5) / size  # rows from the top
    h = 0.5 + 0.25 * np.sin(2 * np.pi * u)[None, :] + 0.25 * np.cos(4 * np.pi * v)[:, None]
    return np.repeat(h[:, :, None], 3, axis=2).astype(np.float32)


def candela(binary, work, origin, target, up):
    scene = {'camera': {'width': 48, 'height': 32, 'fov': 50, 'position': origin,
                        'look_at': target, 'up': up, 'spp': 64},
             'render': {'max_depth': 1},
             'objects': [{'file': os.path.join(work, 'plane.obj'),
                          'material': {'type': 'diffuse', 'color': 0.6,
                                       'bump_map': {'texture': os.path.join(work, 'h.exr'),
                                                    'height': HEIGHT}}}],
             'lights': [{'type': 'directional', 'direction': SUN, 'intensity': 2}]}
    path = os.path.join(work, 'scene.json')
    with open(path, 'w') as f:
        json.dump(scene, f)
    out = os.path.join(work, 'candela.exr')
    subprocess.run([binary, 'render', path, '-o', out, '-q', '--backend', 'cpu'], check=True)
    return np.array(mi.Bitmap(out))[:, :, 0]


def mitsuba(work, origin, target, up):
    # The rectangle's local x -> world x, local y -> world -z, its normal +z -> world +y.
    to_world = [[4, 0, 0, 0], [0, 0, 1, 0], [0, -4, 0, 0], [0, 0, 0, 1]]
    scene = mi.load_dict({
        'type': 'scene', 'integrator': {'type': 'path', 'max_depth': 2},
        'sensor': {'type': 'perspective', 'fov': 50, 'fov_axis': 'x',
                   'to_world': mi.ScalarTransform4f().look_at(origin=origin, target=target, up=up),
                   'film': {'type': 'hdrfilm', 'width': 48, 'height': 32,
                            'rfilter': {'type': 'box'}},
                   'sampler': {'type': 'independent', 'sample_count': 64}},
        'plane': {'type': 'rectangle', 'to_world': mi.ScalarTransform4f(to_world),
                  'bsdf': {'type': 'bumpmap', 'scale': HEIGHT,
                           'texture': {'type': 'bitmap', 'raw': True, 'filter_type': 'bilinear',
                                       'filename': os.path.join(work, 'h.exr')},
                           'bsdf': {'type': 'diffuse',
                                    'reflectance': {'type': 'rgb', 'value': [0.6] * 3}}}},
        'sun': {'type': 'directional', 'direction': SUN,
                'irradiance': {'type': 'rgb', 'value': [2, 2, 2]}}})
    return np.array(mi.render(scene))[:, :, 0]


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--candela', default=os.path.join(os.path.dirname(__file__), '..', 'build',
                                                      'candela'))
    a = ap.parse_args()
    mi.set_variant('scalar_rgb')
    with tempfile.TemporaryDirectory() as work:
        with open(os.path.join(work, 'plane.obj'), 'w') as f:
            f.write('v -4 0 4\nv 4 0 4\nv 4 0 -4\nv -4 0 -4\n'
                    'vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3 4/4\n')
        mi.Bitmap(heights()).write(os.path.join(work, 'h.exr'))
        for name, view in VIEWS.items():
            c, m = candela(a.candela, work, *view), mitsuba(work, *view)
            both = (c > 0) & (m > 0)
            ratio = c[both] / m[both]
            print(f'{name}: {both.sum()} pixels, candela / Mitsuba median {np.median(ratio):.5f}, '
                  f'5th-95th percentile {np.percentile(ratio, 5):.5f}-'
                  f'{np.percentile(ratio, 95):.5f}, means {c[both].mean():.5f} / '
                  f'{m[both].mean():.5f}')
    return 0


if __name__ == '__main__':
    raise SystemExit(main())
