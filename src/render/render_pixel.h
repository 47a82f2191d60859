// One pixel's samples, summed in index order: the unit of work of every backend.
#pragma once

#include <cmath>

#include "render/camera_ray.h"
#include "render/flow.h"
#include "render/integrator.h"

namespace candela {

// NaN fails every comparison; infinities exceed the largest float.
CANDELA_HDI bool isFinite(const Vec3& v) {
  return fabsf(v.x) <= kInfinity && fabsf(v.y) <= kInfinity && fabsf(v.z) <= kInfinity;
}

// A sample's camera ray through pixel (x, y), from the first dimensions of its stream `rng`,
// and in *jx, *jy its place within the pixel.
CANDELA_HDI Ray cameraSample(const SceneView& scene, uint32_t x, uint32_t y, SampleStream& rng,
                             float* jx, float* jy) {
  float lensU = 0.5f, lensV = 0.5f;
  *jx = *jy = 0.5f;
  if (scene.settings.antialiasing) rng.next2D(jx, jy);
  // A pinhole camera passes over the lens dimension, as a point light does over its own.
  rng.next2DIfUsed(scene.camera.apertureRadius > 0.0f, &lensU, &lensV);
  return generateCameraRay(scene.camera, float(x) + *jx, float(y) + *jy, lensU, lensV);
}

// One sample's radiance along its camera ray `ray` (whose first hit is *cameraHit where the
// tracer found it already), added to `sum` unless it is not finite.
template <bool kAovs, class Tracer>
CANDELA_HDI void addSample(const SceneView& scene, const Tracer& tracer, const Ray& ray, float jx,
                           float jy, SampleStream& rng, RayCounters& counters, const Hit* cameraHit,
                           Vec3* sum, AovPixel* aov) {
  ++counters.camera;
  FirstHit first;
  const Vec3 L =
      traceRadiance<kAovs>(scene, tracer, ray, rng, counters, kAovs ? &first : nullptr, cameraHit);
  // A non-finite sample (a degenerate mesh, say) would poison the pixel; it counts as black.
  if (isFinite(L)) *sum += L;
  if constexpr (kAovs) {
    Vec2 flow;
    const bool hasFlow = scene.flow.enabled && sampleFlow(scene, first, ray.direction, &flow);
    addAovSample(aov, first, jx, jy, scene.camera.position, hasFlow, flow);
  }
}

// `sum` plus the radiance of samples [sampleBegin, sampleBegin + sampleCount) of pixel (x, y),
// added one by one in index order (so a pixel rendered in several calls, each continuing the
// last one's sum, is bit-identical to one call). Each sample's random numbers depend only on
// (seed, pixel, sample index, dimension) and spp. `tracer` answers the ray queries
// (geometry/bvh_tracer.h); one whose kCameraPacket exceeds 1 traces up to that many of the
// pixel's camera rays at once (closestPacket), which are nearly parallel. With kAovs the
// samples' first hits are added to `aov` too (render/aov.h); the radiance is the same either way.
template <bool kAovs = false, class Tracer>
CANDELA_HDI Vec3 renderPixelSamples(const SceneView& scene, const Tracer& tracer, uint32_t x,
                                    uint32_t y, uint32_t sampleBegin, uint32_t sampleCount,
                                    RayCounters& counters, Vec3 sum = Vec3(0.0f),
                                    AovPixel* aov = nullptr) {
  const uint64_t pixelIndex = uint64_t(y) * scene.camera.width + x;
  const uint32_t sampleEnd = sampleBegin + sampleCount;
  constexpr uint32_t kPacket = Tracer::kCameraPacket;
  if constexpr (kPacket > 1) {
    for (uint32_t s = sampleBegin, n = 0; s < sampleEnd; s += n) {
      // Packets start at multiples of kPacket, so a pixel rendered in sample ranges that split
      // there groups its rays as one call would.
      const uint32_t toBoundary = kPacket - s % kPacket;
      n = sampleEnd - s < toBoundary ? sampleEnd - s : toBoundary;
      SampleStream rng[kPacket];
      Ray rays[kPacket];
      Hit hits[kPacket];
      float jx[kPacket], jy[kPacket];
      for (uint32_t i = 0; i < n; ++i) {
        rng[i] = SampleStream(scene.settings.seed, pixelIndex, s + i, scene.settings.spp);
        rays[i] = cameraSample(scene, x, y, rng[i], &jx[i], &jy[i]);
      }
      tracer.closestPacket(rays, n, hits);
      for (uint32_t i = 0; i < n; ++i)
        addSample<kAovs>(scene, tracer, rays[i], jx[i], jy[i], rng[i], counters, &hits[i], &sum,
                         aov);
    }
  } else {
    for (uint32_t s = sampleBegin; s < sampleEnd; ++s) {
      SampleStream rng(scene.settings.seed, pixelIndex, s, scene.settings.spp);
      float jx, jy;
      const Ray ray = cameraSample(scene, x, y, rng, &jx, &jy);
      addSample<kAovs>(scene, tracer, ray, jx, jy, rng, counters, nullptr, &sum, aov);
    }
  }
  return sum;
}

}  // namespace candela
