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
import argparse
import json
import os
import subprocess
import tempfile

import mitsuba as mi
import numpy as np

TEXEL = [230, 128, 170]  # the map's normal tilts 67 degrees towards +u
SUN = [0.2, -1.0, 0.4]
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


def candela(binary, work, origin, target, up):
    scene = {'camera': {'width': 48, 'height': 32, 'fov': 50, 'position': origin,
                        'look_at': target, 'up': up, 'spp': 4},
             'render': {'max_depth': 1, 'antialiasing': False},
             'objects': [{'file': os.path.join(work, 'plane.obj'),
                          'material': {'type': 'diffuse', 'color': 0.6,
                                       'normal_map': {'texture': os.path.join(work, 'n.png')}}}],
             'lights': [{'type': 'directional', 'direction': SUN, 'intensity': 2}]}
    path = os.path.join(work, 'scene.json')
    with open(path, 'w') as f:
        json.dump(scene, f)
    out = os.path.join(work, 'candela.exr')
    subprocess.run([binary, 'render', path, '-o', out, '-q'], check=True)
    return np.array(mi.Bitmap(out))[:, :, 0]


def mitsuba(work, origin, target, up):
    texel = np.array(TEXEL, dtype=np.float32) / 255
    mi.Bitmap(np.tile(texel, (4, 4, 1))).write(os.path.join(work, 'n.exr'))
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
                  'bsdf': {'type': 'normalmap', 'use_shadowing_function': False,
                           'normalmap': {'type': 'bitmap', 'raw': True, 'filter_type': 'nearest',
                                         'filename': os.path.join(work, 'n.exr')},
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
        write_png(os.path.join(work, 'n.png'), TEXEL)
        for name, view in VIEWS.items():
            c, m = candela(a.candela, work, *view), mitsuba(work, *view)
            both = (c > 0) & (m > 0)
            ratio = c[both] / m[both]
            print(f'{name}: {both.sum()} pixels, candela / Mitsuba median {np.median(ratio):.7f}, '
                  f'5th-95th percentile {np.percentile(ratio, 5):.7f}-'
                  f'{np.percentile(ratio, 95):.7f}')
    return 0


if __name__ == '__main__':
    raise SystemExit(main())
