"""The candela module without Ray: loading, errors, rendering, sample ranges, images."""
import os
import signal
import subprocess
import sys
import textwrap
import threading

import numpy as np
import pytest

import candela
from conftest import animated_scene, tiny_scene


def test_render_returns_float32_hwc(scene_dict):
    scene_dict["camera"]["width"] = 20  # non-square: rows are height
    img = candela.Scene.from_dict(scene_dict).render(spp=2, backend="cpu")
    assert img.dtype == np.float32 and img.shape == (16, 20, 3)
    assert img.flags["C_CONTIGUOUS"]
    assert np.isfinite(img).all() and img.max() > 0


def test_load_file_and_dict_render_the_same(scene_file, scene_dict):
    a = candela.Scene.load(scene_file).render(backend="cpu")
    b = candela.Scene.from_dict(scene_dict).render(backend="cpu")
    np.testing.assert_array_equal(a, b)


def test_spp_and_seed_override(scene_dict):
    scene = candela.Scene.from_dict(scene_dict)
    assert scene.spp == 4 and scene.seed == 3
    same = scene.render(spp=4, seed=3)
    np.testing.assert_array_equal(scene.render(), same)
    assert not np.array_equal(scene.render(seed=4), same)
    assert not np.array_equal(scene.render(spp=2), same)


def test_scene_error_carries_the_loader_message(scene_dict, tmp_path):
    scene_dict["spheres"][1]["radius"] = -1
    with pytest.raises(candela.SceneError) as err:
        candela.Scene.from_dict(scene_dict)
    assert isinstance(err.value, ValueError)
    assert str(err.value) == "<dict>: spheres[1].radius: expected a positive number, got -1"

    bad = tmp_path / "bad.json"
    bad.write_text('{"camera": {"width": 16,}}')
    with pytest.raises(candela.SceneError, match=r"bad\.json:1:\d+: invalid JSON"):
        candela.Scene.load(bad)
    with pytest.raises(candela.SceneError, match="missing.json"):
        candela.Scene.load(tmp_path / "missing.json")


def test_from_dict_takes_numpy_values_and_paths(tmp_path, scene_dict):
    (tmp_path / "tri.obj").write_text("v -1 0 -1\nv 1 0 -1\nv 0 1 -1\nf 1 2 3\n")
    scene_dict["objects"] = [{"file": "tri.obj", "position": [0, 0.2, 0]}]
    as_lists = candela.Scene.from_dict(scene_dict, base_dir=tmp_path).render(backend="cpu")
    scene_dict["camera"]["position"] = np.array([0, 1.5, 6], dtype=np.float32)
    scene_dict["camera"]["spp"] = np.int64(4)
    scene_dict["spheres"][1]["radius"] = np.float64(0.5)
    scene_dict["spheres"][1]["color"] = (np.float32(0.8), 0.3, 0.2)  # a tuple is an array
    scene_dict["objects"][0]["file"] = tmp_path / "tri.obj"  # a pathlib.Path
    scene_dict["objects"][0]["position"] = np.array([0.0, 0.2, 0.0])
    as_numpy = candela.Scene.from_dict(scene_dict, base_dir=tmp_path).render(backend="cpu")
    np.testing.assert_array_equal(as_numpy, as_lists)


@pytest.mark.parametrize("place, value, message", [
    (("camera", "position"), [0, 1.5, float("nan")],
     "<dict>: camera.position[2]: expected a finite number, got nan"),
    (("spheres", 1, "radius"), np.float32("inf"),
     "<dict>: spheres[1].radius: expected a finite number, got inf"),
    (("lights", 0, "color"), {1, 2, 3},
     "<dict>: lights[0].color: expected a JSON value (an object, array, string, number, "
     "boolean or null), got a value of type set"),
    (("environment",), {1: [0, 0, 0]},
     "<dict>: environment: expected an object whose keys are strings, got the key 1"),
])
def test_from_dict_names_a_value_json_cannot_hold(scene_dict, place, value, message):
    parent = scene_dict
    for key in place[:-1]:
        parent = parent[key]
    parent[place[-1]] = value
    with pytest.raises(candela.SceneError) as err:
        candela.Scene.from_dict(scene_dict)
    assert str(err.value) == message


