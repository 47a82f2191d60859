#!/usr/bin/env python3
"""Renders a candela scene whose OBJ meshes take MTL materials (textures, glossy materials, alpha
masks) with Mitsuba 3.

The shared harness (../shared/reference) reads an OBJ's MTL as `Kd` colours alone and builds meshes
without texture coordinates. This replaces its OBJ loader with one that reads `vt` and the MTL
statements of docs/scene-format.md (MTL materials, Alpha masks, Textures), on top of
tools/mitsuba_materials.py (conductor, plastic, rough glass, sphere textures) and
tools/mitsuba_envmap.py (environment maps), and hands over to their main, so the command line and
the printed line are the same:

    /tmp/mi/bin/python tools/mitsuba_mtl.py SCENE.json OUT.exr [--spp N] [--seed S] [--time]
                                            [--threads T]

Mapping, per MTL material (an object without `material` or `color`; every opaque material wrapped
in `twosided`, as the harness and mitsuba_materials.py do, since candela's reflect on both sides):
  Ke (or map_Ke) not black,  -> emissive: black diffuse + `area` emitter, radiance Ke (times
  and neither a Kd that is not  map_Ke's texture; Ke 1 where black or absent)
  black, a map_Kd nor a Ks
  Ke with one of those       -> the material below, and the same `area` emitter; no alpha
  Ks black                   -> diffuse, reflectance Kd (0.8 without Kd); with map_Kd the texture
                                times Kd (1 without Kd)
  Ks not black, with a       -> plastic / roughplastic (ggx), diffuse_reflectance as above,
  diffuse colour (Kd not        int_ior = Ni where Ni > 1 else 1.5, ext_ior 1, nonlinear false
  black, or map_Kd)
  Ks not black, no diffuse   -> conductor / roughconductor (ggx), material "none",
                                specular_reflectance = Ks
  Ns n (with Ks; 1 where     -> alpha = min(1, sqrt(2 / (n + 2))) (candela's roughness sqrt(alpha));
  absent, as tinyobjloader)     below 0.001 (roughness < 0.032) the smooth plugin
  d a / Tr t / map_d         -> `mask` around the material, opacity a (or 1 - t; d wins) times
                                map_d's alpha channel (its first channel without one), linear: a
                                constant or a one-channel float bitmap. A scene with a mask renders
                                with `volpath` for `path` (same max_depth, rr_depth, hide_emitters):
                                `path` counts a pass-through as a bounce and stops shadow rays at
                                masked surfaces (12% too dark on a check scene); volpath does not
                                count null interactions and weights shadow rays by 1 - opacity, the
                                mean of candela's stochastic alpha
  map_Kd / map_d / map_Ke    -> `bitmap`, bilinear, repeat, raw, of a float EXR written here:
  [-s su sv [sw]] file          8-bit colours decoded from sRGB (masks linear), float images as
                                they are, colours times the Kd (Ke) tint, rows flipped so that the
                                image's bottom row comes first; to_uv = scale(su, sv)
  usemtl of no MTL material  -> diffuse 0.8
  (or none)
UV orientation: Mitsuba's bitmap puts v = 0 at the first row in memory (the image's top row as
read; its OBJ loader stores 1 - v for that reason), candela at the image's bottom row; flipping the
rows makes the two agree for any scale. Checked by render against candela: emissive quads with
random textures, offset uvs and scales 1.3 x 0.7 and -1.7 x 2.2 agree to a median per-pixel
difference of 3e-5 (4e-3 without the flip).
Meshes keep OBJ `vt` (u, v; a third component ignored) per face corner as Mitsuba texcoords; a face
with a corner without `vt` has uv (0, 0). Quads are split along the shorter diagonal (as candela),
larger polygons fanned from the first corner (candela ear-clips concave ones; not done here).
An object with an explicit `material`/`color` keeps it; a texture in it (mitsuba_materials.py's
{"texture", "scale"}) is then looked up with the mesh's `vt` as above.
"""
import atexit
import math
import os
import shutil
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import mitsuba_materials  # noqa: E402  (its mappings, and the harness path via mitsuba_envmap)
import mitsuba_envmap  # noqa: E402
import candela_scene as cs  # noqa: E402
import mitsuba_ref as mr  # noqa: E402

