// Formatting of the render summary line.
#include "apps/cli/summary.h"

#include <cstdio>

namespace candela::cli {

std::string shortCount(uint64_t count) {
  char text[32];
  const double c = double(count);
  if (count < 1000)
    std::snprintf(text, sizeof text, "%llu", (unsigned long long)count);
  else if (c < 1e6)
    std::snprintf(text, sizeof text, "%.1fk", c / 1e3);
  else if (c < 1e9)
    std::snprintf(text, sizeof text, "%.1fM", c / 1e6);
  else
    std::snprintf(text, sizeof text, "%.1fG", c / 1e9);
  return text;
}

std::string renderSummary(const std::string& output, uint32_t spp, const RenderResult& result,
                          double denoiseSeconds) {
  const ImageRGB& image = result.image;
  const double samples = double(image.width) * double(image.height) * double(spp);
  // A tiny render can finish within the clock's resolution; avoid dividing by zero.
  const double seconds = result.seconds > 0 ? result.seconds : 1e-9;
  char line[512];
  std::snprintf(line, sizeof line,
                "%s: %ux%u, %u spp, %.2f s, %.2f Msamples/s, %.2f Mrays/s "
                "(camera %s, bounce %s, shadow %s)",
                output.c_str(), image.width, image.height, spp, result.seconds,
                samples / seconds / 1e6, double(result.rays.total()) / seconds / 1e6,
                shortCount(result.rays.camera).c_str(), shortCount(result.rays.bounce).c_str(),
                shortCount(result.rays.shadow).c_str());
  std::string summary = line;
  if (denoiseSeconds > 0) {
    std::snprintf(line, sizeof line, ", denoised in %.2f s", denoiseSeconds);
    summary += line;
  }
  return summary;
}

}  // namespace candela::cli
