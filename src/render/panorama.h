// Equirectangular panoramas: an image of every direction about the camera, longitude across and
// latitude down, as 360-degree cameras and panorama datasets store them.
//
// In the camera's OpenCV axes (+x right, +y down, +z forward), longitude runs from -180 degrees
// at the left edge through 0 (+z) in the middle to 180 at the right edge, 90 (+x) three quarters
// across; latitude from 90 (up, -y) at the top to -90 at the bottom.
#pragma once

#include <cmath>
#include <cstdint>

#include "core/constants.h"
#include "core/device.h"
#include "core/vec2.h"
#include "core/vec3.h"

namespace candela {

// The camera-space unit direction of point (px, py) of a width x height panorama.
CANDELA_HDI Vec3 panoramaDirection(float px, float py, uint32_t width, uint32_t height) {
  const float longitude = (px / float(width) - 0.5f) * (2.0f * kPi);
  const float polar = py / float(height) * kPi;  // from up
  const float s = sinf(polar);
  return Vec3(s * sinf(longitude), -cosf(polar), s * cosf(longitude));
}

// The point of a width x height panorama that camera-space direction d (any length) falls on.
CANDELA_HDI Vec2 panoramaPixel(const Vec3& d, uint32_t width, uint32_t height) {
  const float longitude = atan2f(d.x, d.z);
  const float polar =
      acosf(fminf(fmaxf(-d.y / sqrtf(d.x * d.x + d.y * d.y + d.z * d.z), -1.0f), 1.0f));
  return Vec2((longitude * (0.5f * kInvPi) + 0.5f) * float(width), polar * kInvPi * float(height));
}

}  // namespace candela
