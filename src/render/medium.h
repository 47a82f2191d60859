// A homogeneous medium inside glass (render/material.h: absorption, scattering): how far a path
// goes through it before it scatters, by free-flight sampling of its extinction in one colour
// channel, and how the path's three channels share that choice.
#pragma once

#include <cmath>

#include "core/device.h"
#include "core/vec3.h"
#include "render/absorption.h"

namespace candela {

// The step a path takes through a medium towards the surface tMax ahead (infinite where it leaves
// the scene from inside): it scatters at distance t < tMax, or passes to the surface. `value` is
// what the step's transport is in each channel (sigmaS Tr(t) at a scattering, Tr(tMax) at the
// surface), and `density` each channel's density of making it had that channel's extinction
// drawn the distance (sigmaT Tr(t), or the chance Tr(tMax) of passing).
struct MediumStep {
  bool scattered = false;
  float t = 0.0f;
  Vec3 value = Vec3(1.0f), density = Vec3(1.0f);
};

// A free-flight sample through a medium of absorption and scattering coefficients sigmaA and
// sigmaS (per unit length and channel), the distance drawn by the extinction sigmaA + sigmaS of
// channel `hero`, from u in [0, 1). Its density in the hero's channel is never 0.
CANDELA_HDI MediumStep sampleMediumStep(const Vec3& sigmaA, const Vec3& sigmaS, int32_t hero,
                                        float tMax, float u) {
  const Vec3 sigmaT = sigmaA + sigmaS;
  const float heroT = sigmaT[hero];
  const float t = heroT > 0.0f ? -log1pf(-u) / heroT : kInfinity;
  MediumStep step;
  step.scattered = t < tMax;
  step.t = step.scattered ? t : tMax;
  const Vec3 kept = beerTransmittance(sigmaT, step.t);
  step.value = step.scattered ? sigmaS * kept : kept;
  step.density = step.scattered ? sigmaT * kept : kept;
  return step;
}

// The channel by which a path draws its distances through media (its hero), picked once per path
// at its first step through a scattering medium, and what its channels make of that: each
// channel's throughput is weighed against all three channels' densities of the path's steps
// through media so far, the balance heuristic over the three ways of drawing them (Wilkie et al.
// 2014's hero wavelengths; pbrt-v4's and Mitsuba 3's spectral MIS). A weight per step alone (each
// channel's value over its own density) would be exact on average too, but its product over many
// scatterings in a medium whose channels differ spreads without bound.
struct HeroChannel {
  int32_t channel = -1;  // -1: not picked yet
  // Picked as the one channel the path carries (after dispersive glass): then the steps are
  // weighed by the hero's density alone, as no other channel could have drawn them.
  bool alone = false;
  Vec3 ratios = Vec3(1.0f);  // each channel's density of the steps so far over the hero's

  // Picks the hero from u in [0, 1), or the path's own channel where it carries one (>= 0).
  CANDELA_HDI void pick(int32_t pathChannel, float u) {
    alone = pathChannel >= 0;
    channel = alone ? pathChannel : int32_t(minf(u * 3.0f, 2.0f));
  }

  CANDELA_HDI float combined(const Vec3& r) const {
    return alone ? r[channel] : (r.x + r.y + r.z) * (1.0f / 3.0f);
  }

  // What step `step`, drawn by the hero, multiplies the path's throughput by.
  CANDELA_HDI Vec3 take(const MediumStep& step) {
    const Vec3 r = ratios * step.density;
    const Vec3 factor = step.value * (combined(ratios) / combined(r));
    ratios = r / step.density[channel];
    return factor;
  }
};

// sigmaS / sigmaT in each channel, the share of what the medium stops that it scatters (0 in a
// channel that stops nothing).
CANDELA_HDI Vec3 singleScatteringAlbedo(const Vec3& sigmaA, const Vec3& sigmaS) {
  Vec3 albedo(0.0f);
  for (int c = 0; c < 3; ++c) {
    const float sigmaT = sigmaA[c] + sigmaS[c];
    albedo[c] = sigmaT > 0.0f ? sigmaS[c] / sigmaT : 0.0f;
  }
  return albedo;
}

}  // namespace candela
