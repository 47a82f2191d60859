// A visibility query that the integrator leaves to its caller, so that a caller holding several
// paths can trace theirs together (render/render_pixel.h).
#pragma once

#include <cstdint>

#include "geometry/ray.h"

namespace candela {

// Shadow rays stop this fraction short of their target (pbrt's ShadowEpsilon): relative, so it
// holds at any scene scale.
constexpr float kShadowEpsilon = 1e-4f;

// A shadow ray, and the radiance it adds to the path when nothing but primitive skipPrim blocks
// it.
struct ShadowQuery {
  Ray ray;
  uint32_t skipPrim = 0xffffffffu;
  Vec3 contribution;  // the path's throughput times the light's weighted share
  bool active = false;
  bool direct = false;  // next-event estimation at the first hit, set only for the passes
};

}  // namespace candela
