// The cone of a spot light: a point light that sends its intensity only within `cutoff` of its
// axis, all of it within `beam`, and between the two a share falling linearly with the angle
// (Mitsuba 3's `spot` emitter, so that the two renderers agree).
#pragma once

#include <cmath>

#include "core/device.h"
#include "core/frame.h"
#include "core/sampling.h"
#include "core/vec3.h"

namespace candela {

struct SpotCone {
  Vec3 axis;                // unit: where the spot points
  float cosCutoff = -2.0f;  // below -1: no cone, a point light's every direction
  float cosBeam = -2.0f;
  float cutoff = 0.0f;         // radians
  float invTransition = 0.0f;  // 1 / (cutoff - beam) in radians, 0 where they are equal
};

CANDELA_HDI bool hasCone(const SpotCone& c) { return c.cosCutoff >= -1.0f; }

// The share of the light's intensity sent in the unit direction w from the light.
CANDELA_HDI float coneFalloff(const SpotCone& c, const Vec3& w) {
  const float cosTheta = dot(w, c.axis);
  if (!(cosTheta > c.cosCutoff)) return 0.0f;
  if (cosTheta >= c.cosBeam) return 1.0f;
  return fminf(1.0f, (c.cutoff - acosf(fminf(cosTheta, 1.0f))) * c.invTransition);
}

// 1 - cos(cutoff): the solid angle the cone holds, over 2 pi.
CANDELA_HDI float coneOneMinusCos(const SpotCone& c) { return 1.0f - c.cosCutoff; }

// A direction drawn uniformly within the cone from (u1, u2); its density is
// uniformConePdf(coneOneMinusCos(c)).
CANDELA_HDI Vec3 sampleConeDirection(const SpotCone& c, float u1, float u2) {
  return normalize(Frame(c.axis).toWorld(sampleUniformCone(u1, u2, coneOneMinusCos(c))));
}

}  // namespace candela
