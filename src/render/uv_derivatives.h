// A surface's derivatives with respect to its texture coordinates, which orient what lies in its
// tangent plane: normal and bump maps (render/normal_map.h) and anisotropic roughness
// (render/surface_tangent.h).
#pragma once

#include "core/constants.h"
#include "core/vec2.h"
#include "core/vec3.h"
#include "geometry/surface.h"
#include "render/scene_view.h"

namespace candela {

// The surface's derivatives dp/du and dp/dv at `hit` with respect to its uvs, or with `exact`
// false only their directions, up to a positive scale each: a face's from its vertices' uvs
// (false where they make no frame), a sphere's from its equirectangular mapping (false at its
// poles).
CANDELA_HDI bool uvDerivatives(const SceneView& scene, const Hit& hit, const SurfacePoint& sp,
                               bool exact, Vec3* dpdu, Vec3* dpdv) {
  if (hit.prim < scene.sphereCount) {
    // u grows with the azimuth atan2(d.x, -d.z), v towards +y (geometry/surface_uv.h):
    // dp/du = 2 pi r (-d.z, 0, d.x), dp/dv = pi r (y - d.y d) / sin(theta).
    const Vec3& d = sp.ng;
    *dpdu = Vec3(-d.z, 0.0f, d.x);
    *dpdv = Vec3(0.0f, 1.0f, 0.0f) - d.y * d;
    const float sinTheta = length(*dpdu);
    if (!(sinTheta > 0.0f)) return false;
    if (exact) {
      const float r = sphereAt(scene, hit.prim, sp.time).radius;
      *dpdu = (2.0f * kPi * r) * *dpdu;
      *dpdv = (kPi * r / sinTheta) * *dpdv;
    }
    return true;
  }
  if (scene.uvCount == 0) return false;
  const Triangle& tri = scene.triangles[hit.prim - scene.sphereCount];
  Vec3 p[3];
  triangleCornersAt(scene, tri, sp.time, p);
  const Vec2 &t0 = scene.uvs[tri.v[0]], &t1 = scene.uvs[tri.v[1]], &t2 = scene.uvs[tri.v[2]];
  const Vec3 e1 = p[1] - p[0], e2 = p[2] - p[0];
  const Vec2 d1(t1.x - t0.x, t1.y - t0.y), d2(t2.x - t0.x, t2.y - t0.y);
  const float det = d1.x * d2.y - d1.y * d2.x;
  if (!(fabsf(det) > 0.0f)) return false;
  // Solving e1 = d1.x dpdu + d1.y dpdv and e2 likewise; for directions alone the common factor
  // 1 / det is kept to its sign.
  const float scale = exact ? 1.0f / det : (det > 0.0f ? 1.0f : -1.0f);
  *dpdu = scale * (d2.y * e1 - d1.y * e2);
  *dpdv = scale * (d1.x * e2 - d2.x * e1);
  return true;
}

}  // namespace candela
