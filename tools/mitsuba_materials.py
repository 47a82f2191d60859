#!/usr/bin/env python3
"""Renders a candela scene that uses conductor, rough glass or plastic materials with Mitsuba 3.

The shared harness (../shared/reference) maps the original contract's materials (diffuse, mirror,
glass, emissive); this adds the fields of issue 20 and then hands over to tools/mitsuba_envmap.py
(which adds environment maps), so the command line is the same:

    /tmp/mi/bin/python tools/mitsuba_materials.py SCENE.json OUT.exr [--spp N] [--seed S] ...

Mapping (docs/scene-format.md, Materials), every opaque material wrapped in `twosided` as the
harness does for diffuse, since candela's reflect on both sides:
  conductor, roughness 0     -> conductor, material "none" + specular_reflectance = color,
                                or material = metal
  conductor, roughness r     -> roughconductor, distribution ggx, alpha = r^2, the same
  glass, roughness r         -> roughdielectric, ggx, alpha = r^2, int_ior = ior, ext_ior 1,
                                specular_transmittance = color
  plastic, roughness 0       -> plastic, int_ior = ior, ext_ior 1, diffuse_reflectance = color,
                                nonlinear false
  plastic, roughness r       -> roughplastic, ggx, alpha = r^2, the same
  glass with transmission_depth d and color c
                             -> the same dielectric, white, with an `interior` homogeneous
                                medium of sigma_t = -ln(c) / d (its largest as `scale`) and
                                albedo 0 (spheres), rendered by
                                `volpath` instead of `path`
  thin_glass                 -> thindielectric, int_ior = ior, ext_ior 1 (Mitsuba's shadow rays stop
                                at it where candela's pass: the same image, Mitsuba's noisier)
  conductor or glass with anisotropy a
                             -> the same, with alpha_u = r^2 sqrt(2 / (1 + (1 - a)^2)) and
                                alpha_v = (1 - a) alpha_u (at least 0.001), on a sphere turned as
                                a textured one below, so that Mitsuba's tangent dp/du runs along
                                candela's azimuth about +y (anisotropy_rotation is not mapped)
  mix (parts inline, shorthand or named)
                             -> blendbsdf of the parts' mappings, weight a number or, for a
                                texture, a `raw` bitmap mapped as a colour texture below (the
                                average of what candela's choice of a part gives)
  emission e (a colour) with emission_strength k, on any of these, on spheres
                             -> the same BSDF with an `area` emitter of radiance k e (one-sided,
                                outwards, as candela's)
  (a roughness r > 0 whose alpha = r^2 is below 0.001 is smooth in candela, docs/scene-format.md's
  Roughness, so it maps as roughness 0)
  {"texture": T, "scale": [su, sv]} as a colour on a sphere (tools/mitsuba_mtl.py maps it on
  meshes, whose uvs the harness does not read) -> a bilinear, repeating `bitmap` of T mirrored left to right, with to_uv
  scaling by (su, sv), on a sphere turned so that Mitsuba's parametrisation (u = atan2(y, x) /
  2 pi, v = acos(z) / pi about local +z, v = 0 on the image's top row) becomes candela's (u =
  0.5 + atan2(d.x, -d.z) / 2 pi, v = 1 - acos(d.y) / pi, v = 0 on the bottom row). Integer scales
  only: the mirroring and the turn agree with candela's lookup up to whole repeats.
"""
import atexit
import math
import os
import shutil
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import mitsuba_envmap  # noqa: E402  (sets up the shared harness's path)
import candela_scene as cs  # noqa: E402
import mitsuba_ref as mr  # noqa: E402

cs.KNOWN['material'] |= {'roughness', 'metal', 'transmission_depth', 'anisotropy', 'materials',
                         'weight', 'emission', 'emission_strength'}
harness_make_mat = cs._make_mat
harness_bsdf_dict = mr.bsdf_dict


WORK = tempfile.mkdtemp(prefix='candela_mitsuba_textures_')
atexit.register(shutil.rmtree, WORK, True)
mirrored = {}
SMOOTH_ALPHA = 0.001  # candela: alpha below this (roughness < 0.032) is smooth (render/microfacet.h)


