"""A ball of glass holding a medium that scatters and absorbs nothing, in a white furnace (a
constant environment of 1 and nothing else), rendered by candela and by Mitsuba 3's volpath.

Behind smooth glass all light comes out again, so every pixel's expectation is exactly 1: an
analytic reference for both renderers. Behind rough glass (GGX, without multiple scattering between
microfacets) some is lost at each crossing, the same in both if they agree. A medium that scatters
the colour channels differently tests how each renderer shares one distance among the channels; a
grey one, the boundaries alone.

Prints each renderer's mean over the ball's middle and its standard error from four seeds.

Usage: /tmp/mi/bin/python tools/mitsuba_media_furnace.py [--roughness 0.4] [--scattering 4 3 2]
           [--spp 256] [--candela build/candela]
"""
import argparse
import tempfile

import mitsuba as mi
import numpy as np

import candela_run

IOR = 1.45
G = 0.3
SIZE = 48
FOV = 25
MAX_DEPTH = 1000  # candela's; Mitsuba's counts the camera ray's vertex too


def candela(binary, work, roughness, scattering, spp, seed):
    scene = {'camera': {'width': SIZE, 'height': SIZE, 'fov': FOV, 'position': [0, 0, 5],
                        'spp': spp},
             'render': {'max_depth': MAX_DEPTH}, 'environment': {'color': 1},
             'spheres': [{'position': [0, 0, 0], 'radius': 1,
                          'material': {'type': 'glass', 'ior': IOR, 'roughness': roughness,
                                       'scattering': scattering, 'scattering_anisotropy': G}}]}
    return candela_run.render(binary, scene, work, 'furnace', seed)[0]


def mitsuba(roughness, scattering, spp, seed):
    bsdf = ({'type': 'roughdielectric', 'distribution': 'ggx', 'alpha': roughness ** 2,
             'int_ior': IOR, 'ext_ior': 1.0} if roughness > 0 else
            {'type': 'dielectric', 'int_ior': IOR, 'ext_ior': 1.0})
    scale = max(scattering)  # Mitsuba reads sigma_t as a colour in [0, 1], times its scale
    medium = {'type': 'homogeneous', 'scale': scale,
              'sigma_t': {'type': 'rgb', 'value': [s / scale for s in scattering]},
              'albedo': {'type': 'rgb', 'value': [1, 1, 1]}, 'phase': {'type': 'hg', 'g': G}}
    scene = {'type': 'scene', 'integrator': {'type': 'volpath', 'max_depth': MAX_DEPTH + 1},
             'sensor': {'type': 'perspective', 'fov': FOV, 'fov_axis': 'x',
                        'to_world': mi.ScalarTransform4f().look_at(origin=[0, 0, 5],
                                                                   target=[0, 0, 0], up=[0, 1, 0]),
                        'film': {'type': 'hdrfilm', 'width': SIZE, 'height': SIZE,
                                 'rfilter': {'type': 'box'}},
                        'sampler': {'type': 'independent', 'sample_count': spp, 'seed': seed}},
             'sky': {'type': 'constant', 'radiance': {'type': 'rgb', 'value': [1, 1, 1]}},
             'ball': {'type': 'sphere', 'radius': 1, 'bsdf': bsdf, 'interior': medium}}
    return np.array(mi.render(mi.load_dict(scene)))[:, :, :3]


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    candela_run.add_candela_option(ap)
    ap.add_argument('--roughness', type=float, default=0.0)
    ap.add_argument('--scattering', type=float, nargs=3, default=[4.0, 3.0, 2.0])
    ap.add_argument('--spp', type=int, default=256)
    args = ap.parse_args()
    mi.set_variant('scalar_rgb')
    seeds = range(1, 5)
    middle = slice(SIZE // 4, 3 * SIZE // 4)  # within the ball's outline
    with tempfile.TemporaryDirectory() as work:
        c = np.array([candela(args.candela, work, args.roughness, args.scattering, args.spp, s)
                      [middle, middle].mean(axis=(0, 1)) for s in seeds])
    m = np.array([mitsuba(args.roughness, args.scattering, args.spp, s)[middle, middle]
                  .mean(axis=(0, 1)) for s in seeds])
    for name, means in (('candela', c), ('Mitsuba', m)):
        error = means.std(axis=0, ddof=1) / np.sqrt(len(seeds))
        print(f'{name}: ' + ', '.join(f'{v:.5f} ± {e:.5f}' for v, e in zip(means.mean(axis=0),
                                                                            error)))


if __name__ == '__main__':
    main()
