"""candela's "checkerboard" texture against Mitsuba 3's `checkerboard`: a glowing panel of red and
blue squares (colour0 red, colour1 blue, repeated 3 x 2 times) seen straight on by a 48 x 48
orthographic camera, box filter. Prints the pixels whose colour differs by more than 0.02 (a
square's edge crossing a pixel is blended by each renderer's samples, within that where both
converge) and by more than 0.2 (a square of the wrong colour).

candela: a `rectangle` shape of scale 2 turned to face +z (u along +x, v along +y), its radiance
{"checkerboard": [red, blue], "scale": [3, 2]}. Mitsuba: its `rectangle` ([-1, 1]^2, uv the same
way), `to_uv` scaling uv by (3, 2).

    /tmp/mi/bin/python tools/mitsuba_checkerboard.py [--candela build/candela]
"""
import argparse
import json
import os
import subprocess
import tempfile

import mitsuba as mi
import numpy as np

SIZE = 48
SPP = 1024


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--candela', default=os.path.join(os.path.dirname(__file__), '..', 'build',
                                                      'candela'))
    args = ap.parse_args()
    mi.set_variant('scalar_rgb')
    red, blue = [1, 0, 0], [0, 0, 1]
    scene = {'camera': {'width': SIZE, 'height': SIZE, 'projection': 'orthographic',
                        'view_width': 2, 'position': [0, 0, 5], 'spp': SPP},
             'render': {'max_depth': 1},
             'objects': [{'shape': 'rectangle', 'scale': 2, 'rotation': [90, 0, 0],
                          'material': {'type': 'emissive', 'radiance': {
                              'checkerboard': [red, blue], 'scale': [3, 2]}}}]}
    with tempfile.TemporaryDirectory() as work:
        path, out = os.path.join(work, 'scene.json'), os.path.join(work, 'candela.exr')
        with open(path, 'w') as f:
            json.dump(scene, f)
        subprocess.run([args.candela, 'render', path, '-o', out, '-q', '--backend', 'cpu'],
                       check=True)
        c = np.array(mi.Bitmap(out))[:, :, :3]
    checker = {'type': 'checkerboard', 'color0': {'type': 'rgb', 'value': red},
               'color1': {'type': 'rgb', 'value': blue},
               'to_uv': mi.ScalarTransform4f().scale([3, 2, 1])}
    m = np.array(mi.render(mi.load_dict({
        'type': 'scene', 'integrator': {'type': 'direct'},
        'sensor': {'type': 'orthographic',
                   'to_world': mi.ScalarTransform4f().look_at(origin=[0, 0, 5], target=[0, 0, 0],
                                                              up=[0, 1, 0]),
                   'film': {'type': 'hdrfilm', 'width': SIZE, 'height': SIZE,
                            'rfilter': {'type': 'box'}},
                   'sampler': {'type': 'multijitter', 'sample_count': SPP}},
        'panel': {'type': 'rectangle', 'emitter': {'type': 'area', 'radiance': checker}}})))
    d = np.abs(c - m[:, :, :3]).max(axis=2)
    print(f'{SIZE * SIZE} pixels: {(d > 0.02).sum()} differ by more than 0.02, '
          f'{(d > 0.2).sum()} by more than 0.2; largest {d.max():.4f}')


if __name__ == '__main__':
    main()
