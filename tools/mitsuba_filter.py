#!/usr/bin/env python3
"""Renders a candela scene with a pixel filter (render "filter") with Mitsuba 3, for reference
images.

The shared harness (../shared/reference/mitsuba_ref.py) maps the original scene contract, whose
pixels are boxes; this maps the filter onto the harness's film and hands everything else to it.

    /tmp/mi/bin/python tools/mitsuba_filter.py SCENE.json OUT.exr [--spp N] [--seed S]
                                               [--threads T]

It prints the harness's two lines (the timing line, then `mean rgb = ...`).

Mapping: candela's "tent" of radius r is Mitsuba's `tent` of the same radius, its "gaussian" of
standard deviation s Mitsuba's `gaussian` of the same `stddev` (both cut off at 4 s; Mitsuba
also subtracts the weight at 4 s, 0.034% of the peak), "box" its `box`. Mitsuba splats each sample
into every pixel within the filter's reach and divides by the weights; candela draws each pixel's
samples from the filter: the same mean. The film samples the border (`sample_border`) so that the
pixels at the image's edges see the plane beyond it, as candela's do.
"""
import argparse
import json
import os
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import mitsuba_envmap  # noqa: E402  (parse_beside, render_and_report; sets up the harness)

mr = mitsuba_envmap.mr
mi, dr = mr.mi, mr.dr

DEFAULT_WIDTH = {'box': None, 'tent': 1.0, 'gaussian': 0.5}


def mitsuba_rfilter(spec):
    """Mitsuba's reconstruction filter for a candela "filter" value (a name or an object)."""
    if isinstance(spec, str):
        spec = {'type': spec}
    kind = spec['type']
    if kind == 'tent':
        return {'type': 'tent', 'radius': spec.get('radius', DEFAULT_WIDTH['tent'])}
    if kind == 'gaussian':
        return {'type': 'gaussian', 'stddev': spec.get('stddev', DEFAULT_WIDTH['gaussian'])}
    return {'type': 'box'}


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
        scene = json.load(f)
    rfilter = mitsuba_rfilter(scene.get('render', {}).pop('filter', 'box'))
    t0 = time.perf_counter()
    sc = mitsuba_envmap.parse_beside(scene, a.scene, 'filter')
    d = mr.scene_dict(sc, spp=a.spp)
    d['sensor']['film'].update(rfilter=rfilter, sample_border=True)
    loaded = mi.load_dict(d)
    mitsuba_envmap.render_and_report(a.scene, sc, loaded, a.out, a.spp, a.seed,
                                     time.perf_counter() - t0)
    return 0


if __name__ == '__main__':
    sys.exit(main())
