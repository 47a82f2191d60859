// Beer's law: what a path keeps of its throughput over a stretch of an absorbing medium (the inside
// of glass with a transmission_depth, render/material.h).
#pragma once

#include <cmath>

#include "core/device.h"
#include "core/vec3.h"

namespace candela {

// exp(-sigma t) in each channel, for absorption coefficients sigma >= 0 and a distance t that may
// be infinite (a ray that leaves the scene from inside); a channel that absorbs nothing keeps all
// of itself, rather than the NaN of 0 times infinity.
CANDELA_HDI Vec3 beerTransmittance(const Vec3& sigma, float t) {
  return {sigma.x > 0.0f ? expf(-sigma.x * t) : 1.0f, sigma.y > 0.0f ? expf(-sigma.y * t) : 1.0f,
          sigma.z > 0.0f ? expf(-sigma.z * t) : 1.0f};
}

}  // namespace candela
