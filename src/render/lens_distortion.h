// Lens distortion: OpenCV's model of a real lens (cv::projectPoints with distCoeffs k1, k2, p1,
// p2, k3, k4, k5, k6), so that a camera calibrated by OpenCV renders the images it takes.
//
// A camera-space point (X, Y, Z) has normalized coordinates x = X / Z, y = Y / Z, r^2 = x^2 + y^2;
// the lens moves them to
//   x' = x R + 2 p1 x y + p2 (r^2 + 2 x^2),   y' = y R + p1 (r^2 + 2 y^2) + 2 p2 x y,
//   R = (1 + k1 r^2 + k2 r^4 + k3 r^6) / (1 + k4 r^2 + k5 r^4 + k6 r^6),
// and K maps (x', y', 1) to the pixel. A camera ray undoes this: from the pixel's (x', y') by
// Newton's method, which the scene loader has checked converges to the one solution over the image
// (scene/camera_resolve.cpp).
#pragma once

#include <cmath>
#include <cstdint>

#include "core/device.h"
#include "core/vec2.h"

namespace candela {

struct LensDistortion {
  float k1 = 0, k2 = 0, p1 = 0, p2 = 0, k3 = 0, k4 = 0, k5 = 0, k6 = 0;
  bool enabled = false;  // false: a pinhole's straight lines (every coefficient 0)
  // Named, so that copies keep them zero: frames compare cameras byte by byte.
  uint8_t padding[3] = {};
};

// The distorted normalized coordinates of (x, y), and in *jacobian (row-major, if not null) their
// derivatives by x and y.
CANDELA_HDI Vec2 distortNormalized(const LensDistortion& d, float x, float y,
                                   float* jacobian = nullptr) {
  const float r2 = x * x + y * y;
  const float num = 1.0f + r2 * (d.k1 + r2 * (d.k2 + r2 * d.k3));
  const float den = 1.0f + r2 * (d.k4 + r2 * (d.k5 + r2 * d.k6));
  const float radial = num / den;
  const Vec2 out(x * radial + 2.0f * d.p1 * x * y + d.p2 * (r2 + 2.0f * x * x),
                 y * radial + d.p1 * (r2 + 2.0f * y * y) + 2.0f * d.p2 * x * y);
  if (jacobian) {
    const float dNum = d.k1 + r2 * (2.0f * d.k2 + r2 * 3.0f * d.k3);
    const float dDen = d.k4 + r2 * (2.0f * d.k5 + r2 * 3.0f * d.k6);
    const float dRadial = (dNum * den - num * dDen) / (den * den);  // by r^2
    const float cross = 2.0f * x * y * dRadial + 2.0f * d.p1 * x + 2.0f * d.p2 * y;
    jacobian[0] = radial + 2.0f * x * x * dRadial + 2.0f * d.p1 * y + 6.0f * d.p2 * x;
    jacobian[1] = cross;
    jacobian[2] = cross;
    jacobian[3] = radial + 2.0f * y * y * dRadial + 6.0f * d.p1 * y + 2.0f * d.p2 * x;
  }
  return out;
}

// The undistorted normalized coordinates whose distortion is `target`: Newton's method from the
// target itself, until a step moves less than a part in 10^7 (or 20 steps). Out of line: most
// cameras have no distortion.
CANDELA_HD_NOINLINE inline Vec2 undistortNormalized(const LensDistortion& d, const Vec2& target) {
  float x = target.x, y = target.y;
  for (int step = 0; step < 20; ++step) {
    float j[4];
    const Vec2 at = distortNormalized(d, x, y, j);
    const float ex = at.x - target.x, ey = at.y - target.y;
    const float det = j[0] * j[3] - j[1] * j[2];
    if (!(det > 0.0f)) break;  // the lens folds here: the loader refuses such images
    const float dx = (j[3] * ex - j[1] * ey) / det, dy = (j[0] * ey - j[2] * ex) / det;
    x -= dx;
    y -= dy;
    if (fabsf(dx) + fabsf(dy) <= 1e-7f * (1.0f + fabsf(x) + fabsf(y))) break;
  }
  return Vec2(x, y);
}

}  // namespace candela
