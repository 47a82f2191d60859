// Vec2: two floats, used for texture coordinates (u, v).
#pragma once

#include "core/device.h"

namespace candela {

struct Vec2 {
  float x = 0, y = 0;

  Vec2() = default;
  CANDELA_HDI constexpr Vec2(float x_, float y_) : x(x_), y(y_) {}
};

CANDELA_HDI Vec2 operator+(const Vec2& a, const Vec2& b) { return {a.x + b.x, a.y + b.y}; }
CANDELA_HDI Vec2 operator*(float s, const Vec2& a) { return {s * a.x, s * a.y}; }

}  // namespace candela
