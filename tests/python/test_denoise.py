"""scene.render(denoise=True): Open Image Denoise guided by the albedo and normal passes."""
import sys

import numpy as np
import pytest

import candela
from conftest import tiny_scene

pyoidn = pytest.importorskip("pyoidn", reason="pyoidn (Open Image Denoise) is not installed")


def relmse(image, reference):
    return float(np.mean((image - reference) ** 2 / (reference ** 2 + 1e-2)))


def test_denoised_low_spp_is_closer_to_the_reference_than_the_raw_render():
    scene = candela.Scene.from_dict(tiny_scene(size=64))
    reference = scene.render(spp=1024, seed=1)
    raw = scene.render(spp=4, seed=2)
    clean = scene.render(spp=4, seed=2, denoise=True)
    assert clean.shape == raw.shape and clean.dtype == np.float32
    assert np.all(np.isfinite(clean))
    assert relmse(clean, reference) < 0.5 * relmse(raw, reference)


def test_with_aovs_the_noisy_image_and_the_asked_passes_come_back():
    scene = candela.Scene.from_dict(tiny_scene(size=32))
    result = scene.render(spp=4, seed=3, aovs=["depth"], denoise=True)
    assert set(result) == {"image", "noisy", "depth"}
    np.testing.assert_array_equal(result["noisy"], scene.render(spp=4, seed=3))
    assert not np.array_equal(result["image"], result["noisy"])


def test_a_missing_denoiser_is_named_before_rendering(monkeypatch):
    monkeypatch.setitem(sys.modules, "pyoidn", None)  # import pyoidn now raises ImportError
    scene = candela.Scene.from_dict(tiny_scene(size=8))
    with pytest.raises(RuntimeError, match="pip install pyoidn"):
        scene.render(spp=1, denoise=True)
