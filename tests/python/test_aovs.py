"""scene.render(aovs=[...]): a dict of the image and the passes (docs/aovs.md); scene.camera."""
import json
import subprocess
import sys

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
    # Backward: frame 1's centre pixel sees the sphere 0.25 off the axis, a point 5 - sqrt(1 -
    # 0.25^2) away that stood 0.25 to its left in frame 0; frame 0 has no frame before it.
    anim = candela.Scene.from_dict(moving)
    back = anim.frame(1).render(backend="cpu", aovs=["backward_flow", "flow"])
    assert back["backward_flow"].shape == (15, 15, 2)
    depth = 5 - np.sqrt(1 - 0.25**2)
    np.testing.assert_allclose(back["backward_flow"][7, 7], [-f * 0.25 / depth, 0], atol=1e-4)
    np.testing.assert_allclose(back["flow"][7, 7], [f * 0.25 / depth, 0], atol=1e-4)
    assert not anim.frame(0).render(backend="cpu", aovs=["backward_flow"])["backward_flow"].any()


ALL_PASSES = ["depth", "distance", "normal", "normal_camera", "albedo", "position", "instance",
              "material", "flow", "backward_flow", "direct", "emission", "alpha", "uv",
              "object_coordinates"]


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


def test_camera_projects_each_pixels_first_hit_onto_its_centre():
    # The camera's matrices (docs/aovs.md, The camera file) against the renderer's own rays:
    # without antialiasing every sample passes through its pixel's centre, so K (R p + t) of the
    # position pass lands on (x + 0.5, y + 0.5), for a look-at camera with non-square intrinsics.
    spec = tiny_scene(spp=1, size=24)
    spec["camera"] = {"width": 24, "height": 18, "intrinsics": {"fx": 20, "fy": 26, "cx": 11, "cy": 9.5},
                      "position": [1.5, 2, 5], "look_at": [0, 0.5, 0], "spp": 1}
    spec["render"]["antialiasing"] = False
    scene = candela.Scene.from_dict(spec)
    camera = scene.camera
    assert (camera["width"], camera["height"]) == (24, 18) and "aperture_radius" not in camera
    K, E = camera["intrinsics"], camera["extrinsics"]
    assert K.dtype == np.float64 and K.shape == (3, 3) and E.shape == (4, 4)
    np.testing.assert_array_equal(K, [[20, 0, 11], [0, 26, 9.5], [0, 0, 1]])
    np.testing.assert_array_equal(E[3], [0, 0, 0, 1])
    R, t = E[:3, :3], E[:3, 3]
    np.testing.assert_allclose(R @ R.T, np.eye(3), atol=1e-6)
    np.testing.assert_allclose(-R.T @ t, [1.5, 2, 5], atol=1e-5)  # the camera's centre
    position = scene.render(backend="cpu", aovs=["position"])["position"].astype(np.float64)
    hit = np.isfinite(position).all(axis=2) & (np.abs(position).sum(axis=2) > 0)
    assert hit.mean() > 0.7  # the rest is sky
    p = (position @ R.T + t) @ K.T
    uv = p[..., :2] / p[..., 2:]
    y, x = np.mgrid[0:18, 0:24]
    np.testing.assert_allclose(uv[hit], np.stack([x + 0.5, y + 0.5], axis=-1)[hit], atol=2e-3)


def test_camera_given_back_renders_the_same_image_and_follows_the_animation():
    spec = animated_scene(frames=3, spp=2)
    spec["animation"]["tracks"].append(
        {"target": "camera", "property": "position", "keys": [[0, [0, 1.5, 6]], [2, [2, 1.5, 6]]]})
    scene = candela.Scene.from_dict(spec)
    for k in range(3):
        frame = scene.frame(k)
        camera = frame.camera
        np.testing.assert_allclose(-camera["extrinsics"][:3, :3].T @ camera["extrinsics"][:3, 3],
                                   [k, 1.5, 6], atol=1e-5)
        still = tiny_scene(spp=2)
        still["spheres"][1]["position"] = [-1 + k, 0.5, 0]
        still["render"]["seed"] = frame.seed
        still["camera"] = dict(camera, spp=2)  # its numpy matrices as they come
        again = candela.Scene.from_dict(still).render(backend="cpu")
        image = frame.render(backend="cpu")
        # Equal up to rounding: the camera's centre comes back as -R^T t.
        assert np.abs(again - image).max() <= 1e-5 * image.max()