np, mi = mr.np, mr.mi

WORK = tempfile.mkdtemp(prefix='candela_mitsuba_mtl_')
atexit.register(shutil.rmtree, WORK, True)
_copies = {}


# ----------------------------------------------------------------------------------------------
# textures
# ----------------------------------------------------------------------------------------------
def srgb_to_linear(s):
    return np.where(s <= 0.04045, s / 12.92, ((s + 0.055) / 1.055) ** 2.4)


def _texels(path):
    """The image as float64 H x W x C (top row first) and whether its 8-bit values are encoded."""
    bmp = mi.Bitmap(path)
    a = np.array(bmp)
    if a.ndim == 2:
        a = a[:, :, None]
    fmt = bmp.pixel_format()
    if a.dtype == np.uint8:
        return a.astype(np.float64) / 255.0, fmt, True
    if a.dtype == np.uint16:
        return a.astype(np.float64) / 65535.0, fmt, True
    return a.astype(np.float64), fmt, False


def linear_copy(path, use, tint=(1.0, 1.0, 1.0), factor=1.0):
    """A float EXR of `path` for a raw bitmap: use 'color' (RGB, sRGB-decoded if 8-bit, times
    tint) or 'mask' (one channel: the alpha channel or else the first, linear, times factor), rows
    flipped (first row in memory = image's bottom row)."""
    key = (path, use, tuple(float(x) for x in tint), float(factor))
    if key in _copies:
        return _copies[key]
    a, fmt, encoded = _texels(path)
    PF = mi.Bitmap.PixelFormat
    has_alpha = fmt in (PF.YA, PF.RGBA) or (fmt not in (PF.Y, PF.RGB) and a.shape[2] in (2, 4))
    if use == 'color':
        rgb = a[:, :, :3] if a.shape[2] >= 3 else np.repeat(a[:, :, :1], 3, axis=2)
        if encoded:
            rgb = srgb_to_linear(rgb)
        out = rgb * np.asarray(key[2])[None, None, :]
    else:
        out = (a[:, :, -1:] if has_alpha else a[:, :, :1]) * factor
    out = np.ascontiguousarray(out[::-1], dtype=np.float32)
    name = os.path.join(WORK, f'{len(_copies)}_{use}_' +
                        os.path.splitext(os.path.basename(path))[0] + '.exr')
    mi.Bitmap(out, pixel_format=PF.RGB if use == 'color' else PF.Y).write(name)
    _copies[key] = name
    return name


def bitmap(filename, scale):
    su, sv = scale
    return {'type': 'bitmap', 'filename': filename, 'raw': True, 'filter_type': 'bilinear',
            'wrap_mode': 'repeat', 'to_uv': mi.ScalarTransform4f().scale([su, sv, 1])}


harness_spectrum = mitsuba_materials.spectrum


def spectrum(c):
    """mitsuba_materials.spectrum, plus textures looked up with a mesh's OBJ uvs."""
    if isinstance(c, dict) and c.get('uv') == 'obj':
        return bitmap(linear_copy(c['texture'], 'color', c.get('tint', (1, 1, 1))), c['scale'])
    return harness_spectrum(c)


def opacity(alpha):
    if alpha.get('texture') is None:
        return float(alpha['constant'])
    return bitmap(linear_copy(alpha['texture'], 'mask', factor=alpha['constant']), alpha['scale'])


# ----------------------------------------------------------------------------------------------
# MTL
# ----------------------------------------------------------------------------------------------
def _reals(tok, n=3):
    """tinyobjloader's parseReal3: missing components are 0."""
    v = [float(x) for x in tok[1:1 + n]]
    return np.array(v + [0.0] * (n - len(v)), float)


