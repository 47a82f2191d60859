// Random inputs shared by the geometry tests.
#pragma once

#include <random>

#include "core/vec3.h"

namespace candela::test {

// A direction uniform on the unit sphere (a normalised Gaussian vector).
inline Vec3 randomUnitVector(std::mt19937& gen) {
  std::normal_distribution<float> normal;
  for (;;) {
    const Vec3 v(normal(gen), normal(gen), normal(gen));
    if (lengthSquared(v) > 1e-6f) return normalize(v);
  }
}

}  // namespace candela::test
