// The path integrator: one iterative loop per camera sample, shared by every backend.
//
// Depth follows the contract: interaction k is the k-th surface hit (the first hit is 1).
// Light reaching interaction k <= max_depth counts, by a shadow ray (next-event estimation) or
// by the ray scattered from k hitting an emitter or the environment; nothing beyond max_depth
// scatters. Emitting spheres and triangles are reached both ways and combined with the power
// heuristic, and so is the environment; point lights are reached only by shadow rays.
#pragma once

#include <cmath>

#include "core/check.h"
#include "core/float_error.h"
#include "core/sobol_sampler.h"
#include "geometry/surface.h"
#include "render/aov.h"
#include "render/bsdf.h"
#include "render/light_sample.h"
#include "render/light_selection.h"
#include "render/ray_counters.h"
#include "render/surface_color.h"

namespace candela {

// Shadow rays stop this fraction short of their target (pbrt's ShadowEpsilon): relative, so it
// holds at any scene scale.
constexpr float kShadowEpsilon = 1e-4f;
// Russian roulette starts after this many interactions (Mitsuba's default; docs/performance.md
// has what earlier starts cost).
constexpr uint32_t kRouletteDepth = 5;

CANDELA_HDI_ALWAYS Ray spawnRay(const SurfacePoint& sp, const Vec3& wi) {
  Ray r;
  r.origin = offsetRayOrigin(sp.p, sp.error, sp.ng, wi);
  r.direction = wi;
  return r;
}

// Direct light at a point with a smooth BSDF lobe from one light, by one shadow ray, weighted by
// the probability selectPmf of sampling that light. `tracer` answers the ray queries
// (geometry/bvh_tracer.h).
template <class Tracer>
CANDELA_HDI Vec3 sampleOneLight(const SceneView& scene, const Tracer& tracer, const Light& light,
                                float selectPmf, const Bsdf& bsdf, const SurfacePoint& sp, float u1,
                                float u2, RayCounters& counters) {
  LightSample ls;
  if (!sampleLight(scene, light, sp.p, u1, u2, &ls)) return Vec3(0.0f);
  float bsdfPdf;
  const Vec3 f = evalBsdf(bsdf, ls.wi, &bsdfPdf);
  if (isBlack(f)) return Vec3(0.0f);
  Ray shadow = spawnRay(sp, ls.wi);
  // The environment lies beyond everything: nothing short of infinity may block it.
  if (ls.distance < kInfinity) {
    const Vec3 target = sp.p + ls.wi * ls.distance;
    shadow.tMax = length(target - shadow.origin) * (1.0f - kShadowEpsilon);
  }
  ++counters.shadow;
  if (tracer.occluded(shadow, lightPrimitive(scene, light))) return Vec3(0.0f);
  const float lightPdf = selectPmf * ls.pdf;
  const float weight = ls.isDelta ? 1.0f : powerHeuristic(lightPdf, bsdfPdf);
  return f * ls.radiance * (weight / lightPdf);
}

// The two numbers a light sample of `light` uses, from the stream's next dimension. A point
// light uses none: its dimension is passed over without computing them, so the stream's layout
// is the same whatever the lights are.
CANDELA_HDI void drawLightNumbers(SampleStream& rng, const Light& light, float* u1, float* u2) {
  rng.next2DIfUsed(light.type != LightType::Point, u1, u2);
}

// Direct light at a point with a smooth BSDF lobe, whose reflecting hemisphere is around
// `hemisphere` (reflectingHemisphere: zero where the surface also transmits): from the scene's
// lone point light (render/light.h, isLonePointLight), else from one light picked by its
// importance here (render/light_selection.h).
template <class Tracer>
CANDELA_HDI Vec3 estimateDirect(const SceneView& scene, const Tracer& tracer, const Bsdf& bsdf,
                                const Vec3& hemisphere, const SurfacePoint& sp, SampleStream& rng,
                                RayCounters& counters) {
  // One dimension for the lone point light, or two for a picked one (the pick and its light's
  // sample), whatever the geometry, so the stream's layout never depends on it.
  float u1 = 0.0f, u2 = 0.0f;
  if (scene.lonePointLight) {
    drawLightNumbers(rng, scene.lights[0], &u1, &u2);
    return sampleOneLight(scene, tracer, scene.lights[0], 1.0f, bsdf, sp, u1, u2, counters);
  }
  const float uLight = rng.next1D();
  float selectPmf;
  const int index = selectLight(scene, sp.p, hemisphere, uLight, &selectPmf);
  if (index < 0) {
    rng.skip();
    return Vec3(0.0f);
  }
  drawLightNumbers(rng, scene.lights[index], &u1, &u2);
  return sampleOneLight(scene, tracer, scene.lights[index], selectPmf, bsdf, sp, u1, u2, counters);
}

// Radiance arriving at the camera along `ray` (one sample). With kAovs, `first` (zeroed by the
// caller) also receives the sample's first hit and albedo (render/aov.h); that work is compiled
// only into the kAovs instance, and it draws no random numbers, so the radiance is the same.
// `cameraHit`, where given, is what tracer.closest answers for `ray` (invalid for a miss),
// found already by a packet of camera rays (render/render_pixel.h).
template <bool kAovs = false, class Tracer>
CANDELA_HDI Vec3 traceRadiance(const SceneView& scene, const Tracer& tracer, Ray ray,
                               SampleStream& rng, RayCounters& counters, FirstHit* first = nullptr,
                               const Hit* cameraHit = nullptr) {
  Vec3 radiance(0.0f), throughput(1.0f);
  uint32_t maxDepth = scene.settings.maxDepth;
  bool specularBounce = true;  // the camera counts as specular: emitters seen directly count fully
  float bsdfPdf = 0.0f;        // pdf of the last non-delta bounce, for MIS on area lights
  // The product of eta^2 over the transmissions so far: Russian roulette judges the throughput
  // without the 1 / eta^2 radiance scaling, which says nothing about the path's worth.
  float etaScale = 1.0f;
  Vec3 bouncePoint(0.0f), bounceHemisphere(0.0f);  // the last bounce's, for the light's pmf

  for (uint32_t depth = 1;; ++depth) {
    Hit hit;
    bool found;
    if (depth == 1 && cameraHit) {
      hit = *cameraHit;
      found = hit.valid();
    } else {
      found = tracer.closest(ray, &hit);
    }
    if (!found) {
      const int32_t light = specularBounce ? -1 : scene.environment.light;
      const float weight =
          light < 0 ? 1.0f
                    : powerHeuristic(bsdfPdf, lightSelectPmf(scene, uint32_t(light), bouncePoint,
                                                             bounceHemisphere) *
                                                  environmentPdf(scene, ray.direction));
      radiance += throughput * environmentRadiance(scene, ray.direction) * weight;
      break;
    }
    const SurfacePoint sp = surfaceAt(scene, ray, hit);
    CANDELA_DCHECK(sp.material < scene.materialCount);
    const Material& m = scene.materials[sp.material];
    const Vec3 wo = -ray.direction;
    [[maybe_unused]] bool albedoHere = false;  // the albedo pass takes this surface's colour
    if constexpr (kAovs) {
      if (depth == 1) {
        first->hit = true;
        first->position = sp.p;
        first->normal = facingNormal(wo, sp.ng, sp.ns);
        first->material = sp.material;
      }
      if (!first->albedoDone && (isEmissive(m) || hasSmoothLobe(m))) {
        first->albedoDone = true;
        if (isEmissive(m))
          first->albedo = dot(wo, sp.ng) > 0.0f ? clampUnit(m.radiance) : Vec3(0.0f);
        else
          albedoHere = true;  // from the surface colour below, looked up once
      }
    }

    if (isEmissive(m)) {
      if (dot(wo, sp.ng) > 0.0f) {  // emitters emit from their outside only
        float weight = 1.0f;
        const int32_t light = specularBounce ? -1 : lightOfPrimitive(scene, hit.prim);
        if (light >= 0) {
          const float selectPmf =
              lightSelectPmf(scene, uint32_t(light), bouncePoint, bounceHemisphere);
          weight = powerHeuristic(bsdfPdf,
                                  selectPmf * emitterPdf(scene, scene.lights[light], bouncePoint,
                                                         ray.direction, hit.t, sp.ng));
        }
        radiance += throughput * surfaceRadiance(scene, m, hit, sp) * weight;
      }
      break;
    }
    if (depth > maxDepth) {
      if constexpr (kAovs)
        if (albedoHere) first->albedo = aovAlbedo(m, surfaceColor(scene, m, hit, sp));
      break;
    }

    const Vec3 color = surfaceColor(scene, m, hit, sp);
    if constexpr (kAovs)
      if (albedoHere) first->albedo = aovAlbedo(m, color);
    const Bsdf bsdf = makeBsdf(m, color, wo, sp.ng, sp.ns);
    const Vec3 hemisphere = reflectingHemisphere(bsdf);
    if (hasSmoothLobe(m)) {
      radiance += throughput * estimateDirect(scene, tracer, bsdf, hemisphere, sp, rng, counters);
      // "direct": the scattered ray below only gathers emission; nothing scatters after it.
      if (scene.settings.integrator == IntegratorType::Direct) maxDepth = depth;
    }

    if (depth == maxDepth && !scene.emissionReachable) break;

    const float uc = usesLobeChoice(m) ? rng.next1D() : 0.0f;
    float u1, u2;
    rng.next2D(&u1, &u2);
    BsdfSample bs;
    if (!sampleBsdf(bsdf, uc, u1, u2, &bs)) break;
    throughput *= bs.weight;
    etaScale *= bs.eta * bs.eta;
    specularBounce = bs.delta;
    bsdfPdf = bs.pdf;
    bouncePoint = sp.p;
    bounceHemisphere = hemisphere;

    if (depth >= kRouletteDepth) {
      const float survive = minf(0.95f, maxComponent(throughput) * etaScale);
      if (rng.next1D() >= survive) break;
      throughput /= survive;
    }
    ray = spawnRay(sp, bs.wi);
    ++counters.bounce;
  }
  return radiance;
}

}  // namespace candela