def colour(ctx, fields, default, path, key='color'):
    """The harness's colour, or a texture reference {'texture': absolute path, 'scale': [su, sv]}."""
    value = fields.get(key, default)
    if isinstance(value, dict):
        for unmapped in ('offset', 'rotation'):
            if unmapped in value:
                ctx.err(f'{path}.{key}.{unmapped}', 'not mapped to Mitsuba by this tool')
        name = value['texture']
        if not os.path.isabs(name):
            name = os.path.join(os.path.dirname(os.path.abspath(ctx.fname)), name)
        return {'texture': name, 'scale': [float(x) for x in value.get('scale', [1, 1])]}
    return ctx.color(value, path + '.color')


def spectrum(c, raw=False):
    """A Mitsuba texture for a colour or a texture reference (`raw`: its 8-bit values read
    linearly, as candela reads a weight)."""
    if not isinstance(c, dict):
        return mr.rgb(c)
    name = c['texture']
    if name not in mirrored:
        image = mr.np.array(mr.mi.Bitmap(name))
        mirrored[name] = os.path.join(WORK, f'{len(mirrored)}_' + os.path.basename(name))
        mr.mi.Bitmap(mr.np.ascontiguousarray(image[:, ::-1])).write(mirrored[name])
    su, sv = c['scale']
    return {'type': 'bitmap', 'filename': mirrored[name], 'filter_type': 'bilinear',
            'wrap_mode': 'repeat', 'raw': raw,
            'to_uv': mr.mi.ScalarTransform4f().scale([su, sv, 1])}


def textured(mat):
    if mat['type'] == 'mix':
        return isinstance(mat['weight'], dict) or any(textured(p) for p in mat['parts'])
    return isinstance(mat.get('color'), dict)


def mix_part(ctx, part, path):
    """A part of a mix: a material object, a shorthand type, or a name under "materials"."""
    if isinstance(part, dict):
        return make_mat(ctx, part['type'], part, path)
    if part in ('diffuse', 'mirror', 'glass'):
        return make_mat(ctx, part, {}, path)
    with open(ctx.fname) as f:
        named = cs.json.load(f)['materials'][part]
    return make_mat(ctx, named['type'], named, f'materials.{part}')


def make_mat(ctx, t, fields, path):
    mat = make_reflecting_mat(ctx, t, fields, path)
    if 'emission' in fields:
        if isinstance(fields['emission'], dict):
            ctx.err(path + '.emission', 'a texture: not mapped to Mitsuba by this tool')
        strength = ctx.number(fields.get('emission_strength', 1.0), path + '.emission_strength',
                              nonneg=True)
        mat['emission'] = [c * strength for c in ctx.color(fields['emission'], path + '.emission')]
    return mat


def make_reflecting_mat(ctx, t, fields, path):
    if t == 'mix':
        parts = [mix_part(ctx, p, f'{path}.materials[{k}]')
                 for k, p in enumerate(fields['materials'])]
        weight = fields.get('weight', 0.5)
        if isinstance(weight, dict):
            weight = colour(ctx, fields, 0.5, path, key='weight')
        return dict(type='mix', parts=parts, weight=weight)
    mat = make_isotropic_mat(ctx, t, fields, path)
    if 'anisotropy' in fields:
        mat['anisotropy'] = ctx.number(fields['anisotropy'], path + '.anisotropy')
    return mat


def make_isotropic_mat(ctx, t, fields, path):
    roughness = float(fields.get('roughness', 0.0))
    if t == 'diffuse' and isinstance(fields.get('color'), dict):
        return dict(type='diffuse', color=colour(ctx, fields, 0.8, path))
    if t == 'conductor':
        return dict(type='conductor', roughness=roughness, metal=fields.get('metal'),
                    color=colour(ctx, fields, 1.0, path))
    if t == 'plastic':
        return dict(type='plastic', roughness=roughness,
                    color=colour(ctx, fields, 0.5, path),
                    ior=ctx.number(fields.get('ior', 1.5), path + '.ior', positive=True))
    if t == 'thin_glass':
        return dict(type='thin_glass',
                    ior=ctx.number(fields.get('ior', 1.5), path + '.ior', positive=True))
    mat = harness_make_mat(ctx, t, fields, path)
    if t == 'glass':
        mat['roughness'] = roughness
        if 'transmission_depth' in fields:
            depth = ctx.number(fields['transmission_depth'], path + '.transmission_depth',
                               positive=True)
            mat['sigma'] = [-math.log(c) / depth for c in mat['color']]
            mat['color'] = ctx.color(1.0, path + '.color')
    return mat


