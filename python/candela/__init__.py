"""candela: a physically based path tracer.

    scene = candela.Scene.load("scenes/default.json")
    img = scene.render(spp=64, seed=0)          # float32 (H, W, 3), linear radiance
    candela.write_image("out.png", img)

Renders release the GIL and stop on Ctrl-C (KeyboardInterrupt). Scene errors raise
candela.SceneError, a ValueError whose message is the CLI's. For rendering on a Ray cluster see
candela.distributed.
"""
from __future__ import annotations

import json
import math
import os
import warnings
from typing import Any, Dict, List, Mapping, Optional, Sequence, Tuple

import numpy as np

from . import _candela
from ._candela import ImageWriteError, SceneError, cuda_available

__all__ = ["Scene", "SceneError", "ImageWriteError", "write_image", "cuda_available", "devices"]
__version__ = "0.1.0"


class Scene:
    """A validated scene, or one frame of an animated scene.

    Keeps where it came from (a file path, or JSON text and a base folder) so that it can be
    rebuilt elsewhere, e.g. in a Ray task: see `spec` and `Scene.from_spec`.
    """

    def __init__(self, core: "_candela._Scene", source: dict):
        self._core = core
        self._source = source

    @classmethod
    def load(cls, path: str | os.PathLike) -> "Scene":
        """Loads and validates a JSON scene file (and its OBJ, PLY and glTF meshes), or a glTF file
        as a scene of its own (docs/scene-format.md, *A glTF file as the scene*). Raises
        SceneError."""
        path = os.fspath(path)
        return cls(_candela._Scene.load(path),
                   {"path": os.path.abspath(path), "label": path})._warned()

    @classmethod
    def from_dict(cls, scene: dict, base_dir: str | os.PathLike = ".") -> "Scene":
        """A scene from a dict in the JSON scene format; mesh paths resolve against base_dir.
        Values may be numpy arrays and scalars (a camera's K and [R|t], say) and paths
        (os.PathLike); a value JSON cannot hold (NaN, a set) raises SceneError naming its place."""
        text = json.dumps(_plain_json(scene, ""))
        base_dir = os.path.abspath(os.fspath(base_dir))
        return cls(_candela._Scene.from_text(text, "<dict>", base_dir),
                   {"text": text, "base_dir": base_dir, "label": "<dict>"})._warned()

    @classmethod
    def from_spec(cls, spec: dict) -> "Scene":
        """Rebuilds a scene from `scene.spec` (a plain dict, cheap to send to another process)."""
        if "path" in spec:
            core = _candela._Scene.load(spec["path"])
        else:
            core = _candela._Scene.from_text(spec["text"], spec.get("label", "<dict>"),
                                             spec["base_dir"])
        source = {k: v for k, v in spec.items() if k != "frame"}
        scene = cls(core, source)
        return scene.frame(spec["frame"]) if spec.get("frame") is not None else scene

    @property
    def warnings(self) -> List[str]:
        """What the scene's files leave to a default their author may not have meant (an MTL
        file that cannot be read, a material no MTL file defines), one message each; `load` and
        `from_dict` also issue each as a UserWarning. The scene renders."""
        return list(self._core.warnings)

    def _warned(self) -> "Scene":
        for message in self._core.warnings:
            warnings.warn(message, UserWarning, stacklevel=3)
        return self

    @property
    def spec(self) -> dict:
        """Where this scene comes from: {"path"} or {"text", "base_dir"}, plus "frame"."""
        return dict(self._source, frame=self._core.frame_index)

    @property
    def frames(self) -> int:
        """Number of animation frames (1 for a still)."""
        return self._core.frames

    @property
    def frame_index(self) -> Optional[int]:
        """Which frame this is, or None for the scene as loaded (renders as frame 0)."""
        return self._core.frame_index

    def frame(self, index: int) -> "Scene":
        """The still scene at animation frame `index` (its seed is render.seed + index); a
        negative index counts from the end, as a list's does (-1: the last frame)."""
        index = _whole(index, "frame index", None, None)
        if not -self.frames <= index < self.frames:
            raise IndexError(f"frame {index} out of range ({self.frames} frames)")
        return Scene(self._core.frame(index % self.frames), self._source)

    @property
    def width(self) -> int:
        return self._core.width

    @property
    def height(self) -> int:
        return self._core.height

    @property
    def spp(self) -> int:
        """Samples per pixel given in the scene (render() uses it when spp is None)."""
        return self._core.spp

    @property
    def seed(self) -> int:
        """The seed this scene (or frame) renders with by default."""
        return self._core.seed

    @property
    def output(self) -> dict:
        """The scene's output encoding as write_image arguments: gamma (or "srgb"), exposure,
        tone_map."""
        srgb, gamma, exposure, tone_map = self._core.output
        return {"gamma": "srgb" if srgb else gamma, "exposure": exposure,
                "tone_map": TONE_MAPS[tone_map]}

    @property
    def instances(self) -> Dict[int, str]:
        """What the numbers of the "instance" pass name: {number: the entity's JSON `id`, else its
        place in the file, e.g. "spheres[2]"}; 0, the background, is not in it."""
        return dict(self._core.instances)

    @property
    def camera(self) -> Dict[str, Any]:
        """This scene's (or frame's) camera as a vision dataset records it, the same as
        `candela render --aov camera` writes beside the image (docs/aovs.md, *The camera file*):
        {"width", "height", "intrinsics": K (3, 3), "extrinsics": [R t; 0 1] (4, 4)}, and
        "aperture_radius" and "focus_distance" for a thin lens, "distortion" (OpenCV's
        coefficients, 5 or 8 of them; a fisheye's 4) for a camera with a lens distortion;
        "projection" for a fisheye or an equirectangular camera, which has it in place of
        "intrinsics". K puts pixel centres at +0.5
        (OpenCV's cx and cy are 0.5 less); a world point p is at R p + t in OpenCV's camera axes
        (+x right, +y down, +z forward). The matrices are float64 arrays holding the float32
        values the renderer uses; given back as a scene's "camera" (the arrays as they are, or
        lists) they render the same image."""
        camera = dict(self._core._camera)
        for key in ("intrinsics", "extrinsics"):
            if key in camera:
                camera[key] = np.array(camera[key], dtype=np.float64)
        return camera

    @property
    def poses(self) -> Dict[int, Dict[str, Any]]:
        """Where each instance is in this scene (or frame), by the instance pass's numbers, the
        same as `candela render --aov poses` writes (docs/aovs.md, *Instance poses*):
        {number: {"name", "object_to_world", "object_to_camera"}}, each matrix a (4, 4) float64
        array [A p; 0 0 0 1] taking the instance's model (an object's mesh as its file has it,
        the unit sphere for a sphere or sphere light, the origin for a point light, a rotation
        turning +z to where it shines for a spot or directional light, the unit square of the xy
        plane for a rectangle light, which shines along +z) to world space, and to
        OpenCV's camera axes (the camera's extrinsics times the first). Every instance with an
        extent also has "model_box", a (2, 3) float64 array of the lowest and highest corner of
        the box its model spans (an object's mesh's vertices as its file binds them; [-1, 1]^3
        for a sphere): the box over which the "object_coordinates" pass runs from 0 to 1, so
        that lo + c * (hi - lo) is the model's point where that pass reads c."""
        poses = {}
        for number, name, world, seen, box in self._core._poses:
            poses[number] = {"name": name,
                             "object_to_world": np.array(world, dtype=np.float64),
                             "object_to_camera": np.array(seen, dtype=np.float64)}
            if box is not None:
                poses[number]["model_box"] = np.array(box, dtype=np.float64)
        return poses

    def render(self, spp: Optional[int] = None, seed: Optional[int] = None,
               backend: str = "auto", sample_range: Optional[Tuple[int, int]] = None,
               threads: int = 0, aovs: Optional[Sequence[str]] = None, denoise: bool = False,
               max_depth: Optional[int] = None,
               crop: Optional[Sequence[int]] = None) -> np.ndarray | Dict[str, np.ndarray]:
        """Renders to a float32 array (height, width, 3) of linear radiance.

        crop=(x, y, width, height): render only pixels x to x + width - 1 and y to
        y + height - 1 of the camera's image, each as the whole image's render has it, passes
        and denoising too (the scene's own camera "crop" is replaced; docs/scene-format.md,
        *Crops*); ValueError where it reaches past the image or is empty.

        denoise: run Intel Open Image Denoise (PyPI `pyoidn`) on the result's direct and
        indirect light, guided by the albedo and normal passes (candela.denoise);
        candela.denoise.DenoiserUnavailable where it is not installed. With aovs as well, "image"
        is the denoised radiance and "noisy" the render as it came.

        aovs: render passes to return as well (docs/aovs.md): "depth", "distance", "normal",
        "normal_camera", "albedo", "position", "instance", "material", "flow", "direct",
        "emission", "alpha", "backward_flow", "uv", "object_coordinates". With aovs the result
        is a dict: "image" the radiance, and one array per pass, (height, width) float32 for
        depth, distance and alpha, (height, width, 2) float32 for flow, backward_flow and uv,
        (height, width, 3) float32 for the others, (height, width) uint32 for the ids. An unknown
        pass name raises ValueError.

        spp, seed and max_depth (the most surface interactions along a path) override the
        scene's, as the CLI's --spp, --seed and --max-depth do. backend: "auto" (the GPU
        where one is usable, else the CPU), "cpu" or "cuda" (an NVIDIA GPU; RuntimeError where
        it cannot run).
        sample_range=(first, count) renders only samples [first, first + count) of the spp and
        returns their mean; the count-weighted mean of disjoint slices equals the full render to
        rounding. threads: CPU threads, 0 for all cores; it holds all of the call's work, the BVH
        build and the denoiser included, not only the tiles.

        Renders of one loaded scene and its frames share the flattened scene and its BVH: a
        later render whose geometry is unchanged (another spp, seed or sample range, or a frame
        where only the camera, lights or materials moved) reuses them, and one where objects
        only moved refits the BVH.
        """
        spp, seed, max_depth = _render_counts(spp, seed, max_depth)
        if sample_range is not None:
            sample_range = (_whole(sample_range[0], "sample_range's first", 0, _U32),
                            _whole(sample_range[1], "sample_range's count", 0, _U32))
        threads = _whole(threads, "threads", 0, 2**31 - 1)
        crop = _crop(crop)
        aovs = _pass_names(aovs)
        result = self._core.render(spp, seed, backend, sample_range, threads,
                                   _passes_to_render(aovs, denoise), max_depth=max_depth,
                                   crop=crop)
        if not denoise:
            return result
        return _denoised(result, aovs, threads,
                         self._core.seen_emitters(result["emission"], spp, seed, backend, threads,
                                                  crop=crop))

    def __repr__(self) -> str:
        frame = "" if self.frame_index is None else f", frame {self.frame_index}"
        return (f"<candela.Scene {self._source.get('label')} {self.width}x{self.height}, "
                f"{self.frames} frame(s){frame}>")