def _unit(ctx, jpath, where, word, value):
    try:
        x = float(value.split()[0])
    except (ValueError, IndexError):
        ctx.err(jpath, f'{where}: {word}: expected a number in [0, 1], got {value!r}')
    if not 0 <= x <= 1:
        ctx.err(jpath, f'{where}: {word}: expected a number in [0, 1], got {value!r}')
    return x


def _map(ctx, jpath, where, folder, keyword, rest):
    """`map_X [-s su sv [sw]] file` -> (absolute path, [su, sv])."""
    scale = [1.0, 1.0]
    while rest.startswith('-'):
        words = rest.split()
        if words[0] != '-s':
            ctx.err(jpath, f'{where}: {keyword} option "{words[0]}" is not supported (only -s)')
        vals, k = [], 1
        while k < len(words) and len(vals) < 3:
            try:
                x = float(words[k])
            except ValueError:
                break
            if not (math.isfinite(x) and x != 0):
                ctx.err(jpath, f'{where}: {keyword} -s: expected finite, non-zero scales')
            vals.append(x)
            k += 1
        if not vals:
            ctx.err(jpath, f'{where}: {keyword} -s: expected a scale')
        scale = [vals[0], vals[1] if len(vals) > 1 else vals[0]]
        rest = ' '.join(words[k:])      # (collapses runs of blanks in a file name)
    if not rest:
        ctx.err(jpath, f'{where}: expected a file name after {keyword}')
    path = rest if os.path.isabs(rest) else os.path.join(folder, rest)
    if not os.path.isfile(path):
        ctx.err(jpath, f'{where}: cannot read the texture: {path}')
    return os.path.abspath(path), scale


