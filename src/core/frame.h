// Orthonormal frame around a unit normal: local +z is the normal.
#pragma once

#include <cmath>

#include "core/vec3.h"

namespace candela {

// Where the frame turns over: normals with n.z above it take one branch, below it the other.
// Duff et al. place it at n.z = 0, but modelled geometry is full of normals whose z is 0 only
// up to rounding (a wall whose normal lies in the x-y plane: its cross product's z is exactly 0
// without fused multiply-adds and +-1e-9 with them): there the two backends, or two builds,
// would turn the frame over differently and send the same sample in mirrored directions. Any
// n.z far from -1 serves (the formula below loses precision only as sign + n.z nears 0), and
// none is more likely than another from rounding alone.
constexpr float kFrameTurnZ = -1e-4f;

struct Frame {
  Vec3 s, t, n;

  // Duff et al. 2017, "Building an Orthonormal Basis, Revisited": branch-free and continuous
  // but where it turns over (kFrameTurnZ).
  CANDELA_HDI_ALWAYS explicit Frame(const Vec3& normal) : n(normal) {
    const float sign = n.z >= kFrameTurnZ ? 1.0f : -1.0f;
    const float a = -1.0f / (sign + n.z);
    const float b = n.x * n.y * a;
    s = Vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
    t = Vec3(b, sign + n.y * n.y * a, -n.y);
  }

  // The frame whose s is `tangent` made perpendicular to the normal (t = n x s); Frame(normal)
  // where the tangent has no part in the normal's plane.
  CANDELA_HDI Frame(const Vec3& normal, const Vec3& tangent) : n(normal) {
    const Vec3 along = tangent - dot(tangent, normal) * normal;
    const float length2 = dot(along, along);
    if (!(length2 > 0.0f)) {
      *this = Frame(normal);
      return;
    }
    s = along * (1.0f / sqrtf(length2));
    t = cross(normal, s);
  }

  CANDELA_HDI Vec3 toLocal(const Vec3& v) const { return {dot(v, s), dot(v, t), dot(v, n)}; }
  CANDELA_HDI Vec3 toWorld(const Vec3& v) const { return s * v.x + t * v.y + n * v.z; }
};

}  // namespace candela
