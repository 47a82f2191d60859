// Vec3: three floats, used for points, directions, normals and linear RGB alike.
#pragma once

#include <cmath>

#include "core/constants.h"
#include "core/device.h"

namespace candela {

struct Vec3 {
  float x = 0, y = 0, z = 0;

  Vec3() = default;
  CANDELA_HDI constexpr Vec3(float x_, float y_, float z_) : x(x_), y(y_), z(z_) {}
  CANDELA_HDI explicit constexpr Vec3(float s) : x(s), y(s), z(s) {}

  CANDELA_HDI float operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  CANDELA_HDI float& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }

  CANDELA_HDI Vec3 operator-() const { return {-x, -y, -z}; }
  CANDELA_HDI Vec3& operator+=(const Vec3& o) { x += o.x; y += o.y; z += o.z; return *this; }
  CANDELA_HDI Vec3& operator-=(const Vec3& o) { x -= o.x; y -= o.y; z -= o.z; return *this; }
  CANDELA_HDI Vec3& operator*=(const Vec3& o) { x *= o.x; y *= o.y; z *= o.z; return *this; }
  CANDELA_HDI Vec3& operator*=(float s) { x *= s; y *= s; z *= s; return *this; }
  CANDELA_HDI Vec3& operator/=(float s) { return *this *= 1.0f / s; }
};

CANDELA_HDI Vec3 operator+(Vec3 a, const Vec3& b) { return a += b; }
CANDELA_HDI Vec3 operator-(Vec3 a, const Vec3& b) { return a -= b; }
CANDELA_HDI Vec3 operator*(Vec3 a, const Vec3& b) { return a *= b; }
CANDELA_HDI Vec3 operator*(Vec3 a, float s) { return a *= s; }
CANDELA_HDI Vec3 operator*(float s, Vec3 a) { return a *= s; }
CANDELA_HDI Vec3 operator/(Vec3 a, float s) { return a /= s; }
CANDELA_HDI Vec3 operator/(const Vec3& a, const Vec3& b) { return {a.x / b.x, a.y / b.y, a.z / b.z}; }

CANDELA_HDI float dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
CANDELA_HDI Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
CANDELA_HDI float lengthSquared(const Vec3& a) { return dot(a, a); }
CANDELA_HDI_ALWAYS float length(const Vec3& a) { return sqrtf(dot(a, a)); }
CANDELA_HDI_ALWAYS Vec3 normalize(const Vec3& a) { return a * (1.0f / length(a)); }
CANDELA_HDI Vec3 abs(const Vec3& a) { return {fabsf(a.x), fabsf(a.y), fabsf(a.z)}; }
// Plain comparisons rather than fminf/fmaxf: those keep IEEE NaN rules that x86-64 compilers
// can only honour with a library call, which costs the BVH build and traversal dearly.
CANDELA_HDI float minf(float a, float b) { return a < b ? a : b; }
CANDELA_HDI float maxf(float a, float b) { return a > b ? a : b; }
CANDELA_HDI Vec3 min(const Vec3& a, const Vec3& b) {
  return {minf(a.x, b.x), minf(a.y, b.y), minf(a.z, b.z)};
}
CANDELA_HDI Vec3 max(const Vec3& a, const Vec3& b) {
  return {maxf(a.x, b.x), maxf(a.y, b.y), maxf(a.z, b.z)};
}
CANDELA_HDI float maxComponent(const Vec3& a) { return maxf(a.x, maxf(a.y, a.z)); }
CANDELA_HDI int maxDimension(const Vec3& a) {
  return (a.x > a.y) ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
}
CANDELA_HDI bool isBlack(const Vec3& a) { return a.x == 0.0f && a.y == 0.0f && a.z == 0.0f; }
// NaN fails every comparison; infinities exceed the largest float.
CANDELA_HDI bool isFinite(const Vec3& v) {
  return fabsf(v.x) <= kInfinity && fabsf(v.y) <= kInfinity && fabsf(v.z) <= kInfinity;
}
// x + y + z in double: what the host weighs colours and powers by (light selection, maps).
inline double componentSum(const Vec3& a) { return double(a.x) + double(a.y) + double(a.z); }
CANDELA_HDI float luminance(const Vec3& c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

// Flips v so that it lies in the hemisphere of n.
CANDELA_HDI Vec3 faceForward(const Vec3& v, const Vec3& n) { return dot(v, n) < 0.0f ? -v : v; }

}  // namespace candela