_U32 = 2**32 - 1


def _whole(value: Any, name: str, low: Optional[int], high: Optional[int]) -> int:
    """`value` as an int in [low, high] (None: unbounded there): TypeError where it is no whole
    number (a float, a bool), ValueError where it is out of range."""
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
        raise TypeError(f"{name} must be an integer, got {type(value).__name__} {value!r}")
    value = int(value)
    if (low is not None and value < low) or (high is not None and value > high):
        bound = f"at least {low}" if high is None else f"in [{low}, {high}]"
        raise ValueError(f"{name} must be {bound}, got {value}")
    return value


def _render_counts(spp, seed, max_depth) -> tuple:
    """render()'s spp, seed and max_depth checked (None keeps the scene's)."""
    return (None if spp is None else _whole(spp, "spp", 1, _U32),
            None if seed is None else _whole(seed, "seed", 0, 2**64 - 1),
            None if max_depth is None else _whole(max_depth, "max_depth", 1, _U32))


def _crop(crop: Optional[Sequence[int]]) -> Optional[tuple]:
    """render()'s crop as a tuple of four whole numbers (None: none); TypeError where it is no
    sequence of four integers."""
    if crop is None:
        return None
    if isinstance(crop, (str, bytes)) or not isinstance(crop, (Sequence, np.ndarray)) \
            or len(crop) != 4:
        raise TypeError(f"crop must be (x, y, width, height), four integers, got {crop!r}")
    return tuple(_whole(v, f"crop's {name}", 0, _U32)
                 for v, name in zip(crop, ("x", "y", "width", "height")))


