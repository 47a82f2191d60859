// The alias table of light selection; see light_selection.h.
#include "scene/light_selection.h"

#include <cstdint>

namespace candela {

void setLightSelection(std::vector<Light>& lights, const std::vector<double>& powers) {
  const size_t n = lights.size();
  if (powers.empty()) {
    for (Light& l : lights) {
      l.selectPmf = 1.0f;
      l.aliasThreshold = 1.0f;
      l.alias = 0;
    }
    return;
  }
  double total = 0.0;
  for (double p : powers) total += p;
  // Vose's construction: slots whose scaled probability is below 1 are topped up by one alias
  // each, taken from slots above 1.
  std::vector<double> scaled(n);
  std::vector<uint32_t> small, large;
  for (size_t i = 0; i < n; ++i) {
    lights[i].selectPmf = total > 0.0 ? float(powers[i] / total) : 0.0f;
    lights[i].alias = uint32_t(i);
    scaled[i] = total > 0.0 ? powers[i] / total * double(n) : 0.0;
    (scaled[i] < 1.0 ? small : large).push_back(uint32_t(i));
  }
  while (!small.empty() && !large.empty()) {
    const uint32_t s = small.back(), l = large.back();
    small.pop_back();
    lights[s].aliasThreshold = float(scaled[s]);
    lights[s].alias = l;
    scaled[l] -= 1.0 - scaled[s];
    if (scaled[l] < 1.0) {
      large.pop_back();
      small.push_back(l);
    }
  }
  // What is left holds probability 1 up to rounding, except a light without power, which hands
  // its slot to the strongest light (without any power at all, selectLight finds no light).
  size_t strongest = 0;
  for (size_t i = 1; i < n; ++i)
    if (powers[i] > powers[strongest]) strongest = i;
  for (uint32_t i : large) lights[i].aliasThreshold = 1.0f;
  for (uint32_t i : small) {
    lights[i].aliasThreshold = powers[i] > 0.0 ? 1.0f : 0.0f;
    if (!(powers[i] > 0.0)) lights[i].alias = uint32_t(strongest);
  }
}

}  // namespace candela
