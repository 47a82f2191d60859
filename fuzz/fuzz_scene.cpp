// See fuzz_scene.h.
#include "fuzz_scene.h"

#include <tbb/global_control.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include "geometry/bvh_tracer.h"
#include "render/render_pixel.h"
#include "scene/animation.h"
#include "scene/flatten.h"
#include "scene/read/scene_loader.h"
#include "scene/scene_error.h"

namespace candela::fuzz {
namespace {

// Two opposite corners and the centre of the image, one sample each, paths cut at a few bounces:
// enough to reach traversal, materials and lights without making slow inputs of long paths.
void traceSomePixels(SceneData& scene) {
  scene.settings.maxDepth = std::min<uint32_t>(scene.settings.maxDepth, 4);
  const SceneView view = scene.view();
  RayCounters counters;
  const uint32_t w = scene.camera.width, h = scene.camera.height;
  const uint32_t pixels[][2] = {{0, 0}, {w / 2, h / 2}, {w - 1, h - 1}};
  for (const auto& p : pixels)
    renderPixelSamples(view, BvhTracer{&view}, p[0], p[1], 0, 1, counters);
}

// makeInputFolder's folder and files, removed at exit.
std::string inputFolder;
std::vector<std::string> inputNames;

void removeInputFolder() {
  for (const std::string& name : inputNames) std::remove((inputFolder + "/" + name).c_str());
  rmdir(inputFolder.c_str());
}

}  // namespace

std::string makeInputFolder(const std::string& target, const std::vector<std::string>& names) {
  std::string pattern = "/tmp/candela-" + target + "-fuzz-XXXXXX";
  if (!mkdtemp(pattern.data())) std::abort();
  inputFolder = pattern;
  inputNames = names;
  std::atexit(removeInputFolder);
  return inputFolder;
}

void writeInput(const std::string& path, const void* data, size_t size) {
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) std::abort();
  std::fwrite(data, 1, size, file);
  std::fclose(file);
}

void limitToOneThread() {
  static const auto control =
      std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, 1);
}

void loadAndTrace(const std::string& text, const std::string& baseDir) {
  try {
    const SceneDesc desc = parseSceneText(text, "fuzz.json", baseDir);
    const uint32_t frames = desc.animation ? desc.animation->frames : 1;
    for (const uint32_t frame : {0u, frames - 1}) {
      SceneData scene = flattenScene(sceneAtFrame(desc, frame));
      traceSomePixels(scene);
      if (frames == 1) break;
    }
  } catch (const SceneError&) {
  }
}

}  // namespace candela::fuzz
