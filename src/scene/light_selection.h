// How next-event estimation picks a light (render/light.h, Light::selectPmf): every light while
// there are few, else one in proportion to its power through Walker's alias table, so that a
// shading point's cost does not grow with the number of emitters.
#pragma once

#include <vector>

#include "render/light.h"

namespace candela {

// Sets every light's selectPmf, aliasThreshold and alias from `powers`: one per light, each >= 0
// (the sum of its RGB power), or empty when every light is sampled (render/light.h,
// sampleEveryLight), which makes each selectPmf 1. Lights without power are never picked.
void setLightSelection(std::vector<Light>& lights, const std::vector<double>& powers);

}  // namespace candela
