"""Shared scenes for the Python tests: tiny (16x16, a few spp) so that every test is quick on two
cores, with a diffuse sphere on a floor lit by a point light."""
import copy
import json
import os
import sys

import pytest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from pfm import read_pfm  # noqa: E402,F401  (the tests' PFM reader: tools/pfm.py)


def tiny_scene(spp=4, seed=3, size=16):
    return {
        "camera": {"width": size, "height": size, "fov": 50, "position": [0, 1.5, 6],
                   "look_at": [0, 0.5, 0], "spp": spp},
        "render": {"max_depth": 4, "seed": seed},
        "environment": {"color": [0.05, 0.07, 0.1]},
        "spheres": [
            {"position": [0, -1000, 0], "radius": 1000, "color": 0.7},
            {"id": "ball", "position": [0, 0.5, 0], "radius": 0.5, "color": [0.8, 0.3, 0.2]},
        ],
        "lights": [{"position": [2, 4, 3], "intensity": 800}],
    }


def animated_scene(frames=4, **kwargs):
    scene = tiny_scene(**kwargs)
    scene["animation"] = {"frames": frames, "tracks": [
        {"target": "ball", "property": "position", "keys": [[0, [-1, 0.5, 0]], [frames - 1, [1, 0.5, 0]]]}]}
    return scene


@pytest.fixture
def scene_dict():
    return copy.deepcopy(tiny_scene())


@pytest.fixture
def scene_file(tmp_path):
    path = tmp_path / "tiny.json"
    path.write_text(json.dumps(tiny_scene()))
    return path


@pytest.fixture
def animation_file(tmp_path):
    path = tmp_path / "anim.json"
    path.write_text(json.dumps(animated_scene()))
    return path