def test_camera_is_what_the_cli_writes_beside_each_frame(tmp_path):
    spec = animated_scene(frames=2, spp=1)
    spec["animation"]["tracks"].append(
        {"target": "camera", "property": "position", "keys": [[0, [0, 1.5, 6]], [1, [0.5, 1, 6]]]})
    path = tmp_path / "anim.json"
    path.write_text(json.dumps(spec))
    cli = subprocess.run([sys.executable, "-m", "candela", "render", str(path), "-q", "--aov", "camera",
                          "-o", str(tmp_path / "f") + "/"], capture_output=True, text=True)
    assert cli.returncode == 0, cli.stderr
    scene = candela.Scene.load(path)
    for k in range(2):
        written = json.loads((tmp_path / "f" / f"frame_000{k}.camera.json").read_text())
        camera = scene.frame(k).camera
        assert written.keys() == camera.keys()
        for key in ("intrinsics", "extrinsics"):  # the file holds the float32 values' shortest text
            np.testing.assert_array_equal(np.float32(written[key]), np.float32(camera[key]))


def test_camera_among_the_passes_points_to_the_property():
    with pytest.raises(ValueError, match=r"scene.camera \(or scene.frame\(k\).camera\)"):
        candela.Scene.from_dict(SCENE).render(aovs=["depth", "camera"])


def test_thin_lens_camera_reports_its_lens():
    spec = tiny_scene()
    spec["camera"].update(aperture_radius=0.1, focus_distance=5.5)
    camera = candela.Scene.from_dict(spec).camera
    assert camera["aperture_radius"] == pytest.approx(0.1) and camera["focus_distance"] == 5.5


def test_distorted_camera_reports_its_lens_and_renders_the_same_image_given_back():
    spec = tiny_scene(spp=2)
    spec["camera"]["distortion"] = [-0.12, 0.03, 0.001, -0.0005, 0.002]
    scene = candela.Scene.from_dict(spec)
    camera = scene.camera
    assert camera["distortion"] == pytest.approx(spec["camera"]["distortion"])
    again = dict(spec, camera=dict(camera, spp=2))
    image = scene.render(backend="cpu")
    assert np.abs(candela.Scene.from_dict(again).render(backend="cpu") - image).max() <= 1e-5 * image.max()
    # The lens changes the picture: without it the same camera renders another image.
    del again["camera"]["distortion"]
    assert np.abs(candela.Scene.from_dict(again).render(backend="cpu") - image).max() > 0.01 * image.max()


def test_panorama_camera_names_its_projection_and_renders_the_same_image_given_back():
    spec = tiny_scene(spp=2)
    spec["camera"] = {"width": 32, "height": 16, "projection": "equirectangular",
                      "position": [0, 1, 4], "look_at": [0, 0.5, 0], "spp": 2}
    scene = candela.Scene.from_dict(spec)
    camera = scene.camera
    assert camera["projection"] == "equirectangular" and "intrinsics" not in camera
    image = scene.render(backend="cpu")
    again = candela.Scene.from_dict(dict(spec, camera=dict(camera, spp=2))).render(backend="cpu")
    assert np.abs(again - image).max() <= 1e-5 * image.max()


def test_poses_map_what_each_pixel_sees_back_onto_its_instances_model(tmp_path):
    # An independent check of the poses (docs/aovs.md, Instance poses): the position pass of each
    # pixel, taken back through its instance's object_to_world, must lie on that instance's model
    # (the unit sphere; the OBJ's square in z = 0), in every frame of an animation that turns,
    # scales and moves them; object_to_camera is the camera's extrinsics times object_to_world.
    (tmp_path / "square.obj").write_text("v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n")
    spec = {
        "camera": {"width": 32, "height": 24, "fov": 50, "position": [0.5, 1, 7], "look_at": [0, 0, 0], "spp": 1},
        "render": {"antialiasing": False},
        "spheres": [{"id": "ball", "position": [-1, 0, 0], "radius": 0.8}],
        "objects": [{"id": "card", "file": "square.obj", "position": [1.2, 0.2, 0.5],
                     "rotation": [20, -30, 10], "scale": [0.9, 1.3, 1]}],
        "lights": [{"position": [0, 4, 4], "intensity": 300}],
        "animation": {"frames": 2, "tracks": [
            {"target": "card", "property": "rotation", "keys": [[0, [20, -30, 10]], [1, [-10, 40, 0]]]},
            {"target": "ball", "property": "radius", "keys": [[0, 0.8], [1, 0.6]]}]},
    }
    (tmp_path / "s.json").write_text(json.dumps(spec))
    scene = candela.Scene.load(tmp_path / "s.json")
    for k in range(2):
        frame = scene.frame(k)
        poses, extrinsics = frame.poses, frame.camera["extrinsics"]
        assert sorted(poses) == [1, 2, 3]
        assert [poses[n]["name"] for n in (1, 2, 3)] == ["ball", "card", "lights[0]"]
        np.testing.assert_allclose(poses[3]["object_to_world"][:3, 3], [0, 4, 4])
        res = frame.render(backend="cpu", aovs=["position", "instance"])
        for number, on_model in ((1, lambda q: np.linalg.norm(q, axis=1) - 1),
                                 (2, lambda q: q[:, 2])):
            world = poses[number]["object_to_world"]
            np.testing.assert_allclose(poses[number]["object_to_camera"], extrinsics @ world,
                                       rtol=1e-6, atol=1e-5)
            seen = res["position"][res["instance"] == number].astype(np.float64)
            assert len(seen) > 20
            q = (seen - world[:3, 3]) @ np.linalg.inv(world[:3, :3]).T
            np.testing.assert_allclose(on_model(q), 0, atol=2e-4)
            if number == 2:
                assert np.abs(q[:, :2]).max() <= 1 + 1e-4


