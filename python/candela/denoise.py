"""Denoising with Intel Open Image Denoise (PyPI `pyoidn`), guided by the albedo and normal passes.

    img = scene.render(spp=16, denoise=True)

OIDN's "RT" filter takes the noisy HDR radiance with the first non-specular surface's albedo and
its world-space normal (docs/aovs.md), which keep edges and textures that the noise would blur;
the direct light (the "direct" pass, less the emitters seen, "emission") and the rest are
filtered apart.
"""
from __future__ import annotations

import threading
from typing import Optional

import numpy as np


class DenoiserUnavailable(RuntimeError):
    """Raised by denoise=True where Open Image Denoise is not installed."""


def _oidn():
    try:
        import pyoidn  # noqa: PLC0415  (optional: only denoising needs it)
    except ImportError as error:
        raise DenoiserUnavailable(
            "denoise=True needs Intel Open Image Denoise: pip install pyoidn") from error
    return pyoidn


_lock = threading.Lock()
_devices = {}


def _cpu_device(pyoidn, threads: int = 0):
    """The process's OIDN CPU device (numpy arrays live in host memory) of at most `threads`
    threads, 0 for all cores: one per thread count, since a device takes it once."""
    if threads not in _devices:
        device = pyoidn.Device(pyoidn.OIDN_DEVICE_TYPE_CPU)
        if threads > 0:
            device.set_int("numThreads", threads)
        device.commit()
        _devices[threads] = device
    return _devices[threads]


def _run(pyoidn, inputs: dict, hdr: bool = False, clean_aux: bool = False,
         threads: int = 0) -> np.ndarray:
    """One "RT" filter over `inputs` (OIDN image name -> (H, W, 3) float32 array)."""
    output = np.empty_like(next(iter(inputs.values())))
    filt = pyoidn.Filter(_cpu_device(pyoidn, threads), pyoidn.OIDN_FILTER_TYPE_RT)
    try:
        for name, pixels in inputs.items():
            filt.set_image(name, pixels, pyoidn.OIDN_FORMAT_FLOAT3)
        filt.set_image(pyoidn.OIDN_IMAGE_OUTPUT, output, pyoidn.OIDN_FORMAT_FLOAT3)
        if hdr:
            filt.set_bool("hdr", True)
        if clean_aux:
            filt.set_bool("cleanAux", True)
        filt.commit()
        filt.execute()
    finally:
        filt.release()
    return output


def denoise(image: np.ndarray, albedo: np.ndarray, normal: np.ndarray,
            direct: Optional[np.ndarray] = None, emission: Optional[np.ndarray] = None,
            threads: int = 0) -> np.ndarray:
    """The denoised (H, W, 3) float32 radiance of `image`, guided by `albedo` and `normal`, on at
    most `threads` CPU threads (0: all cores). With `direct`, the image's direct light pass, the
    direct light and the rest (image - direct) are filtered apart and added, as
    `scene.render(denoise=True)` and `candela render --denoise` do: the direct light is far less
    noisy, and filtered alone it keeps its detail. With `emission` too, the emitters the image
    shows are left out of the direct light's filter and added as they are: they carry no noise
    but their edges', and their radiance, far above the rest, would spread into it
    (docs/performance.md, Denoising).

    The guides come from the same samples as the image and carry a little noise of their own
    (antialiased edges, depth of field, what glass and mirrors show): each is denoised first and
    the image then filtered with clean guides, as OIDN's documentation recommends."""
    pyoidn = _oidn()
    contiguous = lambda a: np.ascontiguousarray(a, dtype=np.float32)  # noqa: E731
    colour = contiguous(image)
    shown = 0.0 if emission is None else contiguous(emission)
    parts = ([colour] if direct is None else
             [contiguous(direct) - shown, colour - contiguous(direct)])
    with _lock:
        albedo = _run(pyoidn, {pyoidn.OIDN_IMAGE_ALBEDO: contiguous(np.clip(albedo, 0.0, 1.0))},
                      threads=threads)
        normal = _run(pyoidn, {pyoidn.OIDN_IMAGE_NORMAL: contiguous(np.clip(normal, -1.0, 1.0))},
                      threads=threads)
        filtered = [_run(pyoidn, {pyoidn.OIDN_IMAGE_COLOR: part, pyoidn.OIDN_IMAGE_ALBEDO: albedo,
                                  pyoidn.OIDN_IMAGE_NORMAL: normal}, hdr=True, clean_aux=True,
                         threads=threads) for part in parts]
        return filtered[0] if direct is None else filtered[0] + filtered[1] + shown
