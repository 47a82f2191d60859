// A clear coat over a material (lacquer over paint, wood or metal; glTF's clearcoat, OpenPBR's and
// Blender's coat): on the share w of the surface (coatWeight, or its texture's value there:
// render/surface_layers.h), a dielectric layer of index coatIor, smooth or GGX-rough
// (coatRoughness, or its texture's value), reflects as a rough dielectric does (Fresnel at the
// microfacet), and the material beneath is seen through it, weighted by the coat's transmittance T
// on the way in and on the way out:
//
//   f = w f_coat + (1 - w + w T(wi) T(wo)) f_base
//
// Reciprocal, and energy is kept: for each direction the coat's reflectance and T sum to at most
// 1. Light the coat reflects back down to the base is not followed, nor is the base's lobe bent
// by the coat (so a white diffuse base under a coat of index 1.5 reflects about 9% less than a
// plastic, which follows both). T is 1 - F for a smooth coat, and for a rough one the table of
// what its BTDF lets through (render/material_prepare.h, as the plastic's; by roughness level
// where a texture gives the roughness). The functions work in the coat's own local frame, wo.z > 0:
// render/bsdf.h's, turned where the coat's normal is not the material's (a normal map tilts one of
// them: render/normal_map.h, applyNormalMaps), and take the layers at the point (`l`: the weight
// w = l.coat, the roughness, the transmittance table).
#pragma once

#include "render/bsdf_plastic.h"
#include "render/bsdf_sample.h"
#include "render/fresnel.h"
#include "render/material.h"
#include "render/microfacet.h"
#include "render/surface_layers.h"

namespace candela {

CANDELA_HDI bool hasCoat(const Material& m) { return m.coatWeight > 0.0f; }

// Whether m's coat is rough at every point (a textured roughness is: surfaceLayers keeps it at
// least the smoothest rough one), so that its lobe has a density.
CANDELA_HDI bool hasRoughCoat(const Material& m) {
  return hasCoat(m) && (m.coatRoughnessTexture.index >= 0 ||
                        !GgxAlpha::isotropic(roughnessToAlpha(m.coatRoughness)).smooth());
}

CANDELA_HDI GgxAlpha coatAlpha(const SurfaceLayers& l) {
  return GgxAlpha::isotropic(roughnessToAlpha(l.coatRoughness));
}

// The coat's transmittance at cos(theta) in [0, 1].
CANDELA_HDI float coatTransmittance(const Material& m, const SurfaceLayers& l, float cosTheta) {
  if (coatAlpha(l).smooth()) return 1.0f - fresnelDielectric(cosTheta, m.coatIor);
  return coatTableAt(l.coatTransmittance, l.coatBlend, cosTheta);
}

// What the base's f |cos| is multiplied by under the coat, for wi and wo of local z cosI and
// cosO.
CANDELA_HDI float coatedBaseFactor(const Material& m, const SurfaceLayers& l, float cosI,
                                   float cosO) {
  return 1.0f - l.coat + l.coat * coatTransmittance(m, l, cosI) * coatTransmittance(m, l, cosO);
}

// The chance of sampling the coat's reflection rather than the base: the coat's reflectance at wo
// against what the base, of mean colour `color`, can reflect through it.
CANDELA_HDI float coatProbability(const Material& m, const SurfaceLayers& l, const Vec3& color,
                                  float cosO) {
  const float coat = l.coat * fresnelDielectric(cosO, m.coatIor);
  const float base = (1.0f - coat) * (color.x + color.y + color.z) * (1.0f / 3.0f);
  return coat + base > 0.0f ? coat / (coat + base) : 1.0f;
}

// The rough coat's reflection, f |cos(wi)|, and the pdf with which its lobe samples wi; zero
// for a smooth coat, whose mirror reflection is a delta lobe.
CANDELA_HDI float coatReflectionEvalPdf(const Material& m, const SurfaceLayers& l, const Vec3& wo,
                                        const Vec3& wi, float* pdf) {
  *pdf = 0.0f;
  const GgxAlpha alpha = coatAlpha(l);
  if (alpha.smooth() || wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
  const Vec3 h = normalize(wo + wi);
  const float d = ggxD(h, alpha), g1o = ggxG1(wo, h, alpha);
  *pdf = g1o * d / (4.0f * wo.z);
  return l.coat * fresnelDielectric(dot(wo, h), m.coatIor) * d * (g1o * ggxG1(wi, h, alpha)) /
         (4.0f * wo.z);
}

// The coated f |cos(wi)| and pdf from those of what lies beneath (baseF, basePdf) at wi, chosen
// against the coat with coatProbability p.
CANDELA_HDI Vec3 coatedEvalPdf(const Material& m, const SurfaceLayers& l, const Vec3& wo,
                               const Vec3& wi, const Vec3& baseF, float basePdf, float p,
                               float* pdf) {
  if (wo.z <= 0.0f || wi.z <= 0.0f) {
    *pdf = 0.0f;
    return Vec3(0.0f);
  }
  float coatPdf;
  const float coat = coatReflectionEvalPdf(m, l, wo, wi, &coatPdf);
  *pdf = p * coatPdf + (1.0f - p) * basePdf;
  return baseF * coatedBaseFactor(m, l, wi.z, wo.z) + Vec3(coat);
}

// A direction from the coat's lobe (chosen with chance p): a smooth coat's mirror direction,
// complete in *s, or a rough coat's microfacet reflection, whose weight the caller completes with
// coatedEvalPdf. False where none leaves.
CANDELA_HDI bool sampleCoatReflection(const Material& m, const SurfaceLayers& l, const Vec3& wo,
                                      float p, float u1, float u2, BsdfSample* s) {
  const GgxAlpha alpha = coatAlpha(l);
  if (alpha.smooth()) {
    s->wi = Vec3(-wo.x, -wo.y, wo.z);
    s->weight = Vec3(l.coat * fresnelDielectric(wo.z, m.coatIor) / p);
    s->pdf = 0.0f;
    s->delta = true;
    s->eta = 1.0f;
    return true;
  }
  s->wi = reflect(wo, sampleGgxVisible(wo, alpha, u1, u2));
  s->delta = false;
  s->eta = 1.0f;
  return s->wi.z > 0.0f;
}

}  // namespace candela
