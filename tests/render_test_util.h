// Helpers for image tests: render a JSON scene given as text, and noise-aware statistics.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "backends/cpu/cpu_renderer.h"
#include "scene/flatten.h"
#include "scene/read/scene_loader.h"

namespace candela::test {

inline SceneData loadTestScene(const std::string& json, const std::string& baseDir = ".") {
  return flattenScene(parseSceneText(json, "test.json", baseDir));
}

inline RenderResult renderTestScene(const std::string& json, int threads = 0,
                                    const std::string& baseDir = ".") {
  const SceneData data = loadTestScene(json, baseDir);
  RenderOptions options;
  options.threads = threads;
  return renderCpu(data.view(), options);
}

// Mean and standard deviation of one channel over a pixel rectangle [x0,x1) x [y0,y1).
struct RegionStats {
  double mean = 0, stddev = 0;
  size_t count = 0;
  // Standard error of the mean, for pixels that are independent estimates of one value.
  double standardError() const { return stddev / std::sqrt(double(count)); }
};

inline RegionStats regionStats(const ImageRGB& img, uint32_t x0, uint32_t y0, uint32_t x1,
                               uint32_t y1, int channel) {
  RegionStats s;
  double sum = 0, sum2 = 0;
  for (uint32_t y = y0; y < y1; ++y)
    for (uint32_t x = x0; x < x1; ++x) {
      const double v = img.at(x, y)[channel];
      sum += v;
      sum2 += v * v;
      ++s.count;
    }
  s.mean = sum / double(s.count);
  s.stddev = std::sqrt(std::max(0.0, sum2 / double(s.count) - s.mean * s.mean));
  return s;
}

}  // namespace candela::test