def load_mtl(path, ctx, jpath):
    """Name -> candela material dict (the mapping in this module's docstring)."""
    if not os.path.isfile(path):
        return {}                       # candela skips an MTL it cannot read
    folder = os.path.dirname(os.path.abspath(path))
    raw, cur = {}, None
    with open(path, errors='replace') as fh:
        for ln, line in enumerate(fh, 1):
            line = line.rstrip('\r\n').strip()
            if not line or line.startswith('#'):
                continue
            tok = line.split()
            kw, rest = tok[0], line[len(tok[0]):].strip()
            if kw == 'newmtl':
                cur = rest
                raw[cur] = {}
            elif cur is not None:
                raw[cur][kw] = (rest, f'{os.path.basename(path)}:{ln}', tok)
    out = {}
    for name, st in raw.items():
        def real3(kw, default):
            if kw not in st:
                return default
            rest, where, tok = st[kw]
            try:
                v = _reals(tok)
            except ValueError:
                ctx.err(jpath, f'{where}: malformed {kw}')
            if not (np.all(np.isfinite(v)) and np.all(v >= 0)):
                ctx.err(jpath, f'{where}: {kw}: expected finite, non-negative values')
            return v

        def real(kw, default):
            if kw not in st:
                return default
            try:
                return float(st[kw][2][1]) if len(st[kw][2]) > 1 else 0.0
            except ValueError:
                ctx.err(jpath, f'{st[kw][1]}: malformed {kw}')

        def tex(kw):
            if kw not in st:
                return None
            rest, where, _ = st[kw]
            return _map(ctx, jpath, where, folder, kw, rest)

        kd = real3('Kd', None)
        ke = real3('Ke', np.zeros(3))
        map_ke = tex('map_Ke')
        if map_ke is not None and not np.any(ke > 0):
            ke = np.ones(3)
        radiance = ke
        if map_ke is not None:
            radiance = {'texture': map_ke[0], 'scale': map_ke[1], 'tint': ke.tolist(), 'uv': 'obj'}
        # As candela: Ke beside a Kd that is not black, a map_Kd or a Ks reflects and emits.
        reflects = (kd is not None and np.any(kd > 0)) or 'map_Kd' in st or \
            np.any(real3('Ks', np.zeros(3)) > 0)
        if np.any(ke > 0) and not reflects:
            out[name] = dict(type='emissive', radiance=radiance)
            continue
        map_kd = tex('map_Kd')
        if map_kd is not None:
            tint = kd if kd is not None else np.ones(3)
            color = {'texture': map_kd[0], 'scale': map_kd[1], 'tint': tint.tolist(), 'uv': 'obj'}
        else:
            color = kd if kd is not None else np.full(3, 0.8)
        has_diffuse = map_kd is not None or np.any(color > 0)
        ks = real3('Ks', np.zeros(3))
        if np.any(ks > 0):
            ns = real('Ns', 1.0)
            if not (math.isfinite(ns) and ns >= 0):
                ctx.err(jpath, f'{st["Ns"][1]}: expected a finite, non-negative Ns')
            alpha = min(1.0, math.sqrt(2.0 / (ns + 2.0)))
            r = 0.0 if alpha < mitsuba_materials.SMOOTH_ALPHA else math.sqrt(alpha)
            if has_diffuse:
                ni = real('Ni', 1.0)
                mat = dict(type='plastic', roughness=r, color=color,
                           ior=ni if math.isfinite(ni) and ni > 1 else 1.5)
            else:
                mat = dict(type='conductor', roughness=r, metal=None, color=ks)
        else:
            mat = dict(type='diffuse', color=color)
        a = 1.0
        if 'd' in st:
            a = _unit(ctx, jpath, st['d'][1], 'd', st['d'][0])
        elif 'Tr' in st:
            a = 1.0 - _unit(ctx, jpath, st['Tr'][1], 'Tr', st['Tr'][0])
        map_d = tex('map_d')
        if map_d is not None:
            mat['alpha'] = dict(constant=a, texture=map_d[0], scale=map_d[1])
        elif a < 1:
            mat['alpha'] = dict(constant=a, texture=None)
        if np.any(ke > 0):  # an emitting surface's alpha is not used
            mat.pop('alpha', None)
            mat['emission'] = radiance
        out[name] = mat
    return out


def uses_uv(mat):
    def t(c):
        return isinstance(c, dict)
    return t(mat.get('color')) or t(mat.get('radiance')) or t(mat.get('emission')) or \
        (mat.get('alpha') or {}).get('texture') is not None


def _mesh_texture(mat):
    """An explicit material's texture colour (mitsuba_materials.py's sphere-style reference) as a
    lookup with the mesh's OBJ uvs."""
    if isinstance(mat.get('color'), dict) and mat['color'].get('uv') != 'obj':
        mat = dict(mat)
        mat['color'] = dict(mat['color'], uv='obj')
    return mat


