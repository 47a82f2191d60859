"""Rendering on a Ray cluster: one task per frame, or one image split by sample ranges.

Scenes travel to tasks as plain specs (a file path, or JSON text and a base folder, plus the
frame), never as C++ objects; with file paths, every node must see the scene and its meshes at
the same absolute path (a shared file system). Each task asks for one GPU when the cluster has
GPUs and `cpus_per_task` CPU cores otherwise, and renders with that many threads. Tasks that
fail (a worker or node dies) are retried up to `max_retries` times; frames are written atomically
(a temporary file renamed into place), so an interrupted run never leaves a partial frame, and
a rerun skips the frames that exist (resume).
"""
from __future__ import annotations

import os
import time
from typing import Dict, Iterable, List, Optional, Sequence, Union

import numpy as np

from . import (Scene, _candela, _crop, _denoised, _pass_names, _passes_to_render,
               _render_counts)


def _ray():
    try:
        import ray
    except ImportError as e:  # pragma: no cover - depends on the installation
        raise ImportError("candela.distributed needs Ray: pip install 'candela[distributed]'") from e
    return ray


def _connect(address: Optional[str]):
    ray = _ray()
    if not ray.is_initialized():
        ray.init(address=address, ignore_reinit_error=True, log_to_driver=False)
    return ray


def _task_backend(ray, backend: str) -> str:
    # "auto" across a cluster means its GPUs where it has any, as on one machine; the tasks are
    # then given "cuda" by name, since a task that asked Ray for no GPU must not take one.
    if backend != "auto":
        return backend
    return "cuda" if ray.cluster_resources().get("GPU", 0) >= 1 else "cpu"


def _task_options(ray, cpus_per_task: int, max_retries: int, backend: str) -> dict:
    # Only tasks on the cuda backend (_task_backend's) render on a GPU, so only they ask for one.
    gpus = ray.cluster_resources().get("GPU", 0)
    options = {"max_retries": max_retries, "retry_exceptions": False, "scheduling_strategy": "SPREAD"}
    if backend == "cuda" and gpus >= 1:
        options.update(num_gpus=1, num_cpus=1)
    else:
        options.update(num_cpus=cpus_per_task)
    return options


def _frame_path(out_dir: str, frame: int, count: int, fmt: str) -> str:
    digits = max(4, len(str(max(count - 1, 0))))  # as the CLI: frame_0000.png
    return os.path.join(out_dir, f"frame_{frame:0{digits}d}.{fmt}")


def _render_frame(spec: dict, path: str, spp, backend: str, threads: int,
                  max_depth: Optional[int] = None) -> dict:
    """Task body: rebuild the scene, render, write atomically; says where it ran."""
    import ray

    from . import write_image

    start = time.time()
    scene = Scene.from_spec(spec)
    img = scene.render(spp=spp, backend=backend, threads=threads, max_depth=max_depth)
    write_image(path, img, **scene.output)
    return {"path": path, "node": ray.get_runtime_context().get_node_id(),
            "seconds": time.time() - start}


def _render_slice(spec: dict, spp: int, seed, first: int, count: int, backend: str,
                  threads: int, passes: Optional[list] = None, max_depth: Optional[int] = None,
                  crop: Optional[tuple] = None):
    """Task body: samples [first, first + count) of the image (of its crop); with passes,
    {"image", "sums"}: the mean image and the passes' per-pixel sums, which merge_pass_sums
    adds."""
    scene = Scene.from_spec(spec)
    if passes is None:
        return scene.render(spp=spp, seed=seed, backend=backend, sample_range=(first, count),
                            threads=threads, max_depth=max_depth, crop=crop)
    return scene._core.render(spp, seed, backend, (first, count), threads, passes, True,
                              max_depth=max_depth, crop=crop)


# How each per-pixel sum merges over sample ranges (render/aov.h's CANDELA_AOV_PIXEL_FIELDS):
# "added", or "nearest", taken from the sample nearest the pixel centre.
_SUMS_BY_MERGE = {merge: tuple(k for k, m in _candela.PASS_SUM_MERGES.items() if m == merge)
                  for merge in ("added", "nearest")}


def merge_pass_sums(parts: Sequence[dict]) -> dict:
    """The pass sums of disjoint sample ranges, given in ascending order of their first sample,
    as one render of their union would hold them: sums added; for the id passes, the sample
    nearest the pixel centre, the earliest of equals (so the one a single render keeps)."""
    merged = None
    for part in parts:
        merged = _merge_into(merged, part)
    return merged


def _merge_into(merged: Optional[dict], part: dict) -> dict:
    """merge_pass_sums of (merged, part), into `merged`'s arrays and returned; with no `merged`
    yet, a copy of `part` (Ray's arrays are read-only)."""
    if merged is None:
        return {k: np.array(v, copy=True) for k, v in part.items()}
    for k in _SUMS_BY_MERGE["added"]:
        np.add(merged[k], part[k], out=merged[k])
    nearer = part["nearest_distance2"] < merged["nearest_distance2"]  # strictly: the earliest
    for k in _SUMS_BY_MERGE["nearest"]:
        np.copyto(merged[k], part[k], where=nearer)
    return merged


def _as_scenes(scenes_or_animation) -> List[Scene]:
    items = scenes_or_animation
    if isinstance(items, (str, os.PathLike, Scene)):
        items = [items]
    scenes = [s if isinstance(s, Scene) else Scene.load(s) for s in items]
    if len(scenes) == 1 and scenes[0].frame_index is None and scenes[0].frames > 1:
        return [scenes[0].frame(i) for i in range(scenes[0].frames)]  # an animation
    for s in scenes:
        if s.frame_index is None and s.frames > 1:
            raise ValueError("an animated scene must be the only item (it renders as frames)")
    return scenes


