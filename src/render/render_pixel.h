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

// `sum` plus the radiance of samples [sampleBegin, sampleBegin + sampleCount) of pixel (x, y),
// added one by one in index order (so a pixel rendered in several calls, each continuing the
// last one's sum, is bit-identical to one call). Each sample's random numbers depend only on
// (seed, pixel, sample index, dimension) and spp. `tracer` answers the ray queries
// (geometry/bvh_tracer.h). With kAovs the samples' first hits are added to `aov` too
// (render/aov.h); the radiance is the same either way.
template <bool kAovs = false, class Tracer>
CANDELA_HDI Vec3 renderPixelSamples(const SceneView& scene, const Tracer& tracer, uint32_t x,
                                    uint32_t y, uint32_t sampleBegin, uint32_t sampleCount,
                                    RayCounters& counters, Vec3 sum = Vec3(0.0f),
                                    AovPixel* aov = nullptr) {
  const uint64_t pixelIndex = uint64_t(y) * scene.camera.width + x;
  for (uint32_t s = sampleBegin; s < sampleBegin + sampleCount; ++s) {
    SampleStream rng(scene.settings.seed, pixelIndex, s, scene.settings.spp);
    float jx = 0.5f, jy = 0.5f, lensU = 0.5f, lensV = 0.5f;
    if (scene.settings.antialiasing) rng.next2D(&jx, &jy);
    // A pinhole camera passes over the lens dimension, as a point light does over its own.
    rng.next2DIfUsed(scene.camera.apertureRadius > 0.0f, &lensU, &lensV);
    const Ray ray = generateCameraRay(scene.camera, float(x) + jx, float(y) + jy, lensU, lensV);
    ++counters.camera;
    FirstHit first;
    const Vec3 L = traceRadiance<kAovs>(scene, tracer, ray, rng, counters, kAovs ? &first : nullptr);
    // A non-finite sample (a degenerate mesh, say) would poison the pixel; it counts as black.
    if (isFinite(L)) sum += L;
    if constexpr (kAovs) {
      Vec2 flow;
      const bool hasFlow = scene.flow.enabled && sampleFlow(scene, first, ray.direction, &flow);
      addAovSample(aov, first, jx, jy, scene.camera.position, hasFlow, flow);
    }
  }
  return sum;
}

}  // namespace candela
