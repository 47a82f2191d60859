// What one render changes of the scene's view for itself alone: the light-path pilot's coarse,
// reseeded images and the choice it makes (backends/light_path_pilot.h), with the scene given to
// the renderer left as it is.
#pragma once

#include <cstdint>

#include "render/scene_view.h"

namespace candela {

struct ViewAdjustment {
  // The render's pixels are every stride-th pixel of the camera's image in x and y, from the
  // middle of each stride x stride block (Camera::pixelStride).
  uint32_t pixelStride = 1;
  bool lightPaths = true;  // false: no light subpaths, whatever the scene allows
  bool reseed = false;     // true: render with `seed` instead of the scene's
  uint64_t seed = 0;
};

inline SceneView adjustedView(SceneView view, const ViewAdjustment& adjust) {
  if (adjust.pixelStride > 1) {
    const uint32_t s = adjust.pixelStride;
    view.camera.width /= s;
    view.camera.height /= s;
    view.camera.pixelStride = s;
  }
  if (!adjust.lightPaths) view.lightPathLights = 0;
  if (adjust.reseed) view.settings.seed = adjust.seed;
  return view;
}

}  // namespace candela
