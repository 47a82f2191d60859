// Sampling a triangle by the solid angle it subtends (Arvo 1995, in pbrt-v4's form): uniform over
// the spherical triangle that the triangle projects to on the unit sphere around a point.
//
// Where a triangle is near and large, sampling by solid angle spreads the samples as the
// directions it covers do, instead of crowding them where its area is seen edge-on; pbrt-v4
// falls back to area sampling where the spherical triangle is too small for float precision or
// nearly a hemisphere, as candela does (kMinSphericalSolidAngle, kMaxSphericalSolidAngle).
#pragma once

#include <cmath>

#include "core/constants.h"
#include "core/vec3.h"

namespace candela {

constexpr float kMinSphericalSolidAngle = 3e-4f;
constexpr float kMaxSphericalSolidAngle = 6.22f;

// The solid angle of the spherical triangle of unit directions a, b, c (Van Oosterom and
// Strackee 1983).
CANDELA_HDI float sphericalTriangleArea(const Vec3& a, const Vec3& b, const Vec3& c) {
  return fabsf(2.0f * atan2f(dot(a, cross(b, c)), 1.0f + dot(a, b) + dot(a, c) + dot(b, c)));
}

CANDELA_HDI float angleBetween(const Vec3& v1, const Vec3& v2) {
  return dot(v1, v2) < 0.0f ? kPi - 2.0f * asinf(minf(1.0f, 0.5f * length(v1 + v2)))
                            : 2.0f * asinf(minf(1.0f, 0.5f * length(v2 - v1)));
}

// v with its component along unit w removed.
CANDELA_HDI Vec3 gramSchmidt(const Vec3& v, const Vec3& w) { return v - dot(v, w) * w; }

// Barycentrics (b0, b1, b2) of a point of triangle (p0, p1, p2) whose direction from p is uniform
// over the triangle's solid angle, from uniform (u1, u2), and that density (1 / solid angle).
// False for a triangle degenerate as seen from p.
CANDELA_HDI bool sampleSphericalTriangle(const Vec3& p0, const Vec3& p1, const Vec3& p2,
                                         const Vec3& p, float u1, float u2, float b[3],
                                         float* pdf) {
  const Vec3 a = normalize(p0 - p), bv = normalize(p1 - p), c = normalize(p2 - p);
  Vec3 nab = cross(a, bv), nbc = cross(bv, c), nca = cross(c, a);
  if (!(lengthSquared(nab) > 0.0f) || !(lengthSquared(nbc) > 0.0f) || !(lengthSquared(nca) > 0.0f))
    return false;
  nab = normalize(nab);
  nbc = normalize(nbc);
  nca = normalize(nca);
  // The spherical triangle's angles at its vertices; their sum less pi is its area.
  const float alpha = angleBetween(nab, -nca), beta = angleBetween(nbc, -nab),
              gamma = angleBetween(nca, -nbc);
  const float areaPlusPi = alpha + beta + gamma;
  const float area = areaPlusPi - kPi;
  if (!(area > 0.0f)) return false;
  *pdf = 1.0f / area;
  // The sub-triangle of area u1 * area: its third vertex c' on the arc from a to c.
  const float sampledPlusPi = kPi + u1 * (areaPlusPi - kPi);
  const float cosAlpha = cosf(alpha), sinAlpha = sinf(alpha);
  const float sinPhi = sinf(sampledPlusPi) * cosAlpha - cosf(sampledPlusPi) * sinAlpha;
  const float cosPhi = cosf(sampledPlusPi) * cosAlpha + sinf(sampledPlusPi) * sinAlpha;
  const float k1 = cosPhi + cosAlpha, k2 = sinPhi - sinAlpha * dot(a, bv);
  float cosBp =
      (k2 + (k2 * cosPhi - k1 * sinPhi) * cosAlpha) / ((k2 * sinPhi + k1 * cosPhi) * sinAlpha);
  cosBp = cosBp < -1.0f ? -1.0f : (cosBp > 1.0f ? 1.0f : cosBp);
  const float sinBp = sqrtf(maxf(0.0f, 1.0f - cosBp * cosBp));
  const Vec3 cp = cosBp * a + sinBp * normalize(gramSchmidt(c, a));
  // A direction uniform on the arc from b to c', by cos(theta) uniform along it.
  const float cosTheta = 1.0f - u2 * (1.0f - dot(cp, bv));
  const float sinTheta = sqrtf(maxf(0.0f, 1.0f - cosTheta * cosTheta));
  const Vec3 w = cosTheta * bv + sinTheta * normalize(gramSchmidt(cp, bv));
  // Where w meets the triangle's plane, as barycentrics (Moller-Trumbore).
  const Vec3 e1 = p1 - p0, e2 = p2 - p0, s1 = cross(w, e2);
  const float divisor = dot(s1, e1);
  if (!(fabsf(divisor) > 0.0f)) return false;
  const Vec3 s = p - p0;
  float b1 = dot(s, s1) / divisor, b2 = dot(w, cross(s, e1)) / divisor;
  b1 = b1 < 0.0f ? 0.0f : (b1 > 1.0f ? 1.0f : b1);
  b2 = b2 < 0.0f ? 0.0f : (b2 > 1.0f ? 1.0f : b2);
  if (b1 + b2 > 1.0f) {
    const float sum = b1 + b2;
    b1 /= sum;
    b2 /= sum;
  }
  b[0] = 1.0f - b1 - b2;
  b[1] = b1;
  b[2] = b2;
  return true;
}

}  // namespace candela
