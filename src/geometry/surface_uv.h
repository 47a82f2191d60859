// Texture coordinates of points on the primitives.
//
// Triangles interpolate their vertices' uvs by barycentrics ((0, 0) without uvs). Spheres map
// equirectangularly, in the environment map's orientation with v flipped to OBJ's convention:
// for d = (p - center) / radius, u = 0.5 + atan2(d.x, -d.z) / (2 pi) wrapped into [0, 1) and
// v = 1 - acos(d.y) / pi, so v = 0 at the bottom pole (-y) and 1 at the top.
#pragma once

#include <cmath>

#include "core/constants.h"
#include "core/trig.h"
#include "core/vec2.h"
#include "core/vec3.h"
#include "geometry/geometry_view.h"

namespace candela {

CANDELA_HDI Vec2 triangleUv(const GeometryView& scene, const Triangle& tri, float b1, float b2) {
  if (scene.uvCount == 0) return Vec2(0.0f, 0.0f);
  const float b0 = 1.0f - b1 - b2;
  return b0 * scene.uvs[tri.v[0]] + b1 * scene.uvs[tri.v[1]] + b2 * scene.uvs[tri.v[2]];
}

// `d` is the unit direction from the sphere's centre to the point.
CANDELA_HDI Vec2 sphereUv(const Vec3& d) {
  float u = 0.5f + atan2Approx(d.x, -d.z) * (0.5f / kPi);
  if (u >= 1.0f) u -= 1.0f;
  const float cosTheta = fminf(1.0f, fmaxf(-1.0f, d.y));
  return Vec2(u, 1.0f - acosf(cosTheta) * (1.0f / kPi));
}

}  // namespace candela
