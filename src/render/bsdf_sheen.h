// Sheen: the soft glow at grazing angles of cloth, velvet and dust, from fibres standing out of a
// surface (glTF's KHR_materials_sheen, Blender's and OpenPBR's sheen and fuzz), as a layer over
// the material beneath. Its lobe is the "Charlie" distribution of fibre normals (Estevez and
// Kulla 2017), D(h) = (2 + 1/a) sin(theta_h)^(1/a) / (2 pi), a = max(r^2, kSheenMinAlpha), with
// Ashikhmin's visibility 1 / (4 (cos_i + cos_o - cos_i cos_o)), as glTF's and Filament's, of
// colour `sheenColor`. That visibility is not a masking term: near the horizon a smooth sheen
// would reflect more than it receives, so the lobe is divided by max(1, E(wi), E(wo)), E its
// directional albedo (reciprocal, and at most 1 by direction). The material beneath is weighted by
// what the sheen lets by on the way in and out, with s = the sheen colour's largest channel and
// K(mu) the normalized lobe's albedo (a table by cos(theta), prepareMaterial):
//
//   f = sheenColor f_sheen + (1 - s K(wi)) (1 - s K(wo)) f_base
//
// Reciprocal, and energy is kept (the colour and the roughness may vary over the surface:
// render/surface_layers.h; the functions take the layers at the point, `l`). Local shading frame
// of render/bsdf.h, wo.z > 0.
#pragma once

#include "core/sampling.h"
#include "render/bsdf_sample.h"
#include "render/material.h"
#include "render/surface_layers.h"

namespace candela {

CANDELA_HDI bool hasSheen(const Material& m) { return maxComponent(m.sheenColor) > 0.0f; }

// The Charlie distribution of alpha a at a half vector of local z `cosH` (>= 0).
CANDELA_HDI float charlieD(float cosH, float a) {
  const float sin2 = maxf(0.0f, 1.0f - cosH * cosH);
  // sin^(1/a) = (sin^2)^(1/(2a)), by exp and log: powf of a tiny base underflows to 0 as it must.
  const float invA = 1.0f / a;
  return (2.0f + invA) * powf(sin2, 0.5f * invA) * (0.5f * kInvPi);
}

// The unnormalized lobe (colour 1) at wi, wo above the surface: D V cos(wi).
CANDELA_HDI float sheenLobeCos(float a, const Vec3& wo, const Vec3& wi) {
  const Vec3 h = normalize(wo + wi);
  return charlieD(h.z, a) * wi.z / (4.0f * (wi.z + wo.z - wi.z * wo.z));
}

// The sheen's tables at the point: the lobe's directional albedo E and the normalized lobe's K.
CANDELA_HDI float sheenAlbedoAt(const SurfaceLayers& l, float cosTheta) {
  return levelTableAt(l.sheenTable, kSheenRow, l.sheenBlend, cosTheta);
}
CANDELA_HDI float sheenKeptAt(const SurfaceLayers& l, float cosTheta) {
  return levelTableAt(l.sheenTable + kPlasticTableSize, kSheenRow, l.sheenBlend, cosTheta);
}

// What the sheen leaves the base at cos(theta): 1 - s K(mu).
CANDELA_HDI float sheenBaseShare(const SurfaceLayers& l, float cosTheta) {
  return 1.0f - maxComponent(l.sheen) * sheenKeptAt(l, cosTheta);
}

// What the base's f |cos| is multiplied by.
CANDELA_HDI float sheenedBaseFactor(const SurfaceLayers& l, float cosI, float cosO) {
  return sheenBaseShare(l, cosI) * sheenBaseShare(l, cosO);
}

// The sheen's f |cos(wi)| (normalized, of the layers' colour), zero where either direction is
// below.
CANDELA_HDI Vec3 sheenEval(const SurfaceLayers& l, const Vec3& wo, const Vec3& wi) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) return Vec3(0.0f);
  const float norm = maxf(1.0f, maxf(sheenAlbedoAt(l, wi.z), sheenAlbedoAt(l, wo.z)));
  return l.sheen * (sheenLobeCos(sheenAlpha(l.sheenRoughness), wo, wi) / norm);
}

// The chance of sampling the sheen rather than the base: its albedo at wo against what the base,
// of mean colour `color`, reflects past it.
CANDELA_HDI float sheenProbability(const SurfaceLayers& l, const Vec3& color, float cosO) {
  const float share = maxComponent(l.sheen) * sheenKeptAt(l, cosO);
  const float base = (1.0f - share) * (color.x + color.y + color.z) * (1.0f / 3.0f);
  return share + base > 0.0f ? share / (share + base) : 1.0f;
}

// The sheen samples the hemisphere uniformly: its lobe is broad, and at low alpha lies at the
// horizon, where a cosine would seldom go.
CANDELA_HDI Vec3 sampleSheenDirection(float u1, float u2) {
  return sampleUniformCone(u1, u2, 1.0f);
}
CANDELA_HDI float sheenDirectionPdf(const Vec3& wi) { return wi.z > 0.0f ? 0.5f * kInvPi : 0.0f; }

}  // namespace candela
