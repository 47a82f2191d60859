// Normal and bump maps: a material's texture of tangent-space normals, or of heights, tilts the
// shading normal (docs/scene-format.md, *Normal maps* and *Bump maps*). A texel c encodes the
// normal 2 c - 1 in the frame of the surface's tangent (along which u grows), bitangent (v) and
// shading normal, the convention of glTF, Blender and MikkTSpace (OpenGL's: green is +v). The
// tangent is made perpendicular to the shading normal and the bitangent completes the frame on the
// side of v's growth, so a mesh whose uvs are mirrored reads its map mirrored too (tangent and
// bitangent follow the image's x and y where the texture is turned or mirrored by its scale or its
// wrap).
#pragma once

#include <cmath>

#include "core/texture.h"
#include "core/vec2.h"
#include "core/vec3.h"
#include "geometry/surface.h"
#include "render/material.h"
#include "render/scene_view.h"
#include "render/uv_derivatives.h"

namespace candela {

// A bump map's normal (heights `map` of amplitude `height`) from the surface's exact derivatives
// at uv, as Mitsuba 3's bumpmap: each derivative turned into the shading plane and raised along
// the shading normal by the height's slope; the normal of the two, on ng's side.
CANDELA_HDI Vec3 bumpedNormal(const SceneView& scene, const TextureRef& map, float height,
                              const SurfacePoint& sp, const Vec2& uv, const Vec3& dpdu,
                              const Vec3& dpdv) {
  float slopeU, slopeV;
  textureLuminanceGradient(scene.texturePool(), map, uv.x, uv.y, &slopeU, &slopeV);
  const Vec3 du = dpdu + (height * slopeU - dot(sp.ns, dpdu)) * sp.ns;
  const Vec3 dv = dpdv + (height * slopeV - dot(sp.ns, dpdv)) * sp.ns;
  const Vec3 n = cross(du, dv);
  return dot(n, sp.ng) < 0.0f ? -n : n;
}

// The tangent-space normal that normal map `map` holds at uv, in the world: sp.ns where the
// surface has no frame there.
CANDELA_HDI Vec3 normalFromMap(const SceneView& scene, const TextureRef& map,
                               const SurfacePoint& sp, const Vec2& uv, const Vec3& dpdu,
                               const Vec3& dpdv) {
  // The directions in which the image's x and y grow on the surface: along u and v unless the
  // texture is turned or mirrored (by its scale, or in a mirrored copy of its wrap).
  float su, sv, tu, tv, signS, signT;
  textureAxes(map, &su, &sv, &tu, &tv);
  textureMirrorSigns(map, uv.x, uv.y, &signS, &signT);
  const Vec3 imageX = signS * (su * dpdu + sv * dpdv), imageY = signT * (tu * dpdu + tv * dpdv);
  const Vec3 along = imageX - dot(imageX, sp.ns) * sp.ns;
  if (!(lengthSquared(along) > 0.0f)) return sp.ns;
  const Vec3 tangent = normalize(along);
  Vec3 bitangent = cross(sp.ns, tangent);
  if (dot(bitangent, imageY) < 0.0f) bitangent = -bitangent;
  const Vec3 c = lookupTexture(scene.texturePool(), map, uv.x, uv.y).rgb;
  return (2.0f * c.x - 1.0f) * tangent + (2.0f * c.y - 1.0f) * bitangent +
         (2.0f * c.z - 1.0f) * sp.ns;
}

// The shading normal at `sp` (at `hit`, seen from direction wo) that normal map `map` gives, or
// bump map `map` of heights `height` where that is not 0: sp.ns where the surface has no frame of
// uvs. Out of line: the integrator calls it only for materials with maps, and the rest of its loop
// stays as tight. A mapped normal that turns its back on wo, which would leave the surface black
// from there, has its tilt mirrored about sp.ns (Mitsuba 3's flip_invalid_normals of its
// normalmap, after Schuessler et al. 2017); one the map tilts below the surface is mirrored above
// it, as ns always lies in ng's hemisphere (geometry/surface.h).
CANDELA_HD_NOINLINE inline Vec3 mappedNormal(const SceneView& scene, const TextureRef& map,
                                             float height, const Hit& hit, const SurfacePoint& sp,
                                             const Vec3& wo) {
  const bool bump = height != 0.0f;
  Vec3 dpdu, dpdv;
  if (!uvDerivatives(scene, hit, sp, bump, &dpdu, &dpdv)) return sp.ns;
  const Vec2 uv = surfaceUv(scene, hit, sp);
  Vec3 n = bump ? bumpedNormal(scene, map, height, sp, uv, dpdu, dpdv)
                : normalFromMap(scene, map, sp, uv, dpdu, dpdv);
  if (dot(wo, sp.ns) * dot(wo, n) <= 0.0f) n = 2.0f * dot(n, sp.ns) * sp.ns - n;
  const float below = dot(n, sp.ng);
  if (below < 0.0f) n = n - 2.0f * below * sp.ng;
  if (!(lengthSquared(n) > 0.0f)) return sp.ns;
  return normalize(n);
}

// Whether m has a normal or bump map, or a coat's normal map (applyNormalMaps has work to do).
CANDELA_HDI bool hasMaps(const Material& m) {
  return m.normalMap.index >= 0 || m.coatNormalMap.index >= 0;
}

// Maps sp->ns by m's normal or bump map where it has one (mappedNormal), and returns the normal
// about which m's clear coat reflects where it is another: the coat's own normal map's, or the
// surface's shading normal unmapped, where a map tilts the material beneath a coat (Blender's,
// OpenPBR's and glTF's coat lies smooth over it); zero where the coat, if any, shares sp->ns.
CANDELA_HDI Vec3 applyNormalMaps(const SceneView& scene, const Material& m, const Hit& hit,
                                 SurfacePoint* sp, const Vec3& wo) {
  const Vec3 unmapped = sp->ns;
  if (m.normalMap.index >= 0) sp->ns = mappedNormal(scene, m.normalMap, m.bumpHeight, hit, *sp, wo);
  if (!(m.coatWeight > 0.0f)) return Vec3(0.0f);
  if (m.coatNormalMap.index >= 0) {
    SurfacePoint beneath = *sp;
    beneath.ns = unmapped;
    return mappedNormal(scene, m.coatNormalMap, 0.0f, hit, beneath, wo);
  }
  return m.normalMap.index >= 0 ? unmapped : Vec3(0.0f);
}

}  // namespace candela