def render_frames(scenes_or_animation: Union[Scene, str, Sequence[Union[Scene, str]]],
                  out_dir: Union[str, os.PathLike], address: Optional[str] = None, *,
                  spp: Optional[int] = None, fmt: str = "png", backend: str = "auto",
                  overwrite: bool = False, max_retries: int = 3,
                  cpus_per_task: int = 1, max_depth: Optional[int] = None) -> List[dict]:
    """Renders an animation (one Scene or scene file with an animation block: one frame each) or
    a sequence of scenes (one frame per scene) to out_dir/frame_NNNN.<fmt>, one Ray task per
    frame. address: a Ray cluster ("HOST:PORT" or "auto"); None starts or joins a local runtime
    when none is connected. Existing frames are skipped unless overwrite. spp and max_depth
    override each frame's, as in Scene.render.

    Returns one dict per frame: frame, path, node (the Ray node id that rendered it, None when
    skipped), seconds.
    """
    if fmt not in ("png", "exr", "pfm"):
        raise ValueError(f"fmt must be png, exr or pfm, got {fmt!r}")
    spp, _, max_depth = _render_counts(spp, None, max_depth)
    scenes = _as_scenes(scenes_or_animation)
    out_dir = os.fspath(out_dir)
    os.makedirs(out_dir, exist_ok=True)
    paths = [_frame_path(out_dir, i, len(scenes), fmt) for i in range(len(scenes))]
    results = [{"frame": i, "path": p, "node": None, "seconds": 0.0} for i, p in enumerate(paths)]
    todo = [i for i, p in enumerate(paths) if overwrite or not os.path.exists(p)]
    if not todo:
        return results

    ray = _connect(address)
    backend = _task_backend(ray, backend)
    options = _task_options(ray, cpus_per_task, max_retries, backend)
    threads = 0 if "num_gpus" in options else cpus_per_task
    task = ray.remote(_render_frame).options(**options)
    refs = {i: task.remote(scenes[i].spec, paths[i], spp, backend, threads, max_depth)
            for i in todo}
    for i, ref in refs.items():
        results[i].update(ray.get(ref), frame=i)
    return results


def split_samples(spp: int, chunks: int) -> List[tuple]:
    """[0, spp) as `chunks` (first, count) slices of near-equal size (fewer if spp < chunks)."""
    if spp <= 0 or chunks <= 0:
        raise ValueError("spp and chunks must be positive")
    chunks = min(chunks, spp)
    bounds = [spp * k // chunks for k in range(chunks + 1)]
    return [(bounds[k], bounds[k + 1] - bounds[k]) for k in range(chunks)]


def render_image(scene: Union[Scene, str], spp: Optional[int] = None, chunks: int = 4,
                 address: Optional[str] = None, *, seed: Optional[int] = None,
                 backend: str = "auto", max_retries: int = 3, cpus_per_task: int = 1,
                 aovs: Optional[Sequence[str]] = None, denoise: bool = False,
                 max_depth: Optional[int] = None,
                 crop: Optional[Sequence[int]] = None) -> Union[np.ndarray, Dict[str, np.ndarray]]:
    """Renders one image as `chunks` Ray tasks, each a slice of the sample indices, and merges
    them weighted by sample count: equal to scene.render(spp, seed, max_depth=max_depth,
    crop=crop) to float rounding.

    aovs and denoise as in Scene.render, with the same result: the tasks return their passes'
    per-pixel sums (merge_pass_sums), which merge as one render's would, so the filtered passes
    equal the single render's to float rounding and the id passes exactly; the denoiser runs
    once, here, on the merged image (the emitters seen sampled again here too, on this machine's
    CPU, as Scene.render(denoise=True) does)."""
    if not isinstance(scene, Scene):
        scene = Scene.load(scene)
    names = _pass_names(aovs)
    passes = _passes_to_render(names, denoise)
    spp, seed, max_depth = _render_counts(spp, seed, max_depth)
    crop = _crop(crop)
    spp = scene.spp if spp is None else spp
    ray = _connect(address)
    backend = _task_backend(ray, backend)
    options = _task_options(ray, cpus_per_task, max_retries, backend)
    threads = 0 if "num_gpus" in options else cpus_per_task
    task = ray.remote(_render_slice).options(**options)
    slices = split_samples(spp, chunks)
    refs = [task.remote(scene.spec, spp, seed, first, count, backend, threads, passes, max_depth,
                        crop)
            for first, count in slices]
    total = None  # of the image's size, or its crop's
    sums = None
    for (first, count), ref in zip(slices, refs):  # in range order, one part held at a time
        part = ray.get(ref)
        image = part if passes is None else part["image"]
        weighted = image.astype(np.float64) * count
        total = weighted if total is None else total + weighted
        if passes is not None:
            sums = _merge_into(sums, part["sums"])
    image = (total / spp).astype(np.float32)
    if passes is None:
        return image
    result = {"image": image}
    result.update(scene._core.passes_from_sums(sums, passes, crop=crop))
    if not denoise:
        return result
    # The emitters seen are sampled again here, as Scene.render does: camera rays alone, a small
    # part of the render's work (backends/seen_emitters.h).
    return _denoised(result, names, seen_emission=scene._core.seen_emitters(
        result["emission"], spp, seed, "auto", 0, crop=crop))
