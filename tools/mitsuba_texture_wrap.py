#!/usr/bin/env python3
"""Holds candela's texture wrap modes and nearest filter (docs/scene-format.md, *Textures*:
`wrap` "repeat", "clamp", "mirror" or one per axis, `filter` "bilinear" or "nearest") against
Mitsuba 3's `bitmap` texture (`wrap_mode`, `filter_type`).

The scene: a square emitter of side 3 facing a 112 x 112 orthographic camera straight on, its uvs
running from -1 to 2 in u (right) and v (up), so that three copies of a 4 x 2 image of distinct
colours (an 8-bit PNG, decoded from sRGB by both renderers: Mitsuba's `raw` stays false) span it
each way; its radiance is the texture, seen directly (max_depth 1), so that each pixel is the mean
of the texture over it. The square fills the central 96 x 96 pixels, 32 to a copy, 8 to a texel
across and 16 down: texel edges and centres and the copies' edges all lie on pixel edges, so that
within each pixel a lookup is bilinear (or constant) and the box filter's mean (both renderers
use `box`) is the texture at the pixel's centre. The script's own model of the docs' convention
evaluates that ("model" columns: 0 but for sampling noise in bilinear pixels). Mitsuba's sampler
is `multijitter`, stratified as candela's samples are (its `independent` sampler leaves ~1e-2 of
noise in bilinear pixels at 64 spp, candela ~2e-4).

Mapping: candela's square is an OBJ quad whose vt run from -1 to 2. Mitsuba's is its `rectangle`
(uv = (x + 1, y + 1) / 2 over [-1, 1]^2), scaled by 1.5, and its bitmap reads uv (0, 0) at the
image's top-left corner (a quick experiment: a 2 x 2 image read at uv (0.1, 0.1) gives its top-left
texel), where candela puts the bottom-left; so the bitmap's `to_uv` maps the rectangle's (s, t) to
(3 s - 1, 1 - (3 t - 1)): candela's u and v with v turned over. Turning v over (t' = 1 - v) keeps
copies and their parity (copy k of v is copy -k of t'), so the wrap modes mean the same. Mitsuba's
`bitmap` takes one `wrap_mode` for both axes: the cases with a mode per axis are held against the
model alone.

    /tmp/mi/bin/python tools/mitsuba_texture_wrap.py [--candela build/candela] [--spp 64]

Prints, per case, over the square's pixels less its outermost ring (the silhouette's pixels, where
a sample's ray may graze the edge), the median and the 5th and 95th percentiles of candela /
Mitsuba per pixel and channel, the largest |candela - Mitsuba|, how many pixels differ by more
than 1e-3 in some channel, and the largest difference of each renderer from the model; then each
renderer's total time. (With the nearest filter a sample that lands on a pixel's edge, a texel's,
may read the texel beyond it after rounding: 1/spp of the step between the two texels.)
"""
import argparse
import os
import sys
import tempfile
import time

import mitsuba as mi
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import candela_run  # noqa: E402
from png8 import png8  # noqa: E402

# The image, rows from the top, 8-bit sRGB (no channel 0, so that every ratio is defined).
TEXELS = [[(230, 60, 50), (250, 200, 40), (60, 180, 75), (40, 120, 220)],
          [(150, 70, 200), (240, 130, 180), (70, 220, 220), (120, 90, 30)]]
SIZE, MARGIN, PX_PER_UNIT = 112, 8, 32  # image pixels; pixels around the square; pixels a copy
VIEW = SIZE / PX_PER_UNIT  # the world width the image spans (the square's side is 3)
# (name, candela's wrap, Mitsuba's wrap_mode or None, filter)
CASES = [(f'{w} {f}', w, w, f) for f in ('bilinear', 'nearest') for w in ('repeat', 'clamp', 'mirror')]
CASES += [('[mirror, clamp] bilinear', ['mirror', 'clamp'], None, 'bilinear'),
          ('[clamp, repeat] nearest', ['clamp', 'repeat'], None, 'nearest')]


def write_inputs(work):
    """The image (tex.png) and candela's square (quad.obj, facing +z, vt from -1 to 2)."""
    with open(os.path.join(work, 'tex.png'), 'wb') as f:
        f.write(png8(4, 2, [[c for texel in row for c in texel] for row in TEXELS]))
    with open(os.path.join(work, 'quad.obj'), 'w') as f:
        f.write('v -1.5 -1.5 0\nv 1.5 -1.5 0\nv 1.5 1.5 0\nv -1.5 1.5 0\n'
                'vt -1 -1\nvt 2 -1\nvt 2 2\nvt -1 2\nf 1/1 2/2 3/3 4/4\n')


def candela(binary, work, wrap, filt, spp):
    """candela's render of the square under `wrap` and `filt`, and the seconds it took."""
    texture = {'texture': 'tex.png', 'wrap': wrap, 'filter': filt}
    scene = {'camera': {'width': SIZE, 'height': SIZE, 'projection': 'orthographic',
                        'view_width': VIEW, 'position': [0, 0, 5], 'look_at': [0, 0, 0],
                        'up': [0, 1, 0], 'spp': spp},
             'render': {'max_depth': 1, 'filter': 'box'},
             'objects': [{'file': 'quad.obj',
                          'material': {'type': 'emissive', 'radiance': texture}}]}
    return candela_run.render(binary, scene, work, 'candela', dtype=np.float64)


