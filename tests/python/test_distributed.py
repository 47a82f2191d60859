"""candela.distributed on a local Ray runtime (ray.init(num_cpus=2)), including a worker killed
mid-frame. Skipped only when Ray is not installed; the two-node cluster is test_cluster.py."""
import json
import os
import signal
import threading
import time

import numpy as np
import pytest

ray = pytest.importorskip("ray", reason="Ray is not installed (scripts/install-python installs it)")

import candela  # noqa: E402
from candela import distributed  # noqa: E402
from conftest import animated_scene, read_pfm, tiny_scene  # noqa: E402

@pytest.fixture(scope="module")
def local_ray():
    # address="local": a fresh runtime even if a `ray start` cluster is running on this machine.
    ray.init(address="local", num_cpus=2, include_dashboard=False, log_to_driver=False)
    yield
    ray.shutdown()


def test_render_frames_animation_and_resume(local_ray, tmp_path):
    path = tmp_path / "anim.json"
    path.write_text(json.dumps(animated_scene(frames=4)))
    out = tmp_path / "frames"
    results = distributed.render_frames(str(path), out, fmt="pfm")
    names = sorted(os.listdir(out))
    assert names == [f"frame_{i:04d}.pfm" for i in range(4)]
    assert all(r["node"] for r in results)
    scene = candela.Scene.load(path)
    for i in range(4):
        np.testing.assert_array_equal(read_pfm(out / names[i]), scene.frame(i).render(backend="cpu"))

    # Resume: nothing to do, then only the missing frame.
    assert all(r["node"] is None for r in distributed.render_frames(str(path), out, fmt="pfm"))
    os.remove(out / names[2])
    again = distributed.render_frames(str(path), out, fmt="pfm")
    assert [r["node"] is not None for r in again] == [False, False, True, False]
    assert sorted(os.listdir(out)) == names


def test_render_frames_sequence_of_dict_scenes(local_ray, tmp_path):
    scenes = [candela.Scene.from_dict(tiny_scene(seed=s)) for s in (1, 2)]
    results = distributed.render_frames(scenes, tmp_path, fmt="png")
    assert [os.path.basename(r["path"]) for r in results] == ["frame_0000.png", "frame_0001.png"]
    assert all(os.path.getsize(r["path"]) > 0 for r in results)


def test_render_image_in_chunks_equals_local_render(local_ray):
    scene = candela.Scene.from_dict(tiny_scene())
    assert distributed.split_samples(10, 3) == [(0, 3), (3, 3), (6, 4)]
    local = scene.render(spp=10, backend="cpu")
    merged = distributed.render_image(scene, spp=10, chunks=3)
    assert merged.dtype == np.float32 and merged.shape == local.shape
    np.testing.assert_allclose(merged, local, rtol=1e-5, atol=1e-6)
    shallow = distributed.render_image(scene, spp=4, chunks=2, max_depth=1)
    np.testing.assert_allclose(shallow, scene.render(spp=4, max_depth=1), rtol=1e-5, atol=1e-6)
    assert shallow.sum() < 0.999 * scene.render(spp=4).sum()


def test_render_image_merges_passes_as_one_render_holds_them(local_ray):
    scene = candela.Scene.from_dict(animated_scene(frames=3, size=20)).frame(1)
    names = ["depth", "normal", "albedo", "instance", "material", "flow"]
    local = scene.render(spp=10, backend="cpu", aovs=names)
    merged = distributed.render_image(scene, spp=10, chunks=3, aovs=names)
    assert set(merged) == {"image"} | set(names)
    for name in ("instance", "material"):
        assert merged[name].dtype == np.uint32
        np.testing.assert_array_equal(merged[name], local[name], err_msg=name)
    for name in ("image", "depth", "normal", "albedo", "flow"):
        np.testing.assert_allclose(merged[name], local[name], rtol=1e-5, atol=1e-5, err_msg=name)
    with pytest.raises(ValueError, match="unknown render pass"):
        distributed.render_image(scene, spp=2, aovs=["nromal"])


