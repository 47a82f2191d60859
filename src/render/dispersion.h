// Dispersion: glass whose index of refraction falls with wavelength (a prism's rainbow, a
// diamond's fire), in an RGB renderer. A glass given an Abbe number has an index for each colour
// channel (scene/cauchy_index.h). A path that meets such glass keeps one channel from then on,
// chosen uniformly and weighted by 3 (so each channel is right on average), and the glass bends
// it by that channel's index. Such glass holds no light vertex (render/light_path.h): a light
// subpath is traced before the camera path has chosen its channel.
#pragma once

#include <cstdint>

#include "core/device.h"
#include "render/material.h"

namespace candela {

// No channel chosen yet: the path carries all three.
constexpr int32_t kAllChannels = -1;

CANDELA_HDI bool isDispersive(const Material& m) { return m.channelIor.x > 0.0f; }

// The index by which material m bends a path that carries `channel`.
CANDELA_HDI float iorFor(const Material& m, int32_t channel) {
  return channel != kAllChannels && isDispersive(m) ? m.channelIor[channel] : m.ior;
}

}  // namespace candela
