"""Glass with a scattering medium inside ("scattering", "scattering_anisotropy") against Mitsuba 3's
volumetric path tracer (volpath) with a homogeneous interior medium of the same coefficients.

On a diffuse floor under an emissive rectangle and a dim constant sky: a ball of milky glass (ior
1.4, chromatic scattering, some absorption, forward-scattering g 0.6) and a cube of smoke held in
glass of ior 1 (back-scattering g -0.3), which Mitsuba models as a null interface around the
medium. Mitsuba's medium takes sigma_t = sigma_a + sigma_s and albedo = sigma_s / sigma_t, and
candela's absorption is -ln(color) / transmission_depth. Both renderers go to a depth at which
truncation is negligible (Mitsuba's max_depth counts the camera ray's vertex too).

Prints each renderer's mean, their difference over the image, and the differences of the means of
8 x 8 pixel blocks, in standard errors from four seeds' spread in each renderer.

Usage: /tmp/mi/bin/python tools/mitsuba_media.py [--candela build/candela] [--spp 256]
"""
import argparse
import json
import math
import os
import subprocess
import tempfile

import mitsuba as mi
import numpy as np

SIZE = (160, 120)
FOV = 40
CAMERA = ([0, 1.8, 5.5], [0, 0.6, 0], [0, 1, 0])
# (both stand a little above the floor: faces that touch it would make a coplanar tie)
# name: (ior, color kept over transmission_depth 1, scattering, g)
MEDIA = {
    'milk': (1.4, [0.8, 0.9, 0.95], [3, 5, 8], 0.6),
    'smoke': (1.0, [0.7, 0.7, 0.7], [1.5, 1.5, 1.5], -0.3),
}
MILK_BALL = ([0.8, 0.72, 0], 0.7)  # position, radius
SMOKE_CUBE = ([-0.9, 0.62, 0.2], [0, 30, 0], 1.2)  # position, rotation (degrees), scale
FLOOR = 0.5
LAMP = ([0, 4, 1], 2.0, 10.0)  # position of the rectangle facing down, side, radiance
SKY = 0.15
MAX_DEPTH = 1000  # candela's


def absorption(color):
    return [-math.log(c) for c in color]


def candela(binary, work, spp, seed):
    materials = {name: {'type': 'glass', 'ior': ior, 'color': color, 'transmission_depth': 1,
                        'scattering': sigma_s, 'scattering_anisotropy': g}
                 for name, (ior, color, sigma_s, g) in MEDIA.items()}
    position, rotation, scale = SMOKE_CUBE
    lamp, side, radiance = LAMP
    origin, target, up = CAMERA
    scene = {'camera': {'width': SIZE[0], 'height': SIZE[1], 'fov': FOV, 'position': origin,
                        'look_at': target, 'up': up, 'spp': spp},
             'render': {'max_depth': MAX_DEPTH}, 'environment': {'color': SKY},
             'materials': materials,
             'spheres': [{'position': MILK_BALL[0], 'radius': MILK_BALL[1], 'material': 'milk'}],
             'objects': [
                 {'shape': 'rectangle', 'scale': [8, 1, 8],
                  'material': {'type': 'diffuse', 'color': FLOOR}},
                 {'shape': 'cube', 'position': position, 'rotation': rotation, 'scale': scale,
                  'material': 'smoke'},
                 {'shape': 'rectangle', 'position': lamp, 'rotation': [180, 0, 0],
                  'scale': [side, 1, side],
                  'material': {'type': 'emissive', 'radiance': radiance}}]}
    path = os.path.join(work, 'media.json')
    with open(path, 'w') as f:
        json.dump(scene, f)
    out = os.path.join(work, f'candela-{seed}.exr')
    subprocess.run([binary, 'render', path, '-o', out, '-q', '--backend', 'cpu', '--seed',
                    str(seed)], check=True)
    return np.array(mi.Bitmap(out))[:, :, :3]


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


def block_means(image, block=8):
    h, w = image.shape[0] // block, image.shape[1] // block
    return image[:h * block, :w * block].reshape(h, block, w, block, 3).mean(axis=(1, 3))


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--candela', default=os.path.join(os.path.dirname(__file__), '..', 'build',
                                                      'candela'))
    ap.add_argument('--spp', type=int, default=256)
    ap.add_argument('--save', help='folder for both renderers\' mean images (EXR)')
    args = ap.parse_args()
    mi.set_variant('scalar_rgb')
    seeds = range(1, 5)
    with tempfile.TemporaryDirectory() as work:
        c = np.array([candela(args.candela, work, args.spp, s) for s in seeds])
    m = np.array([mitsuba(args.spp, s) for s in seeds])
    if args.save:
        os.makedirs(args.save, exist_ok=True)
        for name, images in (('candela', c), ('mitsuba', m)):
            mi.Bitmap(images.mean(axis=0).astype(np.float32)).write(
                os.path.join(args.save, f'{name}.exr'))
    print(f'{args.spp} spp a seed, {len(seeds)} seeds each: candela mean {c.mean():.5f}, '
          f'Mitsuba mean {m.mean():.5f}, difference {(c.mean() - m.mean()) / m.mean():+.3%}')
    # Each 8 x 8 block's difference of means over its standard error: the variance of a block's
    # mean is its pixels' mean variance (each pixel's from the seeds' spread) over its 64 pixels.
    cm, mm = block_means(c.mean(axis=0)), block_means(m.mean(axis=0))
    error = np.sqrt((block_means(c.var(axis=0, ddof=1)) + block_means(m.var(axis=0, ddof=1))) /
                    (64 * len(seeds)))
    z = (cm - mm) / np.maximum(error, 1e-9)
    worst = np.unravel_index(np.abs(z).argmax(), z.shape)
    relative = np.abs(cm - mm) / np.maximum(mm, 1e-3)
    print(f'8 x 8 blocks: median |difference| {np.median(relative):.2%} of Mitsuba\'s; largest '
          f'{np.abs(z).max():.2f} standard errors (block {worst[1]}, {worst[0]}, channel '
          f'{worst[2]}: candela {cm[worst]:.5f}, Mitsuba {mm[worst]:.5f}); beyond 4: '
          f'{int((np.abs(z) > 4).sum())} of {z.size}')


if __name__ == '__main__':
    main()
