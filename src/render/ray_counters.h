// Counts of rays traced, by kind. Summed per tile, then over the image.
#pragma once

#include <cstdint>

#include "core/device.h"

namespace candela {

struct RayCounters {
  uint64_t camera = 0;  // primary rays from the camera
  uint64_t bounce = 0;  // rays scattered at surfaces, and those leaving point lights
  uint64_t shadow = 0;  // visibility rays towards lights and light vertices (render/light_path.h)

  CANDELA_HDI uint64_t total() const { return camera + bounce + shadow; }
  CANDELA_HDI RayCounters& operator+=(const RayCounters& o) {
    camera += o.camera;
    bounce += o.bounce;
    shadow += o.shadow;
    return *this;
  }
};

}  // namespace candela
