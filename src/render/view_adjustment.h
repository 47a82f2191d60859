// What one render changes of the scene's view for itself alone: the pilot's coarse, reseeded
// images and the choices it makes (backends/render_pilot.h), and the windows in which
// the emitters seen are sampled again (backends/seen_emitters.h), with the scene given to the
// renderer left as it is.
#pragma once

#include <cstdint>

#include "render/light_selection.h"
#include "render/scene_view.h"

namespace candela {

// Pixels [x, x + width) x [y, y + height) of the camera's image.
struct PixelWindow {
  uint32_t x = 0, y = 0, width = 0, height = 0;
};

struct ViewAdjustment {
  // The render's pixels are every stride-th pixel of the camera's image in x and y, from the
  // middle of each stride x stride block (Camera::pixelStride).
  uint32_t pixelStride = 1;
  // Where width > 0 (and the stride is 1), the render's pixels are this window of its pixels, each
  // drawing the samples it has in the whole image's render.
  PixelWindow window;
  bool lightPaths = true;  // false: no light subpaths, whatever the scene allows
  // > 0: the light samples of a path's first interaction, instead of the scene's, where a light is
  // picked there (takesFirstHitLightSamples).
  uint32_t firstHitLightSamples = 0;
  // > 0: the deepest interaction connected to the light vertex, instead of the scene's.
  uint32_t lightPathDepth = 0;
  bool reseed = false;     // true: render with `seed` instead of the scene's
  uint64_t seed = 0;
  uint32_t spp = 0;  // > 0: the render's samples per pixel instead of the scene's
  // Only what the camera sees directly (max_depth 0): emitters and the environment, no
  // scattering and no light subpaths.
  bool seenOnly = false;
};

inline SceneView adjustedView(SceneView view, const ViewAdjustment& adjust) {
  if (adjust.pixelStride > 1) {
    const uint32_t s = adjust.pixelStride;
    view.camera.width /= s;
    view.camera.height /= s;
    view.camera.pixelStride = s;
  } else if (adjust.window.width > 0) {
    // The window is of the render's pixels, which may be a window (a crop) of the image already.
    if (view.camera.imageWidth == 0) view.camera.imageWidth = view.camera.width;
    view.camera.windowX += adjust.window.x;
    view.camera.windowY += adjust.window.y;
    view.camera.width = adjust.window.width;
    view.camera.height = adjust.window.height;
  }
  if (!adjust.lightPaths || adjust.seenOnly) view.lightPathLights = 0;
  if (adjust.firstHitLightSamples > 0 && takesFirstHitLightSamples(view))
    view.firstHitLightSamples = adjust.firstHitLightSamples;
  if (adjust.lightPathDepth > 0) view.lightPathDepth = adjust.lightPathDepth;
  if (adjust.seenOnly) view.settings.maxDepth = 0;
  if (adjust.reseed) view.settings.seed = adjust.seed;
  if (adjust.spp > 0) view.settings.spp = adjust.spp;
  return view;
}

}  // namespace candela
