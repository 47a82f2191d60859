// The one-line report printed after a render, e.g.
//   out/default.png: 512x512, 64 spp, 12.34 s, 1.36 Msamples/s, 4.71 Mrays/s
//   (camera 16.8M, bounce 21.3M, shadow 30.1M)            <- same line
// and after a denoised one ", denoised in 1.23 s" (`denoiseSeconds` > 0).
#pragma once

#include <cstdint>
#include <string>

#include "render/render_result.h"

namespace candela::cli {

std::string renderSummary(const std::string& output, uint32_t spp, const RenderResult& result,
                          double denoiseSeconds = 0);

// A count with a k, M or G suffix and one decimal from a thousand on: 950, 16.8M.
std::string shortCount(uint64_t count);

}  // namespace candela::cli