def _plain_json(value: Any, path: str) -> Any:
    """A scene given as Python values, as plain JSON values: numpy arrays and scalars become
    lists and numbers, paths strings. A value JSON cannot hold raises SceneError naming its
    place as the loader's messages do (`camera.position[2]`)."""
    if isinstance(value, np.ndarray):
        value = value.tolist()
    elif isinstance(value, np.generic):
        value = value.item()
    elif isinstance(value, os.PathLike):
        value = os.fspath(value)
    place = f"<dict>: {path}: " if path else "<dict>: at the top level: "
    if value is None or isinstance(value, (str, bool, int)):
        return value
    if isinstance(value, float):
        if not math.isfinite(value):
            raise SceneError(f"{place}expected a finite number, got {value}")
        return value
    if isinstance(value, Mapping):
        plain = {}
        for key, item in value.items():
            if not isinstance(key, str):
                raise SceneError(f"{place}expected an object whose keys are strings, got the key "
                                 f"{key!r}")
            plain[key] = _plain_json(item, f"{path}.{key}" if path else key)
        return plain
    if isinstance(value, (list, tuple)):
        return [_plain_json(item, f"{path}[{i}]") for i, item in enumerate(value)]
    raise SceneError(f"{place}expected a JSON value (an object, array, string, number, boolean "
                     f"or null), got a value of type {type(value).__name__}")


