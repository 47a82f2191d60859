// Orthonormal frame around a unit normal: local +z is the normal.
#pragma once

#include <cmath>

#include "core/vec3.h"

namespace candela {

struct Frame {
  Vec3 s, t, n;

  // Duff et al. 2017, "Building an Orthonormal Basis, Revisited": branch-free and continuous.
  CANDELA_HDI explicit Frame(const Vec3& normal) : n(normal) {
    const float sign = copysignf(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float b = n.x * n.y * a;
    s = Vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
    t = Vec3(b, sign + n.y * n.y * a, -n.y);
  }

  CANDELA_HDI Vec3 toLocal(const Vec3& v) const { return {dot(v, s), dot(v, t), dot(v, n)}; }
  CANDELA_HDI Vec3 toWorld(const Vec3& v) const { return s * v.x + t * v.y + n * v.z; }
};

}  // namespace candela