def test_max_depth_overrides_the_scenes_as_the_cli_does(scene_dict):
    scene_dict["render"]["light_paths"] = "off"  # so that depth 1 cuts the same paths short
    scene = candela.Scene.from_dict(scene_dict)  # max_depth 4
    direct_only = scene.render(max_depth=1, backend="cpu")
    scene_dict["render"]["max_depth"] = 1
    np.testing.assert_array_equal(direct_only,
                                  candela.Scene.from_dict(scene_dict).render(backend="cpu"))
    full = scene.render(backend="cpu")  # the override held for that render alone
    # The same samples cut short: light bounced off the floor and the ball is lost, none gained.
    assert (direct_only <= full + 1e-6).all() and direct_only.sum() < 0.999 * full.sum()
    with pytest.raises(ValueError, match=r"max_depth must be in \[1, 4294967295\], got 0"):
        scene.render(max_depth=0)


def test_counts_out_of_range_or_not_whole_are_named(scene_dict):
    scene = candela.Scene.from_dict(scene_dict)
    with pytest.raises(ValueError, match=r"^spp must be in \[1, 4294967295\], got 1099511627776$"):
        scene.render(spp=2**40)
    with pytest.raises(ValueError, match=r"^seed must be in \[0, 18446744073709551615\], got -1$"):
        scene.render(seed=-1)
    with pytest.raises(TypeError, match=r"^spp must be an integer, got float 4\.5$"):
        scene.render(spp=4.5)
    with pytest.raises(TypeError, match="threads must be an integer"):
        scene.render(threads="all")
    np.testing.assert_array_equal(scene.render(spp=np.int32(4), seed=np.uint64(3)),
                                  scene.render(spp=4, seed=3))


def test_material_warnings_are_user_warnings_and_the_scene_renders(tmp_path, scene_dict):
    (tmp_path / "m.obj").write_text("mtllib gone.mtl\nv -1 -1 0\nv 1 -1 0\nv 0 1 0\nf 1 2 3\n")
    scene_dict["objects"] = [{"file": "m.obj"}]
    expected = ('<dict>: objects[0].file: m.obj:1: cannot read the material library "gone.mtl" '
                "(No such file or directory); the materials it would define are diffuse 0.8")
    with pytest.warns(UserWarning) as caught:
        scene = candela.Scene.from_dict(scene_dict, base_dir=tmp_path)
    assert [str(w.message) for w in caught] == [expected]
    assert caught[0].filename == __file__  # points at the caller, not at candela
    assert scene.warnings == [expected]
    assert scene.render(spp=1).shape[2] == 3
    path = tmp_path / "m.json"
    path.write_text(__import__("json").dumps(scene_dict))
    with pytest.warns(UserWarning, match=r"m\.json: objects\[0\]\.file: m\.obj:1: cannot read"):
        candela.Scene.load(path)


def test_message_matches_the_cli(tmp_path, scene_dict):
    scene_dict["spheres"][1]["radius"] = -1
    path = tmp_path / "neg.json"
    path.write_text(__import__("json").dumps(scene_dict))
    cli = subprocess.run([sys.executable, "-m", "candela", "render", str(path), "-o", str(tmp_path / "x.png")],
                         capture_output=True, text=True, timeout=60)
    assert cli.returncode != 0
    with pytest.raises(candela.SceneError) as err:
        candela.Scene.load(str(path))
    assert str(err.value) in cli.stderr


def test_bad_arguments_raise_value_error(scene_dict):
    scene = candela.Scene.from_dict(scene_dict)
    with pytest.raises(ValueError, match="backend"):
        scene.render(backend="opengl")
    with pytest.raises(ValueError, match="sample range"):
        scene.render(spp=4, sample_range=(2, 3))
    with pytest.raises(ValueError):
        scene.render(spp=4, sample_range=(0, 0))


