// Helpers for the flow pass's tests: a frame of an animation rendered with its flow to the next
// frame and the passes that explain it, and a large square to slide cameras past.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "render/aov_layers.h"
#include "render_test_util.h"
#include "scene/animation.h"
#include "scene/flow_motion.h"

namespace candela::test {

struct FlowRender {
  std::vector<ImageLayer> layers;
  float at(const char* name, uint32_t x, uint32_t y, uint32_t c = 0) const {
    for (const ImageLayer& l : layers)
      if (l.name == name) return l.pixels[l.channels.size() * (size_t(y) * l.width + x) + c];
    throw std::runtime_error(std::string("no layer ") + name);
  }
};

// Frame `frame` of the scene in `json` with its flow to the next frame, and its positions and
// instances.
inline FlowRender renderFlow(const std::string& json, uint32_t frame = 0,
                             const std::string& dir = ".") {
  const SceneDesc desc = parseSceneText(json, "test.json", dir);
  const SceneDesc now = sceneAtFrame(desc, frame), next = sceneAtFrame(desc, frame + 1);
  SceneData scene = flattenScene(now);
  applyFlowMotion(scene, flowMotion(now, next));
  RenderOptions options;
  options.aovs = true;
  const RenderResult result = renderCpu(scene.view(), options);
  return {makeAovLayers(scene, parseAovList("flow,position,instance"), result.aovs)};
}

// The members of a scene (after its camera) in which the camera, starting at the origin, slides
// by (0.3, 0.2, 0) between two frames before quad.obj 7.5 away down -z (writeQuad), with
// antialiasing off: every sample passes through its pixel's centre.
constexpr const char* kCameraSlidingPastTheQuad = R"(
    "render": {"antialiasing": false},
    "objects": [{"file": "quad.obj", "position": [0, 0, -7.5]}],
    "lights": [{"position": [0, 0, 0], "intensity": 100}],
    "animation": {"frames": 2, "tracks": [
      {"target": "camera", "property": "position", "keys": [[0, [0, 0, 0]], [1, [0.3, 0.2, 0]]]}]})";

// Camera space (OpenCV's axes: world x, -y, -z) of world point p for a camera at `eye` with
// rotation 0, in double.
inline std::array<double, 3> unturnedCameraSpace(const Vec3& p, const Vec3& eye = Vec3(0.0f)) {
  return {double(p.x) - eye.x, -(double(p.y) - eye.y), -(double(p.z) - eye.z)};
}

// What the test's own projection `project` (camera space -> pixel) says of a render of the camera
// sliding past the quad (kCameraSlidingPastTheQuad): the largest distance from a pixel's centre
// to the projection of its point in the position pass, and the largest difference between its
// flow and the difference of that point's projections from the two cameras; over the `seen`
// pixels whose samples hit the quad.
struct SlidingCameraErrors {
  double position = 0, flow = 0;
  int seen = 0;
};
template <class Project>
SlidingCameraErrors slidingCameraErrors(const FlowRender& r, uint32_t width, uint32_t height,
                                        Project project) {
  SlidingCameraErrors e;
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) {
      if (r.at("instance", x, y) == 0.0f) continue;
      ++e.seen;
      const Vec3 p(r.at("position", x, y, 0), r.at("position", x, y, 1), r.at("position", x, y, 2));
      const std::array<double, 2> a = project(unturnedCameraSpace(p));
      const std::array<double, 2> b = project(unturnedCameraSpace(p, Vec3(0.3f, 0.2f, 0.0f)));
      e.position = std::max(e.position, std::hypot(a[0] - (x + 0.5), a[1] - (y + 0.5)));
      e.flow = std::max(e.flow, std::hypot(r.at("flow", x, y, 0) - (b[0] - a[0]),
                                           r.at("flow", x, y, 1) - (b[1] - a[1])));
    }
  return e;
}

// A card (quad.obj scaled to 20 across, writeQuad) at (2, 0, 0) spinning 10 degrees a frame about
// its own vertical axis, seen from (0, 0, 40) on a 16 x 12 image of 60 degrees, without
// antialiasing.
constexpr const char* kSpinningCardScene = R"({
    "camera": {"width": 16, "height": 12, "fov": 60, "spp": 1, "position": [0, 0, 40]},
    "render": {"antialiasing": false},
    "objects": [{"id": "card", "file": "quad.obj", "position": [2, 0, 0], "scale": 0.1}],
    "lights": [{"position": [0, 0, 30], "intensity": 1000}],
    "animation": {"frames": 8, "tracks": [
      {"target": "card", "property": "rotation", "keys": [[0, [0, 0, 0]], [7, [0, 70, 0]]]}]}
  })";

// A square whose morph target stretches it along x (stretch.gltf, gltf_test_util.h's
// stretchingSquare), 1 + k / 8 times its width at frame k, seen from (0, 0, 4) on a 16 x 12
// image of 60 degrees, without antialiasing.
constexpr const char* kStretchingSquareScene = R"({
    "camera": {"width": 16, "height": 12, "fov": 60, "spp": 1, "position": [0, 0, 4]},
    "render": {"antialiasing": false},
    "objects": [{"file": "stretch.gltf", "gltf_animation": 0}],
    "lights": [{"position": [0, 0, 4], "intensity": 10}],
    "animation": {"frames": 8, "fps": 8}})";

// Expects each pixel of a 16 x 12 render of 60 degrees from (0, 0, eyeZ) down -z (the scenes
// above) that sees an instance to have as its `pass` the projection of its position-pass point
// moved by `move`, minus the pixel centre (to 2e-3 pixels); returns how many pixels did.
template <class Move>
int expectFlowFollows(const FlowRender& r, const char* pass, float eyeZ, Move move) {
  const float focal = 8.0f / std::tan(30.0f * 3.14159265f / 180.0f);
  int covered = 0;
  for (uint32_t y = 0; y < 12; ++y)
    for (uint32_t x = 0; x < 16; ++x) {
      if (r.at("instance", x, y) == 0.0f) continue;
      ++covered;
      const Vec3 q = move(
          Vec3(r.at("position", x, y, 0), r.at("position", x, y, 1), r.at("position", x, y, 2)));
      const float u = focal * q.x / (eyeZ - q.z) + 8.0f, v = -focal * q.y / (eyeZ - q.z) + 6.0f;
      EXPECT_NEAR(r.at(pass, x, y, 0), u - (x + 0.5f), 2e-3f) << pass << " " << x << "," << y;
      EXPECT_NEAR(r.at(pass, x, y, 1), v - (y + 0.5f), 2e-3f) << pass << " " << x << "," << y;
    }
  return covered;
}

// Writes quad.obj, a square 200 across in the plane z = 0, into `dir`; returns the folder.
inline std::string writeQuad(const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "quad.obj") << "v -100 -100 0\nv 100 -100 0\nv 100 100 0\nv -100 100 0\n"
                                     "f 1 2 3 4\n";
  return dir.string();
}

}  // namespace candela::test
