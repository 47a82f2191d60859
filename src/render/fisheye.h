// Fisheye cameras: OpenCV's fisheye model (cv::fisheye::projectPoints with its coefficients D =
// k1, k2, k3, k4), an equidistant lens whose image radius grows with the angle from the axis.
//
// A camera-space direction (X, Y, Z) at angle theta = atan2(sqrt(X^2 + Y^2), Z) from the optical
// axis lands at radius theta_d = theta (1 + k1 theta^2 + k2 theta^4 + k3 theta^6 + k4 theta^8)
// in normalized coordinates, along its own azimuth: (x', y') = theta_d (X, Y) / sqrt(X^2 + Y^2),
// and K maps (x', y', 1) to the pixel. OpenCV takes theta = atan(r) for points in front of the
// camera; here theta runs on past 90 degrees, so a lens of more than 180 degrees sees behind. A
// camera ray finds theta from theta_d by Newton's method, which the scene loader has checked
// has one solution below 180 degrees over the image (scene/camera_resolve.cpp).
#pragma once

#include <cmath>

#include "core/device.h"
#include "core/vec2.h"
#include "core/vec3.h"
#include "render/lens_distortion.h"

namespace candela {

// theta_d of angle theta for the fisheye coefficients in d (k1 to k4), and its derivative.
CANDELA_HDI float fisheyeRadius(const LensDistortion& d, float theta, float* derivative = nullptr) {
  const float t2 = theta * theta;
  if (derivative)
    *derivative =
        1.0f + t2 * (3.0f * d.k1 + t2 * (5.0f * d.k2 + t2 * (7.0f * d.k3 + t2 * 9.0f * d.k4)));
  return theta * (1.0f + t2 * (d.k1 + t2 * (d.k2 + t2 * (d.k3 + t2 * d.k4))));
}

// The angle from the axis whose image radius is `radius`: Newton's method from the radius itself
// (the undistorted equidistant lens's answer), until a step moves less than a part in 10^7.
CANDELA_HDI float fisheyeAngle(const LensDistortion& d, float radius) {
  float theta = radius;
  for (int step = 0; step < 20; ++step) {
    float slope;
    const float error = fisheyeRadius(d, theta, &slope) - radius;
    if (!(slope > 0.0f)) break;  // the lens folds here: the loader refuses such images
    const float delta = error / slope;
    theta -= delta;
    if (fabsf(delta) <= 1e-7f * (1.0f + theta)) break;
  }
  return theta;
}

// The camera-space unit direction of normalized image point n (K^-1 of the pixel, z = 1).
CANDELA_HD_NOINLINE inline Vec3 fisheyeDirection(const LensDistortion& d, const Vec2& n) {
  const float radius = sqrtf(n.x * n.x + n.y * n.y);
  if (!(radius > 0.0f)) return Vec3(0.0f, 0.0f, 1.0f);
  const float theta = fisheyeAngle(d, radius);
  const float s = sinf(theta) / radius;
  return Vec3(n.x * s, n.y * s, cosf(theta));
}

// The normalized image point of camera-space direction c (any length; not straight back).
CANDELA_HDI Vec2 fisheyePoint(const LensDistortion& d, const Vec3& c) {
  const float rho = sqrtf(c.x * c.x + c.y * c.y);
  if (!(rho > 0.0f)) return Vec2(0.0f, 0.0f);
  const float scale = fisheyeRadius(d, atan2f(rho, c.z)) / rho;
  return Vec2(c.x * scale, c.y * scale);
}

}  // namespace candela
