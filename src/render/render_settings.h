// How a scene is rendered: samples, path length, integrator, pixel filter and seed.
#pragma once

#include <cstdint>

#include "render/pixel_filter.h"

namespace candela {

enum class IntegratorType : uint32_t { Path = 0, Direct = 1 };

// Whether samples start light subpaths from point lights (render/light_path.h): `Auto` lets a
// pilot render decide for each render (backends/light_path_pilot.h).
enum class LightPaths : uint32_t { Auto = 0, On = 1, Off = 2 };

// "auto", "on" or "off", as the scene file spells it.
constexpr const char* lightPathsName(LightPaths lightPaths) {
  return lightPaths == LightPaths::Auto ? "auto" : lightPaths == LightPaths::On ? "on" : "off";
}

struct RenderSettings {
  uint32_t spp = 64;  // samples per pixel (the scene's camera.spp)
  uint32_t maxDepth = 8;
  IntegratorType integrator = IntegratorType::Path;
  bool antialiasing = true;  // false: every sample through the pixel centre, whatever the filter
  PixelFilter filter;
  LightPaths lightPaths = LightPaths::Auto;
  // Next-event estimation at smooth-shaded faces follows their smooth surface near the shadow
  // terminator (render/shadow_ray_origin.h).
  bool smoothTerminator = true;
  uint64_t seed = 0;
};

}  // namespace candela
