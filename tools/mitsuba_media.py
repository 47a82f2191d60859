"""Glass with a scattering medium inside ("scattering", "scattering_anisotropy") against Mitsuba 3's
volumetric path tracer (volpath) with a homogeneous interior medium of the same coefficients.

On a diffuse floor under an emissive rectangle and a dim constant sky: a ball of milky glass (ior
1.4, chromatic scattering, some absorption, forward-scattering g 0.6), a small ball of wax in rough
glass (roughness 0.4: Mitsuba's roughdielectric of GGX alpha 0.16) and a cube of smoke held in
glass of ior 1 (back-scattering g -0.3), which Mitsuba models as a null interface around the
medium. Mitsuba's medium takes sigma_t = sigma_a + sigma_s and albedo = sigma_s / sigma_t, and
candela's absorption is -ln(color) / transmission_depth. Both renderers go to a depth at which
truncation is negligible (Mitsuba's max_depth counts the camera ray's vertex too).

Prints each renderer's mean, their difference over the image, the differences of the means of
8 x 8 pixel blocks, and each object's by channel, in standard errors from the seeds' spread in each
renderer.

Usage: /tmp/mi/bin/python tools/mitsuba_media.py [--candela build/candela] [--spp 256] [--seeds 4]
"""
import argparse
import math
import os
import tempfile

import mitsuba as mi
import numpy as np

import candela_run

from mitsuba_shapes import report

SIZE = (160, 120)
FOV = 40
CAMERA = ([0, 1.8, 5.5], [0, 0.6, 0], [0, 1, 0])
# (both stand a little above the floor: faces that touch it would make a coplanar tie)
# name: (ior, color kept over transmission_depth 1, scattering, g)
MEDIA = {
    'milk': (1.4, [0.8, 0.9, 0.95], [3, 5, 8], 0.6),
    'smoke': (1.0, [0.7, 0.7, 0.7], [1.5, 1.5, 1.5], -0.3),
    'wax': (1.45, [0.9, 0.7, 0.5], [4, 3, 2], 0.3),
}
WAX_ROUGHNESS = 0.4  # GGX alpha = roughness^2 in both renderers
WAX_BALL = ([0.1, 0.37, 1.5], 0.35)
MILK_BALL = ([0.8, 0.72, 0], 0.7)  # position, radius
SMOKE_CUBE = ([-0.9, 0.62, 0.2], [0, 30, 0], 1.2)  # position, rotation (degrees), scale
FLOOR = 0.5
LAMP = ([0, 4, 1], 2.0, 10.0)  # position of the rectangle facing down, side, radiance
SKY = 0.15
MAX_DEPTH = 1000  # candela's
# Where each object lies in the image: rows, then columns.
REGIONS = {'milky ball': (24, 72, 96, 144), 'wax ball': (80, 108, 70, 100),
           'smoke cube': (32, 96, 16, 64)}


def absorption(color):
    return [-math.log(c) for c in color]


def candela(binary, work, spp, seed):
    materials = {name: {'type': 'glass', 'ior': ior, 'color': color, 'transmission_depth': 1,
                        'scattering': sigma_s, 'scattering_anisotropy': g}
                 for name, (ior, color, sigma_s, g) in MEDIA.items()}
    materials['wax']['roughness'] = WAX_ROUGHNESS
    position, rotation, scale = SMOKE_CUBE
    lamp, side, radiance = LAMP
    origin, target, up = CAMERA
    scene = {'camera': {'width': SIZE[0], 'height': SIZE[1], 'fov': FOV, 'position': origin,
                        'look_at': target, 'up': up, 'spp': spp},
             'render': {'max_depth': MAX_DEPTH}, 'environment': {'color': SKY},
             'materials': materials,
             'spheres': [{'position': MILK_BALL[0], 'radius': MILK_BALL[1], 'material': 'milk'},
                         {'position': WAX_BALL[0], 'radius': WAX_BALL[1], 'material': 'wax'}],
             'objects': [
                 {'shape': 'rectangle', 'scale': [8, 1, 8],
                  'material': {'type': 'diffuse', 'color': FLOOR}},
                 {'shape': 'cube', 'position': position, 'rotation': rotation, 'scale': scale,
                  'material': 'smoke'},
                 {'shape': 'rectangle', 'position': lamp, 'rotation': [180, 0, 0],
                  'scale': [side, 1, side],
                  'material': {'type': 'emissive', 'radiance': radiance}}]}
    return candela_run.render(binary, scene, work, 'media', seed)[0]


def rgb(value):
    return {'type': 'rgb', 'value': value if isinstance(value, list) else [value] * 3}


def medium(name):
    _, color, sigma_s, g = MEDIA[name]
    sigma_t = [a + s for a, s in zip(absorption(color), sigma_s)]
    scale = max(sigma_t)  # Mitsuba reads sigma_t as a colour in [0, 1], times its scale
    return {'type': 'homogeneous', 'sigma_t': rgb([t / scale for t in sigma_t]), 'scale': scale,
            'albedo': rgb([s / t for s, t in zip(sigma_s, sigma_t)]),
            'phase': {'type': 'hg', 'g': g}}