def alphas(mat):
    """Mitsuba's alpha, or alpha_u and alpha_v (render/microfacet.h, pointAlpha)."""
    r, a = mat.get('roughness', 0.0), mat.get('anisotropy', 0.0)
    along = r * r * math.sqrt(2 / (1 + (1 - a) ** 2))
    if a == 0:
        return {'alpha': along}
    return {'alpha_u': max(along, SMOOTH_ALPHA), 'alpha_v': max((1 - a) * along, SMOOTH_ALPHA)}


def anisotropic(mat):
    if mat['type'] == 'mix':
        return any(anisotropic(p) for p in mat['parts'])
    return mat.get('anisotropy', 0.0) > 0


def bsdf_dict(mat):
    t = mat['type']
    if t == 'mix':
        w = mat['weight']
        return {'type': 'blendbsdf',
                'weight': spectrum(w, raw=True) if isinstance(w, dict) else float(w),
                'bsdf_0': bsdf_dict(mat['parts'][0]), 'bsdf_1': bsdf_dict(mat['parts'][1])}
    rough = max(alphas(mat).values()) >= SMOOTH_ALPHA
    if t == 'conductor':
        if mat['metal']:
            d = {'material': mat['metal']}
        else:
            d = {'material': 'none', 'specular_reflectance': spectrum(mat['color'])}
        d['type'] = 'conductor'
        if rough:
            d.update(type='roughconductor', distribution='ggx', **alphas(mat))
        return {'type': 'twosided', 'bsdf': d}
    if t == 'plastic':
        d = {'type': 'plastic', 'int_ior': float(mat['ior']), 'ext_ior': 1.0,
             'diffuse_reflectance': spectrum(mat['color']), 'nonlinear': False}
        if rough:
            d.update(type='roughplastic', distribution='ggx', **alphas(mat))
        return {'type': 'twosided', 'bsdf': d}
    if t == 'thin_glass':
        return {'type': 'thindielectric', 'int_ior': float(mat['ior']), 'ext_ior': 1.0}
    if t == 'glass' and rough:
        return {'type': 'roughdielectric', 'distribution': 'ggx', **alphas(mat),
                'int_ior': float(mat['ior']), 'ext_ior': 1.0,
                'specular_transmittance': mr.rgb(mat['color'])}
    if t == 'diffuse' and textured(mat):
        return {'type': 'twosided',
                'bsdf': {'type': 'diffuse', 'reflectance': spectrum(mat['color'])}}
    return harness_bsdf_dict(mat)


# Local sphere axes from candela's world directions d: l = (d.z, d.x, d.y); to_world is the inverse.
SPHERE_TO_WORLD = [[0, 1, 0], [0, 0, 1], [1, 0, 0]]


def scene_dict(sc, *args, **kwargs):
    d = harness_scene_dict(sc, *args, **kwargs)
    for i, s in enumerate(sc['spheres']):
        if 'sigma' in s['mat']:
            top = max(s['mat']['sigma'])  # Mitsuba's RGB values must lie in [0, 1]: scale them
            d[f'sphere{i}']['interior'] = {
                'type': 'homogeneous', 'sigma_t': mr.rgb([c / top for c in s['mat']['sigma']]),
                'scale': top, 'albedo': 0.0}
            d['integrator']['type'] = 'volpath'
    for i, s in enumerate(sc['spheres']):
        if 'emission' in s['mat']:
            d[f'sphere{i}']['emitter'] = {'type': 'area', 'radiance': mr.rgb(s['mat']['emission'])}
    # Meshes with an emission need the build_mesh of tools/mitsuba_mtl.py, which maps it.
    if mr.build_mesh is harness_build_mesh and any('emission' in m['mat'] for m in sc['meshes']):
        raise mr.ConvertError('an "emission" on a mesh: mapped by tools/mitsuba_mtl.py only')
    for i, s in enumerate(sc['spheres']):
        if textured(s['mat']) or anisotropic(s['mat']):
            sphere = d[f'sphere{i}']
            c, r = sphere.pop('center'), sphere.pop('radius')
            M = mr.np.eye(4)
            M[:3, :3] = mr.np.array(SPHERE_TO_WORLD, dtype=float) * r
            M[:3, 3] = c
            sphere['to_world'] = mr.mi.ScalarTransform4f(M.tolist())
    return d


harness_scene_dict = mr.scene_dict
harness_build_mesh = mr.build_mesh
cs._make_mat = make_mat
mr.bsdf_dict = bsdf_dict
mr.scene_dict = scene_dict

if __name__ == '__main__':
    sys.exit(mitsuba_envmap.main())
