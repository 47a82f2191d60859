"""The plane that tools/mitsuba_normal_map.py and tools/mitsuba_bump_map.py render in both
renderers: a diffuse square of side 8 in y = 0 under a directional light, its uvs running along +x
and -z, seen by a 48 x 32 camera. In Mitsuba 3 it is a `rectangle`, turned so that its uvs run the
same way, with a box pixel filter."""
import argparse
import json
import os
import subprocess

import mitsuba as mi
import numpy as np

SIZE = (48, 32)
FOV = 50
SUN = [0.2, -1.0, 0.4]
# (origin, target, up) of each view the tools render the plane from.
VIEWS = {'above': ([0, 5, 0.001], [0, 0, 0], [0, 0, -1]),
         'from the side': ([-4, 3, 1], [0, 0, 0], [0, 1, 0])}


def texel_grid(size):
    """The u of a size x size map's texel centres along a row, the v down a column (rows from the
    top: candela's v = 1), and a map of zeros, for maps made of them."""
    u = (np.arange(size) + 0.5) / size
    v = 1 - (np.arange(size) + 0.5) / size
    return u, v, np.zeros((size, size))


def parse_args(doc):
    """The tools' one option, --candela (the binary; default build/candela), with `doc` as their
    help; also sets Mitsuba's variant (scalar_rgb: no JIT, as the tools' scenes are small)."""
    ap = argparse.ArgumentParser(description=doc, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--candela', default=os.path.join(os.path.dirname(__file__), '..', 'build',
                                                      'candela'))
    mi.set_variant('scalar_rgb')
    return ap.parse_args()


def write_obj(work):
    with open(os.path.join(work, 'plane.obj'), 'w') as f:
        f.write('v -4 0 4\nv 4 0 4\nv 4 0 -4\nv -4 0 -4\n'
                'vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3 4/4\n')


def candela(binary, work, view, material, sun, spp, antialiasing):
    """candela's render of the plane of `material` (a scene-format material) from view (origin,
    target, up): its first channel."""
    origin, target, up = view
    scene = {'camera': {'width': SIZE[0], 'height': SIZE[1], 'fov': FOV, 'position': origin,
                        'look_at': target, 'up': up, 'spp': spp},
             'render': {'max_depth': 1, 'antialiasing': antialiasing},
             'objects': [{'file': os.path.join(work, 'plane.obj'), 'material': material}],
             'lights': [{'type': 'directional', 'direction': sun, 'intensity': 2}]}
    path = os.path.join(work, 'scene.json')
    with open(path, 'w') as f:
        json.dump(scene, f)
    out = os.path.join(work, 'candela.exr')
    subprocess.run([binary, 'render', path, '-o', out, '-q', '--backend', 'cpu'], check=True)
    return np.array(mi.Bitmap(out))[:, :, 0]


def mitsuba(view, bsdf, sun, spp):
    """Mitsuba 3's render of the plane of `bsdf` (a Mitsuba BSDF dict) from view: its first
    channel."""
    origin, target, up = view
    # The rectangle's local x -> world x, local y -> world -z, its normal +z -> world +y.
    to_world = [[4, 0, 0, 0], [0, 0, 1, 0], [0, -4, 0, 0], [0, 0, 0, 1]]
    scene = mi.load_dict({
        'type': 'scene', 'integrator': {'type': 'path', 'max_depth': 2},
        'sensor': {'type': 'perspective', 'fov': FOV, 'fov_axis': 'x',
                   'to_world': mi.ScalarTransform4f().look_at(origin=origin, target=target, up=up),
                   'film': {'type': 'hdrfilm', 'width': SIZE[0], 'height': SIZE[1],
                            'rfilter': {'type': 'box'}},
                   'sampler': {'type': 'independent', 'sample_count': spp}},
        'plane': {'type': 'rectangle', 'to_world': mi.ScalarTransform4f(to_world), 'bsdf': bsdf},
        'sun': {'type': 'directional', 'direction': sun,
                'irradiance': {'type': 'rgb', 'value': [2, 2, 2]}}})
    return np.array(mi.render(scene))[:, :, 0]


def report(name, c, m):
    """One line: candela / Mitsuba over the pixels both see the plane in."""
    both = (c > 0) & (m > 0)
    ratio = c[both] / m[both]
    return (f'{name}: {both.sum()} pixels, candela / Mitsuba median {np.median(ratio):.7f}, '
            f'5th-95th percentile {np.percentile(ratio, 5):.7f}-{np.percentile(ratio, 95):.7f}')


def compare_views(binary, work, label, material, bsdf, spp):
    """Renders the plane of `material` (candela) and `bsdf` (Mitsuba) under SUN from each of VIEWS
    at spp samples a pixel, antialiased, and prints a report line for each."""
    for name, view in VIEWS.items():
        c = candela(binary, work, view, material, SUN, spp, True)
        print(report(f'{label}, {name}', c, mitsuba(view, bsdf, SUN, spp)), flush=True)