def test_sample_range_slices_sum_to_full_render(scene_dict):
    scene = candela.Scene.from_dict(scene_dict)
    full = scene.render(spp=8, backend="cpu").astype(np.float64)
    merged = np.zeros_like(full)
    for first, count in [(0, 3), (3, 1), (4, 4)]:
        merged += scene.render(spp=8, sample_range=(first, count), backend="cpu") * count
    np.testing.assert_allclose(merged / 8, full, rtol=1e-5, atol=1e-6)
    # A slice alone is a different (noisier) estimate, not the full image.
    assert not np.array_equal(scene.render(spp=8, sample_range=(0, 3)), full.astype(np.float32))


def test_animation_frames():
    scene = candela.Scene.from_dict(animated_scene(frames=4))
    assert scene.frames == 4 and scene.frame_index is None
    frames = [scene.frame(i) for i in range(4)]
    assert [f.frame_index for f in frames] == [0, 1, 2, 3]
    assert [f.seed for f in frames] == [3, 4, 5, 6]  # render.seed + frame
    imgs = [f.render(backend="cpu") for f in frames]
    assert not np.array_equal(imgs[0], imgs[3])
    np.testing.assert_array_equal(scene.render(backend="cpu"), imgs[0])
    with pytest.raises(IndexError):
        scene.frame(4)
    assert scene.frame(-1).frame_index == 3 and scene.frame(-4).frame_index == 0  # as a list's
    with pytest.raises(IndexError, match=r"frame -5 out of range \(4 frames\)"):
        scene.frame(-5)
    rebuilt = candela.Scene.from_spec(frames[2].spec)
    np.testing.assert_array_equal(rebuilt.render(backend="cpu"), imgs[2])


def test_renders_of_one_scene_reuse_its_flattened_scene():
    # Frames share one flattened scene, as the CLI's sequences do: the ball's moves refit the
    # BVH, a render with other samples reuses it whole, and the images equal fresh renders.
    scene = candela.Scene.from_dict(animated_scene(frames=3))
    assert scene._core._last_change is None
    first = scene.frame(0).render(backend="cpu")
    assert scene._core._last_change == "structure"
    moved = scene.frame(1).render(backend="cpu")
    assert scene._core._last_change == "motion"
    again = scene.frame(1).render(spp=2, seed=9, backend="cpu")
    assert scene._core._last_change == "values"
    fresh = candela.Scene.from_dict(animated_scene(frames=3))
    np.testing.assert_array_equal(first, fresh.frame(0).render(backend="cpu"))
    np.testing.assert_array_equal(moved, candela.Scene.from_dict(animated_scene(frames=3))
                                  .frame(1).render(backend="cpu"))
    np.testing.assert_array_equal(again, candela.Scene.from_dict(animated_scene(frames=3))
                                  .frame(1).render(spp=2, seed=9, backend="cpu"))


def test_write_image_formats(tmp_path, scene_dict):
    img = candela.Scene.from_dict(scene_dict).render()
    for name in ["a.png", "a.exr", "a.pfm"]:
        candela.write_image(tmp_path / name, img)
        assert (tmp_path / name).stat().st_size > 0
    candela.write_image(tmp_path / "s.png", img, gamma="srgb", exposure=1.0)
    assert sorted(os.listdir(tmp_path)) == ["a.exr", "a.pfm", "a.png", "s.png"]  # no temp files
    with pytest.raises(ValueError, match="unsupported"):
        candela.write_image(tmp_path / "a.bmp", img)
    with pytest.raises(ValueError, match="shape"):
        candela.write_image(tmp_path / "b.png", img[..., 0])
    # Folders are made as the CLI's -o makes them; a file in the way is an error naming the path.
    candela.write_image(tmp_path / "new" / "nested" / "c.png", img)
    assert (tmp_path / "new" / "nested" / "c.png").stat().st_size > 0
    (tmp_path / "file").write_text("")
    with pytest.raises(OSError, match="'.*file' is not a folder"):
        candela.write_image(tmp_path / "file" / "d.png", img)


