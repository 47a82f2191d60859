#!/usr/bin/env python3
"""Renders a candela scene with spot, directional or rectangle lights with Mitsuba 3, for reference
images.

The shared harness (../shared/reference/mitsuba_ref.py) maps the original scene contract, whose
lights are point and sphere lights; this adds spot, directional and rectangle lights (and an
environment map, as tools/mitsuba_envmap.py maps it, and a pixel filter, as tools/mitsuba_filter.py
maps it) and hands everything else to it.

    /tmp/mi/bin/python tools/mitsuba_lights.py SCENE.json OUT.exr [--spp N] [--seed S]
                                               [--threads T]

It prints the harness's two lines (the timing line, then `mean rgb = ...`).

Mapping: a candela directional light is Mitsuba's `directional` with the same `direction` and
its `irradiance` color * intensity (both the irradiance of a surface facing the light). A spot
light (docs/scene-format.md, Lights) is Mitsuba's `spot` with the same
`cutoff_angle` and `beam_width` (both renderers fall off linearly in angle between them), its
`intensity` the radiant intensity of the point light it limits, color * intensity / (4 pi), as the
harness maps a point light, and its `to_world` a look-at from its position along its direction (or
to its look_at point); the up vector only turns the spot about its axis, which changes nothing.
A rectangle light is Mitsuba's `rectangle` shape ([-1, 1]^2 in its xy plane, shining along +z)
placed by a to_world whose columns are candela's width, height and normal axes scaled by half
the width and height, with an `area` emitter of radiance color * intensity / (pi width height)
and a black `diffuse` BSDF (candela's emitters reflect nothing; Mitsuba's default BSDF would).
A two-sided rectangle light (Mitsuba's area emitter has one side) is two such rectangles back to
back, each of half the power, the second with `flip_normals` and moved BACK_OFFSET behind the
first so that a ray from either side meets the one facing it first. A rectangle light whose
`color` is a texture gets a `bitmap` radiance: the image decoded to linear, times
intensity / (pi width height), written as an EXR, its v turned over (Mitsuba's rectangle has
uv = (x + 1, y + 1) / 2 in its plane and its bitmaps put v = 0 on the top row; candela puts
v = 0 on the bottom row, up the light's height).
"""
import argparse
import atexit
import json
import math
import os
import shutil
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REFERENCE = os.environ.get('CANDELA_REFERENCE_DIR',
                           os.path.join(HERE, '..', '..', 'shared', 'reference'))
sys.path.insert(0, REFERENCE)
sys.path.insert(0, HERE)

import mitsuba_envmap  # noqa: E402  (environment_map, parse_beside, render_and_report)
import mitsuba_filter  # noqa: E402  (take_filter, apply_filter)
import mitsuba_ref as mr  # noqa: E402  (the harness sets up mitsuba and drjit)

mi, dr, np = mr.mi, mr.dr, mr.np

SPOT_KEYS = ('direction', 'look_at', 'cutoff_angle', 'beam_width')
# How far behind a two-sided rectangle light its back's rectangle lies, in scene units.
BACK_OFFSET = 1e-4


WORK = tempfile.mkdtemp(prefix='candela_mitsuba_lights_')
atexit.register(shutil.rmtree, WORK, True)


def split_lights(scene, folder='.'):
    """The scene for the harness, with its spot lights made point lights and its directional and
    rectangle lights taken out; the spots by index, and the others' Mitsuba emitters (or
    emitting shapes)."""
    spots = {}
    emitters = []
    harness_lights = []
    for i, light in enumerate(scene.get('lights', [])):
        if light.get('type') == 'directional':
            emitters.append(directional_emitter(light))
            continue
        if light.get('type') == 'rectangle':
            emitters.extend(rectangle_emitters(light, folder))
            continue
        if light.get('type') == 'spot':
            spots[len(harness_lights)] = {k: light[k] for k in SPOT_KEYS if k in light}
            spots[len(harness_lights)].update(position=light['position'],
                                              intensity=light['intensity'],
                                              color=light.get('color', 1.0))
            light['type'] = 'point'
            for k in SPOT_KEYS:
                light.pop(k, None)
        harness_lights.append(light)
    scene['lights'] = harness_lights
    return scene, spots, emitters


def rgb_of(color):
    return np.array(color if isinstance(color, list) else [color] * 3, dtype=np.float64)


def directional_emitter(light):
    return {'type': 'directional', 'direction': [float(x) for x in light['direction']],
            'irradiance': mr.rgb(rgb_of(light.get('color', 1.0)) * light['intensity'])}


def unit(v):
    v = np.array(v, dtype=np.float64)
    return v / np.linalg.norm(v)


