"""scene.render(aovs=[...]): a dict of the image and the passes (docs/aovs.md)."""
import numpy as np
import pytest

import candela

# A grey unit sphere 5 before the camera; the centre pixel of the 15x15 image is on its axis.
SCENE = {
    "camera": {"width": 15, "height": 15, "fov": 30, "spp": 4, "position": [0, 0, 5]},
    "render": {"antialiasing": False},
    "spheres": [{"position": [0, 0, 0], "radius": 1, "color": 0.5}],
    "lights": [{"position": [0, 3, 3], "intensity": 100}],
}


def test_aovs_return_a_dict_of_arrays_and_leave_the_image_alone():
    scene = candela.Scene.from_dict(SCENE)
    plain = scene.render(backend="cpu")
    assert isinstance(plain, np.ndarray)  # without aovs the return type is unchanged
    res = scene.render(backend="cpu", aovs=["depth", "normal", "albedo", "instance", "material"])
    assert set(res) == {"image", "depth", "normal", "albedo", "instance", "material"}
    np.testing.assert_array_equal(res["image"], plain)
    assert res["depth"].shape == (15, 15) and res["depth"].dtype == np.float32
    assert res["normal"].shape == (15, 15, 3)
    assert res["instance"].dtype == np.uint32 and res["instance"].shape == (15, 15)
    assert res["depth"][7, 7] == pytest.approx(4.0, abs=1e-5)
    np.testing.assert_allclose(res["normal"][7, 7], [0, 0, 1], atol=1e-6)
    np.testing.assert_allclose(res["albedo"][7, 7], [0.5, 0.5, 0.5])
    assert res["instance"][7, 7] == 1 and res["material"][7, 7] == 1
    assert np.isinf(res["depth"][0, 0]) and res["instance"][0, 0] == 0


def test_unknown_aov_is_a_value_error_naming_the_known_ones():
    with pytest.raises(ValueError, match='unknown render pass "nromal"; the passes are: depth'):
        candela.Scene.from_dict(SCENE).render(aovs=["nromal"])


def test_flow_of_an_animated_frame_is_an_h_w_2_array_in_pixels():
    # The sphere moves right by 0.25 a frame: the centre pixel's point, 4 from the camera in
    # frame 0, moves f 0.25 / 4 pixels right; the background stays.
    moving = dict(SCENE)
    moving["spheres"] = [dict(SCENE["spheres"][0], id="ball")]
    moving["animation"] = {"frames": 3, "tracks": [
        {"target": "ball", "property": "position", "keys": [[0, [0, 0, 0]], [2, [0.5, 0, 0]]]}]}
    res = candela.Scene.from_dict(moving).frame(0).render(backend="cpu", aovs=["flow"])
    assert res["flow"].shape == (15, 15, 2) and res["flow"].dtype == np.float32
    f = 7.5 / np.tan(np.radians(15))
    np.testing.assert_allclose(res["flow"][7, 7], [f * 0.25 / 4, 0], atol=1e-4)
    np.testing.assert_array_equal(res["flow"][0, 0], [0, 0])
    # A still scene does not move at all.
    still = candela.Scene.from_dict(SCENE).render(backend="cpu", aovs=["flow"])
    assert not still["flow"].any()
