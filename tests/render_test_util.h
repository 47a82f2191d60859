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

// A small room of sphere walls lit by a point light half a unit below its ceiling, whose bright
// patch there lights the rest (the case light-vertex connections are for), with a ball on its
// floor; `camera` and `render` are the JSON objects' inner fields.
inline std::string lampUnderTheCeiling(const std::string& camera, const std::string& render) {
  return R"({
    "camera": {"fov": 70, "position": [0, 2, 9], "look_at": [0, 2, 0], )" +
         camera + R"(},
    "render": {)" +
         render + R"(},
    "spheres": [{"position": [-1005, 0, 0], "radius": 1000, "color": [0.7, 0.3, 0.2]},
                {"position": [1005, 0, 0], "radius": 1000, "color": [0.3, 0.4, 0.7]},
                {"position": [0, 0, -1005], "radius": 1000, "color": 0.7},
                {"position": [0, 0, 1010], "radius": 1000, "color": 0.7},
                {"position": [0, -1000, 0], "radius": 1000, "color": 0.6},
                {"position": [0, 1006, 0], "radius": 1000, "color": 0.8},
                {"position": [1, 1, -1], "radius": 1, "color": 0.5}],
    "lights": [{"position": [-3, 5.5, -3], "intensity": 400}]})";
}

}  // namespace candela::test
