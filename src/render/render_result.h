// What a backend returns: the mean-radiance image, ray counts and wall time.
#pragma once

#include "image/image.h"
#include "render/ray_counters.h"

namespace candela {

struct RenderResult {
  ImageRGB image;  // mean radiance per pixel
  RayCounters rays;
  double seconds = 0;
  bool cancelled = false;  // stopped early on request; the image is then incomplete
};

}  // namespace candela
