// Unit quaternions for interpolating rotations: a motion-blurred camera turns between its poses
// along the shortest arc at constant angular speed (slerp), as pbrt-v4's AnimatedTransform does.
#pragma once

#include <cmath>

#include "core/mat3.h"

namespace candela {

struct Quaternion {
  float x = 0, y = 0, z = 0, w = 1;  // w + xi + yj + zk
};

// The rotation matrix of unit quaternion q.
CANDELA_HDI Mat3 rotationMatrix(const Quaternion& q) {
  const float xx = q.x * q.x, yy = q.y * q.y, zz = q.z * q.z;
  const float xy = q.x * q.y, xz = q.x * q.z, yz = q.y * q.z;
  const float wx = q.w * q.x, wy = q.w * q.y, wz = q.w * q.z;
  Mat3 r;
  r.m[0][0] = 1 - 2 * (yy + zz), r.m[0][1] = 2 * (xy - wz), r.m[0][2] = 2 * (xz + wy);
  r.m[1][0] = 2 * (xy + wz), r.m[1][1] = 1 - 2 * (xx + zz), r.m[1][2] = 2 * (yz - wx);
  r.m[2][0] = 2 * (xz - wy), r.m[2][1] = 2 * (yz + wx), r.m[2][2] = 1 - 2 * (xx + yy);
  return r;
}

// The unit quaternion of rotation r (orthonormal, determinant +1), by Shepperd's method: the
// square root is taken of the largest of the four diagonal sums, which keeps it well away from 0
// (host only).
inline Quaternion quaternionOf(const Mat3& r) {
  const auto& m = r.m;
  const double trace = double(m[0][0]) + m[1][1] + m[2][2];
  double q[4];  // x, y, z, w
  if (trace > m[0][0] && trace > m[1][1] && trace > m[2][2]) {
    const double s = 2 * std::sqrt(1 + trace);
    q[3] = s / 4;
    q[0] = (double(m[2][1]) - m[1][2]) / s;
    q[1] = (double(m[0][2]) - m[2][0]) / s;
    q[2] = (double(m[1][0]) - m[0][1]) / s;
  } else {
    const int i = m[0][0] >= m[1][1] && m[0][0] >= m[2][2] ? 0 : (m[1][1] >= m[2][2] ? 1 : 2);
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    const double s = 2 * std::sqrt(1 + double(m[i][i]) - m[j][j] - m[k][k]);
    q[i] = s / 4;
    q[j] = (double(m[j][i]) + m[i][j]) / s;
    q[k] = (double(m[k][i]) + m[i][k]) / s;
    q[3] = (double(m[k][j]) - m[j][k]) / s;
  }
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  return {float(q[0] / n), float(q[1] / n), float(q[2] / n), float(q[3] / n)};
}

// The rotation a fraction t of the way from a to b along the shorter arc (q and -q are one
// rotation), at constant angular speed.
CANDELA_HDI Quaternion slerp(const Quaternion& a, Quaternion b, float t) {
  float cosAngle = a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w;
  if (cosAngle < 0.0f) {
    b = {-b.x, -b.y, -b.z, -b.w};
    cosAngle = -cosAngle;
  }
  float wa = 1.0f - t, wb = t;
  // Nearly equal rotations: sin(angle) would lose its digits, and the chord is the arc.
  if (cosAngle < 0.9995f) {
    const float angle = acosf(cosAngle), invSin = 1.0f / sinf(angle);
    wa = sinf(wa * angle) * invSin;
    wb = sinf(wb * angle) * invSin;
  }
  Quaternion q{wa * a.x + wb * b.x, wa * a.y + wb * b.y, wa * a.z + wb * b.z, wa * a.w + wb * b.w};
  const float invNorm = 1.0f / sqrtf(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
  return {q.x * invNorm, q.y * invNorm, q.z * invNorm, q.w * invNorm};
}

}  // namespace candela
