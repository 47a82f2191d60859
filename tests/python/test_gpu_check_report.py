"""scripts/gpu-check's tables (tools/gpu_check_report.py) on renders made up here: the verdict
that a GPU image is off, the rows of failed renders, the passes and ptxas's figures. Needs
neither a GPU nor candela."""
import json
import os
import sys

import numpy as np
import pytest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(REPO, 'tools'))
import gpu_check_report as report  # noqa: E402
from pfm import read_pfm, write_pfm  # noqa: E402

PTXAS_LOG = """\
ptxas info    : Compiling entry function '_ZN7candela12_GLOBAL__N_116renderPassKernelILb0EEEvNS_9SceneViewEjjP6float3PNS_8AovPixelEPy' for 'sm_90'
ptxas info    : Function properties for _ZN7candela12_GLOBAL__N_116renderPassKernelILb0EEEvNS_9SceneViewEjjP6float3PNS_8AovPixelEPy
    4544 bytes stack frame, 0 bytes spill stores, 0 bytes spill loads
ptxas info    : Used 211 registers, used 1 barriers, 4544 bytes cumulative stack size
ptxas info    : Compiling entry function '_ZN7candela12_GLOBAL__N_116renderPassKernelILb1EEEvNS_9SceneViewEjjP6float3PNS_8AovPixelEPy' for 'sm_90'
ptxas info    : Function properties for _ZN7candela12_GLOBAL__N_116renderPassKernelILb1EEEvNS_9SceneViewEjjP6float3PNS_8AovPixelEPy
    4552 bytes stack frame, 8 bytes spill stores, 8 bytes spill loads
ptxas info    : Used 255 registers, used 1 barriers, 4552 bytes cumulative stack size
"""


def render(folder, name, tag, image, samples_per_second=1e6):
    write_pfm(os.path.join(folder, f'{name}.{tag}.pfm'), image)
    with open(os.path.join(folder, f'{name}.{tag}.json'), 'w') as f:
        json.dump({'samples_per_second': samples_per_second,
                   'rays_per_second': 4 * samples_per_second}, f)


def sky_passes(folder, ids_equal=1.0):
    depth = np.full((8, 8, 1), 3.0, np.float32)
    depth[0] = np.inf  # the background
    ids = np.ones((8, 8, 1), np.float32)
    for backend in ('cpu', 'cuda'):
        write_pfm(os.path.join(folder, f'passes.{backend}.depth.pfm'), depth)
        gpu_ids = ids.copy()
        if backend == 'cuda':
            gpu_ids.reshape(-1)[:int(round((1 - ids_equal) * 64))] = 2
        write_pfm(os.path.join(folder, f'passes.{backend}.instance.pfm'), gpu_ids)


@pytest.fixture
def image():
    return np.random.default_rng(1).uniform(0.1, 2.0, (8, 8, 3)).astype(np.float32)


def test_the_pfm_helpers_keep_an_image(tmp_path, image):
    write_pfm(tmp_path / 'a.pfm', image)
    np.testing.assert_array_equal(read_pfm(tmp_path / 'a.pfm'), image)


def test_gpu_images_equal_to_rounding_pass(tmp_path, image):
    render(tmp_path, 'room', 'cpu', image, 1e6)
    render(tmp_path, 'room', 'cuda', image * (1 + 1e-6), 2e7)
    sky_passes(tmp_path)
    table = tmp_path / 'gpu-check.md'
    assert report.main(['parity', str(tmp_path), str(table), 'depth,instance', 'x/room.json']) == 0
    text = table.read_text()
    assert '| 1.00000 1.00000 1.00000 | 1 | 20 | 20 | 4 | 80 |' in text
    assert '| instance | 100.00% equal |' in text


def test_a_gpu_image_one_percent_brighter_fails(tmp_path, image):
    render(tmp_path, 'room', 'cpu', image)
    render(tmp_path, 'room', 'cuda', image * 1.01)
    sky_passes(tmp_path)
    assert report.main(['parity', str(tmp_path), str(tmp_path / 't.md'), 'depth', 'room.json']) == 1


def test_a_failed_render_is_a_row_with_its_last_log_line(tmp_path, image):
    render(tmp_path, 'room', 'cpu', image)
    (tmp_path / 'room.cuda.log').write_text('rendering\ncandela: error: out of GPU memory\n')
    rows, failed = report.parity_rows(str(tmp_path), ['room.json'])
    assert failed
    assert rows[-1].startswith('| room | failed: candela: error: out of GPU memory |')


def test_ids_that_differ_in_more_than_one_pixel_in_a_hundred_fail(tmp_path):
    sky_passes(tmp_path, ids_equal=0.95)
    rows, failed = report.pass_rows(str(tmp_path), ['depth', 'instance'])
    assert failed
    assert '| depth | 0.00e+00 |  |' in rows


def test_ptxas_figures_of_both_kernels(tmp_path):
    log = tmp_path / 'build.log'
    log.write_text(PTXAS_LOG)
    assert report.kernel_resources(str(log)) == {
        'image': '211 regs, 4544 B stack, spills 0/0 B',
        'passes': '255 regs, 4552 B stack, spills 8/8 B'}


def test_variants_add_a_row_per_build(tmp_path, image):
    render(tmp_path, 'room', 'cpu', image)
    render(tmp_path, 'room', 'cuda', image, 3e7)
    render(tmp_path, 'room', 'variant0', image * 1.001, 2.5e7)
    (tmp_path / 'build.log').write_text(PTXAS_LOG)
    (tmp_path / 'variant0.build.log').write_text(PTXAS_LOG.replace('Used 211', 'Used 190'))
    table = tmp_path / 't.md'
    report.main(['variants', str(tmp_path), str(tmp_path / 'build.log'), str(table),
                 '--fmad=false;', 'room.json'])
    rows = table.read_text().splitlines()
    assert rows[-2].startswith('| default | 211 regs, 4544 B stack, spills 0/0 B | 255 regs')
    assert '| 30 | 0.00e+00 |  |' in rows[-2]
    assert rows[-1].startswith('| --fmad=false | 190 regs')
    a = image.astype(np.float64)
    expected = np.mean((0.001 * a) ** 2 / (a ** 2 + 1e-2))  # image * 1.001 against image
    assert f'| 25 | {expected:.2e} | {expected:.2e} |' in rows[-1]
