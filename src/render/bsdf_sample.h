// What sampling a BSDF gives: a direction and the factor the path throughput is multiplied by.
#pragma once

#include "core/vec3.h"

namespace candela {

struct BsdfSample {
  Vec3 wi;
  Vec3 weight;         // f |cos(wi)| / pdf
  float pdf = 0.0f;    // solid-angle density; meaningful only when !delta
  bool delta = false;  // from a lobe of zero width (mirror or smooth glass): no MIS, no density
  // The relative index eta_t / eta_i crossed by a transmission (1 for a reflection): radiance
  // is scaled by 1 / eta^2 there, which Russian roulette takes out again.
  float eta = 1.0f;
};

}  // namespace candela
