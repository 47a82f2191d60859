"""candela's built-in shapes ("shape": "rectangle", "disk", "cube", "cylinder") against Mitsuba 3's
own shapes of those names, placed where candela's lie: a diffuse rectangle floor, a cube and a
cylinder on it, an emissive disk overhead facing down, under a dim constant sky, seen by a
perspective camera with a box pixel filter.

Mitsuba's flat shapes and cube span [-1, 1] and face +z, so each is turned by -90 degrees about
x and halved (candela's fill the unit box and face +y); its cylinder is exact and open, so
candela's closed cylinder is Mitsuba's from (0, -0.5, 0) to (0, 0.5, 0) of radius 0.5 with two
disks for caps (and takes a uniform scale, as Mitsuba's cylinder requires). candela's disk and
cylinder are polygons of 256 sides.

Prints each renderer's mean, their difference over the image, and the differences of the means of
8 x 8 pixel blocks, in standard errors from four seeds' spread in each renderer.

Usage: /tmp/mi/bin/python tools/mitsuba_shapes.py [--candela build/candela] [--spp 256]
"""
import argparse
import tempfile

import mitsuba as mi
import numpy as np

import candela_run

SIZE = (160, 120)
FOV = 45
CAMERA = ([0, 2.5, 7], [0, 0.6, 0], [0, 1, 0])
# (shape, position, rotation in degrees, scale, candela material, Mitsuba bsdf or emitter)
OBJECTS = [
    ('rectangle', [0, 0, 0], [0, 0, 0], [8, 1, 8], 'floor'),
    ('cube', [-1.2, 0.6, 0], [0, 35, 0], [1.2, 1.2, 1.2], 'red'),
    ('cylinder', [1.1, 0.8, 0.3], [10, 0, -15], [1.6, 1.6, 1.6], 'white'),
    ('disk', [0, 4, 1], [180, 0, 0], [2.5, 2.5, 2.5], 'lamp'),
]
MATERIALS = {'floor': 0.5, 'red': [0.7, 0.15, 0.1], 'white': 0.8}
LAMP = 8.0
SKY = 0.15
MAX_DEPTH = 5  # candela's; Mitsuba's counts the camera ray's vertex too


def rgb(value):
    return value if isinstance(value, list) else [value] * 3


def candela(binary, work, spp, seed):
    objects = []
    for shape, position, rotation, scale, material in OBJECTS:
        m = ({'type': 'emissive', 'radiance': LAMP} if material == 'lamp'
             else {'type': 'diffuse', 'color': MATERIALS[material]})
        objects.append({'shape': shape, 'position': position, 'rotation': rotation,
                        'scale': scale, 'material': m})
    origin, target, up = CAMERA
    scene = {'camera': {'width': SIZE[0], 'height': SIZE[1], 'fov': FOV, 'position': origin,
                        'look_at': target, 'up': up, 'spp': spp},
             'render': {'max_depth': MAX_DEPTH}, 'environment': {'color': SKY},
             'objects': objects}
    return candela_run.render(binary, scene, work, 'shapes', seed)[0]


def placement(position, rotation, scale):
    """candela's p_world = position + Rz Ry Rx (scale * p) as a Mitsuba transform."""
    t = mi.ScalarTransform4f().translate(position)
    for axis, angle in (([0, 0, 1], rotation[2]), ([0, 1, 0], rotation[1]),
                        ([1, 0, 0], rotation[0])):
        t = t @ mi.ScalarTransform4f().rotate(axis, angle)
    return t @ mi.ScalarTransform4f().scale(scale)


