"""Denoising with Intel Open Image Denoise (PyPI `pyoidn`), guided by the albedo and normal passes.

    img = scene.render(spp=16, denoise=True)

OIDN's "RT" filter takes the noisy HDR radiance with the first non-specular surface's albedo and
its world-space normal (docs/aovs.md), which keep edges and textures that the noise would blur;
the direct light (the "direct" pass, less the emitters seen, "emission") and the rest are
filtered apart. pyoidn provides the library; the filtering is the C++ behind `candela render
--denoise` (src/apps/denoise/oidn_denoiser.h), on OIDN's CPU device.
"""
from __future__ import annotations

import os
from typing import Optional

import numpy as np

from . import _candela


class DenoiserUnavailable(RuntimeError):
    """Raised by denoise=True where Open Image Denoise is not installed."""


def _oidn():
    try:
        import pyoidn  # noqa: PLC0415  (optional: only denoising needs it)
    except ImportError as error:
        raise DenoiserUnavailable(
            "denoise=True needs Intel Open Image Denoise: pip install pyoidn") from error
    return pyoidn


def _library() -> str:
    """The Open Image Denoise library inside the pyoidn package, or "" to let candela look for it
    where `candela render --denoise` does (its layout may change)."""
    path = os.path.join(os.path.dirname(_oidn().__file__), "oidn", "lib",
                        "libOpenImageDenoise.so.2")
    return path if os.path.exists(path) else ""


def denoise(image: np.ndarray, albedo: np.ndarray, normal: np.ndarray,
            direct: Optional[np.ndarray] = None, emission: Optional[np.ndarray] = None,
            threads: int = 0, seen_emission: Optional[np.ndarray] = None) -> np.ndarray:
    """The denoised (H, W, 3) float32 radiance of `image`, guided by `albedo` and `normal`, on at
    most `threads` CPU threads (0: all cores). With `direct`, the image's direct light pass, the
    direct light and the rest (image - direct) are filtered apart and added, as
    `scene.render(denoise=True)` and `candela render --denoise` do: the direct light is far less
    noisy, and filtered alone it keeps its detail. With `emission` too, the emitters the image
    shows are left out of the direct light's filter and added as they are: they carry no noise
    but their edges', and their radiance, far above the rest, would spread into it
    (docs/performance.md, Denoising). `seen_emission`, where given, is what is added back in
    their place: the same emitters sampled again with more camera rays, as
    `scene.render(denoise=True)` does where the image shows emitters (their edges within a
    pixel are what no filter can place from few samples).

    The guides come from the same samples as the image and carry a little noise of their own
    (antialiased edges, depth of field, what glass and mirrors show): each is denoised first and
    the image then filtered with clean guides, as OIDN's documentation recommends."""
    def contiguous(a):
        if a is None:
            return None
        a = np.ascontiguousarray(a, dtype=np.float32)
        if a.ndim != 3 or a.shape[2] != 3:
            raise ValueError(f"denoise: expected images of shape (H, W, 3), got {a.shape}")
        return a
    return _candela.denoise(_library(), contiguous(image), contiguous(albedo), contiguous(normal),
                            contiguous(direct), contiguous(emission),
                            seen_emission=contiguous(seen_emission), threads=threads)
