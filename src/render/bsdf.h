// The three scattering materials: Lambertian diffuse, perfect mirror and smooth glass.
//
// Conventions: wo points from the surface towards where the light goes (the previous vertex);
// ng is the geometric normal on the primitive's outside, ns the shading normal in ng's
// hemisphere. Diffuse and mirror reflect on both sides; glass tells outside from inside by ng.
// A sample's `weight` is f * |cos| / pdf, the factor the path throughput is multiplied by.
#pragma once

#include "core/frame.h"
#include "core/sampling.h"
#include "render/fresnel.h"
#include "render/material.h"

namespace candela {

struct BsdfSample {
  Vec3 wi;
  Vec3 weight;
  float pdf = 0;       // solid-angle density; meaningful only when !specular
  bool specular = false;
};

// The shading normal turned to wo's side of the surface (decided by the geometric normal).
CANDELA_HDI Vec3 facingNormal(const Vec3& wo, const Vec3& ng, const Vec3& ns) {
  return dot(wo, ng) >= 0.0f ? ns : -ns;
}

// Diffuse f * cos for a direction wi; zero when wi leaves through the other side of the surface.
CANDELA_HDI Vec3 evalDiffuse(const Material& m, const Vec3& wo, const Vec3& ng, const Vec3& ns,
                             const Vec3& wi) {
  if (dot(wo, ng) * dot(wi, ng) <= 0.0f) return Vec3(0.0f);
  const float cosTheta = dot(wi, facingNormal(wo, ng, ns));
  return cosTheta > 0.0f ? m.color * (cosTheta * kInvPi) : Vec3(0.0f);
}

CANDELA_HDI float diffusePdf(const Vec3& wo, const Vec3& ng, const Vec3& ns, const Vec3& wi) {
  if (dot(wo, ng) * dot(wi, ng) <= 0.0f) return 0.0f;
  return cosineHemispherePdf(dot(wi, facingNormal(wo, ng, ns)));
}

// Samples a scattered direction; false when the path ends (the sample left through the wrong
// side of the surface, which shading normals can cause).
CANDELA_HDI bool sampleBsdf(const Material& m, const Vec3& wo, const Vec3& ng, const Vec3& ns,
                            float u1, float u2, BsdfSample* s) {
  const Vec3 n = facingNormal(wo, ng, ns);
  const float side = dot(wo, ng) >= 0.0f ? 1.0f : -1.0f;  // wo's side of the geometry
  switch (m.type) {
    case MaterialType::Diffuse: {
      const Vec3 local = sampleCosineHemisphere(u1, u2);
      s->wi = Frame(n).toWorld(local);
      s->pdf = cosineHemispherePdf(local.z);
      s->weight = m.color;  // (albedo / pi) * cos / (cos / pi)
      s->specular = false;
      return side * dot(s->wi, ng) > 0.0f && s->pdf > 0.0f;
    }
    case MaterialType::Mirror: {
      s->wi = reflect(wo, n);
      s->weight = m.color;
      s->pdf = 0.0f;
      s->specular = true;
      return side * dot(s->wi, ng) > 0.0f;
    }
    case MaterialType::Glass: {
      // eta = eta_t / eta_i: entering from outside the ratio is ior, leaving it is 1 / ior.
      const float eta = side > 0.0f ? m.ior : 1.0f / m.ior;
      const float cosThetaI = maxf(0.0f, dot(wo, n));
      const float reflectance = fresnelDielectric(cosThetaI, eta);
      s->pdf = 0.0f;
      s->specular = true;
      if (u1 < reflectance) {
        s->wi = reflect(wo, n);
        s->weight = Vec3(1.0f);  // F / (probability F)
        return side * dot(s->wi, ng) > 0.0f;
      }
      if (!refract(wo, n, eta, &s->wi)) return false;  // unreachable: F = 1 under TIR
      // (1 - F) / (probability 1 - F), radiance scaled by (eta_i / eta_t)^2, tinted by color.
      s->weight = m.color * (1.0f / (eta * eta));
      return side * dot(s->wi, ng) < 0.0f;
    }
    case MaterialType::Emissive:
      return false;
  }
  return false;
}

}  // namespace candela
