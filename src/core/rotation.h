// Euler rotations as the scene contract defines them: rotate about world x by rx, then world y
// by ry, then world z by rz, i.e. R = Rz * Ry * Rx, angles in degrees, counter-clockwise when
// looking down the axis towards the origin.
#pragma once

#include <cmath>

#include "core/constants.h"
#include "core/mat3.h"

namespace candela {

inline Mat3 rotationX(float degrees) {
  const float a = degrees * (kPi / 180.0f), c = std::cos(a), s = std::sin(a);
  Mat3 r;
  r.m[1][1] = c;
  r.m[1][2] = -s;
  r.m[2][1] = s;
  r.m[2][2] = c;
  return r;
}

inline Mat3 rotationY(float degrees) {
  const float a = degrees * (kPi / 180.0f), c = std::cos(a), s = std::sin(a);
  Mat3 r;
  r.m[0][0] = c;
  r.m[0][2] = s;
  r.m[2][0] = -s;
  r.m[2][2] = c;
  return r;
}

inline Mat3 rotationZ(float degrees) {
  const float a = degrees * (kPi / 180.0f), c = std::cos(a), s = std::sin(a);
  Mat3 r;
  r.m[0][0] = c;
  r.m[0][1] = -s;
  r.m[1][0] = s;
  r.m[1][1] = c;
  return r;
}

inline Mat3 eulerRotation(const Vec3& degrees) {
  return rotationZ(degrees.z) * rotationY(degrees.y) * rotationX(degrees.x);
}

// The Euler angles (degrees) of rotation r, so that eulerRotation of them is r (host only). x comes
// from the third row and z from x and the first two rows (Shoemake's order of solving), so that
// near y = +-90 degrees, where x and z turn about one axis, the pair still gives r to rounding.
inline Vec3 eulerDegrees(const Mat3& r) {
  const auto& m = r.m;
  const double x = std::atan2(double(m[2][1]), double(m[2][2]));
  const double y = std::atan2(-double(m[2][0]), std::hypot(double(m[0][0]), double(m[1][0])));
  const double sx = std::sin(x), cx = std::cos(x);
  const double z = std::atan2(sx * m[0][2] - cx * m[0][1], cx * m[1][1] - sx * m[1][2]);
  const double degrees = 180.0 / kPiDouble;
  return Vec3(float(x * degrees), float(y * degrees), float(z * degrees));
}

// The Euler angles of rotation r nearest `near` (host only): of the two triples that make r,
// (x, y, z) and (x + 180, 180 - y, z + 180), each component moved by whole turns to within 180
// degrees of near's, the one that differs from near least. Keys made so from a sequence of poses
// (a glTF camera's, frame by frame) turn the short way between them, where tracks interpolate.
inline Vec3 eulerDegreesNear(const Mat3& r, const Vec3& near) {
  const Vec3 a = eulerDegrees(r);
  const auto closest = [](float angle, float to) {
    return angle + 360.0f * std::round((to - angle) / 360.0f);
  };
  const auto nearest = [&](const Vec3& e) {
    return Vec3(closest(e.x, near.x), closest(e.y, near.y), closest(e.z, near.z));
  };
  const Vec3 first = nearest(a), second = nearest(Vec3(a.x + 180.0f, 180.0f - a.y, a.z + 180.0f));
  const auto spread = [&](const Vec3& e) {
    return std::fabs(e.x - near.x) + std::fabs(e.y - near.y) + std::fabs(e.z - near.z);
  };
  return spread(second) < spread(first) ? second : first;
}

// Inverse of a general 3x3 matrix (host only: used for K and normal transforms).
// Returns false when the matrix is singular.
inline bool invert(const Mat3& a, Mat3* out) {
  const auto& m = a.m;
  const double c00 = double(m[1][1]) * m[2][2] - double(m[1][2]) * m[2][1];
  const double c01 = double(m[1][2]) * m[2][0] - double(m[1][0]) * m[2][2];
  const double c02 = double(m[1][0]) * m[2][1] - double(m[1][1]) * m[2][0];
  const double det = m[0][0] * c00 + m[0][1] * c01 + m[0][2] * c02;
  if (det == 0.0 || !std::isfinite(det)) return false;
  const double inv = 1.0 / det;
  Mat3 r;
  r.m[0][0] = float(c00 * inv);
  r.m[1][0] = float(c01 * inv);
  r.m[2][0] = float(c02 * inv);
  r.m[0][1] = float((double(m[0][2]) * m[2][1] - double(m[0][1]) * m[2][2]) * inv);
  r.m[1][1] = float((double(m[0][0]) * m[2][2] - double(m[0][2]) * m[2][0]) * inv);
  r.m[2][1] = float((double(m[0][1]) * m[2][0] - double(m[0][0]) * m[2][1]) * inv);
  r.m[0][2] = float((double(m[0][1]) * m[1][2] - double(m[0][2]) * m[1][1]) * inv);
  r.m[1][2] = float((double(m[0][2]) * m[1][0] - double(m[0][0]) * m[1][2]) * inv);
  r.m[2][2] = float((double(m[0][0]) * m[1][1] - double(m[0][1]) * m[1][0]) * inv);
  *out = r;
  return true;
}

}  // namespace candela
