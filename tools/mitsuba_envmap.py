#!/usr/bin/env python3
"""Renders a candela scene whose environment is a map with Mitsuba 3, for reference images.

The shared harness (../shared/reference/mitsuba_ref.py) maps the original scene contract, which
has no environment maps; this adds them. Everything else goes through the harness unchanged.

    /tmp/mi/bin/python tools/mitsuba_envmap.py SCENE.json OUT.exr [--spp N] [--seed S] [--time]
                                               [--threads T]

It prints the harness's line (`SCENE: WxH spp=N variant=llvm_ad_rgb camera=mitsuba load=Ls
render=Rs samples/s=...`, then `mean rgb = ...`), which bench/run parses for its timings; --time
renders 1 spp first (JIT warm-up) and times the render after it, as the harness does.

Mapping: candela looks a map frame direction d up at u = 0.5 + atan2(d.x, -d.z) / (2 pi), Mitsuba's
envmap at u = atan2(d.x, -d.z) / (2 pi) (its seam at -z), the same mapping turned 180 degrees about
+y; so Mitsuba's to_world is candela's rotation times a half turn about y. The two place a map's
rows at different latitudes (rows_at_mitsubas_latitudes), so Mitsuba gets the map resampled to
candela's. `strength` is the envmap's scale; a `color` tint multiplies the texels.
"""
import argparse
import json
import os
import sys
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


def rows_at_mitsubas_latitudes(texels):
    """The map Mitsuba must be given to see candela's radiance at every latitude.

    candela puts row j's centre at v = (j + 0.5) / H and holds the first and last rows' values up
    to the poles; Mitsuba's envmap puts row j of an H'-row bitmap at v = j / (H' - 1), its first
    and last rows on the poles. With 2H + 1 rows, Mitsuba's row j lies at v = j / (2H): an odd j
    on candela's row (j - 1) / 2, an even one halfway between two of candela's rows (or on a pole,
    where candela holds its edge row), so that Mitsuba's linear interpolation between its rows is
    candela's. Columns need nothing: both put column i at u = (i + 0.5) / W and wrap.
    """
    first, last = texels[:1], texels[-1:]
    out = np.empty((2 * texels.shape[0] + 1,) + texels.shape[1:], dtype=texels.dtype)
    out[1::2] = texels
    out[0::2] = 0.5 * (np.concatenate([first, texels]) + np.concatenate([texels, last]))
    return out


def envmap_emitter(env, base_dir):
    path = env['map'] if os.path.isabs(env['map']) else os.path.join(base_dir, env['map'])
    color = env.get('color', 1.0)
    tint = np.array(color if isinstance(color, list) else [color] * 3, dtype=np.float32)
    texels = np.array(mi.Bitmap(path).convert(mi.Bitmap.PixelFormat.RGB, mi.Struct.Type.Float32,
                                              False)) * tint
    R = np.array(euler_R(*env.get('rotation', [0, 0, 0])), dtype=np.float64)
    half_turn = np.diag([-1.0, 1.0, -1.0])
    M = np.eye(4)
    M[:3, :3] = R @ half_turn
    return {'type': 'envmap', 'bitmap': mi.Bitmap(rows_at_mitsubas_latitudes(texels)),
            'scale': float(env.get('strength', 1.0)),
            'to_world': mi.ScalarTransform4f(M.tolist())}


def parse_beside(scene, scene_file, tag):
    """The harness's reading of `scene` (a dict), written for it beside scene_file, so that its
    relative mesh paths still resolve."""
    path = os.path.join(os.path.dirname(os.path.abspath(scene_file)),
                        f'.mitsuba_{tag}_{os.getpid()}.json')
    with open(path, 'w') as f:
        json.dump(scene, f)
    try:
        return mr.parse_scene(path)
    finally:
        os.remove(path)


def render_and_report(scene_file, sc, loaded, out, spp, seed, t_load, warm=False):
    """Renders the loaded scene (a 1-spp warm-up first with `warm`), writes `out` and prints the
    harness's two lines."""
    spp = spp or sc['camera']['spp']
    t_warm = None
    if warm:
        t1 = time.perf_counter()
        mr.render(sc, loaded, 1, seed + 987654)
        t_warm = time.perf_counter() - t1
    t = time.perf_counter()
    img = mr.render(sc, loaded, spp, seed)
    seconds = time.perf_counter() - t
    mr.write_exr(out, img)
    W, H = sc['camera']['W'], sc['camera']['H']
    ns = W * H * spp
    msg = (f'{scene_file}: {W}x{H} spp={spp} variant=llvm_ad_rgb camera=mitsuba '
           f'load={t_load:.2f}s render={seconds:.2f}s '
           f'samples/s={ns / seconds:.4g} ({ns / seconds / 1e6:.3f} Msamples/s)')
    if t_warm is not None:
        msg += f' warmup(1spp)={t_warm:.2f}s'
    print(msg)
    print(f'mean rgb = {img.reshape(-1, 3).astype(np.float64).mean(0).tolist()}  '
          f'nonfinite={int((~np.isfinite(img)).sum())}')


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('scene')
    ap.add_argument('out')
    ap.add_argument('--spp', type=int, default=None)
    ap.add_argument('--seed', type=int, default=0)
    ap.add_argument('--time', action='store_true', help='a 1-spp warm-up first, then time')
    ap.add_argument('--threads', type=int, default=None)
    a = ap.parse_args(argv)
    mi.set_variant('llvm_ad_rgb')
    env, scene = environment_map(a.scene)
    if env is None:
        return mr.main([a.scene, a.out, '--seed', str(a.seed)] +
                       (['--spp', str(a.spp)] if a.spp else []) + (['--time'] if a.time else []) +
                       (['--threads', str(a.threads)] if a.threads else []))
    if a.threads:
        dr.set_thread_count(a.threads)
    t0 = time.perf_counter()
    sc = parse_beside(scene, a.scene, 'envmap')
    d = mr.scene_dict(sc, spp=a.spp)
    d['envmap'] = envmap_emitter(env, os.path.dirname(os.path.abspath(a.scene)))
    loaded = mi.load_dict(d)
    render_and_report(a.scene, sc, loaded, a.out, a.spp, a.seed, time.perf_counter() - t0,
                      warm=a.time)
    return 0


if __name__ == '__main__':
    sys.exit(main())
