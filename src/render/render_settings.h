// How a scene is rendered: samples, path length, integrator, pixel filter and seed.
#pragma once

#include <cstdint>

#include "render/pixel_filter.h"

namespace candela {

enum class IntegratorType : uint32_t { Path = 0, Direct = 1 };

// Whether samples start light subpaths from point lights (render/light_path.h): `Auto` lets a
// pilot render decide for each render (backends/render_pilot.h).
enum class LightPaths : uint32_t { Auto = 0, On = 1, Off = 2 };

// "auto", "on" or "off", as the scene file spells it.
constexpr const char* lightPathsName(LightPaths lightPaths) {
  return lightPaths == LightPaths::Auto ? "auto" : lightPaths == LightPaths::On ? "on" : "off";
}

// The most light samples a path's first interaction takes (RenderSettings::firstHitLightSamples;
// render/shadow_query.h holds that many queries).
constexpr uint32_t kMaxFirstHitLightSamples = 4;

// RenderSettings::lightPathDepth for connections at every interaction ("all").
constexpr uint32_t kEveryInteraction = UINT32_MAX;

struct RenderSettings {
  uint32_t spp = 64;  // samples per pixel (the scene's camera.spp)
  uint32_t maxDepth = 8;
  IntegratorType integrator = IntegratorType::Path;
  bool antialiasing = true;  // false: every sample through the pixel centre, whatever the filter
  PixelFilter filter;
  LightPaths lightPaths = LightPaths::Auto;
  // How many lights next-event estimation samples at a path's first interaction, 1 to
  // kMaxFirstHitLightSamples; 0 ("auto"): a pilot render decides (backends/render_pilot.h).
  uint32_t firstHitLightSamples = 0;
  // The deepest interaction of a camera path that is connected to its sample's light vertex
  // (render/light_path.h), from 1; kEveryInteraction for all (the default); 0 ("auto"): a pilot
  // render decides between all and the first two (backends/render_pilot.h), which is not the
  // default since the bench's renders of more samples than the pilot's found the limit dearer
  // than it did (docs/performance.md, *Connections at the first two interactions*).
  uint32_t lightPathDepth = kEveryInteraction;
  // Next-event estimation at smooth-shaded faces follows their smooth surface near the shadow
  // terminator (render/shadow_ray_origin.h).
  bool smoothTerminator = true;
  uint64_t seed = 0;
};

}  // namespace candela
