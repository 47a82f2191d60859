// Lights that next-event estimation samples: point lights and the emitting surfaces of the scene.
//
// Every emitter is a light. A point light is declared in the scene; the environment, unless it
// is black, is a light (render/environment.h); every sphere and every
// triangle whose material is emissive (a declared sphere light included) is an area light whose
// shape is that primitive: its position and size are the primitive's, its radiance the
// material's, and the primitive names the light back (Sphere::light, or the triangle lights'
// order: see lightOfPrimitive), so BSDF-sampled rays that hit it are weighted by multiple
// importance sampling.
#pragma once

#include <cstdint>

#include "core/vec3.h"

namespace candela {

enum class LightType : uint32_t { Point = 0, Sphere = 1, Triangle = 2, Environment = 3 };

// Lights outside the light tree (the environment, lights without power) have this trail.
constexpr uint64_t kNotInLightTree = ~uint64_t(0);

struct Light {
  LightType type = LightType::Point;
  Vec3 position;       // point lights
  Vec3 power;          // point lights: total emitted power (color * intensity)
  uint32_t shape = 0;  // area lights: index into the scene's spheres or triangles, by type
  // The light's path in the light tree (render/light_tree.h): its slot at each level, 3 bits
  // a level from the lowest, the root's first.
  uint64_t trail = kNotInLightTree;
};

// Up to this many point lights, and no other light, every shading point samples each of them:
// a point light's shadow ray has no sampling noise of its own, so the noise of picking one
// outweighs the rays it saves (docs/performance.md). An area light or the environment is sampled
// with noise anyway, and there picking one light costs less per unit of error (the
// Cornell box's quad: 0.83x the time to equal error of sampling both its triangles). Beyond
// kSampleEveryLightUpTo the cost per shading point would grow with the light count. Otherwise
// one light is picked: the environment in a fixed share of the picks, the rest from the light
// tree (render/light_selection.h).
constexpr uint32_t kSampleEveryLightUpTo = 8;

// Whether next-event estimation samples each of `count` lights (else one is picked).
inline bool sampleEveryLight(const Light* lights, size_t count) {
  if (count > kSampleEveryLightUpTo) return false;
  for (size_t i = 0; i < count; ++i)
    if (lights[i].type != LightType::Point) return false;
  return true;
}

}  // namespace candela
