// A 3-vector in double, for the host's geometry where float would lose what it needs: unit
// vectors of directions far from 1 in length, frames built from them, the shapes of tiny or huge
// triangles. The kernel works in float (core/vec3.h).
#pragma once

#include <cmath>

#include "core/vec3.h"

namespace candela {

struct DVec3 {
  double x, y, z;
};

inline DVec3 dvec3(const Vec3& v) { return {v.x, v.y, v.z}; }
inline Vec3 toVec3(const DVec3& v) { return Vec3(float(v.x), float(v.y), float(v.z)); }

inline DVec3 operator+(const DVec3& a, const DVec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline DVec3 operator-(const DVec3& a, const DVec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline DVec3 operator*(double s, const DVec3& a) { return {s * a.x, s * a.y, s * a.z}; }
inline double dot(const DVec3& a, const DVec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline DVec3 cross(const DVec3& a, const DVec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// v / |v|; not finite for a zero v.
inline DVec3 unit(const DVec3& v) {
  const double length = std::sqrt(dot(v, v));
  return {v.x / length, v.y / length, v.z / length};
}

}  // namespace candela
