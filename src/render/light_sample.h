// Next-event estimation towards point and sphere lights.
//
// A point light of power P seen from distance d contributes irradiance (P / 4 pi) cos / d^2.
// A sphere light is sampled uniformly by the solid angle of the cone it subtends, so its pdf
// can be evaluated again when a BSDF-sampled ray hits it (multiple importance sampling).
#pragma once

#include <cmath>

#include "core/frame.h"
#include "core/sampling.h"
#include "scene/scene_view.h"

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

// Solid-angle pdf with which sampleLight picks a direction towards sphere light `l` from p;
// 0 when p is inside the light (which then shows it no emitting surface).
CANDELA_HDI float sphereLightPdf(const Light& l, const Vec3& p) {
  const float dist2 = lengthSquared(l.position - p);
  const float r2 = l.radius * l.radius;
  if (dist2 <= r2) return 0.0f;
  return 1.0f / (2.0f * kPi * sphereConeOneMinusCos(r2 / dist2));
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

CANDELA_HDI bool sampleLight(const Light& l, const Vec3& p, float u1, float u2, LightSample* s) {
  const Vec3 toCenter = l.position - p;
  const float dist2 = lengthSquared(toCenter);
  if (l.type == LightType::Point) {
    if (dist2 <= 0.0f) return false;
    s->distance = sqrtf(dist2);
    s->wi = toCenter / s->distance;
    s->radiance = l.power * (kInv4Pi / dist2);
    s->pdf = 1.0f;
    s->isDelta = true;
    return true;
  }
  const float r2 = l.radius * l.radius;
  if (dist2 <= r2) return false;
  const float dc = sqrtf(dist2);
  const float sin2ThetaMax = r2 / dist2;
  const float oneMinusCosMax = sphereConeOneMinusCos(sin2ThetaMax);
  // Uniform in the cone: cos(theta) = 1 - u (1 - cos(theta_max)).
  const float cosTheta = 1.0f - u1 * oneMinusCosMax;
  const float sin2Theta = maxf(0.0f, 1.0f - cosTheta * cosTheta);
  const float phi = 2.0f * kPi * u2;
  const float sinTheta = sqrtf(sin2Theta);
  const Vec3 axis = toCenter / dc;
  s->wi = normalize(Frame(axis).toWorld(Vec3(cosf(phi) * sinTheta, sinf(phi) * sinTheta, cosTheta)));
  // Distance to the near intersection with the sphere along wi (clamped at the tangent).
  const float b = dc * cosTheta;
  const float disc = maxf(0.0f, r2 - dc * dc * sin2Theta);
  s->distance = b - sqrtf(disc);
  s->radiance = l.radiance;
  s->pdf = 1.0f / (2.0f * kPi * oneMinusCosMax);
  s->isDelta = false;
  return s->distance > 0.0f;
}

}  // namespace candela