def _pass_names(aovs: Optional[Sequence[str]]) -> Optional[list]:
    """The pass names as a list (None for none); TypeError for a bare string, ValueError for an
    unknown name."""
    if aovs is None:
        return None
    if isinstance(aovs, str):
        raise TypeError("aovs must be a list of pass names, e.g. ['depth', 'normal']")
    names = [str(a) for a in aovs]
    for name, what in (("camera", "the camera's matrices"), ("poses", "each instance's pose")):
        if name in names:  # the CLI's --aov writes them as files; here they are properties
            raise ValueError(f'"{name}" is no render pass: scene.{name} (or '
                             f"scene.frame(k).{name}) gives {what}")
    _candela.check_aovs(names)
    return names


def _passes_to_render(aovs: Optional[list], denoise: bool) -> Optional[list]:
    """The passes a render needs: those asked for, and with denoise the denoiser's guides, the
    direct light and the emission. With denoise, fails before rendering where the denoiser is
    missing."""
    if not denoise:
        return aovs
    from . import denoise as oidn
    oidn._oidn()
    return list(dict.fromkeys((aovs or []) + ["albedo", "normal", "direct", "emission"]))


def _denoised(result: Dict[str, np.ndarray], aovs: Optional[list], threads: int = 0,
              seen_emission: Optional[np.ndarray] = None):
    """A render's result with its passes and guides, denoised as Scene.render(denoise=True)
    returns it: the clean image alone without aovs, else the asked passes plus "image" (clean)
    and "noisy". `seen_emission`: the emission pass with the emitters seen sampled again (the
    core's seen_emitters; None where none are), added back in place of the render's own."""
    from . import denoise as oidn
    clean = oidn.denoise(result["image"], result["albedo"], result["normal"], result["direct"],
                         result["emission"], threads=threads, seen_emission=seen_emission)
    if aovs is None:
        return clean
    result["noisy"] = result["image"]
    result["image"] = clean
    return {k: v for k, v in result.items() if k in ("image", "noisy") or k in aovs}


def devices(threads: int = 0) -> List[Dict[str, Any]]:
    """What each backend would render on here, or why it cannot: one dict per backend, the CPU's
    then the GPU's, {"backend": "cpu" or "cuda", "usable": bool, "summary": str (the processor,
    or the reason), "auto": bool (the backend that backend="auto" renders on)}. threads: CPU
    threads, as Scene.render's (0 for all cores). `candela devices` prints the same."""
    return _candela.devices(int(threads))


TONE_MAPS = ("clamp", "reinhard", "aces")  # as the scene's render.tone_map names them


def write_image(path: str | os.PathLike, img: Any, gamma: float | str = 2.2,
                exposure: float = 0.0, tone_map: str = "clamp", alpha: Any = None) -> None:
    """Writes a linear (H, W, 3) image as the CLI does: .png (exposure in stops, then the tone map,
    "clamp", "reinhard" or "aces", then gamma, or gamma="srgb"), .exr or .pfm (linear float),
    creating the folders it goes in. The file is replaced atomically. With `alpha`, an (H, W)
    render's "alpha" pass, by which the image is premultiplied: a .png is RGBA of straight colour
    (the image divided by alpha), an .exr has A beside R, G, B; a .pfm has no alpha channel."""
    arr = np.ascontiguousarray(img, dtype=np.float32)
    if arr.ndim != 3 or arr.shape[2] != 3:
        raise ValueError(f"expected an image of shape (H, W, 3), got {arr.shape}")
    if alpha is not None:
        alpha = np.ascontiguousarray(alpha, dtype=np.float32)
        if alpha.shape != arr.shape[:2]:
            raise ValueError(f"expected alpha of the image's shape {arr.shape[:2]}, "
                             f"got {alpha.shape}")
    srgb = isinstance(gamma, str)
    if srgb and gamma.lower() != "srgb":
        raise ValueError(f"gamma must be a number or 'srgb', got {gamma!r}")
    if tone_map not in TONE_MAPS:
        raise ValueError(f"tone_map must be one of {', '.join(TONE_MAPS)}, got {tone_map!r}")
    path = os.fspath(path)
    try:
        os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
    except OSError:
        pass  # a file where a folder should be: the writer below names it
    _candela.write_image(path, arr, srgb, 2.2 if srgb else float(gamma), float(exposure),
                         TONE_MAPS.index(tone_map), alpha)