def test_object_coordinates_through_the_model_box_and_pose_land_where_the_pixel_looked(tmp_path):
    # docs/aovs.md's 2D-3D correspondence: lo + c * (hi - lo) over the pose's model_box is the
    # model's point, and object_to_world takes it to what the position pass saw, for a mesh off
    # its file's origin (turned and scaled) and a sphere; a point light has no box.
    (tmp_path / "block.obj").write_text(
        "v 1 -2 0.5\nv 3 -2 0.5\nv 3 0 0.5\nv 1 0 0.5\nv 1 -2 1.5\nv 3 -2 1.5\nv 3 0 1.5\n"
        "v 1 0 1.5\nf 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n")
    spec = {
        "camera": {"width": 40, "height": 30, "fov": 70, "position": [0, 0, 0],
                   "look_at": [0, 0, -1], "spp": 1},
        "render": {"antialiasing": False},
        "spheres": [{"id": "ball", "position": [2.5, -1, -9], "radius": 1.5}],
        "objects": [{"id": "block", "file": "block.obj", "position": [-5, 1.5, -9],
                     "rotation": [25, 40, -15], "scale": [1.5, 0.8, 1.2]}],
        "lights": [{"position": [0, 4, 4], "intensity": 300}],
    }
    scene = candela.Scene.from_dict(spec, base_dir=tmp_path)
    poses = scene.poses
    np.testing.assert_array_equal(poses[2]["model_box"], [[1, -2, 0.5], [3, 0, 1.5]])
    np.testing.assert_array_equal(poses[1]["model_box"], [[-1, -1, -1], [1, 1, 1]])
    assert "model_box" not in poses[3]
    res = scene.render(backend="cpu", aovs=["position", "instance", "object_coordinates"])
    for number in (1, 2):
        lo, hi = poses[number]["model_box"]
        hit = res["instance"] == number
        assert hit.sum() > 15
        model = lo + res["object_coordinates"][hit].astype(np.float64) * (hi - lo)
        world = poses[number]["object_to_world"]
        np.testing.assert_allclose(model @ world[:3, :3].T + world[:3, 3],
                                   res["position"][hit], atol=2e-3)


