#!/usr/bin/env python3
"""Renders a candela scene that uses conductor, rough glass or plastic materials with Mitsuba 3.

The shared harness (../shared/reference) maps the original contract's materials (diffuse, mirror,
glass, emissive); this adds the fields of issue 20 and then hands over to tools/mitsuba_envmap.py
(which adds environment maps), so the command line is the same:

    /tmp/mi/bin/python tools/mitsuba_materials.py SCENE.json OUT.exr [--spp N] [--seed S] ...

Mapping (docs/scene-format.md, Materials), every opaque material wrapped in `twosided` as the
harness does for diffuse, since candela's reflect on both sides:
  conductor, roughness 0      -> conductor, material "none" + specular_reflectance = color,
                                 or material = metal
  conductor, roughness r > 0  -> roughconductor, distribution ggx, alpha = r^2, the same
  glass, roughness r > 0      -> roughdielectric, ggx, alpha = r^2, int_ior = ior, ext_ior 1,
                                 specular_transmittance = color
  plastic, roughness 0        -> plastic, int_ior = ior, ext_ior 1, diffuse_reflectance = color,
                                 nonlinear false
  plastic, roughness r > 0    -> roughplastic, ggx, alpha = r^2, the same
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import mitsuba_envmap  # noqa: E402  (sets up the shared harness's path)
import candela_scene as cs  # noqa: E402
import mitsuba_ref as mr  # noqa: E402

cs.KNOWN['material'] |= {'roughness', 'metal'}
harness_make_mat = cs._make_mat
harness_bsdf_dict = mr.bsdf_dict


def make_mat(ctx, t, fields, path):
    roughness = float(fields.get('roughness', 0.0))
    if t == 'conductor':
        mat = dict(type='conductor', roughness=roughness, metal=fields.get('metal'),
                   color=ctx.color(fields.get('color', 1.0), path + '.color'))
        return mat
    if t == 'plastic':
        return dict(type='plastic', roughness=roughness,
                    color=ctx.color(fields.get('color', 0.5), path + '.color'),
                    ior=ctx.number(fields.get('ior', 1.5), path + '.ior', positive=True))
    mat = harness_make_mat(ctx, t, fields, path)
    if t == 'glass':
        mat['roughness'] = roughness
    return mat


def bsdf_dict(mat):
    t, r = mat['type'], mat.get('roughness', 0.0)
    alpha = r * r
    if t == 'conductor':
        if mat['metal']:
            d = {'material': mat['metal']}
        else:
            d = {'material': 'none', 'specular_reflectance': mr.rgb(mat['color'])}
        d['type'] = 'conductor'
        if r > 0:
            d.update(type='roughconductor', distribution='ggx', alpha=alpha)
        return {'type': 'twosided', 'bsdf': d}
    if t == 'plastic':
        d = {'type': 'plastic', 'int_ior': float(mat['ior']), 'ext_ior': 1.0,
             'diffuse_reflectance': mr.rgb(mat['color']), 'nonlinear': False}
        if r > 0:
            d.update(type='roughplastic', distribution='ggx', alpha=alpha)
        return {'type': 'twosided', 'bsdf': d}
    if t == 'glass' and r > 0:
        return {'type': 'roughdielectric', 'distribution': 'ggx', 'alpha': alpha,
                'int_ior': float(mat['ior']), 'ext_ior': 1.0,
                'specular_transmittance': mr.rgb(mat['color'])}
    return harness_bsdf_dict(mat)


cs._make_mat = make_mat
mr.bsdf_dict = bsdf_dict

if __name__ == '__main__':
    sys.exit(mitsuba_envmap.main())
