// The primitives the renderer intersects: spheres and triangles, in world space.
//
// `material` indexes the scene's materials and `light` its lights; geometry carries both as plain
// indices and never reads what they name.
#pragma once

#include <cstdint>

#include "core/vec3.h"

namespace candela {

struct Sphere {
  Vec3 center;
  float radius = 1;
  uint32_t material = 0;
  int32_t light = -1;  // the light this sphere is the surface of (a sphere light), else -1
};

// Vertex indices into positions (and into normals, which when present run parallel to
// positions). The face's outside is the side of (v1-v0)x(v2-v0) (counter-clockwise seen from
// outside). 16 bytes: the renderer's triangles stay small.
struct Triangle {
  uint32_t v[3];
  uint32_t material;
};
static_assert(sizeof(Triangle) == 16, "Triangle must stay 16 bytes");

}  // namespace candela
