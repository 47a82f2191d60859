// Helpers for the flow pass's tests: a frame of an animation rendered with its flow to the next
// frame and the passes that explain it, and a large square to slide cameras past.
#pragma once

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

// Writes quad.obj, a square 200 across in the plane z = 0, into `dir`; returns the folder.
inline std::string writeQuad(const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "quad.obj") << "v -100 -100 0\nv 100 -100 0\nv 100 100 0\nv -100 100 0\n"
                                     "f 1 2 3 4\n";
  return dir.string();
}

}  // namespace candela::test
