// Render passes (AOVs): what a camera sample records at its first hit, besides radiance, and how
// a pixel sums those records (docs/aovs.md).
//
// The integrator fills a FirstHit only when asked (traceRadiance<true>); a render without passes
// never touches one. A pixel keeps sums for the filtered passes (means over the samples that hit
// a surface, or over all samples for albedo) and, for the id passes, the record of the sample
// whose jitter lies nearest the pixel centre. The host turns them into images
// (render/aov_layers.h), so the kernel stores nothing it could derive there (depth, camera-space
// normals and ids all come from these fields).
#pragma once

#include <cstdint>

#include "core/vec2.h"
#include "core/vec3.h"
#include "render/bsdf_conductor.h"
#include "render/material.h"

namespace candela {

// One camera sample's first hit. `albedo` is that of the first surface with a non-delta lobe
// along the sampled path (mirrors and smooth glass are followed), or of an emitter's radiance
// clamped to [0, 1]; `albedoDone` says it was found. `direct` is the part of the sample's
// radiance that the path gathered by at most one scattering: what it would carry at max_depth 1
// (emitters and the environment seen at its first two hits, next-event estimation at its first);
// `emission` the radiance of an emitting surface that is its first hit. `seesNothing`: the camera
// ray left the scene where the camera sees no backdrop (no environment, or one hidden from it),
// so the sample is transparent in the alpha pass.
struct FirstHit {
  Vec3 position{0.0f};  // world space
  Vec3 normal{0.0f};    // world-space shading normal, turned to face the incoming ray
  Vec3 albedo{0.0f};
  Vec3 direct{0.0f};
  Vec3 emission{0.0f};
  Vec2 uv;                // texture coordinates (geometry/surface_uv.h), when `hit`
  Vec3 objectCoordinates{0.0f};  // render/object_coordinates.h, when `hit`
  uint32_t material = 0;  // flattened material index, valid when `hit`
  uint32_t prim = 0;      // the primitive hit and where on it (geometry/ray.h), when `hit`
  float b1 = 0, b2 = 0;
  bool hit = false;
  bool albedoDone = false;
  bool seesNothing = false;
};

// What a pass uses as the colour of a material whose colour (texture included) is `color` and
// transmittance `transmittance` (0 but where it is translucent): the BSDF's colour, with a named
// metal's reflectance at normal incidence; for a translucent sheet all it scatters, both sides.
CANDELA_HDI Vec3 aovAlbedo(const Material& m, const Vec3& color, const Vec3& transmittance) {
  if (m.type == MaterialType::Conductor) return conductorFresnel(m, color, 1.0f);
  return m.type == MaterialType::Translucent ? min(Vec3(1.0f), color + transmittance) : color;
}

CANDELA_HDI Vec3 clampUnit(const Vec3& v) { return min(Vec3(1.0f), max(Vec3(0.0f), v)); }

// A pixel's passes, summed over its samples in index order like its radiance.
struct AovPixel {
  Vec3 positionSum{0.0f};  // over samples that hit
  Vec3 normalSum{0.0f};    // over samples that hit
  Vec3 albedoSum{0.0f};    // over all samples (the background adds the environment's share)
  Vec3 directSum{0.0f};    // over all samples, as the radiance (a non-finite sample adds 0)
  Vec3 emissionSum{0.0f};  // likewise
  float distanceSum = 0.0f;  // |position - camera centre|, over samples that hit
  Vec2 uvSum;                // over samples that hit
  Vec3 objectCoordinatesSum{0.0f};  // over samples that hit
  Vec2 flowSum;              // over samples whose flow is defined (render/flow.h)
  uint32_t flowSamples = 0;
  Vec2 backwardFlowSum;  // likewise, towards the previous frame
  uint32_t backwardFlowSamples = 0;
  uint32_t hits = 0;
  uint32_t covered = 0;  // samples that saw something, the alpha pass's (not seesNothing)
  uint32_t samples = 0;
  // The id passes' sample: the one nearest the pixel centre, the earliest of equals.
  float nearestDistance2 = 3.0f;  // above any squared jitter offset, so sample 0 always wins
  int32_t nearestMaterial = -1;   // -1: that sample saw the background
};

// The mean over all of a pixel's samples of a pass summed over them all (`sum`: its albedoSum,
// directSum or emissionSum); 0 for a pixel without samples.
inline Vec3 meanOverSamples(const AovPixel& pixel, const Vec3& sum) {
  return pixel.samples > 0 ? sum / float(pixel.samples) : Vec3(0.0f);
}

// AovPixel's fields, as X(member, name, scalar type, channels, merge): the one list that the
// Python module's conversions expand (`name` is the array's name there) and that says how the
// sums of two sample ranges of a pixel merge: Added, or Nearest, the id passes' sample, taken
// from the later range only where its nearestDistance2 is strictly smaller (as addAovSample
// keeps the earliest of equals).
#define CANDELA_AOV_PIXEL_FIELDS(X)                                   \
  X(positionSum, "position_sum", float, 3, Added)                     \
  X(normalSum, "normal_sum", float, 3, Added)                         \
  X(albedoSum, "albedo_sum", float, 3, Added)                         \
  X(directSum, "direct_sum", float, 3, Added)                         \
  X(emissionSum, "emission_sum", float, 3, Added)                     \
  X(distanceSum, "distance_sum", float, 1, Added)                     \
  X(uvSum, "uv_sum", float, 2, Added)                                 \
  X(objectCoordinatesSum, "object_coordinates_sum", float, 3, Added)  \
  X(flowSum, "flow_sum", float, 2, Added)                             \
  X(flowSamples, "flow_samples", uint32_t, 1, Added)                  \
  X(backwardFlowSum, "backward_flow_sum", float, 2, Added)            \
  X(backwardFlowSamples, "backward_flow_samples", uint32_t, 1, Added) \
  X(hits, "hits", uint32_t, 1, Added)                                 \
  X(covered, "covered", uint32_t, 1, Added)                           \
  X(samples, "samples", uint32_t, 1, Added)                           \
  X(nearestDistance2, "nearest_distance2", float, 1, Nearest)         \
  X(nearestMaterial, "nearest_material", int32_t, 1, Nearest)

#define CANDELA_AOV_FIELD_BYTES(member, name, Scalar, channels, merge) \
  +sizeof(Scalar) * (channels)
static_assert(sizeof(AovPixel) == 0 CANDELA_AOV_PIXEL_FIELDS(CANDELA_AOV_FIELD_BYTES),
              "CANDELA_AOV_PIXEL_FIELDS lists every field of AovPixel, without padding");
#undef CANDELA_AOV_FIELD_BYTES

// A sample's optical flow towards the next frame and the previous, each where it is defined.
struct SampleFlows {
  Vec2 forward, backward;
  bool hasForward = false, hasBackward = false;
};

// Adds sample `first` taken at jitter (jx, jy) in the pixel, by a camera centred at `eye`, and
// its optical flows; its direct light and emission only where its radiance was finite (and so
// counted).
CANDELA_HDI void addAovSample(AovPixel* pixel, const FirstHit& first, float jx, float jy,
                              const Vec3& eye, const SampleFlows& flows, bool finite) {
  ++pixel->samples;
  if (finite) {
    pixel->directSum += first.direct;
    pixel->emissionSum += first.emission;
  }
  if (flows.hasForward) {
    pixel->flowSum = pixel->flowSum + flows.forward;
    ++pixel->flowSamples;
  }
  if (flows.hasBackward) {
    pixel->backwardFlowSum = pixel->backwardFlowSum + flows.backward;
    ++pixel->backwardFlowSamples;
  }
  pixel->albedoSum += first.albedo;
  if (!first.seesNothing) ++pixel->covered;
  if (first.hit) {
    pixel->positionSum += first.position;
    pixel->normalSum += first.normal;
    pixel->distanceSum += length(first.position - eye);
    pixel->uvSum = pixel->uvSum + first.uv;
    pixel->objectCoordinatesSum += first.objectCoordinates;
    ++pixel->hits;
  }
  const float dx = jx - 0.5f, dy = jy - 0.5f, d2 = dx * dx + dy * dy;
  if (d2 < pixel->nearestDistance2) {
    pixel->nearestDistance2 = d2;
    pixel->nearestMaterial = first.hit ? int32_t(first.material) : -1;
  }
}

}  // namespace candela
