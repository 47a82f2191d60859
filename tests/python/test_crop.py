"""A camera's "crop" (docs/scene-format.md, Crops) from Python: the render is that part of the
image, each pixel as the whole image's render has it, passes too; scene.camera says which part."""
import copy

import numpy as np
import pytest

import candela
from conftest import tiny_scene


def cropped(spec, crop):
    spec = copy.deepcopy(spec)
    spec["camera"]["crop"] = crop
    return spec


def test_a_crop_renders_the_whole_images_pixels_there():
    spec = tiny_scene(size=24)
    whole = candela.Scene.from_dict(spec).render(backend="cpu", aovs=["depth", "instance"])
    scene = candela.Scene.from_dict(cropped(spec, [5, 9, 11, 7]))
    crop = scene.render(backend="cpu", aovs=["depth", "instance"])
    for name in ("image", "depth", "instance"):
        assert crop[name].shape[:2] == (7, 11)
        np.testing.assert_array_equal(crop[name], whole[name][9:16, 5:16], err_msg=name)
    assert scene.camera["crop"] == (5, 9, 11, 7)
    assert (scene.width, scene.height) == (24, 24)  # the camera's image, of which the crop is part
    assert "crop" not in candela.Scene.from_dict(spec).camera


def test_a_crop_outside_the_image_is_refused_naming_it():
    with pytest.raises(ValueError, match=r"camera.crop: the crop \[20, 0, 8, 8\] reaches past "
                                         r"the 24 x 24 image"):
        candela.Scene.from_dict(cropped(tiny_scene(size=24), [20, 0, 8, 8]))


def test_render_takes_a_crop_as_the_cameras_crop_does():
    spec = tiny_scene(size=24)
    scene = candela.Scene.from_dict(spec)
    whole = scene.render(backend="cpu", aovs=["depth", "instance", "alpha"])
    crop = scene.render(backend="cpu", aovs=["depth", "instance", "alpha"], crop=(5, 9, 11, 7))
    by_camera = candela.Scene.from_dict(cropped(spec, [5, 9, 11, 7])).render(
        backend="cpu", aovs=["depth", "instance", "alpha"])
    for name in ("image", "depth", "instance", "alpha"):
        assert crop[name].shape[:2] == (7, 11), name
        np.testing.assert_array_equal(crop[name], whole[name][9:16, 5:16], err_msg=name)
        np.testing.assert_array_equal(crop[name], by_camera[name], err_msg=name)
    # The keyword replaces the scene's own crop, and leaves the scene as it was.
    again = candela.Scene.from_dict(cropped(spec, [0, 0, 4, 4])).render(backend="cpu",
                                                                        crop=(5, 9, 11, 7))
    np.testing.assert_array_equal(again, crop["image"])
    assert "crop" not in scene.camera
    assert scene.render(backend="cpu").shape == (24, 24, 3)


def test_render_refuses_a_crop_it_cannot_take_naming_it():
    scene = candela.Scene.from_dict(tiny_scene(size=24))
    with pytest.raises(ValueError, match=r"crop: the crop \[20, 0, 8, 8\] reaches past the "
                                         r"24 x 24 image"):
        scene.render(backend="cpu", crop=(20, 0, 8, 8))
    with pytest.raises(ValueError, match=r"crop: the crop \[0, 0, 0, 8\] is empty"):
        scene.render(backend="cpu", crop=[0, 0, 0, 8])
    with pytest.raises(TypeError, match=r"crop must be \(x, y, width, height\)"):
        scene.render(backend="cpu", crop=(1, 2, 3))
    with pytest.raises(TypeError, match=r"crop's width must be an integer"):
        scene.render(backend="cpu", crop=(1, 2, 3.5, 4))
    with pytest.raises(ValueError, match=r"crop's x must be in \[0, "):
        scene.render(backend="cpu", crop=(-1, 2, 3, 4))
