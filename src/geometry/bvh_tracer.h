// BvhTracer: the ray engine over candela's own BVH (geometry/bvh_traverse.h), the one the CUDA
// backend uses and the CPU's fallback.
//
// The integrator reaches geometry through a tracer, a small value with two queries:
//   closest(ray, &hit)   the nearest hit for t in (0, ray.tMax), as intersectClosest;
//   occluded(ray, skip)  whether anything but primitive `skip` blocks the ray, as intersectAny.
// Any engine with that pair (the CPU's Embree tracer, backends/cpu/embree_tracer.h) renders the
// same image up to rounding, with the primitive numbering of geometry/geometry_view.h. An engine
// whose kPacketWidth exceeds 1 also answers closestPacket(rays, n, hits) and
// occludedPacket(rays, skipPrims, n, blocked), the same queries for up to that many rays at
// once, which a pixel's camera rays and their first shadow rays go through
// (render/render_pixel.h).
#pragma once

#include "geometry/bvh_traverse.h"

namespace candela {

struct BvhTracer {
  static constexpr uint32_t kPacketWidth = 1;  // every ray alone
  const GeometryView* geometry;

  CANDELA_HD_GPU_CALL bool closest(const Ray& ray, Hit* hit) const {
    return intersectClosest(*geometry, ray, hit);
  }
  CANDELA_HD_GPU_CALL bool occluded(const Ray& ray, uint32_t skipPrim) const {
    return intersectAny(*geometry, ray, skipPrim);
  }
};

}  // namespace candela
