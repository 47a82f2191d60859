// The BSDF of a surface point: one interface (eval, pdf, sample, and whether a smooth lobe exists)
// over every material, dispatched by a switch on the material's tag, so the integrator never
// names a material type and the code runs unchanged in CUDA.
//
// Conventions: wo points from the surface towards where the light goes (the previous vertex);
// ng is the geometric normal on the primitive's outside, ns the shading normal in ng's
// hemisphere. The materials work in a local shading frame whose +z is ns turned to wo's side, so
// each sees wo above its surface; glass alone tells outside from inside (by ng) and inverts its
// index inside. A direction that the local frame calls a reflection must leave on wo's side of
// the geometry, and a transmission on the other, or it carries nothing: shading normals must not
// let light through an opaque surface or leak around a glass one.
#pragma once

#include "core/constants.h"
#include "core/frame.h"
#include "render/bsdf_coat.h"
#include "render/bsdf_conductor.h"
#include "render/bsdf_dielectric.h"
#include "render/bsdf_diffuse.h"
#include "render/bsdf_plastic.h"
#include "render/bsdf_sample.h"
#include "render/bsdf_sheen.h"
#include "render/dispersion.h"
#include "render/material.h"
#include "render/scene_view.h"
#include "render/surface_layers.h"

namespace candela {

// +1 where wo lies on ng's side (outside), else -1.
CANDELA_HDI float sideOf(const Vec3& wo, const Vec3& ng) {
  return dot(wo, ng) >= 0.0f ? 1.0f : -1.0f;
}

// The shading normal turned to wo's side of the surface (decided by the geometric normal).
CANDELA_HDI Vec3 facingNormal(const Vec3& wo, const Vec3& ng, const Vec3& ns) {
  return sideOf(wo, ng) > 0.0f ? ns : -ns;
}

// Whether m has a sheen or a coat over it (render/bsdf_sheen.h, render/bsdf_coat.h).
CANDELA_HDI bool hasLayers(const Material& m) { return hasCoat(m) || hasSheen(m); }

// Whether m is Lambertian with nothing over it: the common case, which needs no wo.
CANDELA_HDI bool isBareDiffuse(const Material& m) {
  return m.type == MaterialType::Diffuse && !hasLayers(m);
}

// Whether m lets light through diffusely (its transmittance is then read at each hit:
// render/surface_color.h, surfaceTransmittance).
CANDELA_HDI bool isTranslucent(const Material& m) { return m.type == MaterialType::Translucent; }

// Frame(n, tangent), out of line: only anisotropic materials have a tangent.
CANDELA_HD_NOINLINE inline Frame tangentFrame(const Vec3& n, const Vec3& tangent) {
  return Frame(n, tangent);
}

struct Bsdf {
  const Material* material;
  Vec3 color;   // the material's colour at this point (textures resolved)
  Vec3 transmittance;  // a translucent diffuse material's at this point (else unread)
  GgxAlpha alpha;    // conductor, glass, plastic: the microfacets' alphas at this point
  PlasticCoat coat;  // plastic: its coat at this point
  Frame frame;  // +z: the shading normal on wo's side; +x: the tangent of an anisotropic material
  Vec3 ng;
  float side;  // +1 when wo lies on ng's side (outside), else -1
  Vec3 wo;     // local (zero for a diffuse surface)
  float eta;   // glass: eta_t / eta_i for light leaving towards wo's side
  SurfaceLayers layers;  // the coat and the sheen here (render/surface_layers.h; where m has them)
  // The normal the coat reflects about, in the local frame: +z unless a map tilts the material
  // beneath or the coat (render/normal_map.h, applyNormalMaps).
  Vec3 coatUp;
};

// The frame of the coat's normal within the local frame (the identity where it is +z).
CANDELA_HDI Frame coatFrame(const Bsdf& b) { return Frame(b.coatUp); }

// The BSDF of material m at a point of colour `color`, transmittance `transmittance` (read where m
// is translucent) and roughness `roughness` (their textures' there: render/surface_color.h),
// tangent `tangent` (render/surface_tangent.h: zero for an isotropic material) and layers `layers`
// (render/surface_layers.h: unread where m has none), seen from wo, for a path that carries
// `channel` (render/dispersion.h).
CANDELA_HDI_ALWAYS Bsdf makeBsdf(const SceneView& scene, const Material& m, const Vec3& color,
                                 const Vec3& transmittance, float roughness, const Vec3& tangent,
                                 const SurfaceLayers& layers, const Vec3& wo, const Vec3& ng,
                                 const Vec3& ns, int32_t channel) {
  const float side = sideOf(wo, ng);
  const Vec3 n = facingNormal(wo, ng, ns);
  const Frame frame = tangent.x == 0.0f && tangent.y == 0.0f && tangent.z == 0.0f
                          ? Frame(n)
                          : tangentFrame(n, tangent);
  // A diffuse surface, the most common, never reads wo.
  if (isBareDiffuse(m))
    return {
        &m,   color,      Vec3(0.0f), GgxAlpha::isotropic(0.0f), PlasticCoat(),         frame, ng,
        side, Vec3(0.0f), 1.0f,       SurfaceLayers(),           Vec3(0.0f, 0.0f, 1.0f)};
  const PlasticCoat coat = m.type == MaterialType::Plastic
                               ? plasticCoatAt(m, scene.plasticCoats, roughness)
                               : PlasticCoat();
  return {&m,
          color,
          transmittance,
          pointAlpha(m, roughness),
          coat,
          frame,
          ng,
          side,
          frame.toLocal(wo),
          side > 0.0f ? iorFor(m, channel) : 1.0f / iorFor(m, channel),
          layers,
          isBlack(layers.coatNormal) ? Vec3(0.0f, 0.0f, 1.0f)
                                     : frame.toLocal(facingNormal(wo, ng, layers.coatNormal))};
}

// Whether some lobe has a density (next-event estimation and MIS apply), rather than only mirror
// and refraction directions.
CANDELA_HDI bool hasSmoothLobe(const Material& m) {
  if (hasSheen(m) || hasRoughCoat(m)) return true;
  switch (m.type) {
    case MaterialType::Diffuse:
    case MaterialType::Translucent:
    case MaterialType::Plastic:
      return true;
    case MaterialType::Conductor:
    case MaterialType::Glass:
      return !isSmooth(m);
    case MaterialType::Emissive:
    case MaterialType::Mix:  // never met: render/material_mix.h chooses a part
      return false;
  }
  return false;
}

// Whether sampleBsdf reads its first number (a choice between lobes); the integrator draws it
// only for such materials.
CANDELA_HDI bool usesLobeChoice(const Material& m) {
  return hasLayers(m) || m.type == MaterialType::Plastic ||
         (m.type == MaterialType::Glass && !isSmooth(m)) || m.type == MaterialType::Translucent;
}

// Whether m emits and reflects nothing (a path that meets it ends there).
CANDELA_HDI bool isEmissive(const Material& m) { return m.type == MaterialType::Emissive; }

// Whether emitting material m, on a surface of geometric normal ng, sends light towards wo: from
// its outside, or from either side where it is two-sided.
CANDELA_HDI bool emitsTowards(const Material& m, const Vec3& wo, const Vec3& ng) {
  const float side = dot(wo, ng);
  return side > 0.0f || (m.twoSided && side < 0.0f);
}

// Whether material m sends light through its surface as well as back (glass, a translucent
// diffuse surface), rather than only back (every other material).
CANDELA_HDI bool transmits(const Material& m) {
  return m.type == MaterialType::Glass || m.type == MaterialType::Translucent;
}

// Whether m bounds a solid whose inside absorbs (glass: render/absorption.h), so that a
// transmission through it enters or leaves that inside; a translucent sheet has none.
CANDELA_HDI bool boundsAnInside(const Material& m) { return m.type == MaterialType::Glass; }

// The normal of the hemisphere outside which the BSDF scatters nothing (leavesOnItsSide): the
// geometric normal on wo's side for the surfaces that only reflect; zero for those that also
// transmit (glass, a translucent sheet).
CANDELA_HDI Vec3 reflectingHemisphere(const Bsdf& b) {
  return transmits(*b.material) ? Vec3(0.0f) : b.ng * b.side;
}

// reflectingHemisphere of the BSDF that makeBsdf would build for material m with wo and ng.
CANDELA_HDI Vec3 reflectingHemisphere(const Material& m, const Vec3& wo, const Vec3& ng) {
  return transmits(m) ? Vec3(0.0f) : ng * sideOf(wo, ng);
}

// Whether wi, local z of sign wiLocalZ, leaves on the side of the geometry the lobe implies.
CANDELA_HDI bool leavesOnItsSide(const Bsdf& b, const Vec3& wi, float wiLocalZ) {
  const float geometric = b.side * dot(wi, b.ng);
  return wiLocalZ > 0.0f ? geometric > 0.0f : geometric < 0.0f;
}

// f |cos(wi)| and the pdf of the material beneath any layers, at wi in the local frame.
CANDELA_HDI Vec3 evalBase(const Bsdf& b, const Vec3& wi, float* pdf) {
  const Material& m = *b.material;
  switch (m.type) {
    case MaterialType::Diffuse:
      *pdf = wi.z > 0.0f ? cosineHemispherePdf(wi.z) : 0.0f;
      return diffuseEval(b.color, wi);
    case MaterialType::Translucent:
      return translucentEvalPdf(b.color, b.transmittance, wi, pdf);
    case MaterialType::Conductor:
      return conductorEvalPdf(m, b.color, b.alpha, b.wo, wi, pdf);
    case MaterialType::Glass:
      return dielectricEvalPdf(b.color, b.alpha, b.eta, b.wo, wi, pdf);
    case MaterialType::Plastic:
      return plasticEvalPdf(m, b.coat, b.alpha, b.color, b.wo, wi, pdf);
    case MaterialType::Emissive:
    case MaterialType::Mix:  // never met: render/material_mix.h chooses a part
      break;
  }
  *pdf = 0.0f;
  return Vec3(0.0f);
}

// evalBase under the material's layers: its sheen (render/bsdf_sheen.h), and over that its coat
// (render/bsdf_coat.h).
CANDELA_HD_NOINLINE inline Vec3 evalLayered(const Bsdf& b, const Vec3& wi, float* pdf) {
  *pdf = 0.0f;
  if (wi.z <= 0.0f || b.wo.z <= 0.0f) return Vec3(0.0f);
  const Material& m = *b.material;
  float p;
  Vec3 f = evalBase(b, wi, &p);
  if (hasSheen(m)) {
    const float chance = sheenProbability(b.layers, b.color, b.wo.z);
    f = f * sheenedBaseFactor(b.layers, wi.z, b.wo.z) + sheenEval(b.layers, b.wo, wi);
    p = chance * sheenDirectionPdf(wi) + (1.0f - chance) * p;
  }
  if (hasCoat(m)) {  // in the coat's frame
    const Frame coat = coatFrame(b);
    const Vec3 wo = coat.toLocal(b.wo);
    f = coatedEvalPdf(m, b.layers, wo, coat.toLocal(wi), f, p,
                      coatProbability(m, b.layers, b.color, wo.z), &p);
  }
  *pdf = p;
  return f;
}

// evalBsdf for every material but a bare diffuse one, at wi in the local frame.
CANDELA_HD_NOINLINE inline Vec3 evalNonDiffuse(const Bsdf& b, const Vec3& wi, float* pdf) {
  if (hasLayers(*b.material)) return evalLayered(b, wi, pdf);
  return evalBase(b, wi, pdf);
}

// f |cos(wi)| and the solid-angle pdf with which sampleBsdf picks wi (zero for delta lobes).
CANDELA_HDI Vec3 evalBsdf(const Bsdf& b, const Vec3& wi, float* pdf) {
  *pdf = 0.0f;
  if (isBareDiffuse(*b.material)) {  // the common case needs only the cosine
    const float cosTheta = dot(wi, b.frame.n);
    if (!leavesOnItsSide(b, wi, cosTheta)) return Vec3(0.0f);
    *pdf = cosineHemispherePdf(cosTheta);
    return diffuseEval(b.color, Vec3(0.0f, 0.0f, cosTheta));
  }
  const Vec3 local = b.frame.toLocal(wi);
  if (!leavesOnItsSide(b, wi, local.z)) return Vec3(0.0f);
  return evalNonDiffuse(b, local, pdf);
}

// evalBsdf for a shadow ray from a raised point (render/shadow_ray_origin.h): a surface that only
// reflects takes wi wherever its shading frame puts it above, also behind the face's plane, where
// no BSDF sample goes (the density there is 0: next-event estimation alone reaches it). Out of
// line: only smooth-shaded faces near the terminator need it.
CANDELA_HD_NOINLINE inline Vec3 evalBsdfAcrossFace(const Bsdf& b, const Vec3& wi, float* pdf) {
  if (transmits(*b.material)) return evalBsdf(b, wi, pdf);
  *pdf = 0.0f;
  const Vec3 local = b.frame.toLocal(wi);
  if (!(local.z > 0.0f)) return Vec3(0.0f);
  Vec3 f;
  if (isBareDiffuse(*b.material)) {
    *pdf = cosineHemispherePdf(local.z);
    f = diffuseEval(b.color, local);
  } else {
    f = evalNonDiffuse(b, local, pdf);
  }
  if (!leavesOnItsSide(b, wi, local.z)) *pdf = 0.0f;
  return f;
}

// Whether a path may follow both lobes of the material at once (sampleBothDeltaLobes): smooth
// glass, whose random choice between reflection and refraction is otherwise most of the noise
// of what it shows.
CANDELA_HDI bool hasTwoDeltaLobes(const Material& m) {
  return m.type == MaterialType::Glass && isSmooth(m);
}

// Both lobes of a material with two delta lobes, as two samples whose weights sum to what
// sampleBsdf's choice between them gives on average: *first the transmission, *second the
// reflection. False where they are not two (total internal reflection) or either leaves through
// the wrong side of the geometry: sampleBsdf then chooses as always.
CANDELA_HDI bool sampleBothDeltaLobes(const Bsdf& b, BsdfSample* first, BsdfSample* second) {
  if (!smoothDielectricBothLobes(b.color, b.eta, b.wo, first, second)) return false;
  const float firstZ = first->wi.z, secondZ = second->wi.z;
  first->wi = b.frame.toWorld(first->wi);
  second->wi = b.frame.toWorld(second->wi);
  return leavesOnItsSide(b, first->wi, firstZ) && leavesOnItsSide(b, second->wi, secondZ);
}

// sampleBsdf of the material beneath any layers, in the local frame.
CANDELA_HDI bool sampleBase(const Bsdf& b, float uc, float u1, float u2, BsdfSample* s) {
  const Material& m = *b.material;
  switch (m.type) {
    case MaterialType::Diffuse:
      return diffuseSample(b.color, u1, u2, s);
    case MaterialType::Translucent:
      return translucentSample(b.color, b.transmittance, uc, u1, u2, s);
    case MaterialType::Conductor:
      return conductorSample(m, b.color, b.alpha, b.wo, u1, u2, s);
    case MaterialType::Glass:
      return dielectricSample(b.color, b.alpha, b.eta, b.wo, uc, u1, u2, s);
    case MaterialType::Plastic:
      return plasticSample(m, b.coat, b.alpha, b.color, b.wo, uc, u1, u2, s);
    case MaterialType::Emissive:
    case MaterialType::Mix:  // never met: render/material_mix.h chooses a part
      break;
  }
  return false;
}

// sampleBase under the material's layers: uc chooses the coat's reflection, or else (rescaled)
// the sheen, or else (rescaled again) the base and its own lobe.
CANDELA_HD_NOINLINE inline bool sampleLayered(const Bsdf& b, float uc, float u1, float u2,
                                              BsdfSample* s) {
  const Material& m = *b.material;
  if (b.wo.z <= 0.0f) return false;
  const SurfaceLayers& layers = b.layers;
  // The coat's lobe, and what it lets through, in its own frame.
  const Frame coatLocal = coatFrame(b);
  const Vec3 coatWo = coatLocal.toLocal(b.wo);
  if (hasCoat(m) && coatWo.z <= 0.0f) return false;  // seen from below the coat: nothing
  const float coat = hasCoat(m) ? coatProbability(m, layers, b.color, coatWo.z) : 0.0f;
  if (uc < coat) {
    if (!sampleCoatReflection(m, layers, coatWo, coat, u1, u2, s)) return false;
    s->wi = coatLocal.toWorld(s->wi);
    if (s->delta) return true;
  } else {
    uc = minf((uc - coat) / (1.0f - coat), kOneMinusEpsilon);
    const float sheen = hasSheen(m) ? sheenProbability(layers, b.color, b.wo.z) : 0.0f;
    if (uc < sheen) {
      s->wi = sampleSheenDirection(u1, u2);
      s->delta = false;
      s->eta = 1.0f;
    } else {
      if (!sampleBase(b, minf((uc - sheen) / (1.0f - sheen), kOneMinusEpsilon), u1, u2, s))
        return false;
      if (s->delta) {  // the layers' share of it, over the chance of choosing the base
        if (hasSheen(m)) s->weight *= sheenedBaseFactor(layers, s->wi.z, b.wo.z) / (1.0f - sheen);
        if (hasCoat(m))
          s->weight *=
              coatedBaseFactor(m, layers, coatLocal.toLocal(s->wi).z, coatWo.z) / (1.0f - coat);
        return true;
      }
    }
  }
  const Vec3 f = evalLayered(b, s->wi, &s->pdf);
  if (!(s->pdf > 0.0f)) return false;
  s->weight = f / s->pdf;
  return true;
}

// sampleBsdf for every material but a bare diffuse one, in the local frame.
CANDELA_HD_NOINLINE inline bool sampleNonDiffuse(const Bsdf& b, float uc, float u1, float u2,
                                                 BsdfSample* s) {
  if (hasLayers(*b.material)) return sampleLayered(b, uc, u1, u2, s);
  return sampleBase(b, uc, u1, u2, s);
}

// A scattered direction from (uc, u1, u2): uc picks a lobe where usesLobeChoice says so. False
// when the path ends (no direction, or one leaving through the wrong side of the geometry).
CANDELA_HDI bool sampleBsdf(const Bsdf& b, float uc, float u1, float u2, BsdfSample* s) {
  const bool sampled = isBareDiffuse(*b.material) ? diffuseSample(b.color, u1, u2, s)
                                                  : sampleNonDiffuse(b, uc, u1, u2, s);
  if (!sampled) return false;
  const float localZ = s->wi.z;
  s->wi = b.frame.toWorld(s->wi);
  return leavesOnItsSide(b, s->wi, localZ);
}

}  // namespace candela
