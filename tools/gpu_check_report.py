"""scripts/gpu-check's tables: the GPU's renders held against the CPU's, and what other nvcc flags
did to the render kernel. Reads what gpu-check left in its renders folder: NAME.BACKEND.pfm and
NAME.BACKEND.json (`candela render --stats`) per scene, passes.BACKEND.PASS.pfm, and for each
flag variant i NAME.varianti.pfm/.json and varianti.build.log.

    python3 tools/gpu_check_report.py parity RENDERS TABLE.md PASSES SCENE.json...
    python3 tools/gpu_check_report.py variants RENDERS BUILD.log TABLE.md 'FLAGS;FLAGS;' SCENE...

`parity` writes its table to TABLE.md and exits 1 where a GPU image is off (relMSE above 1e-3, a
channel mean off by more than 0.5%, ids equal in 99% of pixels or fewer) or a render failed;
`variants` appends its table and always exits 0 (the verdict is parity's).
"""
import json
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pfm import read_pfm  # noqa: E402

REL_MSE_LIMIT = 1e-3
MEAN_RATIO_LIMIT = 5e-3
IDS_EQUAL_LIMIT = 0.99


def rel_mse(reference, image):
    """The mean of (a - b)^2 / (a^2 + 0.01), a from `reference`: relative where a value is bright,
    absolute near black (as tests/image_difference.h)."""
    return float(np.mean((image - reference) ** 2 / (reference ** 2 + 1e-2)))


def scene_name(scene):
    return os.path.splitext(os.path.basename(scene))[0]


def _image(renders, name, tag):
    return read_pfm(os.path.join(renders, f'{name}.{tag}.pfm'), np.float64)


def _stats(renders, name, tag):
    with open(os.path.join(renders, f'{name}.{tag}.json')) as f:
        return json.load(f)


def _last_log_line(renders, name, why):
    """The last line of a failed render's log (the CPU's or the GPU's), else `why`."""
    for backend in ('cpu', 'cuda'):
        try:
            with open(os.path.join(renders, f'{name}.{backend}.log')) as f:
                lines = f.read().strip().splitlines()
            why = lines[-1] if lines else why
        except OSError:
            pass
    return why


def parity_rows(renders, scenes):
    """The table's rows, one per scene, and whether any failed."""
    rows = ['| scene | relMSE GPU vs CPU | values off by > 1e-3 relative | channel mean ratio GPU / '
            'CPU | CPU Msamples/s | GPU Msamples/s | GPU / CPU | CPU Mrays/s | GPU Mrays/s |',
            '| --- | --- | --- | --- | --- | --- | --- | --- | --- |']
    failed = False
    for name in map(scene_name, scenes):
        try:
            cpu, gpu = _image(renders, name, 'cpu'), _image(renders, name, 'cuda')
            sc, sg = _stats(renders, name, 'cpu'), _stats(renders, name, 'cuda')
            rel = rel_mse(cpu, gpu)
            off = float(np.mean(np.abs(gpu - cpu) > 1e-3 * (np.abs(cpu) + 1e-2)))
            ratios = gpu.reshape(-1, 3).mean(0) / cpu.reshape(-1, 3).mean(0)
            a, b = sc['samples_per_second'] / 1e6, sg['samples_per_second'] / 1e6
            rows.append(f'| {name} | {rel:.2e} | {off:.2%} | '
                        f'{" ".join(f"{r:.5f}" for r in ratios)} | {a:.3g} | {b:.3g} | '
                        f'{b / a:.3g} | {sc["rays_per_second"] / 1e6:.4g} | '
                        f'{sg["rays_per_second"] / 1e6:.4g} |')
            failed |= not (rel < REL_MSE_LIMIT and np.all(np.abs(ratios - 1) < MEAN_RATIO_LIMIT))
        except Exception as e:  # noqa: BLE001  (a row says what failed; the others still come)
            why = _last_log_line(renders, name, repr(e))
            rows.append(f'| {name} | failed: {why.replace("|", "/")} | | | | | | | |')
            failed = True
    return rows, failed


