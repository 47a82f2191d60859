"""scene.render(denoise=True): Open Image Denoise on the direct and the indirect light apart, guided
by the albedo and normal passes."""
import sys

import numpy as np
import pytest

import candela
from conftest import read_pfm, tiny_scene

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


def with_emitter(size):
    spec = tiny_scene(size=size)
    spec["spheres"].append({"position": [-1.2, 0.3, 0.5], "radius": 0.3,
                            "material": {"type": "emissive", "radiance": 40}})
    return spec


def test_direct_and_indirect_light_are_denoised_apart_and_emitters_seen_sampled_again():
    from candela import denoise as oidn
    scene = candela.Scene.from_dict(with_emitter(32))
    result = scene.render(spp=4, seed=3, aovs=["albedo", "normal", "direct", "emission"],
                          denoise=True)
    guides = (result["noisy"], result["albedo"], result["normal"])
    # The emitters seen, sampled again around where they are (16 times the samples, camera rays
    # alone), are added back in place of the render's own emission pass.
    seen = scene._core.seen_emitters(result["emission"], 4, 3, "auto", 0)
    replaced = (seen != result["emission"]).any(axis=2)
    assert 0 < replaced.mean() < 0.5
    np.testing.assert_allclose(
        result["image"],
        oidn.denoise(*guides, result["direct"], result["emission"], seen_emission=seen),
        rtol=1e-5, atol=1e-6)
    assert result["emission"].max() == 40.0
    for other in (oidn.denoise(*guides), oidn.denoise(*guides, result["direct"]),
                  oidn.denoise(*guides, result["direct"], result["emission"])):
        assert np.abs(result["image"] - other).max() > 1e-2 * other.max()
    no_emitter = scene.from_dict(tiny_scene(size=32))
    assert no_emitter._core.seen_emitters(np.zeros((32, 32, 3), np.float32), 4, 3, "auto",
                                          0) is None
    with pytest.raises(ValueError, match=r"the render's, \(32, 32, 3\)"):
        no_emitter._core.seen_emitters(np.zeros((16, 32, 3), np.float32), 4, 3, "auto", 0)


def test_emitters_seen_sampled_again_bring_the_denoised_image_closer_to_the_reference():
    # The emitter's rim, a sliver of a pixel that one of few samples may land on, is what the
    # filter cannot place; sampled again, the denoised image comes closer to the converged one.
    from candela import denoise as oidn
    scene = candela.Scene.from_dict(with_emitter(64))
    reference = scene.render(spp=1024, seed=1)
    result = scene.render(spp=4, seed=2, aovs=["albedo", "normal", "direct", "emission"],
                          denoise=True)
    own = oidn.denoise(result["noisy"], result["albedo"], result["normal"], result["direct"],
                       result["emission"])
    assert relmse(result["image"], reference) < 0.8 * relmse(own, reference)


def test_passes_of_another_shape_are_refused_by_name():
    from candela import denoise as oidn
    image = np.ones((4, 5, 3), np.float32)
    with pytest.raises(ValueError, match=r"the image's shape \(4, 5, 3\)"):
        oidn.denoise(image, image[:3], image)
    with pytest.raises(ValueError, match=r"shape \(H, W, 3\), got \(4, 5\)"):
        oidn.denoise(image[..., 0], image, image)


def test_a_missing_denoiser_is_named_before_rendering(monkeypatch):
    monkeypatch.setitem(sys.modules, "pyoidn", None)  # import pyoidn now raises ImportError
    scene = candela.Scene.from_dict(tiny_scene(size=8))
    with pytest.raises(RuntimeError, match="pip install pyoidn"):
        scene.render(spp=1, denoise=True)


# --- `candela render --denoise`: the command line loads the same OIDN (pyoidn's library) --------

REPO = __import__("pathlib").Path(__file__).resolve().parents[2]
CLI = REPO / "build" / "candela"


def cli(*args, env=None, unset=()):
    """The command line run with `args`, this process's environment with `env` added and the
    variables named in `unset` removed."""
    import os
    import subprocess
    if not CLI.exists():
        pytest.skip(f"{CLI} is not built (scripts/build builds it)")
    environment = {k: v for k, v in {**os.environ, **(env or {})}.items() if k not in unset}
    return subprocess.run([str(CLI), *map(str, args)], capture_output=True, text=True,
                          stdin=subprocess.DEVNULL, env=environment)