# ----------------------------------------------------------------------------------------------
# OBJ
# ----------------------------------------------------------------------------------------------
def load_obj(path, ctx, jpath):
    if not os.path.isfile(path):
        ctx.err(jpath, f'OBJ file not found: {path}')
    V, VN, VT = [], [], []
    faces = []          # (corners [(v, n or None, t or None)], mtl name or None)
    mtl = {}
    cur = None
    with open(path, errors='replace') as fh:
        for ln, raw_line in enumerate(fh, 1):
            line = raw_line.split('#', 1)[0].strip()
            if not line:
                continue
            tok = line.split()
            kw = tok[0]
            if kw == 'usemtl':  # as tinyobjloader: the next word, '#' and all
                words = raw_line.split()
                cur = words[1] if len(words) > 1 else None
                continue
            try:
                if kw == 'v':
                    if len(tok) < 4:
                        raise ValueError
                    V.append([float(x) for x in tok[1:4]])
                elif kw == 'vt':
                    if len(tok) < 2:
                        raise ValueError
                    VT.append([float(tok[1]), float(tok[2]) if len(tok) > 2 else 0.0])
                elif kw == 'vn':
                    if len(tok) < 4:
                        raise ValueError
                    VN.append([float(x) for x in tok[1:4]])
                elif kw == 'f':
                    if len(tok) < 4:
                        raise ValueError('face with fewer than 3 vertices')
                    corners = []
                    for t in tok[1:]:
                        parts = t.split('/')
                        ids = []
                        for k, n in ((0, len(V)), (1, len(VT)), (2, len(VN))):
                            if len(parts) > k and parts[k] != '':
                                a = int(parts[k])
                                a = a - 1 if a > 0 else n + a
                                if not 0 <= a < n:
                                    raise ValueError(f'index {parts[k]} out of range')
                                ids.append(a)
                            elif k == 0:
                                raise ValueError('missing vertex index')
                            else:
                                ids.append(None)
                        corners.append(tuple(ids))
                    faces.append((corners, cur))
                elif kw == 'mtllib':
                    for name in tok[1:]:
                        mtl.update(load_mtl(os.path.join(os.path.dirname(path), name), ctx, jpath))
            except (ValueError, IndexError) as e:
                ctx.err(jpath, f'{path}:{ln}: malformed OBJ line {line!r} ({e})')
    return (np.array(V, float).reshape(-1, 3), np.array(VN, float).reshape(-1, 3),
            np.array(VT, float).reshape(-1, 2), faces, mtl)


def triangles(corners, P):
    """candela's split: a quad along its shorter diagonal, larger polygons as a fan."""
    n = len(corners)
    if n == 4:
        p = [P[c[0]] for c in corners]
        if np.sum((p[0] - p[2]) ** 2) <= np.sum((p[1] - p[3]) ** 2):
            return [(0, 1, 2), (0, 2, 3)]
        return [(0, 1, 3), (1, 2, 3)]
    return [(0, k, k + 1) for k in range(1, n - 1)]


def object_meshes(ctx, o, path, named, base_dir, idx):
    if 'file' not in o:
        ctx.err(path + '.file', 'missing')
    if not isinstance(o['file'], str):
        ctx.err(path + '.file', 'expected a string')
    fpath = os.path.join(base_dir, o['file'])
    pos = ctx.vec3(o.get('position', [0, 0, 0]), path + '.position')
    rot = ctx.vec3(o.get('rotation', [0, 0, 0]), path + '.rotation')
    sc = o.get('scale', 1.0)
    s = ctx.vec3(sc, path + '.scale') if isinstance(sc, list) else \
        np.full(3, ctx.number(sc, path + '.scale'))
    if np.any(s == 0):
        ctx.err(path + '.scale', 'must be non-zero')
    smooth = o.get('smooth', True)
    if not isinstance(smooth, bool):
        ctx.err(path + '.smooth', 'expected true or false')
    mat_obj = cs._resolve_material(ctx, o, path, named, default=None)
    if mat_obj is not None:
        mat_obj = _mesh_texture(mat_obj)

    V, VN, VT, faces, mtl = load_obj(fpath, ctx, path + '.file')
    if not faces:
        ctx.err(path + '.file', f'{fpath}: no faces')
    M = cs.euler_R(*rot) @ np.diag(s)
    Pw = V @ M.T + pos
    Nw = VN @ np.linalg.inv(M)
    if len(Nw):
        nrm = np.linalg.norm(Nw, axis=1, keepdims=True)
        if np.any(nrm == 0):
            ctx.err(path + '.file', f'{fpath}: zero-length vertex normal')
        Nw = Nw / nrm

    fallback = dict(type='diffuse', color=np.full(3, 0.8))
    groups = {}
    for corners, mname in faces:
        if mat_obj is not None:
            key, mat = '', mat_obj
        elif mname is not None and mname in mtl:
            key, mat = 'mtl:' + mname, mtl[mname]
        else:
            key, mat = 'fallback', fallback
        use_n = smooth and all(c[2] is not None for c in corners)
        use_t = uses_uv(mat)
        has_t = all(c[1] is not None for c in corners)
        g = groups.setdefault((key, use_n), dict(mat=mat, smooth=use_n, uv=use_t, tris=[]))
        ck = [(c[0], c[2] if use_n else None, (c[1] if has_t else None) if use_t else None)
              for c in corners]
        for tri in triangles(corners, V):
            g['tris'].append([ck[k] for k in tri])
    out = []
    for gi, g in enumerate(groups.values()):
        remap, F = {}, []
        for tri in g['tris']:
            F.append([remap.setdefault(c, len(remap)) for c in tri])
        keys = list(remap.keys())
        P = Pw[[c[0] for c in keys]]
        N = Nw[[c[1] for c in keys]] if g['smooth'] else None
        UV = None
        if g['uv']:
            UV = np.zeros((len(keys), 2))
            ti = np.array([-1 if c[2] is None else c[2] for c in keys])
            UV[ti >= 0] = VT[ti[ti >= 0]]
        out.append(dict(name=f'obj{idx}_{gi}', P=P, N=N, UV=UV, F=np.array(F, np.int64),
                        mat=g['mat'], file=fpath))
    return out


