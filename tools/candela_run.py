"""What the tools that hold candela against another renderer share: the candela binary as an
option, and a scene (a dict) rendered by it on the CPU into a numpy array."""
import json
import os
import subprocess
import time

import numpy as np

from pfm import read_pfm

DEFAULT_BINARY = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'build',
                              'candela')


def add_candela_option(parser):
    parser.add_argument('--candela', default=DEFAULT_BINARY,
                        help='the candela binary (default: build/candela)')


def render(binary, scene, work, name, seed=None, dtype=np.float32):
    """`scene` written to WORK/NAME.json and rendered on the CPU (with `seed` where given): its
    image, (H, W, 3) rows from the top, and the seconds the render took."""
    path, out = os.path.join(work, name + '.json'), os.path.join(work, name + '.pfm')
    with open(path, 'w') as f:
        json.dump(scene, f)
    command = [binary, 'render', path, '-o', out, '-q', '--backend', 'cpu']
    if seed is not None:
        command += ['--seed', str(seed)]
    start = time.perf_counter()
    subprocess.run(command, check=True)
    return read_pfm(out, dtype), time.perf_counter() - start
