// A GeometryView (spheres, vertices, triangles), for intersection and BVH tests.
#pragma once

#include <vector>

#include "geometry/geometry_view.h"

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

}  // namespace candela::test
