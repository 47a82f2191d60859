#!/usr/bin/env python3
"""Renders a candela scene whose environment is a map with Mitsuba 3, for reference images.

The shared harness (../shared/reference/mitsuba_ref.py) maps the original scene contract, which
has no environment maps; this adds them. Everything else goes through the harness unchanged.

    /tmp/mi/bin/python tools/mitsuba_envmap.py SCENE.json OUT.exr [--spp N] [--seed S] [--time]

Mapping: candela looks a map frame direction d up at u = 0.5 + atan2(d.x, -d.z) / (2 pi), Mitsuba's
envmap at u = atan2(d.x, -d.z) / (2 pi) (its seam at -z), the same mapping turned 180 degrees about
+y; so Mitsuba's to_world is candela's rotation times a half turn about y. `strength` is the
envmap's scale; a `color` tint other than 1 multiplies the texels into a temporary EXR.
"""
import argparse
import json
import os
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REFERENCE = os.environ.get('CANDELA_REFERENCE_DIR',
                           os.path.join(HERE, '..', '..', 'shared', 'reference'))
sys.path.insert(0, REFERENCE)

import mitsuba_ref as mr  # noqa: E402  (the harness sets up mitsuba and drjit)
from candela_scene import euler_R  # noqa: E402

mi, dr, np = mr.mi, mr.dr, mr.np


def environment_map(scene_file):
    """The scene's environment if it is a map, else None; the scene as text without it."""
    with open(scene_file) as f:
        scene = json.load(f)
    env = scene.get('environment')
    if not isinstance(env, dict) or 'map' not in env:
        return None, None
    scene['environment'] = {'color': 0}
    return env, scene


def envmap_emitter(env, base_dir, work):
    path = env['map'] if os.path.isabs(env['map']) else os.path.join(base_dir, env['map'])
    color = env.get('color', 1.0)
    tint = np.array(color if isinstance(color, list) else [color] * 3, dtype=np.float32)
    if np.any(tint != 1.0):
        texels = np.array(mi.Bitmap(path).convert(mi.Bitmap.PixelFormat.RGB,
                                                  mi.Struct.Type.Float32, False))
        path = os.path.join(work, 'tinted.exr')
        mi.Bitmap(texels * tint).write(path)
    R = np.array(euler_R(*env.get('rotation', [0, 0, 0])), dtype=np.float64)
    half_turn = np.diag([-1.0, 1.0, -1.0])
    M = np.eye(4)
    M[:3, :3] = R @ half_turn
    return {'type': 'envmap', 'filename': path, 'scale': float(env.get('strength', 1.0)),
            'to_world': mi.ScalarTransform4f(M.tolist())}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('scene')
    ap.add_argument('out')
    ap.add_argument('--spp', type=int, default=None)
    ap.add_argument('--seed', type=int, default=0)
    ap.add_argument('--time', action='store_true', help='a 1-spp warm-up first, then time')
    a = ap.parse_args(argv)
    mi.set_variant('llvm_ad_rgb')
    env, scene = environment_map(a.scene)
    if env is None:
        return mr.main([a.scene, a.out, '--seed', str(a.seed)] +
                       (['--spp', str(a.spp)] if a.spp else []) + (['--time'] if a.time else []))
    base_dir = os.path.dirname(os.path.abspath(a.scene))
    with tempfile.TemporaryDirectory() as work:
        # Beside the original, so that its relative mesh paths still resolve.
        stripped = os.path.join(base_dir, f'.mitsuba_envmap_{os.getpid()}.json')
        with open(stripped, 'w') as f:
            json.dump(scene, f)
        try:
            sc = mr.parse_scene(stripped)
        finally:
            os.remove(stripped)
        d = mr.scene_dict(sc, spp=a.spp)
        d['envmap'] = envmap_emitter(env, base_dir, work)
        loaded = mi.load_dict(d)
        spp = a.spp or sc['camera']['spp']
        if a.time:
            mr.render(sc, loaded, 1, a.seed + 987654)
        t = time.perf_counter()
        img = mr.render(sc, loaded, spp, a.seed)
        seconds = time.perf_counter() - t
    mr.write_exr(a.out, img)
    print(f'{a.scene}: spp={spp} render={seconds:.2f}s '
          f'mean rgb = {img.reshape(-1, 3).astype(np.float64).mean(0).tolist()}')
    return 0


if __name__ == '__main__':
    sys.exit(main())