def test_scene_output_and_tone_maps(tmp_path, scene_dict):
    scene_dict["render"].update(gamma="srgb", exposure=1.5, tone_map="aces")
    scene = candela.Scene.from_dict(scene_dict)
    assert scene.output == {"gamma": "srgb", "exposure": 1.5, "tone_map": "aces"}
    assert candela.Scene.from_dict(tiny_scene()).output["tone_map"] == "clamp"
    # Values above 1: clamped they are all white, tone-mapped they keep their differences.
    img = np.repeat(np.linspace(0.5, 8, 16, dtype=np.float32)[None, :, None], 3, axis=2)
    for tone_map in ("clamp", "reinhard", "aces"):
        candela.write_image(tmp_path / f"{tone_map}.png", img, tone_map=tone_map)
    files = {t: (tmp_path / f"{t}.png").read_bytes() for t in ("clamp", "reinhard", "aces")}
    assert len(set(files.values())) == 3
    with pytest.raises(ValueError, match="tone_map must be one of clamp, reinhard, aces"):
        candela.write_image(tmp_path / "x.png", img, tone_map="filmic")
    scene_dict["render"]["tone_map"] = "filmic"
    with pytest.raises(candela.SceneError, match=r"render\.tone_map"):
        candela.Scene.from_dict(scene_dict)


def test_render_releases_the_gil(scene_dict):
    scene_dict["camera"].update(width=64, height=64)
    scene = candela.Scene.from_dict(scene_dict)
    ticks = 0
    done = threading.Event()

    def count():
        nonlocal ticks
        while not done.is_set():
            ticks += 1

    t = threading.Thread(target=count)
    t.start()
    scene.render(spp=64, threads=1)
    done.set()
    t.join()
    assert ticks > 1000  # the counter thread ran while C++ rendered


def test_ctrl_c_cancels_a_render(tmp_path):
    # The child sets Python's own SIGINT handler: started from a background job (as CI runs),
    # it inherits SIGINT ignored, and Python then leaves it ignored.
    script = textwrap.dedent(f"""
        import signal, sys, time
        signal.signal(signal.SIGINT, signal.default_int_handler)
        sys.path.insert(0, {os.path.dirname(__file__)!r})
        import candela
        from conftest import tiny_scene
        scene = candela.Scene.from_dict(tiny_scene(size=128))
        print("ready", flush=True)
        start = time.time()
        try:
            scene.render(spp=100000, threads=1)
            print("finished")
        except KeyboardInterrupt:
            print("interrupted after", round(time.time() - start, 1), flush=True)
    """)
    proc = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True)
    assert proc.stdout.readline().strip() == "ready"
    import time
    time.sleep(1.0)
    proc.send_signal(signal.SIGINT)
    out, _ = proc.communicate(timeout=30)
    assert out.startswith("interrupted after"), out


def test_devices_name_the_cpu_and_say_where_auto_renders():
    reports = candela.devices(threads=1)
    assert [r["backend"] for r in reports] == ["cpu", "cuda"]
    cpu, gpu = reports
    assert cpu["usable"] and ", 1 thread, " in cpu["summary"]
    assert gpu["usable"] == candela.cuda_available()
    assert gpu["usable"] or gpu["summary"].startswith("not usable: ")
    # auto: the GPU where one is usable, else the CPU
    assert [r["backend"] for r in reports if r["auto"]] == ["cuda" if gpu["usable"] else "cpu"]


def _triangle_gltf(**more):
    """A glTF document of one triangle (its buffer a data URI), with `more` members."""
    import base64
    import struct
    data = struct.pack("9f", -1, -1, 0, 1, -1, 0, 0, 1, 0)
    gltf = {"asset": {"version": "2.0"},
            "buffers": [{"byteLength": len(data), "uri": "data:application/octet-stream;base64,"
                         + base64.b64encode(data).decode()}],
            "bufferViews": [{"buffer": 0, "byteLength": len(data)}],
            "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}],
            "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
            "nodes": [{"mesh": 0}]}
    gltf.update(more)
    return gltf