def test_cli_denoise_matches_python_and_beats_the_raw_render(tmp_path):
    import json
    scene_file = tmp_path / "scene.json"
    scene_file.write_text(json.dumps(with_emitter(64)))  # its emitter sampled again by both
    raw, clean = tmp_path / "raw.pfm", tmp_path / "clean.pfm"
    assert cli("render", scene_file, "-q", "--spp", 4, "--seed", 2, "-o", raw).returncode == 0
    done = cli("render", scene_file, "-q", "--spp", 4, "--seed", 2, "--denoise", "-o", clean)
    assert done.returncode == 0, done.stderr
    reference = candela.Scene.load(str(scene_file)).render(spp=1024, seed=1)
    assert relmse(read_pfm(clean), reference) < 0.5 * relmse(read_pfm(raw), reference)
    # The same render, guides and filter as scene.render(denoise=True): one implementation
    # (src/apps/denoise/oidn_denoiser.h) behind both, so the same bits.
    python = candela.Scene.load(str(scene_file)).render(spp=4, seed=2, denoise=True)
    np.testing.assert_array_equal(read_pfm(clean), python)


def test_cli_without_the_denoiser_says_how_to_install_it_and_writes_nothing(tmp_path):
    import json
    scene_file = tmp_path / "scene.json"
    scene_file.write_text(json.dumps(tiny_scene(size=8)))
    out = tmp_path / "out.png"
    done = cli("render", scene_file, "--denoise", "-o", out,
               env={"CANDELA_OIDN_LIBRARY": str(tmp_path / "missing.so")})
    assert done.returncode == 2
    assert "pip install pyoidn" in done.stderr and "Traceback" not in done.stderr
    assert not out.exists()


def test_cli_with_a_python_that_lacks_pyoidn_says_how_to_install_it(tmp_path):
    """The command line looks for pyoidn through the python3 on PATH (without importing it);
    one whose packages are out of reach (-S) has none, and the error says how to install it."""
    import json
    import os
    import shutil
    import subprocess
    # (A process of its own: this one has loaded pyoidn's copy, which dlopen would find.)
    on_path = subprocess.run(
        [shutil.which("python3"), "-S", "-c",
         "import ctypes; ctypes.CDLL('libOpenImageDenoise.so.2')"],
        capture_output=True, stdin=subprocess.DEVNULL).returncode == 0
    if on_path:
        pytest.skip("libOpenImageDenoise.so.2 is on the library path: pyoidn is not looked for")
    bin_dir = tmp_path / "bin"
    bin_dir.mkdir()
    wrapper = bin_dir / "python3"
    wrapper.write_text(f'#!/bin/sh\nexec "{shutil.which("python3")}" -S "$@"\n')
    wrapper.chmod(0o755)
    scene_file = tmp_path / "scene.json"
    scene_file.write_text(json.dumps(tiny_scene(size=8)))
    out = tmp_path / "out.png"
    done = cli("render", scene_file, "--denoise", "-o", out,
               env={"PATH": f"{bin_dir}{os.pathsep}{os.environ.get('PATH', '')}"},
               unset=("CANDELA_OIDN_LIBRARY",))
    assert done.returncode == 2, done.stderr
    assert "pip install pyoidn" in done.stderr and "Traceback" not in done.stderr
    assert not out.exists()


def test_cli_reports_the_denoisers_time(tmp_path):
    """`--denoise` reports the denoiser's seconds on the summary line and in --stats (0 without)."""
    import json
    scene_file = tmp_path / "scene.json"
    scene_file.write_text(json.dumps(with_emitter(32)))
    for denoise in (False, True):
        stats = tmp_path / f"stats-{denoise}.json"
        args = ["render", scene_file, "--spp", 2, "-o", tmp_path / "out.pfm", "--stats", stats]
        done = cli(*args, *(["--denoise"] if denoise else []))
        assert done.returncode == 0, done.stderr
        seconds = json.loads(stats.read_text())["denoise_seconds"]
        if denoise:
            assert 0 < seconds < 60
            assert f", denoised in {seconds:.2f} s" in done.stdout, done.stdout
        else:
            assert seconds == 0
            assert "denoised" not in done.stdout, done.stdout


def test_a_cropped_denoised_render_is_that_part_of_the_denoised_image():
    scene = candela.Scene.from_dict(with_emitter(32))
    part = (slice(6, 22), slice(4, 24))
    reference = scene.render(spp=1024, seed=1)[part]
    whole = scene.render(spp=4, seed=3, denoise=True)[part]
    crop = scene.render(spp=4, seed=3, denoise=True, crop=(4, 6, 20, 16))
    noisy = scene.render(spp=4, seed=3, crop=(4, 6, 20, 16))
    assert crop.shape == (16, 20, 3) and np.all(np.isfinite(crop))
    # The filter sees less around the crop's edges, so the two differ, but far less than the
    # noise it takes away; and the crop is as clean as that part of the whole denoised image.
    spec = with_emitter(32)
    spec["camera"]["crop"] = [4, 6, 20, 16]
    by_camera = candela.Scene.from_dict(spec).render(spp=4, seed=3, denoise=True)
    np.testing.assert_array_equal(by_camera, crop)
    assert relmse(crop, whole) < 0.25 * relmse(noisy, whole)
    assert relmse(crop, reference) < 0.5 * relmse(noisy, reference)
    assert relmse(crop, reference) < 1.25 * relmse(whole, reference)
