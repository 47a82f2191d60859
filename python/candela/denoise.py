"""Denoising with Intel Open Image Denoise (PyPI `pyoidn`), guided by the albedo and normal passes.

    img = scene.render(spp=16, denoise=True)

OIDN's "RT" filter takes the noisy HDR radiance with the first non-specular surface's albedo and
its world-space normal (docs/aovs.md), which keep edges and textures that the noise would blur.
"""
from __future__ import annotations

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


def denoise(image: np.ndarray, albedo: np.ndarray, normal: np.ndarray) -> np.ndarray:
    """The denoised (H, W, 3) float32 radiance of `image`, guided by `albedo` and `normal`.

    The guides come from the same samples as the image, so they carry some noise of their own
    (antialiasing, depth of field, glossy paths): OIDN prefilters them (clean_aux false)."""
    pyoidn = _oidn()
    colour = np.ascontiguousarray(image, dtype=np.float32)
    albedo = np.ascontiguousarray(np.clip(albedo, 0.0, 1.0), dtype=np.float32)
    normal = np.ascontiguousarray(np.clip(normal, -1.0, 1.0), dtype=np.float32)
    return np.asarray(pyoidn.denoise(colour, albedo, normal, hdr=True), dtype=np.float32)
