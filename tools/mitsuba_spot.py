#!/usr/bin/env python3
"""Renders a candela scene with spot lights with Mitsuba 3, for reference images.

The shared harness (../shared/reference/mitsuba_ref.py) maps the original scene contract, whose
lights are point and sphere lights; this adds spot lights and hands everything else to it.

    /tmp/mi/bin/python tools/mitsuba_spot.py SCENE.json OUT.exr [--spp N] [--seed S]
                                             [--threads T]

It prints the harness's two lines (the timing line, then `mean rgb = ...`).

Mapping: a candela spot light (docs/scene-format.md, Lights) is Mitsuba's `spot` with the same
`cutoff_angle` and `beam_width` (both renderers fall off linearly in angle between them), its
`intensity` the radiant intensity of the point light it limits, color * intensity / (4 pi), as the
harness maps a point light, and its `to_world` a look-at from its position along its direction (or
to its look_at point); the up vector only turns the spot about its axis, which changes nothing.
"""
import argparse
import json
import math
import os
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REFERENCE = os.environ.get('CANDELA_REFERENCE_DIR',
                           os.path.join(HERE, '..', '..', 'shared', 'reference'))
sys.path.insert(0, REFERENCE)
sys.path.insert(0, HERE)

import mitsuba_envmap  # noqa: E402  (parse_beside, render_and_report)
import mitsuba_ref as mr  # noqa: E402  (the harness sets up mitsuba and drjit)

mi, dr, np = mr.mi, mr.dr, mr.np

SPOT_KEYS = ('direction', 'look_at', 'cutoff_angle', 'beam_width')


def split_spots(scene):
    """The scene with its spot lights made point lights for the harness, and the spots by index."""
    spots = {}
    for i, light in enumerate(scene.get('lights', [])):
        if light.get('type') == 'spot':
            spots[i] = {k: light[k] for k in SPOT_KEYS if k in light}
            spots[i].update(position=light['position'], intensity=light['intensity'],
                            color=light.get('color', 1.0))
            light['type'] = 'point'
            for k in SPOT_KEYS:
                light.pop(k, None)
    return scene, spots


def spot_emitter(spot):
    position = np.array(spot['position'], dtype=np.float64)
    if 'look_at' in spot:
        axis = np.array(spot['look_at'], dtype=np.float64) - position
    else:
        axis = np.array(spot['direction'], dtype=np.float64)
    axis /= np.linalg.norm(axis)
    up = [0.0, 1.0, 0.0] if abs(axis[1]) < 0.9 else [1.0, 0.0, 0.0]
    color = spot['color'] if isinstance(spot['color'], list) else [spot['color']] * 3
    cutoff = float(spot.get('cutoff_angle', 20.0))
    return {'type': 'spot',
            'intensity': mr.rgb(np.array(color, dtype=np.float64) * spot['intensity'] /
                                (4 * math.pi)),
            'cutoff_angle': cutoff,
            'beam_width': float(spot.get('beam_width', 0.75 * cutoff)),
            'to_world': mi.ScalarTransform4f().look_at(origin=position.tolist(),
                                                       target=(position + axis).tolist(), up=up)}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('scene')
    ap.add_argument('out')
    ap.add_argument('--spp', type=int, default=None)
    ap.add_argument('--seed', type=int, default=0)
    ap.add_argument('--threads', type=int, default=None)
    a = ap.parse_args(argv)
    mi.set_variant('llvm_ad_rgb')
    if a.threads:
        dr.set_thread_count(a.threads)
    with open(a.scene) as f:
        scene, spots = split_spots(json.load(f))
    t0 = time.perf_counter()
    sc = mitsuba_envmap.parse_beside(scene, a.scene, 'spot')
    d = mr.scene_dict(sc, spp=a.spp)
    for i, spot in spots.items():
        d[f'light{i}'] = spot_emitter(spot)
    loaded = mi.load_dict(d)
    mitsuba_envmap.render_and_report(a.scene, sc, loaded, a.out, a.spp, a.seed,
                                     time.perf_counter() - t0)
    return 0


if __name__ == '__main__':
    sys.exit(main())