def test_alpha_is_the_share_of_samples_that_saw_something_and_goes_into_the_file(tmp_path):
    # An emitter of radiance 1 over nothing (no environment): the image is its alpha, and the
    # antialiased edge pixels lie between 0 and 1; sample ranges merge into the same alpha.
    from candela.distributed import _render_slice, merge_pass_sums, split_samples

    spec = dict(SCENE, render={"antialiasing": True}, lights=[])
    spec["spheres"] = [{"position": [0, 0, 0], "radius": 1,
                        "material": {"type": "emissive", "radiance": 1}}]
    scene = candela.Scene.from_dict(spec)
    res = scene.render(spp=16, backend="cpu", aovs=["alpha"])
    alpha = res["alpha"]
    assert alpha.shape == (15, 15) and alpha.dtype == np.float32
    np.testing.assert_allclose(res["image"][..., 0], alpha, atol=1e-6)
    assert alpha[7, 7] == 1 and alpha[0, 0] == 0 and ((alpha > 0) & (alpha < 1)).any()
    parts = [_render_slice(scene.spec, 16, None, first, count, "cpu", 0, ["alpha"])
             for first, count in split_samples(16, 3)]
    merged = scene._core.passes_from_sums(merge_pass_sums([p["sums"] for p in parts]), ["alpha"])
    np.testing.assert_allclose(merged["alpha"], alpha, atol=1e-6)

    candela.write_image(tmp_path / "cut.png", res["image"], alpha=alpha)
    header = (tmp_path / "cut.png").read_bytes()[:26]
    assert header[25] == 6  # the IHDR's colour type: RGBA
    candela.write_image(tmp_path / "plain.png", res["image"])
    assert (tmp_path / "plain.png").read_bytes()[25] == 2  # RGB
    with pytest.raises(ValueError, match="alpha of the image's shape"):
        candela.write_image(tmp_path / "bad.png", res["image"], alpha=alpha[:, :3])
    with pytest.raises(Exception, match="a .pfm has no alpha channel"):
        candela.write_image(tmp_path / "cut.pfm", res["image"], alpha=alpha)


def test_uv_is_the_first_hits_texture_coordinates(tmp_path):
    # A quad whose corners' uvs run from (0, 0) to (1, 1), seen whole and head-on, under a plain
    # colour that reads no uvs: the pass keeps them and shows the coordinates through each pixel.
    (tmp_path / "quad.obj").write_text("v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
                                       "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3 4/4\n")
    scene = candela.Scene.from_dict({
        "camera": {"width": 16, "height": 16, "position": [0, 0, 5], "spp": 1,
                   "projection": "orthographic", "view_width": 2},
        "render": {"antialiasing": False},
        "objects": [{"file": "quad.obj", "color": 0.5}],
        "lights": [{"position": [0, 0, 3], "intensity": 10}]}, base_dir=tmp_path)
    uv = scene.render(backend="cpu", aovs=["uv"])["uv"]
    assert uv.shape == (16, 16, 2) and uv.dtype == np.float32
    centres = (np.arange(16) + 0.5) / 16
    np.testing.assert_allclose(uv[..., 0], np.tile(centres, (16, 1)), atol=1e-5)
    np.testing.assert_allclose(uv[..., 1], np.tile(centres[::-1, None], (1, 16)), atol=1e-5)


def test_object_coordinates_stay_on_the_object_wherever_it_moves(tmp_path):
    # The same quad, moved and scaled between two frames: each pixel's coordinates are its
    # point taken back into the quad's file and over its box, whatever the frame's placement.
    (tmp_path / "quad.obj").write_text("v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n")
    scene = candela.Scene.from_dict({
        "camera": {"width": 16, "height": 16, "position": [0, 0, 5], "spp": 1,
                   "projection": "orthographic", "view_width": 4},
        "render": {"antialiasing": False},
        "objects": [{"id": "quad", "file": "quad.obj", "color": 0.5}],
        "animation": {"frames": 2, "tracks": [
            {"target": "quad", "property": "position", "keys": [[0, [0, 0, 0]], [1, [1, 0, 0]]]},
            {"target": "quad", "property": "scale", "keys": [[0, 1], [1, 0.5]]}]}},
        base_dir=tmp_path)
    first = scene.frame(0).render(backend="cpu", aovs=["object_coordinates"])
    second = scene.frame(1).render(backend="cpu", aovs=["object_coordinates"])
    assert first["object_coordinates"].shape == (16, 16, 3)
    # Pixel centres at x = -1.875 + 0.25 i: frame 0's quad spans pixels 4-11, frame 1's 10-13;
    # pixel 12's point, x = 1.125, lies outside frame 0's quad (the background's 0), and at
    # (1.125 - 1) / 0.5 = 0.25 in frame 1's, (0.25 + 1) / 2 = 0.625 over its box.
    oc0, oc1 = first["object_coordinates"], second["object_coordinates"]
    np.testing.assert_allclose(oc0[8, 4:12, 0], (np.arange(4, 12) * 0.25 - 1.875 + 1) / 2,
                               atol=1e-5)
    np.testing.assert_allclose(oc1[8, 10:14, 0], ((np.arange(10, 14) * 0.25 - 1.875 - 1) / 0.5
                                                  + 1) / 2, atol=1e-5)
    assert oc0[8, 12].tolist() == [0, 0, 0]
    np.testing.assert_allclose(oc1[8, 12], [0.625, oc1[8, 12, 1], 0.5], atol=1e-5)

