// Normal maps: a material's texture of tangent-space normals tilts the shading normal
// (docs/scene-format.md, *Normal maps*). A texel c encodes the normal 2 c - 1 in the frame of the
// surface's tangent (along which u grows), bitangent (v) and shading normal, the convention of
// glTF, Blender and MikkTSpace (OpenGL's: green is +v). The tangent is made perpendicular to the
// shading normal and the bitangent completes the frame on the side of v's growth, so a mesh whose
// uvs are mirrored reads its map mirrored too.
#pragma once

#include <cmath>

#include "core/texture.h"
#include "core/vec2.h"
#include "core/vec3.h"
#include "geometry/surface.h"
#include "render/material.h"
#include "render/scene_view.h"

namespace candela {

// The directions in which u and v grow across the surface at `hit`, up to scale: a face's from
// its vertices' uvs (false where they make no frame), a sphere's from its equirectangular mapping
// (false at its poles).
CANDELA_HDI bool uvDirections(const SceneView& scene, const Hit& hit, const SurfacePoint& sp,
                              Vec3* dpdu, Vec3* dpdv) {
  if (hit.prim < scene.sphereCount) {
    // u grows with the azimuth atan2(d.x, -d.z), v towards +y (geometry/surface_uv.h).
    const Vec3& d = sp.ng;
    *dpdu = Vec3(-d.z, 0.0f, d.x);
    *dpdv = Vec3(0.0f, 1.0f, 0.0f) - d.y * d;
    return lengthSquared(*dpdu) > 0.0f;
  }
  if (scene.uvCount == 0) return false;
  const Triangle& tri = scene.triangles[hit.prim - scene.sphereCount];
  const Vec3& p0 = scene.positions[tri.v[0]];
  const Vec2 &t0 = scene.uvs[tri.v[0]], &t1 = scene.uvs[tri.v[1]], &t2 = scene.uvs[tri.v[2]];
  const Vec3 e1 = scene.positions[tri.v[1]] - p0, e2 = scene.positions[tri.v[2]] - p0;
  const Vec2 d1(t1.x - t0.x, t1.y - t0.y), d2(t2.x - t0.x, t2.y - t0.y);
  const float det = d1.x * d2.y - d1.y * d2.x;
  if (!(fabsf(det) > 0.0f)) return false;
  // Solving e1 = d1.x dpdu + d1.y dpdv and e2 likewise; only the directions matter, so the
  // common factor 1 / det is kept to its sign.
  const float sign = det > 0.0f ? 1.0f : -1.0f;
  *dpdu = sign * (d2.y * e1 - d1.y * e2);
  *dpdv = sign * (d1.x * e2 - d2.x * e1);
  return true;
}

// The shading normal at `sp` (of material m, which has a normal map, at `hit`, seen from direction
// wo) that m's normal map gives: sp.ns where the surface has no frame of uvs. Out of line: the
// integrator calls it only for normal-mapped materials, and the rest of its loop stays as tight. A
// mapped normal that turns its back on wo, which would leave the surface black from there, has its
// tilt mirrored about sp.ns (Mitsuba 3's flip_invalid_normals, after Schuessler et al. 2017); one
// the map tilts below the surface is mirrored above it, as ns always lies in ng's hemisphere
// (geometry/surface.h).
CANDELA_HD_NOINLINE inline Vec3 mappedNormal(const SceneView& scene, const Material& m,
                                             const Hit& hit, const SurfacePoint& sp,
                                             const Vec3& wo) {
  Vec3 dpdu, dpdv;
  if (!uvDirections(scene, hit, sp, &dpdu, &dpdv)) return sp.ns;
  const Vec3 along = dpdu - dot(dpdu, sp.ns) * sp.ns;
  if (!(lengthSquared(along) > 0.0f)) return sp.ns;
  const Vec3 tangent = normalize(along);
  Vec3 bitangent = cross(sp.ns, tangent);
  if (dot(bitangent, dpdv) < 0.0f) bitangent = -bitangent;
  const Vec2 uv = surfaceUv(scene, hit, sp);
  const Vec3 c = lookupTexture(scene.texturePool(), m.normalMap, uv.x, uv.y).rgb;
  Vec3 n =
      (2.0f * c.x - 1.0f) * tangent + (2.0f * c.y - 1.0f) * bitangent + (2.0f * c.z - 1.0f) * sp.ns;
  if (dot(wo, sp.ns) * dot(wo, n) <= 0.0f) n = 2.0f * dot(n, sp.ns) * sp.ns - n;
  const float below = dot(n, sp.ng);
  if (below < 0.0f) n = n - 2.0f * below * sp.ng;
  if (!(lengthSquared(n) > 0.0f)) return sp.ns;
  return normalize(n);
}

}  // namespace candela