# ----------------------------------------------------------------------------------------------
# Mitsuba
# ----------------------------------------------------------------------------------------------
materials_bsdf_dict = mr.bsdf_dict          # mitsuba_materials.bsdf_dict (harness underneath)


def bsdf_dict(mat):
    if mat['type'] == 'emissive':
        return {'type': 'diffuse', 'reflectance': mr.rgb([0, 0, 0])}
    alpha = mat.get('alpha')
    if alpha is None:
        return materials_bsdf_dict(mat)
    inner = {k: v for k, v in mat.items() if k != 'alpha'}
    return {'type': 'mask', 'opacity': opacity(alpha), 'bsdf': materials_bsdf_dict(inner)}


def build_mesh(m):
    """The harness's build_mesh, with texture coordinates and textured emission."""
    P = np.ascontiguousarray(m['P'], np.float32)
    F = np.ascontiguousarray(m['F'], np.uint32)
    has_n = m['N'] is not None
    has_t = m.get('UV') is not None
    props = mi.Properties()
    props['bsdf'] = mi.load_dict(mr.bsdf_dict(m['mat']))
    if m['mat']['type'] == 'emissive' or 'emission' in m['mat']:
        radiance = m['mat']['radiance' if m['mat']['type'] == 'emissive' else 'emission']
        props['emitter'] = mi.load_dict({'type': 'area', 'radiance': spectrum(radiance)})
    mesh = mi.Mesh(m['name'], len(P), len(F), props, has_vertex_normals=has_n,
                   has_vertex_texcoords=has_t)
    params = mi.traverse(mesh)
    params['vertex_positions'] = type(params['vertex_positions'])(P.ravel())
    params['faces'] = type(params['faces'])(F.ravel())
    if has_n:
        params['vertex_normals'] = type(params['vertex_normals'])(
            np.ascontiguousarray(m['N'], np.float32).ravel())
    if has_t:
        params['vertex_texcoords'] = type(params['vertex_texcoords'])(
            np.ascontiguousarray(m['UV'], np.float32).ravel())
    params.update()
    return mesh


materials_scene_dict = mr.scene_dict


def scene_dict(sc, *args, **kwargs):
    d = materials_scene_dict(sc, *args, **kwargs)
    if any(m['mat'].get('alpha') for m in sc['meshes']):
        d['integrator']['type'] = 'volpath'
    return d


cs._object_meshes = object_meshes
mitsuba_materials.spectrum = spectrum
mr.bsdf_dict = bsdf_dict
mr.build_mesh = build_mesh
mr.scene_dict = scene_dict

if __name__ == '__main__':
    sys.exit(mitsuba_envmap.main())