def pass_rows(renders, passes):
    """The passes' rows (sky, 4 spp) and whether any failed: the same first hits, so values agree
    up to rounding (depth is infinite on the background alike) and ids are equal but where
    rounding flips a rare hit."""
    rows = ['', '| pass (sky, 4 spp) | relMSE GPU vs CPU, or ids equal | |', '| --- | --- | --- |']
    failed = False
    for name in passes:
        try:
            cpu, gpu = (_image(renders, 'passes', f'{b}.{name}') for b in ('cpu', 'cuda'))
            if name in ('instance', 'material'):
                equal = float(np.mean(cpu == gpu))
                rows.append(f'| {name} | {equal:.2%} equal | |')
                failed |= not equal > IDS_EQUAL_LIMIT
            else:
                finite = np.isfinite(cpu)
                same_inf = bool(np.all(finite == np.isfinite(gpu)))
                rel = rel_mse(cpu[finite], gpu[finite]) if same_inf else float('inf')
                rows.append(f'| {name} | {rel:.2e} | '
                            f'{"" if same_inf else "infinite in other pixels"} |')
                failed |= not (rel < REL_MSE_LIMIT and same_inf)
        except Exception as e:  # noqa: BLE001
            rows.append(f'| {name} | failed: {repr(e).replace("|", "/")} | |')
            failed = True
    return rows, failed


def kernel_resources(log):
    """ptxas's figures for the render kernel in a build log: {'image' or 'passes' (the kernel that
    also writes the passes): 'R regs, S B stack, spills W/L B'}."""
    found, kernel, figures = {}, None, None
    try:
        with open(log, errors='replace') as f:
            lines = f.read().splitlines()
    except OSError:
        return found
    for line in lines:
        entry = re.search(r"Compiling entry function '(\S+)'", line)
        if entry:
            name = entry.group(1)
            kernel = None
            if 'renderPassKernel' in name:
                kernel = 'passes' if 'ILb1E' in name else 'image'
            figures = None
            continue
        if kernel is None or kernel in found:
            continue
        stack = re.search(r'(\d+) bytes stack frame, (\d+) bytes spill stores, '
                          r'(\d+) bytes spill loads', line)
        if stack and figures is None:
            figures = stack.groups()
        used = re.search(r'Used (\d+) registers', line)
        if used and figures:
            found[kernel] = (f'{used.group(1)} regs, {figures[0]} B stack, '
                             f'spills {figures[1]}/{figures[2]} B')
    return found


def variant_rows(renders, base_log, variants, scenes):
    """One row per build, the default first: its kernels, its speed on each scene, and its
    largest relMSE against the CPU and against the default GPU build."""
    names = [scene_name(s) for s in scenes]
    rows = ['', '| GPU build | render kernel | kernel with passes | '
            + ' | '.join(f'{n} Msamples/s' for n in names)
            + ' | largest relMSE against the CPU | largest against the default GPU build |',
            '| --- | --- | --- | ' + ' | '.join('---' for _ in names) + ' | --- | --- |']
    for i, flags in [(None, 'default')] + list(enumerate(variants)):
        tag = 'cuda' if i is None else f'variant{i}'
        log = base_log if i is None else os.path.join(renders, f'variant{i}.build.log')
        kernels = kernel_resources(log)
        speeds, cpu, gpu = [], [], []
        for n in names:
            try:
                speeds.append(f"{_stats(renders, n, tag)['samples_per_second'] / 1e6:.3g}")
                image = _image(renders, n, tag)
                cpu.append(rel_mse(_image(renders, n, 'cpu'), image))
                if i is not None:
                    gpu.append(rel_mse(_image(renders, n, 'cuda'), image))
            except Exception:  # noqa: BLE001  (a render that failed: its log is in the archive)
                speeds.append('failed')
        rows.append(f"| {flags} | {kernels.get('image', '?')} | {kernels.get('passes', '?')} | "
                    + ' | '.join(speeds) + f" | {f'{max(cpu):.2e}' if cpu else ''} | "
                    + f"{f'{max(gpu):.2e}' if gpu else ''} |")
    return rows


def main(argv):
    if len(argv) >= 4 and argv[0] == 'parity':
        renders, table, passes, scenes = argv[1], argv[2], argv[3].split(','), argv[4:]
        rows, failed = parity_rows(renders, scenes)
        more, passes_failed = pass_rows(renders, passes)
        text = '\n'.join(rows + more) + '\n'
        with open(table, 'w') as f:
            f.write(text)
        print(text)
        return 1 if failed or passes_failed else 0
    if len(argv) >= 5 and argv[0] == 'variants':
        # gpu-check ends each variant with ';', so that variant i is the i-th field.
        renders, base_log, table, variants, scenes = (argv[1], argv[2], argv[3],
                                                      argv[4].split(';')[:-1], argv[5:])
        text = '\n'.join(variant_rows(renders, base_log, variants, scenes)) + '\n'
        with open(table, 'a') as f:
            f.write(text)
        print(text)
        return 0
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
