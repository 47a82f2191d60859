// The isotropic GGX (Trowbridge-Reitz) microfacet distribution in the local shading frame (+z the
// macro normal): D, Smith's masking G1, and sampling of the normals visible from a direction
// (Heitz 2018, "Sampling the GGX Distribution of Visible Normals").
//
// Masking-shadowing is Smith's separable form G = G1(wo) G1(wi), as in Mitsuba 3's microfacet.h,
// which the references are rendered with; pbrt-v4's height-correlated form differs from it by
// under 1% of the reflected energy at the roughnesses people use.
#pragma once

#include <cmath>

#include "core/constants.h"
#include "core/vec3.h"
#include "render/material.h"

namespace candela {

// Below this alpha a surface is treated as perfectly smooth (pbrt-v4's EffectivelySmooth): D
// would exceed float range, and the delta lobe is what the roughness means there.
constexpr float kSmoothAlpha = 1e-3f;

// alpha = roughness^2 (the Disney, glTF and Blender convention).
CANDELA_HDI float roughnessToAlpha(float roughness) { return roughness * roughness; }

// Whether m's roughness makes it perfectly smooth: a delta lobe. A textured roughness never does.
CANDELA_HDI bool isSmooth(const Material& m) {
  return m.roughnessTexture.index < 0 && roughnessToAlpha(m.roughness) < kSmoothAlpha;
}

// The alpha of m at a point of roughness `roughness` (its texture's value there). A textured
// material is rough everywhere, its smoothest texels as rough as kSmoothAlpha, so that what is
// decided per material (isSmooth, hasSmoothLobe) holds at every point.
CANDELA_HDI float pointAlpha(const Material& m, float roughness) {
  const float alpha = roughnessToAlpha(roughness);
  return m.roughnessTexture.index >= 0 && alpha < kSmoothAlpha ? kSmoothAlpha : alpha;
}

// The roughness of the smoothest rough surface, where a textured plastic's coat table begins.
CANDELA_HDI float smoothestRoughRoughness() { return sqrtf(kSmoothAlpha); }

// Density of microfacet normal m (m.z > 0) per unit projected area.
CANDELA_HDI float ggxD(const Vec3& m, float alpha) {
  if (m.z <= 0.0f) return 0.0f;
  const float a2 = alpha * alpha;
  const float cos2 = m.z * m.z;
  const float t = (m.x * m.x + m.y * m.y) / a2 + cos2;
  return 1.0f / (kPi * a2 * t * t);
}

// Smith's masking of direction w by the microfacets, for a visible facet m (w.m and w.z of one
// sign; 0 otherwise).
CANDELA_HDI float ggxG1(const Vec3& w, const Vec3& m, float alpha) {
  if (dot(w, m) * w.z <= 0.0f) return 0.0f;
  const float cos2 = w.z * w.z;
  const float tan2 = maxf(0.0f, 1.0f - cos2) / cos2;
  return 2.0f / (1.0f + sqrtf(1.0f + alpha * alpha * tan2));
}

// The density of visible normals from wo (wo.z > 0): D_wo(m) = G1(wo, m) max(0, wo.m) D(m) / wo.z,
// from g1o = ggxG1(wo, m, alpha) and d = ggxD(m, alpha), which the BSDFs have at hand.
CANDELA_HDI float ggxVisiblePdf(const Vec3& wo, const Vec3& m, float g1o, float d) {
  return g1o * maxf(0.0f, dot(wo, m)) * d / wo.z;
}

// A microfacet normal visible from wo (wo.z > 0), distributed by ggxVisiblePdf.
CANDELA_HDI Vec3 sampleGgxVisible(const Vec3& wo, float alpha, float u1, float u2) {
  // Stretch to the hemisphere configuration, sample the projected disk, unstretch.
  const Vec3 vh = normalize(Vec3(alpha * wo.x, alpha * wo.y, wo.z));
  const float lensq = vh.x * vh.x + vh.y * vh.y;
  const Vec3 t1 = lensq > 0.0f ? Vec3(-vh.y, vh.x, 0.0f) * (1.0f / sqrtf(lensq)) : Vec3(1, 0, 0);
  const Vec3 t2 = cross(vh, t1);
  const float r = sqrtf(u1), phi = 2.0f * kPi * u2;
  const float p1 = r * cosf(phi);
  float p2 = r * sinf(phi);
  const float s = 0.5f * (1.0f + vh.z);
  p2 = (1.0f - s) * sqrtf(maxf(0.0f, 1.0f - p1 * p1)) + s * p2;
  const Vec3 nh = t1 * p1 + t2 * p2 + vh * sqrtf(maxf(0.0f, 1.0f - p1 * p1 - p2 * p2));
  return normalize(Vec3(alpha * nh.x, alpha * nh.y, maxf(1e-6f, nh.z)));
}

}  // namespace candela
