#!/usr/bin/env python3
"""Issue 22's denoising measurement: on each bench scene, relMSE against candela's converged image
of candela at 16 spp denoised as scene.render(denoise=True) does it (Open Image Denoise on the
direct and indirect light apart, albedo and normal guides) and of candela at 256 spp raw, each
over several seeds. relMSE is bench/run's: compare.py's, on images divided by the reference's
mean.

A denoiser is judged against the image its renderer converges to: the reference is candela's own
render at --ref-spp (default 1024), made once and kept in the work folder as
NAME.candela-ref<spp>.pfm. (Against bench/run's Mitsuba references, the two renderers' small
differences, such as the pixel filter at edges, added more to every column than the 256-spp noise
itself, and decided nothing.) The reference's own noise adds about relMSE(256 spp) x 256 / ref_spp
to every column alike, so it cannot turn the comparison; the table prints it.

    python3 tools/denoise_table.py [--scenes cornell,lamp,sky] [--work out/bench] [--seeds 3]

Needs the candela Python package (scripts/install-python) with pyoidn, and a bench/run work
folder (its NAME.json scenes). Prints a markdown table.
"""
import argparse
import os
import sys
import time

import numpy as np

import candela

REFERENCE_DIR = os.environ.get('CANDELA_REFERENCE_DIR',
                               os.path.join(os.path.dirname(__file__), '..', '..', 'shared',
                                            'reference'))
sys.path.insert(0, REFERENCE_DIR)
import compare  # noqa: E402  (the shared harness's PFM reader and relMSE)


def relmse(image, reference):
    """compare.py's relMSE on both images divided by the reference's mean, as bench/run's."""
    scale = 1.0 / reference.mean()
    return compare.metrics(image * scale, reference * scale)['relmse']


def reference_image(scene, path, spp):
    """candela's render at `spp` with a seed no column uses, from `path` if it is there."""
    if not os.path.exists(path):
        candela.write_image(path, scene.render(spp=spp, seed=1000))
    return compare.read_image(path)


def spread(values):
    """'mean (min–max)' of relMSE values."""
    return f'{np.mean(values):.3g} ({min(values):.3g}–{max(values):.3g})'


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--scenes', default='cornell,lamp,sky')
    ap.add_argument('--work', default=os.path.join(os.path.dirname(__file__), '..', 'out', 'bench'))
    ap.add_argument('--seeds', type=int, default=3, help='seeds per column (default 3)')
    ap.add_argument('--ref-spp', type=int, default=1024)
    a = ap.parse_args()
    print('| scene | relMSE, 16 spp raw | relMSE, 16 spp denoised | relMSE, 256 spp raw | '
          "reference's own share | seconds, 16 spp + denoise | seconds, 256 spp |")
    print('| --- | --- | --- | --- | --- | --- | --- |')
    for name in a.scenes.split(','):
        scene = candela.Scene.load(os.path.join(a.work, f'{name}.json'))
        reference = reference_image(
            scene, os.path.join(a.work, f'{name}.candela-ref{a.ref_spp}.pfm'), a.ref_spp)
        raw16, denoised16, raw256, t16, t256 = [], [], [], [], []
        for k in range(a.seeds):
            t = time.perf_counter()
            low = scene.render(spp=16, seed=11 + k, aovs=[], denoise=True)
            t16.append(time.perf_counter() - t)
            raw16.append(relmse(low['noisy'], reference))
            denoised16.append(relmse(low['image'], reference))
            t = time.perf_counter()
            high = scene.render(spp=256, seed=111 + k)
            t256.append(time.perf_counter() - t)
            raw256.append(relmse(high, reference))
        # relMSE(x, ref) ~ E(x) + E(ref), and E falls as 1/spp for a raw image.
        own = np.mean(raw256) * (256 / a.ref_spp) / (1 + 256 / a.ref_spp)
        print(f'| {name} | {spread(raw16)} | {spread(denoised16)} | {spread(raw256)} | '
              f'{own:.2g} | {np.median(t16):.1f} | {np.median(t256):.1f} |', flush=True)


if __name__ == '__main__':
    main()
