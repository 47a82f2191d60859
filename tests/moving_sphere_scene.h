// The flow tests' animation: a grey unit sphere 5 before the camera (15x15 pixels, fov 30, the
// centre pixel on its axis) moving right by 0.25 a frame, frames 0 to 2.
#pragma once

namespace candela::test {

inline const char* kMovingSphereScene = R"({
  "camera": {"width": 15, "height": 15, "fov": 30, "spp": 1, "position": [0, 0, 5]},
  "render": {"antialiasing": false},
  "spheres": [{"id": "ball", "position": [0, 0, 0], "radius": 1, "color": 0.5}],
  "lights": [{"position": [0, 3, 3], "intensity": 100}],
  "animation": {"frames": 3, "tracks": [
    {"target": "ball", "property": "position", "keys": [[0, [0, 0, 0]], [2, [0.5, 0, 0]]]}]}
})";

}  // namespace candela::test