def mitsuba(spp, seed):
    # candela's rectangle and cube from Mitsuba's: halved, then +z turned to +y.
    to_candela = (mi.ScalarTransform4f().rotate([1, 0, 0], -90) @
                  mi.ScalarTransform4f().scale(0.5))
    position, rotation, scale = SMOKE_CUBE
    lamp, side, radiance = LAMP
    origin, target, up = CAMERA
    milk_ior = MEDIA['milk'][0]
    scene = {
        'type': 'scene', 'integrator': {'type': 'volpath', 'max_depth': MAX_DEPTH + 1},
        'sensor': {'type': 'perspective', 'fov': FOV, 'fov_axis': 'x',
                   'to_world': mi.ScalarTransform4f().look_at(origin=origin, target=target, up=up),
                   'film': {'type': 'hdrfilm', 'width': SIZE[0], 'height': SIZE[1],
                            'rfilter': {'type': 'box'}},
                   'sampler': {'type': 'independent', 'sample_count': spp, 'seed': seed}},
        'sky': {'type': 'constant', 'radiance': rgb(SKY)},
        'floor': {'type': 'rectangle',
                  'to_world': mi.ScalarTransform4f().scale([8, 1, 8]) @ to_candela,
                  'bsdf': {'type': 'diffuse', 'reflectance': rgb(FLOOR)}},
        'milk': {'type': 'sphere', 'center': MILK_BALL[0], 'radius': MILK_BALL[1],
                 'bsdf': {'type': 'dielectric', 'int_ior': milk_ior, 'ext_ior': 1.0},
                 'interior': medium('milk')},
        'wax': {'type': 'sphere', 'center': WAX_BALL[0], 'radius': WAX_BALL[1],
                'bsdf': {'type': 'roughdielectric', 'distribution': 'ggx',
                         'alpha': WAX_ROUGHNESS ** 2, 'int_ior': MEDIA['wax'][0], 'ext_ior': 1.0},
                'interior': medium('wax')},
        'smoke': {'type': 'cube',
                  'to_world': (mi.ScalarTransform4f().translate(position) @
                               mi.ScalarTransform4f().rotate([0, 1, 0], rotation[1]) @
                               mi.ScalarTransform4f().scale(scale) @ to_candela),
                  'bsdf': {'type': 'null'}, 'interior': medium('smoke')},
        'lamp': {'type': 'rectangle',
                 'to_world': (mi.ScalarTransform4f().translate(lamp) @
                              mi.ScalarTransform4f().rotate([1, 0, 0], 180) @
                              mi.ScalarTransform4f().scale([side, 1, side]) @ to_candela),
                 'emitter': {'type': 'area', 'radiance': rgb(radiance)},
                 'bsdf': {'type': 'diffuse', 'reflectance': rgb(0)}},
    }
    assert rotation[0] == rotation[2] == 0
    return np.array(mi.render(mi.load_dict(scene)))[:, :, :3]


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    candela_run.add_candela_option(ap)
    ap.add_argument('--spp', type=int, default=256)
    ap.add_argument('--seeds', type=int, default=4)
    ap.add_argument('--save', help='folder for both renderers\' mean images (EXR)')
    args = ap.parse_args()
    mi.set_variant('scalar_rgb')
    seeds = range(1, args.seeds + 1)
    with tempfile.TemporaryDirectory() as work:
        c = np.array([candela(args.candela, work, args.spp, s) for s in seeds])
    m = np.array([mitsuba(args.spp, s) for s in seeds])
    if args.save:
        os.makedirs(args.save, exist_ok=True)
        for name, images in (('candela', c), ('mitsuba', m)):
            mi.Bitmap(images.mean(axis=0).astype(np.float32)).write(
                os.path.join(args.save, f'{name}.exr'))
    report(c, m, args.spp)
    # Each object's pixels (rows, columns) by channel: the difference of the means, in standard
    # errors of the seeds' spread.
    for name, (r0, r1, c0, c1) in REGIONS.items():
        cs, ms = c[:, r0:r1, c0:c1].mean(axis=(1, 2)), m[:, r0:r1, c0:c1].mean(axis=(1, 2))
        line = []
        for ch, channel in enumerate('RGB'):
            d = cs[:, ch].mean() - ms[:, ch].mean()
            error = np.sqrt((cs[:, ch].var(ddof=1) + ms[:, ch].var(ddof=1)) / len(seeds))
            line.append(f'{channel} {cs[:, ch].mean():.5f} against {ms[:, ch].mean():.5f} '
                        f'({d / ms[:, ch].mean():+.2%}, {d / error:+.1f} SE)')
        print(f"{name}: " + "; ".join(line))


if __name__ == '__main__':
    main()
