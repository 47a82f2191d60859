// What a backend returns: the mean-radiance image, the passes' sums, ray counts and wall time.
#pragma once

#include <vector>

#include "image/image.h"
#include "render/aov.h"
#include "render/ray_counters.h"

namespace candela {

struct RenderResult {
  ImageRGB image;  // mean radiance per pixel
  // Per pixel, rows from the top, when the render was asked for passes (RenderOptions::aovs);
  // render/aov_layers.h makes images of them.
  std::vector<AovPixel> aovs;
  RayCounters rays;
  double seconds = 0;
  bool cancelled = false;  // stopped early on request; the image is then incomplete
};

}  // namespace candela
