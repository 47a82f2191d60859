// Lights that next-event estimation samples: point lights and sphere lights.
//
// A sphere light is the surface of one of the scene's spheres: its centre and radius are that
// sphere's, its radiance is the sphere's emissive material's. The sphere names the light back
// (Sphere::light), so BSDF-sampled rays that hit it are weighted by multiple importance sampling.
#pragma once

#include <cstdint>

#include "core/vec3.h"

namespace candela {

enum class LightType : uint32_t { Point = 0, Sphere = 1 };

struct Light {
  LightType type = LightType::Point;
  Vec3 position;        // point lights
  Vec3 power;           // point lights: total emitted power (color * intensity)
  uint32_t sphere = 0;  // sphere lights: their index in the scene's spheres
  // The probability that next-event estimation samples this light at a shading point: 1 when
  // the scene has at most kSampleEveryLightUpTo lights (each gets its own shadow ray), else one
  // light is picked in proportion to power. selectCdf is the running sum of the picking
  // probabilities up to and including this light, 1 from the last light with any power on.
  float selectPmf = 0;
  float selectCdf = 0;
};

// Up to this many lights every shading point samples each of them, since the extra noise of
// picking one outweighs the shadow rays it saves (docs/performance.md). Beyond it the cost per
// shading point would grow with the light count, and one light is picked.
constexpr uint32_t kSampleEveryLightUpTo = 8;

}  // namespace candela
