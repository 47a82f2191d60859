// Next-event estimation towards point and sphere lights.
//
// A point light of power P seen from distance d contributes irradiance (P / 4 pi) cos / d^2.
// A sphere light is sampled uniformly by the solid angle of the cone it subtends, so its pdf
// can be evaluated again when a BSDF-sampled ray hits it (multiple importance sampling).
#pragma once

#include <cmath>

#include "core/check.h"
#include "core/frame.h"
#include "core/sampling.h"
#include "render/scene_view.h"

namespace candela {

struct LightSample {
  Vec3 wi;           // unit direction from the shading point towards the light
  float distance;    // to the sampled light point
  Vec3 radiance;     // incident radiance (area light) or intensity / d^2 (point light)
  float pdf;         // solid-angle density; 1 for point lights
  bool isDelta;      // point lights cannot be hit by BSDF sampling
};

// 1 - cos(theta_max) of the cone a sphere subtends, accurate also for tiny, far spheres.
CANDELA_HDI float sphereConeOneMinusCos(float sin2ThetaMax) {
  return sin2ThetaMax < 0.00068523f ? 0.5f * sin2ThetaMax  // 1 - sqrt(1 - x) ~ x / 2
                                    : 1.0f - sqrtf(1.0f - sin2ThetaMax);
}

// Solid-angle pdf with which sampleLight picks a direction towards the sphere light whose
// surface is `s` from p; 0 when p is inside it (which then shows it no emitting surface).
CANDELA_HDI float sphereLightPdf(const Sphere& s, const Vec3& p) {
  const float dist2 = lengthSquared(s.center - p);
  const float r2 = s.radius * s.radius;
  if (dist2 <= r2) return 0.0f;
  return uniformConePdf(sphereConeOneMinusCos(r2 / dist2));
}

// The light that next-event estimation samples for uniform u in [0, 1): light i with probability
// scene.lights[i].selectPmf (pbrt-v4's power light sampler), found by bisecting the running
// sums. -1 when no light has any power.
CANDELA_HDI int selectLight(const SceneView& scene, float u) {
  uint32_t lo = 0, hi = scene.lightCount;  // the answer is the first light with u < selectCdf
  while (lo < hi) {
    const uint32_t mid = (lo + hi) / 2;
    if (u < scene.lights[mid].selectCdf) {
      hi = mid;
    } else {
      lo = mid + 1;
    }
  }
  return lo < scene.lightCount ? static_cast<int>(lo) : -1;
}

CANDELA_HDI bool samplePointLight(const Light& l, const Vec3& p, LightSample* s) {
  const Vec3 toLight = l.position - p;
  const float dist2 = lengthSquared(toLight);
  if (dist2 <= 0.0f) return false;
  s->distance = sqrtf(dist2);
  s->wi = toLight / s->distance;
  s->radiance = l.power * (kInv4Pi / dist2);
  s->pdf = 1.0f;
  s->isDelta = true;
  return true;
}

CANDELA_HDI bool sampleSphereLight(const SceneView& scene, const Light& l, const Vec3& p, float u1,
                                   float u2, LightSample* s) {
  CANDELA_DCHECK(l.sphere < scene.sphereCount);
  const Sphere& sphere = scene.spheres[l.sphere];
  const Vec3 toCenter = sphere.center - p;
  const float dist2 = lengthSquared(toCenter);
  const float r2 = sphere.radius * sphere.radius;
  if (dist2 <= r2) return false;
  const float dc = sqrtf(dist2);
  const float oneMinusCosMax = sphereConeOneMinusCos(r2 / dist2);
  const Vec3 local = sampleUniformCone(u1, u2, oneMinusCosMax);
  const Vec3 axis = toCenter / dc;
  s->wi = normalize(Frame(axis).toWorld(local));
  // Distance to the near intersection with the sphere along wi (clamped at the tangent).
  const float cosTheta = local.z;
  const float sin2Theta = maxf(0.0f, 1.0f - cosTheta * cosTheta);
  const float b = dc * cosTheta;
  const float disc = maxf(0.0f, r2 - dc * dc * sin2Theta);
  s->distance = b - sqrtf(disc);
  s->radiance = scene.materials[sphere.material].radiance;
  s->pdf = uniformConePdf(oneMinusCosMax);
  s->isDelta = false;
  return s->distance > 0.0f;
}

// A sample of light `l` as seen from p, from the uniform numbers (u1, u2) (a point light uses
// neither); false when the light shows p nothing.
CANDELA_HDI bool sampleLight(const SceneView& scene, const Light& l, const Vec3& p, float u1,
                             float u2, LightSample* s) {
  switch (l.type) {
    case LightType::Point:
      return samplePointLight(l, p, s);
    case LightType::Sphere:
      return sampleSphereLight(scene, l, p, u1, u2, s);
  }
  return false;
}

}  // namespace candela
