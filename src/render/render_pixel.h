// One pixel's samples, summed in index order: the unit of work of every backend.
#pragma once

#include <cmath>

#include "render/camera_ray.h"
#include "render/flow.h"
#include "render/integrator.h"
#include "render/packet_slots.h"

namespace candela {

// A sample's camera ray through pixel (x, y), from the first dimensions of its stream `rng`,
// in *jx, *jy its place relative to the pixel (within it for the box filter, around its centre for
// the wider ones: render/pixel_filter.h), and in *eye the camera's centre at the sample's time.
CANDELA_HDI Ray cameraSample(const SceneView& scene, uint32_t x, uint32_t y, SampleStream& rng,
                             float* jx, float* jy, Vec3* eye) {
  float lensU = 0.5f, lensV = 0.5f;
  *jx = *jy = 0.5f;
  if (scene.settings.antialiasing) {
    rng.next2D(jx, jy);
    *jx = sampleFilter(scene.settings.filter, *jx);
    *jy = sampleFilter(scene.settings.filter, *jy);
  }
  // A pinhole camera passes over the lens dimension, as a point light does over its own.
  rng.next2DIfUsed(scene.camera.apertureRadius > 0.0f, &lensU, &lensV);
  const uint32_t stride = scene.camera.pixelStride, offset = stride / 2;
  const float px = float(scene.camera.windowX + x * stride + offset) + *jx;
  const float py = float(scene.camera.windowY + y * stride + offset) + *jy;
  Ray ray;
  // Only a frame whose camera or geometry moves while the shutter is open draws a time, so that
  // the samples of every other keep the numbers they had before motion blur existed.
  float time = 0.0f;
  if (scene.cameraPoseCount > 1 || scene.motionTimeCount > 1)
    time = py * scene.camera.shutterRowSlope + rng.next1D() * scene.camera.shutterRowShare;
  if (scene.cameraPoseCount > 1) {
    const Camera posed =
        cameraAtShutterTime(scene.camera, scene.cameraPoses, scene.cameraPoseCount, time);
    ray = generateCameraRay(posed, px, py, lensU, lensV);
    *eye = posed.position;
  } else {
    ray = generateCameraRay(scene.camera, px, py, lensU, lensV);
    *eye = scene.camera.position;
  }
  ray.time = time;
  ray.alphaKey = rayKeyFor(scene, rng, kCameraRay);
  return ray;
}

// Adds one sample's radiance L, whose camera ray is `ray` through (jx, jy) in the pixel from a
// camera centred at `eye`, to `sum` unless it is not finite; with kAovs its first hit `first` to
// `aov`.
template <bool kAovs>
CANDELA_HDI void addSample(const SceneView& scene, const Vec3& L, const Ray& ray, float jx,
                           float jy, const Vec3& eye, const FirstHit& first, Vec3* sum,
                           AovPixel* aov) {
  // A non-finite sample (a degenerate mesh, say) would poison the pixel; it counts as black.
  const bool finite = isFinite(L);
  if (finite) *sum += L;
  if constexpr (kAovs) {
    SampleFlows flows;
    flows.hasForward = scene.flow.enabled &&
                       sampleFlow(scene, forwardFlow(scene), first, ray.direction, &flows.forward);
    flows.hasBackward = scene.backwardFlow.enabled && sampleFlow(scene, backwardFlow(scene), first,
                                                                 ray.direction, &flows.backward);
    addAovSample(aov, first, jx, jy, eye, flows, finite);
  }
}

// A pixel's shadow rays towards a few lights are nearly parallel, like its camera rays; towards
// many (a mesh lamp's triangles, picked one by one) they part, and packets of them were slower
// than rays alone (docs/performance.md).
constexpr uint32_t kShadowPacketsUpToLights = 4;
static_assert(kEachDeltaLightUpTo <= kShadowPacketsUpToLights,
              "a scene whose every light is sampled at the first hit traces those rays as packets");

// Samples [s, s + n) of a pixel, n <= Tracer::kPacketWidth, their paths in step up to their
// first interaction: the camera rays traced as one packet, then the shadow rays of that
// interaction (as a packet where the scene has few lights; the light vertices' rays and
// connections one by one, as they part); each path then goes on alone. The same
// arithmetic as traceRadiance path by path, so the same radiance but where a packet's hit differs
// from a lone ray's by rounding.
template <bool kAovs, class Tracer>
CANDELA_HDI void renderPacket(const SceneView& scene, const Tracer& tracer, uint32_t x, uint32_t y,
                              PixelKey pixel, uint32_t s, uint32_t n, RayCounters& counters,
                              Vec3* sum, AovPixel* aov, SampleTable* table) {
  constexpr uint32_t kWidth = Tracer::kPacketWidth;
  static_assert(kWidth <= SampleTable::kLanes, "a packet's samples fit a sample table");
  PacketSlots<SampleStream, kWidth> rng;
  Ray rays[kWidth];
  float jx[kWidth], jy[kWidth];
  Vec3 eyes[kWidth];
  if (table) table = table->serve(pixel.value, s, n, scene.settings.spp);
  for (uint32_t i = 0; i < n; ++i) {
    rng.emplace(i, pixel, s + i, scene.settings.spp, table, i);
    rays[i] = cameraSample(scene, x, y, rng[i], &jx[i], &jy[i], &eyes[i]);
  }
  Hit hits[kWidth];
  tracer.closestPacket(rays, n, hits);
  counters.camera += n;

  PacketSlots<PathState, kWidth> paths;
  FirstHit first[kAovs ? kWidth : 1];  // only the passes read them
  bool goesOn[kWidth];
  PacketSlots<LightQueries, kWidth> lights;
  uint32_t mostQueries = 0;  // the most shadow queries of one path
  for (uint32_t i = 0; i < n; ++i) {
    paths.emplace(i, scene, rays[i]);
    lights.emplace(i);
    if (scene.lightPathLights > 0)
      traceLightVertex(scene, tracer, rng[i], counters, rays[i].time, &paths[i].lightVertex);
    ShadowQuery connect;
    goesOn[i] = interact<kAovs>(scene, &paths[i], hits[i].valid(), hits[i], rng[i], counters,
                                &first[kAovs ? i : 0], &lights[i], &connect) ||
                resumeBranch(&paths[i], &rng[i]);
    mostQueries = lights[i].count > mostQueries ? lights[i].count : mostQueries;
    if (connect.active)
      resolveShadow<kAovs>(connect, shadowTransmittance(scene, tracer, connect), &paths[i],
                           &first[kAovs ? i : 0]);
  }
  // The paths' k-th shadow rays together (towards light k, where each point light is sampled).
  for (uint32_t k = 0; k < mostQueries; ++k) {
    Ray shadowRays[kWidth];
    uint32_t skipPrims[kWidth], shadowLane[kWidth], shadowCount = 0;
    for (uint32_t i = 0; i < n; ++i) {
      if (k >= lights[i].count || !lights[i].query[k].active) continue;
      shadowRays[shadowCount] = lights[i].query[k].ray;
      skipPrims[shadowCount] = lights[i].query[k].skipPrim;
      shadowLane[shadowCount++] = i;
    }
    if (shadowCount == 0) continue;
    if (scene.indexMatchedMedia) {  // each ray hit by hit through the media it crosses
      for (uint32_t j = 0; j < shadowCount; ++j) {
        const ShadowQuery& q = lights[shadowLane[j]].query[k];
        resolveShadow<kAovs>(q, shadowTransmittance(scene, tracer, q), &paths[shadowLane[j]],
                             &first[kAovs ? shadowLane[j] : 0]);
      }
      continue;
    }
    bool blocked[kWidth];
    if (scene.lightCount <= kShadowPacketsUpToLights) {
      tracer.occludedPacket(shadowRays, skipPrims, shadowCount, blocked);
    } else {
      for (uint32_t j = 0; j < shadowCount; ++j)
        blocked[j] = tracer.occluded(shadowRays[j], skipPrims[j]);
    }
    for (uint32_t j = 0; j < shadowCount; ++j)
      resolveShadow<kAovs>(lights[shadowLane[j]].query[k], blocked[j] ? Vec3(0.0f) : Vec3(1.0f),
                           &paths[shadowLane[j]], &first[kAovs ? shadowLane[j] : 0]);
  }

  for (uint32_t i = 0; i < n; ++i) {
    FirstHit& f = first[kAovs ? i : 0];
    const Vec3 L = goesOn[i] ? finishPath<kAovs>(scene, tracer, &paths[i], rng[i], counters, &f)
                             : paths[i].radiance;
    addSample<kAovs>(scene, L, rays[i], jx[i], jy[i], eyes[i], f, sum, aov);
  }
}

// `sum` plus the radiance of samples [sampleBegin, sampleBegin + sampleCount) of pixel (x, y),
// added one by one in index order (so a pixel rendered in several calls, each continuing the
// last one's sum, is bit-identical to one call). Each sample's random numbers depend only on
// (seed, pixel, sample index, dimension) and spp. `tracer` answers the ray queries
// (geometry/bvh_tracer.h); one whose kPacketWidth exceeds 1 takes the pixel's samples that many
// at a time (renderPacket). With kAovs the samples' first hits are added to `aov` too
// (render/aov.h); the radiance is the same either way. With a `table` (whose fill is set), the
// samples' random numbers are computed there, up to SampleTable::kLanes samples at a time (and
// at least SampleTable::kMinLanes): the same numbers.
template <bool kAovs = false, class Tracer>
CANDELA_HDI Vec3 renderPixelSamples(const SceneView& scene, const Tracer& tracer, uint32_t x,
                                    uint32_t y, uint32_t sampleBegin, uint32_t sampleCount,
                                    RayCounters& counters, Vec3 sum = Vec3(0.0f),
                                    AovPixel* aov = nullptr, SampleTable* table = nullptr) {
  const PixelKey pixel{samplePixelKey(scene.settings.seed, samplePixelIndex(scene.camera, x, y))};
  const uint32_t sampleEnd = sampleBegin + sampleCount;
  constexpr uint32_t kWidth = Tracer::kPacketWidth;
  if constexpr (kWidth > 1) {
    for (uint32_t s = sampleBegin, n = 0; s < sampleEnd; s += n) {
      // Packets start at multiples of kWidth, so a pixel rendered in sample ranges that split
      // there groups its rays as one call would.
      const uint32_t toBoundary = kWidth - s % kWidth;
      n = sampleEnd - s < toBoundary ? sampleEnd - s : toBoundary;
      renderPacket<kAovs>(scene, tracer, x, y, pixel, s, n, counters, &sum, aov, table);
    }
  } else {
    uint32_t tableStart = sampleBegin;  // the first sample of the table's lanes
    SampleTable* lanesTable = nullptr;  // the table, where it serves these lanes
    for (uint32_t s = sampleBegin; s < sampleEnd; ++s) {
      // One after another too, a pixel's samples take their numbers from a table kLanes at a
      // time.
      if (table && (s == sampleBegin || s - tableStart == SampleTable::kLanes)) {
        tableStart = s;
        const uint32_t left = sampleEnd - s;
        lanesTable =
            table->serve(pixel.value, s, left < SampleTable::kLanes ? left : SampleTable::kLanes,
                         scene.settings.spp);
      }
      SampleStream rng(pixel, s, scene.settings.spp, lanesTable, s - tableStart);
      float jx, jy;
      Vec3 eye;
      const Ray ray = cameraSample(scene, x, y, rng, &jx, &jy, &eye);
      ++counters.camera;
      FirstHit first;
      const Vec3 L = traceRadiance<kAovs>(scene, tracer, ray, rng, counters, &first);
      addSample<kAovs>(scene, L, ray, jx, jy, eye, first, &sum, aov);
    }
  }
  return sum;
}

}  // namespace candela
