// The GGX (Trowbridge-Reitz) microfacet distribution in the local shading frame (+z the macro
// normal, +x the tangent): D, Smith's masking G1, and sampling of the normals visible from a
// direction (Heitz 2018, "Sampling the GGX Distribution of Visible Normals"); anisotropic, with
// one alpha along the tangent and one along the bitangent, as Mitsuba 3's and pbrt-v4's.
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

// The distribution's alpha along the local x (the tangent) and y (the bitangent).
struct GgxAlpha {
  float x, y;
  CANDELA_HDI static GgxAlpha isotropic(float alpha) { return {alpha, alpha}; }
  // Both alphas below kSmoothAlpha: a delta lobe.
  CANDELA_HDI bool smooth() const { return x < kSmoothAlpha && y < kSmoothAlpha; }
};

// alpha = roughness^2 (the Disney, glTF and Blender convention).
CANDELA_HDI float roughnessToAlpha(float roughness) { return roughness * roughness; }

// The tangent's alpha at roughness r and anisotropy a (OpenPBR's specular_roughness_anisotropy):
// r^2 sqrt(2 / (1 + (1 - a)^2)), the bitangent's (1 - a) times it, so that the mean of the two
// squared alphas stays r^4 and the highlight stretches along the tangent as a grows.
CANDELA_HDI float tangentAlpha(float roughness, float anisotropy) {
  const float b = 1.0f - anisotropy;
  return roughnessToAlpha(roughness) * sqrtf(2.0f / (1.0f + b * b));
}

// Whether m's roughness makes it perfectly smooth: a delta lobe. A textured roughness never does.
CANDELA_HDI bool isSmooth(const Material& m) {
  return m.roughnessTexture.index < 0 && tangentAlpha(m.roughness, m.anisotropy) < kSmoothAlpha;
}

// The alphas of m at a point of roughness `roughness` (its texture's value there). A rough
// material (isSmooth false) has neither below kSmoothAlpha: a textured one is rough everywhere,
// its smoothest texels as rough as kSmoothAlpha, so that what is decided per material (isSmooth,
// hasSmoothLobe) holds at every point, and full anisotropy keeps a lobe along the bitangent.
CANDELA_HDI GgxAlpha pointAlpha(const Material& m, float roughness) {
  if (m.anisotropy == 0.0f) {  // the common case, without tangentAlpha's square root
    const float alpha = roughnessToAlpha(roughness);
    return GgxAlpha::isotropic(m.roughnessTexture.index >= 0 ? maxf(alpha, kSmoothAlpha) : alpha);
  }
  const float along = tangentAlpha(roughness, m.anisotropy);
  if (m.roughnessTexture.index < 0 && along < kSmoothAlpha) return GgxAlpha::isotropic(along);
  return {maxf(along, kSmoothAlpha), maxf((1.0f - m.anisotropy) * along, kSmoothAlpha)};
}

// The roughness of the smoothest rough surface, where a textured plastic's coat table begins.
CANDELA_HDI float smoothestRoughRoughness() { return sqrtf(kSmoothAlpha); }

// Density of microfacet normal m (m.z > 0) per unit projected area.
CANDELA_HDI float ggxD(const Vec3& m, GgxAlpha alpha) {
  if (m.z <= 0.0f) return 0.0f;
  const float sx = m.x / alpha.x, sy = m.y / alpha.y;
  const float t = sx * sx + sy * sy + m.z * m.z;
  return 1.0f / (kPi * alpha.x * alpha.y * t * t);
}

// Smith's masking of direction w by the microfacets, for a visible facet m (w.m and w.z of one
// sign; 0 otherwise). alpha^2 tan^2(theta) is, anisotropic, (alpha_x^2 w.x^2 + alpha_y^2 w.y^2) /
// w.z^2: the roughness seen along w's azimuth.
CANDELA_HDI float ggxG1(const Vec3& w, const Vec3& m, GgxAlpha alpha) {
  if (dot(w, m) * w.z <= 0.0f) return 0.0f;
  const float sx = alpha.x * w.x, sy = alpha.y * w.y;
  const float a2tan2 = (sx * sx + sy * sy) / (w.z * w.z);
  return 2.0f / (1.0f + sqrtf(1.0f + a2tan2));
}

// The density of visible normals from wo (wo.z > 0): D_wo(m) = G1(wo, m) max(0, wo.m) D(m) / wo.z,
// from g1o = ggxG1(wo, m, alpha) and d = ggxD(m, alpha), which the BSDFs have at hand.
CANDELA_HDI float ggxVisiblePdf(const Vec3& wo, const Vec3& m, float g1o, float d) {
  return g1o * maxf(0.0f, dot(wo, m)) * d / wo.z;
}

// A microfacet normal visible from wo (wo.z > 0), distributed by ggxVisiblePdf.
CANDELA_HDI Vec3 sampleGgxVisible(const Vec3& wo, GgxAlpha alpha, float u1, float u2) {
  // Stretch to the hemisphere configuration, sample the projected disk, unstretch.
  const Vec3 vh = normalize(Vec3(alpha.x * wo.x, alpha.y * wo.y, wo.z));
  const float lensq = vh.x * vh.x + vh.y * vh.y;
  const Vec3 t1 = lensq > 0.0f ? Vec3(-vh.y, vh.x, 0.0f) * (1.0f / sqrtf(lensq)) : Vec3(1, 0, 0);
  const Vec3 t2 = cross(vh, t1);
  const float r = sqrtf(u1), phi = 2.0f * kPi * u2;
  const float p1 = r * cosf(phi);
  float p2 = r * sinf(phi);
  const float s = 0.5f * (1.0f + vh.z);
  p2 = (1.0f - s) * sqrtf(maxf(0.0f, 1.0f - p1 * p1)) + s * p2;
  const Vec3 nh = t1 * p1 + t2 * p2 + vh * sqrtf(maxf(0.0f, 1.0f - p1 * p1 - p2 * p2));
  return normalize(Vec3(alpha.x * nh.x, alpha.y * nh.y, maxf(1e-6f, nh.z)));
}

}  // namespace candela
