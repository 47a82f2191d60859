// libFuzzer target: the input is a glTF file, text or binary (.glb), rendered by a fixed small
// scene; what its URIs name is looked for in a temporary folder that holds only it (data URIs and
// a .glb's own buffer are what the seeds use), its cameras are read as a scene's camera would
// take them (the first also following the file's first animation), the file is rendered as a scene
// of its own (as `candela render m.gltf` does), and a file with lights is rendered again by them
// ({"gltf": file} in "lights"); an object plays its first animation. See docs/fuzzing.md.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_scene.h"
#include "scene/read/gltf_camera.h"
#include "scene/read/gltf_lights.h"
#include "scene/read/gltf_scene.h"
#include "scene/scene_error.h"

namespace {

const char* const kScene = R"({
  "camera": {"width": 8, "height": 8, "fov": 60, "position": [0, 0, 5], "look_at": [0, 0, 0]},
  "lights": [{"position": [1, 2, 5], "intensity": 10}],
  "objects": [{"file": "m.gltf", "rotation": [10, 20, 30], "smooth": 60}]
})";

// The same, lit by the file's lights.
const char* const kLitScene = R"({
  "camera": {"width": 8, "height": 8, "fov": 60, "position": [0, 0, 5], "look_at": [0, 0, 0]},
  "lights": [{"gltf": "m.gltf"}],
  "objects": [{"file": "m.gltf", "rotation": [10, 20, 30], "smooth": 60}]
})";

// Playing its first animation (nodes, morph weights, skins) over three frames, each blurred.
const char* const kPlayedScene = R"({
  "camera": {"width": 8, "height": 8, "fov": 60, "position": [0, 0, 5], "look_at": [0, 0, 0]},
  "lights": [{"position": [1, 2, 5], "intensity": 10}],
  "objects": [{"file": "m.gltf", "gltf_animation": 0, "smooth": 60}],
  "animation": {"frames": 3, "fps": 2, "shutter": 0.5}
})";

std::string folder;  // makeInputFolder's

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  candela::fuzz::limitToOneThread();
  folder = candela::fuzz::makeInputFolder("gltf", {"m.gltf"});
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  candela::fuzz::writeInput(folder + "/m.gltf", data, size);
  candela::fuzz::loadAndTrace(kScene, folder);
  candela::fuzz::loadAndTrace(kPlayedScene, folder);
  // Its first and second cameras, as a scene's camera would take them ("gltf").
  for (const uint32_t number : {0u, 1u}) {
    try {
      candela::readGltfCamera(folder + "/m.gltf", "m.gltf", number);
    } catch (const candela::SceneError&) {
    }
  }
  // Its first camera following its first animation, as "gltf_animation" plays it.
  try {
    candela::readGltfCameraPoses(folder + "/m.gltf", "m.gltf", 0, "", 0, {0.0, 0.37, 1.0, 1e3});
  } catch (const candela::SceneError&) {
  }
  // As a scene of its own (`candela render m.gltf`): framed by its bounds, or by its camera.
  std::string own;
  try {
    own = candela::gltfSceneText(folder + "/m.gltf", "m.gltf");
  } catch (const candela::SceneError&) {
    return 0;
  }
  candela::fuzz::loadAndTrace(own, folder);
  try {
    candela::readGltfLights(folder + "/m.gltf", "m.gltf");
  } catch (const candela::SceneError&) {
    return 0;
  }
  candela::fuzz::loadAndTrace(kLitScene, folder);
  return 0;
}
