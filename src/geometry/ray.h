// Ray: origin + t * direction for t in (0, tMax). Directions need not be unit length.
#pragma once

#include <cstdint>

#include "core/constants.h"
#include "core/vec3.h"

namespace candela {

struct Ray {
  Vec3 origin;
  Vec3 direction;
  float tMax = kInfinity;
  // The alpha test's key (geometry/alpha_test.h), drawn from the ray's sample stream where its
  // path casts it (SampleStream::rayKey), so that it does not depend on the ray's rounding; 0
  // in a scene without alpha masks, where nothing reads it (render/ray_kind.h, rayKeyFor).
  uint32_t alphaKey = 0;
  // When the ray is cast, from 0 (the shutter opens) to 1 (it closes): where moving primitives
  // stand for it (geometry/motion.h). Every ray of a sample's paths carries its camera ray's.
  float time = 0.0f;
};

// What traversal reports: the nearest primitive and where on it. Surface data (normals, error
// bounds, material) is reconstructed from this afterwards, once, for the winning hit only.
struct Hit {
  float t = kInfinity;
  uint32_t prim = 0xffffffffu;  // primitive index (geometry/geometry_view.h)
  float b1 = 0, b2 = 0;         // barycentrics of vertices 1 and 2 (triangles only)

  CANDELA_HDI bool valid() const { return prim != 0xffffffffu; }
};

}  // namespace candela