def rectangle_axes(light):
    """candela's width, height and normal axes (scene/light_emission_desc.h, rectangleAxes)."""
    position = np.array(light['position'], dtype=np.float64)
    if 'look_at' in light:
        n = unit(np.array(light['look_at'], dtype=np.float64) - position)
    else:
        n = unit(light['direction'])
    if 'up' in light:
        up = np.array(light['up'], dtype=np.float64)
    else:
        up = np.array([0.0, 0.0, 1.0] if np.linalg.norm(np.cross(n, [0, 1, 0])) < 1e-6
                      else [0.0, 1.0, 0.0])
    height = unit(up - np.dot(up, n) * n)
    return np.cross(height, n), height, n


def textured_radiance(texture, scale, folder):
    """A `bitmap` of the texture object `texture` (relative to `folder`) times `scale`."""
    if 'scale' in texture:
        raise SystemExit('mitsuba_lights.py: a textured light\'s "scale" is not mapped')
    name = os.path.join(folder, texture['texture'])
    linear = mi.Bitmap(name).convert(mi.Bitmap.PixelFormat.RGB, mi.Struct.Type.Float32,
                                     srgb_gamma=False)
    out = os.path.join(WORK, f'{len(os.listdir(WORK))}.exr')
    mi.Bitmap(np.array(linear) * scale).write(out)
    return {'type': 'bitmap', 'filename': out, 'raw': True, 'filter_type': 'bilinear',
            'wrap_mode': 'repeat',
            'to_uv': mi.ScalarTransform4f().translate([0, 1, 0]).scale([1, -1, 1])}


def rectangle_emitters(light, folder='.'):
    """The rectangle light's emitting shapes: one, or two back to back where it is two-sided."""
    size = light['size'] if isinstance(light['size'], list) else [light['size']] * 2
    width, height, normal = rectangle_axes(light)
    m = np.eye(4)
    m[:3, 0] = width * size[0] / 2
    m[:3, 1] = height * size[1] / 2
    m[:3, 2] = normal
    m[:3, 3] = light['position']
    sides = 2 if light.get('two_sided', False) else 1
    color = light.get('color', 1.0)
    scale = light['intensity'] / (math.pi * sides * size[0] * size[1])
    radiance = (textured_radiance(color, scale, folder) if isinstance(color, dict)
                else mr.rgb(rgb_of(color) * scale))
    shapes = []
    for side in range(sides):
        if side == 1:
            m[:3, 3] = np.array(light['position'], dtype=np.float64) - BACK_OFFSET * normal
        shapes.append({'type': 'rectangle', 'to_world': mi.ScalarTransform4f(m.tolist()),
                       'flip_normals': side == 1,
                       'emitter': {'type': 'area', 'radiance': radiance},
                       'bsdf': {'type': 'diffuse', 'reflectance': mr.rgb(np.zeros(3))}})
    return shapes


def spot_emitter(spot):
    position = np.array(spot['position'], dtype=np.float64)
    if 'look_at' in spot:
        axis = np.array(spot['look_at'], dtype=np.float64) - position
    else:
        axis = np.array(spot['direction'], dtype=np.float64)
    axis /= np.linalg.norm(axis)
    up = [0.0, 1.0, 0.0] if abs(axis[1]) < 0.9 else [1.0, 0.0, 0.0]
    cutoff = float(spot.get('cutoff_angle', 20.0))
    return {'type': 'spot',
            'intensity': mr.rgb(rgb_of(spot['color']) * spot['intensity'] / (4 * math.pi)),
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
    env, scene = mitsuba_envmap.environment_map(a.scene)
    if env is None:
        with open(a.scene) as f:
            scene = json.load(f)
    scene, spots, emitters = split_lights(scene, os.path.dirname(os.path.abspath(a.scene)))
    rfilter = mitsuba_filter.take_filter(scene)
    t0 = time.perf_counter()
    sc = mitsuba_envmap.parse_beside(scene, a.scene, 'lights')
    d = mr.scene_dict(sc, spp=a.spp)
    mitsuba_filter.apply_filter(d, rfilter)
    for i, spot in spots.items():
        d[f'light{i}'] = spot_emitter(spot)
    for i, emitter in enumerate(emitters):
        d[f'emitter{i}'] = emitter
    if env is not None:
        d['envmap'] = mitsuba_envmap.envmap_emitter(env, os.path.dirname(os.path.abspath(a.scene)))
    loaded = mi.load_dict(d)
    mitsuba_envmap.render_and_report(a.scene, sc, loaded, a.out, a.spp, a.seed,
                                     time.perf_counter() - t0)
    return 0


if __name__ == '__main__':
    sys.exit(main())
