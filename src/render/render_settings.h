// How a scene is rendered: samples, path length, integrator, pixel filter and seed.
#pragma once

#include <cstdint>

namespace candela {

enum class IntegratorType : uint32_t { Path = 0, Direct = 1 };

struct RenderSettings {
  uint32_t spp = 64;  // samples per pixel (the scene's camera.spp)
  uint32_t maxDepth = 8;
  IntegratorType integrator = IntegratorType::Path;
  bool antialiasing = true;
  uint64_t seed = 0;
};

}  // namespace candela
