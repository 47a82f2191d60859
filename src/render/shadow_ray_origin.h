// Next-event estimation from a face shaded by its vertex normals, near where the light grazes it
// (the shadow terminator), as Cycles' shadow terminator geometry offset does it (Hanika 2021):
// its shadow ray leaves from the point raised to the smooth surface those normals describe
// (geometry/surface.h, terminatorLift), so that a coarse mesh's neighbouring faces do not shadow
// what its shading lights; and the light is taken wherever the shading normal faces it, also a
// little behind the face's own plane, where a coarse face's lighting would otherwise stop, face
// by face, in a stair of dark facets. render.smooth_terminator false keeps the face's own point
// and plane, as Mitsuba and pbrt do.
#pragma once

#include "core/float_error.h"
#include "geometry/ray.h"
#include "geometry/surface.h"
#include "render/scene_view.h"
#include "render/shadow_query.h"

namespace candela {

// Whether a shadow ray from sp towards w leaves from the raised point: the shading normal
// `facing` the viewer on the side the vertex normals face, and w above it.
CANDELA_HDI bool raisesShadowRay(const SceneView& scene, const SurfacePoint& sp, const Vec3& facing,
                                 const Vec3& w) {
  return scene.settings.smoothTerminator && dot(facing, sp.lift) > 0.0f && dot(w, facing) > 0.0f;
}

// The origin of a shadow ray from sp towards w that raisesShadowRay: the raised point, or, for a
// w behind the face's plane, where the ray from it crosses that plane, so that the face itself,
// which the ray from the raised point would cross, cannot stop it (Cycles skips the ray's own
// face instead); on a convex patch nothing else lies between the two. Moved off the face towards
// w's side by the point's error bound (p's, and the rounding of its making).
CANDELA_HDI Vec3 raisedShadowRayOrigin(const SurfacePoint& sp, const Vec3& w) {
  Vec3 origin = sp.p + sp.lift;
  const float height = dot(sp.lift, sp.ng), along = dot(w, sp.ng);
  if (height * along < 0.0f) origin += w * (-height / along);
  return offsetRayOrigin(origin, sp.error + gammaBound(4) * (abs(origin) + abs(sp.lift)), sp.ng, w);
}

// The shadow ray from sp towards a light at `distance` along w (kInfinity: the environment or a
// directional light) that raisesShadowRay, keyed `key`: from raisedShadowRayOrigin, aimed at the
// light's point from there. Out of line: only smooth-shaded faces raise theirs.
CANDELA_HD_NOINLINE inline Ray raisedShadowRay(const SurfacePoint& sp, const Vec3& w,
                                               float distance, uint32_t key) {
  Ray ray;
  ray.origin = raisedShadowRayOrigin(sp, w);
  ray.direction = w;
  ray.alphaKey = key;
  ray.time = sp.time;
  if (distance < kInfinity) {
    const Vec3 span = (sp.p + w * distance) - ray.origin;
    const float length = sqrtf(dot(span, span));
    ray.direction = span / length;
    ray.tMax = length * (1.0f - kShadowEpsilon);
  }
  return ray;
}

}  // namespace candela
