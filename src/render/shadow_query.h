// A visibility query that the integrator leaves to its caller, so that a caller holding several
// paths can trace theirs together (render/render_pixel.h).
#pragma once

#include <cstdint>

#include "geometry/ray.h"
#include "render/packet_slots.h"

namespace candela {

// Shadow rays stop this fraction short of their target (pbrt's ShadowEpsilon): relative, so it
// holds at any scene scale.
constexpr float kShadowEpsilon = 1e-4f;

// A shadow ray, and the radiance it adds to the path when nothing but primitive skipPrim blocks
// it.
struct ShadowQuery {
  Ray ray;
  uint32_t skipPrim = 0xffffffffu;
  Vec3 contribution;  // the path's throughput times the light's weighted share
  bool active = false;
  bool direct = false;  // next-event estimation at the first hit, set only for the passes
  // The medium the ray starts in (PathState::medium), read where it may cross index-matched glass
  // (render/shadow_transmittance.h).
  int32_t medium = -1;
};

// The most shadow queries next-event estimation leaves at one interaction: one for each point
// light at a path's first interaction in scenes of a few point lights (render/light.h,
// firstHitDeltaLights), else one.
constexpr uint32_t kMaxLightQueries = 4;

// Next-event estimation's shadow queries at one interaction: query[0, count), each constructed by
// the interaction that leaves it (an interaction costs one query's construction, not
// kMaxLightQueries'), of which the active ones are traced (query[k] towards light k where each
// light is sampled).
struct LightQueries {
  PacketSlots<ShadowQuery, kMaxLightQueries> query;
  uint32_t count = 0;
};

}  // namespace candela
