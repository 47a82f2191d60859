"""Motion blur through the Python API: a frame of a moving camera under an open shutter
(docs/scene-format.md, *Motion blur*)."""
import numpy as np
import pytest

import candela


def sliding(shutter=None, to=1.0):
    """A camera sliding along x from -1 (frame 0) to `to` (frame 1) before a lit sphere."""
    animation = {"frames": 2, "tracks": [
        {"target": "camera", "property": "position", "keys": [[0, [-1, 0, 0]], [1, [to, 0, 0]]]}]}
    if shutter is not None:
        animation["shutter"] = shutter
    return {
        "camera": {"width": 24, "height": 16, "fov": 40, "spp": 16},
        "spheres": [{"position": [0, 0, -5], "radius": 1, "color": 0.6}],
        "lights": [{"position": [0, 4, 0], "intensity": 60}],
        "animation": animation,
    }


def test_open_shutter_blurs_a_moving_camera_and_not_a_still_one():
    closed = candela.Scene.from_dict(sliding()).frame(0).render(backend="cpu")
    blurred = candela.Scene.from_dict(sliding([0, 1])).frame(0).render(backend="cpu")
    # The sphere sweeps right to left across the image during the exposure: the blurred frame
    # spreads its light over more columns than the sharp one.
    lit = lambda image: int((image.sum(axis=(0, 2)) > 1e-3 * image.sum()).sum())  # noqa: E731
    assert lit(blurred) > lit(closed) + 2
    still = lambda shutter: candela.Scene.from_dict(sliding(shutter, to=-1)).frame(0).render(  # noqa: E731
        backend="cpu")
    np.testing.assert_array_equal(still([0, 1]), still(None))


def test_blurred_samples_merge_over_sample_ranges_as_one_render():
    scene = candela.Scene.from_dict(sliding(0.5)).frame(1)
    whole = scene.render(spp=12, backend="cpu")
    first = scene.render(spp=12, backend="cpu", sample_range=(0, 5))
    rest = scene.render(spp=12, backend="cpu", sample_range=(5, 7))
    np.testing.assert_allclose((5 * first + 7 * rest) / 12, whole, rtol=1e-5, atol=1e-6)


def test_bad_shutter_is_a_value_error_naming_the_path():
    with pytest.raises(ValueError, match=r"animation\.shutter: expected \[open, close\]"):
        candela.Scene.from_dict(sliding([0.5, 0.2]))


def moving_sphere(shutter=None):
    """A camera holding still before a lit sphere that slides along x from -1 (frame 0) to 1."""
    animation = {"frames": 2, "tracks": [
        {"target": "ball", "property": "position", "keys": [[0, [-1, 0, -5]], [1, [1, 0, -5]]]}]}
    if shutter is not None:
        animation["shutter"] = shutter
    return {
        "camera": {"width": 24, "height": 16, "fov": 40, "spp": 16},
        "spheres": [{"id": "ball", "position": [0, 0, -5], "radius": 1, "color": 0.6}],
        "lights": [{"position": [0, 4, 0], "intensity": 60}],
        "animation": animation,
    }


def test_open_shutter_blurs_a_moving_sphere_and_its_samples_merge():
    lit = lambda image: int((image.sum(axis=(0, 2)) > 1e-3 * image.sum()).sum())  # noqa: E731
    closed = candela.Scene.from_dict(moving_sphere()).frame(0).render(backend="cpu")
    scene = candela.Scene.from_dict(moving_sphere([0, 1])).frame(0)
    blurred = scene.render(backend="cpu")
    assert lit(blurred) > lit(closed) + 2
    first = scene.render(backend="cpu", sample_range=(0, 6))
    rest = scene.render(backend="cpu", sample_range=(6, 10))
    np.testing.assert_allclose((6 * first + 10 * rest) / 16, blurred, rtol=1e-5, atol=1e-6)