def test_gltf_meshes_load_with_their_warnings_and_render(tmp_path, scene_dict):
    import json
    gltf = _triangle_gltf(
        nodes=[{"mesh": 0}, {"camera": 0}],
        cameras=[{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}}])
    (tmp_path / "m.gltf").write_text(json.dumps(gltf))
    scene_dict["objects"] = [{"file": "m.gltf"}]
    expected = ("<dict>: objects[0].file: m.gltf: the file's cameras are not used "
                "(the scene's camera takes one with \"gltf\")")
    with pytest.warns(UserWarning) as caught:
        scene = candela.Scene.from_dict(scene_dict, base_dir=tmp_path)
    assert [str(w.message) for w in caught] == [expected]
    img = scene.render(spp=1, backend="cpu")
    assert np.isfinite(img).all()


def test_a_gltf_file_is_a_scene_of_its_own(tmp_path):
    import json
    gltf = _triangle_gltf()
    (tmp_path / "tri.gltf").write_text(json.dumps(gltf))
    scene = candela.Scene.load(tmp_path / "tri.gltf")
    img = scene.render(spp=2, backend="cpu")
    assert img.shape == (540, 960, 3)
    # Framed: the triangle covers the image's centre; the pale sky (radiance 0.6) its corner.
    assert abs(img[270, 480] - 0.6).max() > 0.01
    assert abs(img[5, 5] - 0.6).max() < 1e-6


def test_built_in_shapes_need_no_file():
    # A glowing unit cube, 2 units wide, seen straight on by an orthographic camera 4 units
    # across: the middle half of the image glows, the rest is black.
    scene = {"camera": {"width": 16, "height": 16, "projection": "orthographic",
                        "view_width": 4, "position": [0, 0, 5], "spp": 1},
             "render": {"antialiasing": False, "max_depth": 1},
             "objects": [{"shape": "cube", "scale": 2,
                          "material": {"type": "emissive", "radiance": 1}}]}
    img = candela.Scene.from_dict(scene).render(backend="cpu")
    expected = np.zeros((16, 16, 3), np.float32)
    expected[4:12, 4:12] = 1
    np.testing.assert_array_equal(img, expected)
    scene["objects"][0]["shape"] = "ball"
    with pytest.raises(candela.SceneError, match=r"objects\[0\]\.shape: expected one of"):
        candela.Scene.from_dict(scene)


def test_material_libraries_and_the_sky_from_a_dict(tmp_path, scene_dict):
    # A library beside a texture in its own folder, named from a dict scene whose base_dir is
    # the library's parent; under the analytic sky. The file scene renders the same.
    import json
    lib = tmp_path / "lib"
    lib.mkdir()
    (lib / "grey.pfm").write_bytes(b"PF\n1 1\n-1\n" + np.float32([0.5, 0.5, 0.5]).tobytes())
    (lib / "studio.json").write_text(json.dumps(
        {"grey": {"type": "diffuse", "color": {"texture": "grey.pfm"}}}))
    scene_dict["materials"] = "lib/studio.json"
    scene_dict["spheres"][1]["material"] = "grey"
    scene_dict["spheres"][1].pop("color", None)
    scene_dict["environment"] = {"sky": {"sun": [0.3, 0.8, 0.2], "turbidity": 4},
                                 "strength": 0.1}
    from_dict = candela.Scene.from_dict(scene_dict, base_dir=tmp_path).render(backend="cpu")
    assert np.isfinite(from_dict).all() and from_dict.max() > 0
    (tmp_path / "scene.json").write_text(json.dumps(scene_dict))
    from_file = candela.Scene.load(tmp_path / "scene.json").render(backend="cpu")
    np.testing.assert_array_equal(from_dict, from_file)
    (lib / "studio.json").unlink()
    with pytest.raises(candela.SceneError, match=r"materials: cannot open the material library"):
        candela.Scene.from_dict(scene_dict, base_dir=tmp_path)
