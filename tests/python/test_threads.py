"""A render given a thread count keeps all of its work to that many threads: not only the tiles
but the flattening, the BVH build (Embree's too) and the light-path pilot, which run on oneTBB,
and the denoiser. A Ray task given one CPU renders with threads=1 (candela.distributed) and must
not build or denoise on every core of its node.

Measured by the CPU time each thread of a fresh process gains during the render
(/proc/self/task/*/schedstat, in nanoseconds), on a machine of at least two cores, for scenes
whose work outside the tiles is large: the build of a 500k-triangle mesh seen by 8x8 pixels at
1 spp, and the denoising of a 256x256 image at 1 spp. Counted are the threads besides the
caller's that took a share: the render runs on a thread of its own, which ends with it and is not
seen, so with one thread no oneTBB worker may work, and the denoiser only on one of OIDN's."""
import json
import os
import subprocess
import sys
import textwrap

import pytest

PROBE = textwrap.dedent("""
    import json, os, sys
    import candela

    def cpu_nanoseconds():
        times = {}
        for tid in os.listdir('/proc/self/task'):
            try:
                with open(f'/proc/self/task/{tid}/schedstat') as f:
                    times[tid] = int(f.read().split()[0])
            except OSError:
                pass  # a thread that ended meanwhile
        return times

    scene = candela.Scene.load(sys.argv[1])
    options = json.loads(sys.argv[2])
    before = cpu_nanoseconds()
    scene.render(**options)
    after = cpu_nanoseconds()
    # The caller's own thread waits for the render, or prepares the denoiser's input: not counted.
    print(json.dumps({tid: t - before.get(tid, 0) for tid, t in after.items()
                      if tid != str(os.getpid())}))
""")


def write_grid_scene(folder, cells):
    """A scene of one grid mesh of 2 * cells^2 triangles, 8x8 pixels at 1 spp."""
    import numpy as np
    n = cells + 1
    i, j = np.meshgrid(np.arange(n), np.arange(n), indexing='ij')
    vertices = np.stack([i.ravel() / cells - 0.5, (i * j % 7).ravel() * 1e-3,
                         j.ravel() / cells - 0.5], axis=1)
    corner = (i[:-1, :-1] * n + j[:-1, :-1]).ravel() + 1  # OBJ indices from 1
    faces = np.concatenate([np.stack([corner, corner + n, corner + 1], axis=1),
                            np.stack([corner + 1, corner + n, corner + n + 1], axis=1)])
    with open(folder / 'grid.obj', 'w') as f:
        np.savetxt(f, vertices, fmt='v %.6f %.6f %.6f')
        np.savetxt(f, faces, fmt='f %d %d %d')
    scene = {
        "camera": {"width": 8, "height": 8, "fov": 50, "position": [0, 1, 1.5],
                   "look_at": [0, 0, 0], "spp": 1},
        "objects": [{"file": "grid.obj", "color": 0.6}],
        "lights": [{"position": [0, 2, 0], "intensity": 10}],
    }
    path = folder / 'grid.json'
    path.write_text(json.dumps(scene))
    return path


def busy_threads(scene_path, **options):
    """How many threads of a fresh process, besides the caller's, took a share of the work (20 ms
    of CPU or more; what only waited takes a few at most) in scene.render(**options). numpy's
    OpenBLAS, whose idle threads spin for a while, is kept to the caller's thread."""
    environment = dict(os.environ, OPENBLAS_NUM_THREADS='1', OMP_NUM_THREADS='1')
    run = subprocess.run([sys.executable, '-c', PROBE, str(scene_path), json.dumps(options)],
                         capture_output=True, text=True, timeout=300, stdin=subprocess.DEVNULL,
                         env=environment)
    assert run.returncode == 0, run.stderr
    return sum(ns >= 20e6 for ns in json.loads(run.stdout).values())


def most_busy_threads(scene_path, tries=6, **options):
    """busy_threads with all cores, the most of up to `tries` runs, stopping at the first with two
    or more: that several threads *can* share the work needs one run that shows it, and on a
    shared virtual machine whose other core the host lends elsewhere for a moment, one run in CI
    saw only one busy thread (the same commit showed two in five runs after it); session 75's CI
    saw one in three runs in a row (three reruns then showed two), so up to six are tried."""
    most = 0
    for _ in range(tries):
        most = max(most, busy_threads(scene_path, **options))
        if most >= 2:
            break
    return most


pytestmark = [
    pytest.mark.skipif(not os.path.exists(f'/proc/self/task/{os.getpid()}/schedstat'),
                       reason="needs Linux's /proc/self/task/*/schedstat to see threads' CPU time"),
    pytest.mark.skipif(len(os.sched_getaffinity(0)) < 2,
                       reason='needs two cores to tell one thread from several'),
]


def test_a_render_given_one_thread_builds_on_one(tmp_path):
    scene = write_grid_scene(tmp_path, 500)
    one, all_cores = busy_threads(scene, threads=1), most_busy_threads(scene)
    assert one <= 1 and all_cores > one, (
        f'busy threads: {one} with threads=1, {all_cores} with all cores')


def test_a_denoised_render_given_one_thread_denoises_on_one(tmp_path):
    pytest.importorskip('pyoidn', reason='denoising needs pyoidn')
    from conftest import tiny_scene
    path = tmp_path / 'tiny.json'
    path.write_text(json.dumps(tiny_scene(spp=1, size=256)))
    one = busy_threads(path, threads=1, denoise=True)
    all_cores = most_busy_threads(path, denoise=True)
    assert one <= 1 and all_cores > one, (
        f'busy threads: {one} with threads=1, {all_cores} with all cores')
