// Which sample indices a render covers. Samples are counter-based (render/render_pixel.h), so a
// render of samples [begin, begin + count) is one exact slice of the full render, and the
// count-weighted mean of disjoint slices equals the full render up to float rounding. This is
// what lets a cluster split one image across machines.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace candela {

struct SampleRange {
  uint32_t begin = 0;
  uint32_t count = 0;  // number of samples per pixel; 0 means "all of [begin, spp)"
};

// The range to render for a scene of `spp` samples per pixel. Throws std::invalid_argument for an
// empty range or one that reaches past spp (a slice that would not belong to this render).
inline SampleRange resolveSampleRange(SampleRange requested, uint32_t spp) {
  if (requested.begin >= spp)
    throw std::invalid_argument("sample range starts at " + std::to_string(requested.begin) +
                                " but the scene has only " + std::to_string(spp) + " spp");
  const uint32_t available = spp - requested.begin;
  if (requested.count == 0) return {requested.begin, available};
  if (requested.count > available)
    throw std::invalid_argument("sample range [" + std::to_string(requested.begin) + ", " +
                                std::to_string(uint64_t(requested.begin) + requested.count) +
                                ") reaches past spp " + std::to_string(spp));
  return requested;
}

}  // namespace candela