def mitsuba(spp, seed):
    # candela's rectangle, disk and cube from Mitsuba's: halved, then +z turned to +y.
    to_candela = (mi.ScalarTransform4f().rotate([1, 0, 0], -90) @
                  mi.ScalarTransform4f().scale(0.5))
    origin, target, up = CAMERA
    scene = {'type': 'scene', 'integrator': {'type': 'path', 'max_depth': MAX_DEPTH + 1},
             'sensor': {'type': 'perspective', 'fov': FOV, 'fov_axis': 'x',
                        'to_world': mi.ScalarTransform4f().look_at(origin=origin, target=target,
                                                                   up=up),
                        'film': {'type': 'hdrfilm', 'width': SIZE[0], 'height': SIZE[1],
                                 'rfilter': {'type': 'box'}},
                        'sampler': {'type': 'independent', 'sample_count': spp, 'seed': seed}},
             'sky': {'type': 'constant', 'radiance': {'type': 'rgb', 'value': rgb(SKY)}}}
    for i, (shape, position, rotation, scale, material) in enumerate(OBJECTS):
        place = placement(position, rotation, scale)
        looks = ({'emitter': {'type': 'area', 'radiance': {'type': 'rgb', 'value': rgb(LAMP)}},
                  'bsdf': {'type': 'diffuse', 'reflectance': {'type': 'rgb', 'value': [0] * 3}}}
                 if material == 'lamp' else
                 {'bsdf': {'type': 'diffuse',
                           'reflectance': {'type': 'rgb', 'value': rgb(MATERIALS[material])}}})
        if shape != 'cylinder':
            scene[f'shape{i}'] = {'type': shape, 'to_world': place @ to_candela, **looks}
            continue
        assert scale[0] == scale[1] == scale[2], "Mitsuba's cylinder takes a uniform scale"
        scene[f'shape{i}'] = {'type': 'cylinder', 'p0': [0, -0.5, 0], 'p1': [0, 0.5, 0],
                              'radius': 0.5, 'to_world': place, **looks}
        for end, turn, name in ((0.5, -90, 'top'), (-0.5, 90, 'bottom')):
            cap = (place @ mi.ScalarTransform4f().translate([0, end, 0]) @
                   mi.ScalarTransform4f().rotate([1, 0, 0], turn) @
                   mi.ScalarTransform4f().scale(0.5))
            scene[f'shape{i}_{name}'] = {'type': 'disk', 'to_world': cap, **looks}
    return np.array(mi.render(mi.load_dict(scene)))[:, :, :3]


def block_means(image, block=8):
    h, w = image.shape[0] // block, image.shape[1] // block
    return image[:h * block, :w * block].reshape(h, block, w, block, 3).mean(axis=(1, 3))


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    candela_run.add_candela_option(ap)
    ap.add_argument('--spp', type=int, default=256)
    args = ap.parse_args()
    mi.set_variant('scalar_rgb')
    seeds = range(1, 5)
    with tempfile.TemporaryDirectory() as work:
        c = np.array([candela(args.candela, work, args.spp, s) for s in seeds])
    m = np.array([mitsuba(args.spp, s) for s in seeds])
    report(c, m, args.spp)


def report(c, m, spp):
    """Prints how candela's renders c and Mitsuba's m (seeds x height x width x 3) differ."""
    seeds = len(c)
    print(f'{spp} spp a seed, {seeds} seeds each: candela mean {c.mean():.5f}, '
          f'Mitsuba mean {m.mean():.5f}, difference {(c.mean() - m.mean()) / m.mean():+.3%}')
    # Each 8 x 8 block's difference of means over its standard error: the variance of a block's
    # mean is its pixels' mean variance (each pixel's from the seeds' spread) over its 64 pixels.
    cm, mm = block_means(c.mean(axis=0)), block_means(m.mean(axis=0))
    error = np.sqrt((block_means(c.var(axis=0, ddof=1)) + block_means(m.var(axis=0, ddof=1))) /
                    (64 * seeds))
    z = (cm - mm) / np.maximum(error, 1e-9)
    worst = np.unravel_index(np.abs(z).argmax(), z.shape)
    relative = np.abs(cm - mm) / np.maximum(mm, 1e-3)
    print(f'8 x 8 blocks: median |difference| {np.median(relative):.2%} of Mitsuba\'s; largest '
          f'{np.abs(z).max():.2f} standard errors (block {worst[1]}, {worst[0]}, channel '
          f'{worst[2]}: candela {cm[worst]:.5f}, Mitsuba {mm[worst]:.5f}); beyond 4: '
          f'{int((np.abs(z) > 4).sum())} of {z.size}')

if __name__ == '__main__':
    main()