def test_render_image_denoises_the_merged_image(local_ray):
    pytest.importorskip("pyoidn", reason="the denoiser (PyPI pyoidn) is not installed")
    spec = tiny_scene()  # with an emitter in view, which both sample again alike
    spec["spheres"].append({"position": [-1.2, 0.3, 0.5], "radius": 0.3,
                            "material": {"type": "emissive", "radiance": 40}})
    scene = candela.Scene.from_dict(spec)
    local = scene.render(spp=8, backend="cpu", aovs=["depth"], denoise=True)
    merged = distributed.render_image(scene, spp=8, chunks=2, aovs=["depth"], denoise=True)
    assert set(merged) == {"image", "noisy", "depth"}
    np.testing.assert_allclose(merged["noisy"], local["noisy"], rtol=1e-5, atol=1e-6)
    np.testing.assert_allclose(merged["image"], local["image"], rtol=1e-3, atol=1e-3)


def _ray_worker_pids(title):
    pids = []
    for pid in filter(str.isdigit, os.listdir("/proc")):
        try:
            with open(f"/proc/{pid}/cmdline", "rb") as f:
                if f.read().startswith(title.encode()):
                    pids.append(int(pid))
        except OSError:
            pass
    return pids


def test_worker_killed_mid_frame_leaves_no_partial_file_and_retries(local_ray, tmp_path):
    scene = candela.Scene.from_dict(tiny_scene(size=48, spp=1500))
    out = tmp_path / "frames"
    results = {}
    thread = threading.Thread(
        target=lambda: results.update(r=distributed.render_frames(scene, out, max_retries=2)))
    thread.start()
    deadline = time.time() + 60
    pids = []
    while not pids and time.time() < deadline:
        pids = _ray_worker_pids("ray::_render_frame")
        time.sleep(0.05)
    assert pids, "no worker ever ran the frame task"
    time.sleep(0.3)  # mid-frame
    os.kill(pids[0], signal.SIGKILL)
    assert not os.path.exists(out / "frame_0000.png")
    thread.join(timeout=120)
    assert not thread.is_alive()
    assert os.listdir(out) == ["frame_0000.png"]  # the retry wrote it; no temporary left behind
    assert results["r"][0]["node"]


class _Cluster:
    """Stands for `ray` where only the cluster's resources are read."""

    def __init__(self, gpus):
        self.gpus = gpus

    def cluster_resources(self):
        return {"CPU": 16.0, "GPU": float(self.gpus)} if self.gpus else {"CPU": 16.0}


def test_auto_tasks_take_the_clusters_gpus_where_it_has_any():
    # A task on "auto" must not render on a GPU it did not ask Ray for: auto is resolved once,
    # for the cluster, and the GPU tasks ask for one GPU each.
    with_gpus, without = _Cluster(2), _Cluster(0)
    assert distributed._task_backend(with_gpus, "auto") == "cuda"
    assert distributed._task_backend(without, "auto") == "cpu"
    assert distributed._task_backend(with_gpus, "cpu") == "cpu"
    assert distributed._task_options(with_gpus, 3, 1, "cuda")["num_gpus"] == 1
    assert "num_gpus" not in distributed._task_options(with_gpus, 3, 1, "cpu")
    assert distributed._task_options(without, 3, 1, "cpu")["num_cpus"] == 3


def test_render_image_of_a_crop_is_that_part_of_the_image(local_ray):
    # The merged image takes the crop's size from the tasks' parts, not the camera's.
    spec = tiny_scene(spp=4, size=20)
    spec["camera"]["crop"] = [3, 4, 9, 6]
    scene = candela.Scene.from_dict(spec)
    merged = distributed.render_image(scene, chunks=2, backend="cpu")
    assert merged.shape == (6, 9, 3)
    np.testing.assert_allclose(merged, scene.render(backend="cpu"), rtol=1e-5, atol=1e-6)
    # The keyword takes the scene's whole image's part, passes too, as Scene.render's does.
    whole = candela.Scene.from_dict(tiny_scene(spp=4, size=20))
    parts = distributed.render_image(whole, chunks=2, backend="cpu", crop=(3, 4, 9, 6),
                                     aovs=["depth", "instance"])
    single = whole.render(backend="cpu", crop=(3, 4, 9, 6), aovs=["depth", "instance"])
    np.testing.assert_allclose(parts["image"], merged, rtol=1e-5, atol=1e-6)
    np.testing.assert_allclose(parts["depth"], single["depth"], rtol=1e-5, atol=1e-6)
    np.testing.assert_array_equal(parts["instance"], single["instance"])
