// A GeometryView (spheres, vertices, triangles) and rays, for intersection and BVH tests.
#pragma once

#include <vector>

#include "geometry/geometry_view.h"
#include "geometry/ray.h"

namespace candela::test {

inline GeometryView geometryView(const std::vector<Sphere>& spheres, const std::vector<Vec3>& positions,
                              const std::vector<OctNormal>& normals,
                              const std::vector<Triangle>& triangles) {
  GeometryView v;
  v.spheres = spheres.data();
  v.sphereCount = static_cast<uint32_t>(spheres.size());
  v.positions = positions.data();
  v.positionCount = static_cast<uint32_t>(positions.size());
  v.normals = normals.data();
  v.normalCount = static_cast<uint32_t>(normals.size());
  v.triangles = triangles.data();
  v.triangleCount = static_cast<uint32_t>(triangles.size());
  return v;
}

// From the origin down -z.
inline Ray rayDownMinusZ() {
  Ray ray;
  ray.origin = Vec3(0.0f);
  ray.direction = Vec3(0, 0, -1);
  return ray;
}

}  // namespace candela::test