def mitsuba(work, wrap, filt, spp):
    """Mitsuba 3's render of the square (see the docstring's mapping), and the seconds it took."""
    to_uv = mi.ScalarTransform3f([[3, 0, -1], [0, -3, 2], [0, 0, 1]])  # (s, t) -> (u, 1 - v)
    radiance = {'type': 'bitmap', 'filename': os.path.join(work, 'tex.png'), 'wrap_mode': wrap,
                'filter_type': filt, 'to_uv': to_uv}
    camera = (mi.ScalarTransform4f().look_at(origin=[0, 0, 5], target=[0, 0, 0], up=[0, 1, 0]) @
              mi.ScalarTransform4f().scale([VIEW / 2, VIEW / 2, 1]))
    scene = mi.load_dict({
        'type': 'scene', 'integrator': {'type': 'path', 'max_depth': 1},
        'sensor': {'type': 'orthographic', 'to_world': camera,
                   'film': {'type': 'hdrfilm', 'width': SIZE, 'height': SIZE,
                            'rfilter': {'type': 'box'}},
                   'sampler': {'type': 'multijitter', 'sample_count': spp}},
        'square': {'type': 'rectangle', 'to_world': mi.ScalarTransform4f().scale([1.5, 1.5, 1]),
                   'emitter': {'type': 'area', 'radiance': radiance}}})
    t = time.perf_counter()
    image = np.array(mi.render(scene), dtype=np.float64)[:, :, :3]
    return image, time.perf_counter() - t


def srgb_to_linear(c):
    c = np.asarray(c, dtype=np.float64) / 255
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


def texel_span(a, n, wrap, filt, from_top):
    """The docs' lookup along one axis of n texels at image coordinates a: the two texels and the
    fraction towards the second."""
    if wrap == 'repeat':
        c = a - np.floor(a)
    elif wrap == 'clamp':
        c = np.clip(a, 0, 1)
    else:
        m = a - 2 * np.floor(a / 2)
        c = np.where(m > 1, 2 - m, m)
    x = (1 - c if from_top else c) * n
    if filt == 'nearest':
        i = np.minimum(np.floor(x), n - 1).astype(int)
        return i, i, np.zeros_like(x)
    i0 = np.floor(x - 0.5).astype(int)
    if wrap == 'repeat':
        return i0 % n, (i0 + 1) % n, x - 0.5 - i0
    return np.clip(i0, 0, n - 1), np.clip(i0 + 1, 0, n - 1), x - 0.5 - i0


def model(wrap, filt):
    """The texture at each pixel's centre by the docs' convention (nan off the square)."""
    wraps = wrap if isinstance(wrap, list) else [wrap, wrap]
    centres = (np.arange(SIZE) + 0.5 - MARGIN) / PX_PER_UNIT - 1  # u left to right, -1 to 2
    u, v = np.meshgrid(centres, centres[::-1])  # rows from the top: v from 2 down to -1
    img = srgb_to_linear(TEXELS)
    x0, x1, fx = texel_span(u, 4, wraps[0], filt, False)
    y0, y1, fy = texel_span(v, 2, wraps[1], filt, True)
    fx, fy = fx[..., None], fy[..., None]
    out = ((1 - fx) * (1 - fy) * img[y0, x0] + fx * (1 - fy) * img[y0, x1] +
           (1 - fx) * fy * img[y1, x0] + fx * fy * img[y1, x1])
    inside = (np.abs(u - 0.5) < 1.5) & (np.abs(v - 0.5) < 1.5)
    return np.where(inside[..., None], out, np.nan)


def interior():
    """The square's pixels less its outermost ring."""
    keep = np.zeros((SIZE, SIZE), dtype=bool)
    keep[MARGIN + 1:SIZE - MARGIN - 1, MARGIN + 1:SIZE - MARGIN - 1] = True
    return keep


def report(name, c, m, ref, keep):
    """One row of the table (m None: Mitsuba cannot express the case)."""
    dc = np.abs(c - ref)[keep].max()
    if m is None:
        return f'{name:26} {"(no Mitsuba equivalent)":>59} {"":4} {"-":>9} {dc:9.2e}'
    ratio = c[keep] / m[keep]
    p5, med, p95 = np.percentile(ratio, [5, 50, 95])
    far = (np.abs(c - m).max(axis=2) > 1e-3)[keep].sum()
    return (f'{name:26} {keep.sum():6d} {med:11.7f} {p5:11.7f} {p95:11.7f} '
            f'{np.abs(c - m)[keep].max():11.2e} {far:4d} {np.abs(m - ref)[keep].max():9.2e} {dc:9.2e}')


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    candela_run.add_candela_option(ap)
    ap.add_argument('--spp', type=int, default=64)
    a = ap.parse_args()
    mi.set_variant('scalar_rgb')
    keep = interior()
    print(f'{"case":26} {"pixels":>6} {"median c/M":>11} {"5th pct":>11} {"95th pct":>11} '
          f'{"max |c - M|":>11} {">1e-3":>4} {"M-model":>9} {"c-model":>9}')
    seconds = [0.0, 0.0]
    with tempfile.TemporaryDirectory() as work:
        write_inputs(work)
        for name, wrap, mi_wrap, filt in CASES:
            c, tc = candela(os.path.abspath(a.candela), work, wrap, filt, a.spp)
            m, tm = mitsuba(work, mi_wrap, filt, a.spp) if mi_wrap else (None, 0.0)
            seconds[0] += tc
            seconds[1] += tm
            print(report(name, c, m, model(wrap, filt), keep), flush=True)
    print(f'{a.spp} spp; candela {seconds[0]:.2f} s in all (process start, load and render), '
          f'Mitsuba {seconds[1]:.2f} s in all (mi.render)')
    return 0


if __name__ == '__main__':
    raise SystemExit(main())
