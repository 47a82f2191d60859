// Mix materials: a surface that is one material in some places and another elsewhere (rust on
// steel, a decal's print on its paper, a glTF metalness map), or a blend of two at each point.
//
// As pbrt-v4's MixMaterial, a path that meets a mix takes one of its two parts, the second with
// the chance its weight gives there, and then sees only that part: the BSDF, next-event
// estimation and the light vertices all work with the part, so nothing below names a mix. On
// average over the choices the surface reflects weight times the second part's BSDF plus (1 -
// weight) times the first's (Mitsuba 3's blendbsdf), at the cost of the noise of the choice where
// the weight lies strictly between 0 and 1. The choice draws one number from the path's sample,
// so a part that is itself a mix chooses by the same number, rescaled.
#pragma once

#include <cstdint>

#include "core/check.h"
#include "core/constants.h"
#include "core/sobol_sampler.h"
#include "geometry/surface.h"
#include "render/material.h"
#include "render/scene_view.h"
#include "render/surface_color.h"

namespace candela {

// The share of mix m's second part at the point: its weight, or its texture's value there (at
// most 1).
CANDELA_HDI float mixWeightAt(const SceneView& scene, const Material& m, const Hit& hit,
                              const SurfacePoint& sp) {
  return surfaceUnitValue(scene, m.mixWeight, m.mixWeightTexture, m.mixWeightChannel, hit, sp);
}

// The index of the material a path meets at the point of a surface of material `index`, given u
// in [0, 1): `index` itself unless it is a mix, else the part u chooses (the second where u <
// weight), and so on down while that part is a mix. Out of line: most scenes have no mix.
CANDELA_HD_NOINLINE inline uint32_t chooseMixPart(const SceneView& scene, uint32_t index,
                                                  const Hit& hit, const SurfacePoint& sp, float u) {
  while (scene.materials[index].type == MaterialType::Mix) {
    const Material& m = scene.materials[index];
    const float w = mixWeightAt(scene, m, hit, sp);
    // Parts follow their mix (scene/flatten.cpp), so this walk ends.
    CANDELA_DCHECK(m.mixParts[0] > index && m.mixParts[1] > index);
    if (u < w) {
      index = m.mixParts[1];
      u = u / w;
    } else {
      index = m.mixParts[0];
      u = (u - w) / (1.0f - w);
    }
    u = minf(u, kOneMinusEpsilon);
  }
  return index;
}

// The index of the material a path meets at a surface of material `index`, drawing the choice
// from `rng` only where the surface is a mix.
CANDELA_HDI uint32_t materialMet(const SceneView& scene, uint32_t index, const Hit& hit,
                                 const SurfacePoint& sp, SampleStream& rng) {
  if (scene.materials[index].type != MaterialType::Mix) return index;
  return chooseMixPart(scene, index, hit, sp, rng.next1D());
}

}  // namespace candela
