#!/usr/bin/env python3
"""Issue 22's denoising measurement: on each bench scene, relMSE against a converged reference of
candela at 16 spp denoised (Open Image Denoise, albedo and normal guides) and of candela at 256
spp raw. The references are bench/run's Mitsuba renders, converted to PFM (out/bench/NAME.ref512.pfm,
from NAME.ref512.exr, which this Python cannot read without OpenEXR); their own
noise adds the same amount to both columns, so it cannot decide which is lower.

    python3 tools/denoise_table.py [--scenes cornell,lamp,sky] [--work out/bench]

Needs the candela Python package (scripts/install-python) with pyoidn, and a bench/run work
folder (its NAME.json scenes and references). Prints a markdown table.
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
import compare  # noqa: E402  (the shared harness's image reader and relMSE)


def relmse(image, reference):
    return compare.metrics(image, reference)['relmse']


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('--scenes', default='cornell,lamp,sky')
    ap.add_argument('--work', default=os.path.join(os.path.dirname(__file__), '..', 'out', 'bench'))
    a = ap.parse_args()
    print('| scene | relMSE, 16 spp raw | relMSE, 16 spp denoised | relMSE, 256 spp raw | '
          'seconds, 16 spp + denoise | seconds, 256 spp |')
    print('| --- | --- | --- | --- | --- | --- |')
    for name in a.scenes.split(','):
        reference = compare.read_image(os.path.join(a.work, f'{name}.ref512.pfm'))
        scene = candela.Scene.load(os.path.join(a.work, f'{name}.json'))
        t = time.perf_counter()
        low = scene.render(spp=16, seed=11, aovs=[], denoise=True)
        t_low = time.perf_counter() - t
        t = time.perf_counter()
        high = scene.render(spp=256, seed=12)
        t_high = time.perf_counter() - t
        print(f'| {name} | {relmse(low["noisy"], reference):.3g} | '
              f'{relmse(low["image"], reference):.3g} | {relmse(high, reference):.3g} | '
              f'{t_low:.1f} | {t_high:.1f} |', flush=True)


if __name__ == '__main__':
    main()
