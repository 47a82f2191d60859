#!/usr/bin/env python3
"""Compares the vertex normals candela computes for an OBJ without `vn` (an object's `"smooth":
180`) with Mitsuba 3's, by their shading-normal passes.

Mitsuba's `obj` plugin computes the normals of a file without `vn` itself (angle-weighted, Thuermer
and Wuethrich 1998), as candela does at a crease angle of 180 degrees; Mitsuba has no crease angle.
This renders the scene's first object that way with Mitsuba's `aov` integrator (`sh_normal`),
candela's `--aov normal` of the same scene, and of the scene with `"smooth": true` (flat faces,
for contrast), and Mitsuba's of another seed (the noise), and prints, over the pixels where both see the object, the angle between the two
renderers' pixel-averaged normals, inside the object's outline (the pixels whose instance id, and
their eight neighbours', is the object's):

    /tmp/mi/bin/python tools/mitsuba_vertex_normals.py SCENE.json [--spp N] [--candela PATH]

The scene is mapped by the shared harness (../shared/reference) with that object's `smooth` set to
true; its mesh is then replaced by the `obj` plugin on the file, placed by the same transform.
candela turns a normal to face the ray and Mitsuba does not, so normals are compared up to sign.
A pixel's normal is the mean over its samples, which differ between renderers and seeds: with
candela's own noise far below Mitsuba's (its samples are stratified, Mitsuba's `independent`),
normals that agree differ from Mitsuba's by about Mitsuba's noise, 1/sqrt(2) of the difference
between its two seeds.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
REFERENCE = os.environ.get('CANDELA_REFERENCE_DIR',
                           os.path.join(HERE, '..', '..', 'shared', 'reference'))
sys.path.insert(0, REFERENCE)

import mitsuba_ref as mr  # noqa: E402
from candela_scene import euler_R  # noqa: E402

mi, np = mr.mi, mr.np


def with_smooth(scene, value, folder):
    """The scene as text, its first object's `smooth` set to value and files made absolute."""
    scene = json.loads(json.dumps(scene))
    for o in scene.get('objects', []):
        if not os.path.isabs(o['file']):
            o['file'] = os.path.normpath(os.path.join(folder, o['file']))
    scene['objects'][0]['smooth'] = value
    return scene


def candela_normals(candela, scene, spp, work, name, seed=1):
    path = os.path.join(work, name + '.json')
    with open(path, 'w') as f:
        json.dump(scene, f)
    out = os.path.join(work, name + '.exr')
    subprocess.run([candela, 'render', path, '-o', out, '--spp', str(spp), '--seed', str(seed),
                    '--aov', 'normal,instance', '--quiet'], check=True)
    layers = dict(mi.Bitmap(out).split())
    ids = np.array(layers['instance'], dtype=np.float64)
    return np.array(layers['normal'], dtype=np.float64), ids.reshape(ids.shape[:2])


def mitsuba_normals(scene, spp, work, seed):
    path = os.path.join(work, 'mitsuba.json')
    with open(path, 'w') as f:
        json.dump(scene, f)
    sc = mr.parse_scene(path)
    d = mr.scene_dict(sc, spp=spp)
    o = scene['objects'][0]
    for name in [k for k in d if k.startswith('obj0_')]:
        del d[name]
    s = o.get('scale', 1)
    s = [s, s, s] if not isinstance(s, list) else s
    M = np.eye(4)
    M[:3, :3] = euler_R(*o.get('rotation', [0, 0, 0])) @ np.diag(s)
    M[:3, 3] = o.get('position', [0, 0, 0])
    d['shape'] = {'type': 'obj', 'filename': o['file'], 'face_normals': False,
                  'to_world': mi.ScalarTransform4f(M.tolist())}
    d['integrator'] = {'type': 'aov', 'aovs': 'n:sh_normal'}
    image = mi.render(mi.load_dict(d), spp=spp, seed=seed)
    return np.array(image, dtype=np.float64)[:, :, :3]


def inside(ids, number):
    """The pixels of instance `number` whose eight neighbours are too."""
    mask = ids == number
    core = mask.copy()
    for dy in (-1, 0, 1):
        for dx in (-1, 0, 1):
            core[1:-1, 1:-1] &= mask[1 + dy:mask.shape[0] - 1 + dy, 1 + dx:mask.shape[1] - 1 + dx]
    core[0, :] = core[-1, :] = core[:, 0] = core[:, -1] = False
    return core


def angles(a, b, where):
    """Degrees between the pixels' normals, up to sign, at the pixels `where`."""
    na, nb = np.linalg.norm(a, axis=2), np.linalg.norm(b, axis=2)
    both = where & (na > 0) & (nb > 0)
    c = np.abs(np.sum(a * b, axis=2))[both] / (na[both] * nb[both])
    return np.degrees(np.arccos(np.clip(c, -1, 1)))


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('scene')
    ap.add_argument('--spp', type=int, default=64)
    ap.add_argument('--candela', default=os.path.join(HERE, '..', 'build', 'candela'))
    a = ap.parse_args()
    mi.set_variant('llvm_ad_rgb')
    with open(a.scene) as f:
        scene = json.load(f)
    folder = os.path.dirname(os.path.abspath(a.scene))
    with tempfile.TemporaryDirectory() as work:
        reference = mitsuba_normals(with_smooth(scene, True, folder), a.spp, work, 3)
        another = mitsuba_normals(with_smooth(scene, True, folder), a.spp, work, 4)
        number = len(scene.get('spheres', [])) + 1  # the first object's instance number
        smooth, ids = candela_normals(a.candela, with_smooth(scene, 180, folder), a.spp, work, 's')
        where = inside(ids, number)
        flat, _ = candela_normals(a.candela, with_smooth(scene, True, folder), a.spp, work, 'f')
        for label, ours, theirs in (('candela smooth 180 against Mitsuba', smooth, reference),
                                    ('candela flat against Mitsuba', flat, reference),
                                    ('Mitsuba against itself, another seed', another, reference)):
            d = angles(ours, theirs, where)
            print(f'{label}: {d.size} pixels, angle median {np.median(d):.4f}, '
                  f'mean {d.mean():.4f}, 99th percentile {np.percentile(d, 99):.3f} degrees')


if __name__ == '__main__':
    main()
