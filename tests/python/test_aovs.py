"""scene.render(aovs=[...]): a dict of the image and the passes (docs/aovs.md)."""
import numpy as np
import pytest

import candela
from conftest import animated_scene, tiny_scene

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


ALL_PASSES = ["depth", "distance", "normal", "normal_camera", "albedo", "position", "instance",
              "material", "flow", "direct", "emission"]


@pytest.mark.parametrize("animated", [True, False], ids=["animation frame", "still scene"])
def test_pass_sums_of_sample_ranges_merge_into_the_passes_of_one_render(animated):
    # What candela.distributed.render_image does with its chunks, without Ray: frame 1 of an
    # animated scene (flow is defined) or a still scene, antialiased, so the edge pixels' ids
    # depend on which sample lies nearest the pixel centre.
    from candela.distributed import _render_slice, merge_pass_sums, split_samples

    scene = (candela.Scene.from_dict(animated_scene(frames=3, size=24)).frame(1) if animated
             else candela.Scene.from_dict(tiny_scene()))
    whole = scene.render(spp=10, backend="cpu", aovs=ALL_PASSES)
    parts = [_render_slice(scene.spec, 10, None, first, count, "cpu", 0, ALL_PASSES)
             for first, count in split_samples(10, 3)]
    merged = scene._core.passes_from_sums(merge_pass_sums([p["sums"] for p in parts]),
                                          ALL_PASSES)
    assert set(merged) == set(ALL_PASSES)
    for name in ("instance", "material"):
        np.testing.assert_array_equal(merged[name], whole[name], err_msg=name)
    assert len(np.unique(whole["instance"])) == 3  # ground, ball and background
    for name in ALL_PASSES:
        if name not in ("instance", "material"):
            np.testing.assert_allclose(merged[name], whole[name], rtol=1e-5, atol=1e-5,
                                       err_msg=name)
    # Sums that lack a field are refused, naming it.
    with pytest.raises(ValueError, match="nearest_material"):
        del parts[0]["sums"]["nearest_material"]
        scene._core.passes_from_sums(parts[0]["sums"], ["instance"])


def test_instances_name_the_numbers_of_the_instance_pass():
    scene = candela.Scene.from_dict(tiny_scene())  # ground sphere, "ball", one point light
    assert scene.instances == {1: "spheres[0]", 2: "ball", 3: "lights[0]"}
    ids = scene.render(spp=2, backend="cpu", aovs=["instance"])["instance"]
    assert set(np.unique(ids)) == {0, 1, 2}  # the background, the ground and the ball
    assert ids[7, 8] == 2  # beside the image's centre, on the ball
