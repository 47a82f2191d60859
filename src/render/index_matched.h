// Glass of index 1: a surface that bends and reflects nothing, only the boundary of the medium
// inside it (smoke or fog in a box). Paths and shadow rays cross it as Mitsuba 3's null interface,
// so that light is sampled through it (render/shadow_transmittance.h).
#pragma once

#include "core/device.h"
#include "render/bsdf.h"
#include "render/dispersion.h"
#include "render/material.h"
#include "render/normal_map.h"

namespace candela {

// Whether m is smooth glass of index 1 with nothing on it: at eta 1 Fresnel reflects nothing and
// a transmission keeps its direction, so crossing it only tints by its colour.
CANDELA_HDI bool isIndexMatched(const Material& m) {
  return m.type == MaterialType::Glass && m.ior == 1.0f && m.roughness == 0.0f &&
         m.roughnessTexture.index < 0 && !isDispersive(m) && !hasLayers(m) && !hasMaps(m) &&
         !hasEmission(m);
}

}  // namespace candela
