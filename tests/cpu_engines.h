// The CPU ray engines a build has, for tests that must hold on each: candela's own BVH always,
// Embree where the build has it.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "backends/cpu/cpu_engine.h"
#include "backends/cpu/cpu_renderer.h"
#include "scene/flatten.h"
#include "scene/read/scene_loader.h"

namespace candela::test {

inline std::vector<CpuEngine> builtCpuEngines() {
  std::vector<CpuEngine> list = {CpuEngine::Bvh};
  if (embreeAvailable()) list.push_back(CpuEngine::Embree);
  return list;
}

// A parameterised test's name for its engine.
inline std::string cpuEngineName(const ::testing::TestParamInfo<CpuEngine>& engine) {
  return engine.param == CpuEngine::Embree ? "Embree" : "Bvh";
}

// The image of scene `json` (files relative to `baseDir`) traced by `engine` alone: with Embree,
// no BVH of candela's own is built.
inline ImageRGB renderWithEngine(const std::string& json, CpuEngine engine,
                                 const std::string& baseDir) {
  SceneDesc desc = parseSceneText(json, "test.json", baseDir);
  if (engine == CpuEngine::Embree) desc.ownBvh = OwnBvh::None;
  const SceneData data = flattenScene(desc);
  CpuRenderer renderer(engine);
  renderer.setScene(data, SceneChange::Structure);
  return renderer.render(RenderOptions{}).image;
}

}  // namespace candela::test
