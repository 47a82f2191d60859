// The tangent that orients an anisotropic material's roughness (render/microfacet.h): the
// direction in which the surface's u grows, turned about the shading normal by the material's
// rotation, as Blender's UV tangents and OpenPBR's default geometry_tangent.
#pragma once

#include <cmath>

#include "geometry/surface.h"
#include "render/material.h"
#include "render/scene_view.h"
#include "render/uv_derivatives.h"

namespace candela {

// The tangent of anisotropic m at `sp` of `hit`: zero where the surface has no uvs there. Out of
// line: only anisotropic materials need it.
CANDELA_HD_NOINLINE inline Vec3 anisotropicTangent(const SceneView& scene, const Material& m,
                                                   const Hit& hit, const SurfacePoint& sp) {
  Vec3 dpdu, dpdv;
  if (!uvDerivatives(scene, hit, sp, false, &dpdu, &dpdv)) return Vec3(0.0f);
  if (m.anisotropyRotation == 0.0f) return dpdu;
  const Vec3 along = dpdu - dot(dpdu, sp.ns) * sp.ns;
  return cosf(m.anisotropyRotation) * along + sinf(m.anisotropyRotation) * cross(sp.ns, along);
}

// m's tangent at `sp` of `hit`, zero where m is isotropic or the surface has no uvs there: the
// shading frame is then the one core/frame.h builds about the normal alone (as Mitsuba 3's is).
CANDELA_HDI Vec3 surfaceTangent(const SceneView& scene, const Material& m, const Hit& hit,
                                const SurfacePoint& sp) {
  return m.anisotropy == 0.0f ? Vec3(0.0f) : anisotropicTangent(scene, m, hit, sp);
}

}  // namespace candela
