// The kernel's camera: a pinhole or thin lens given by K^-1, its lens distortion and its pose.
//
// Camera space follows OpenCV: +x right, +y down, +z forward.
#pragma once

#include <cstdint>

#include "core/device.h"
#include "core/mat3.h"
#include "core/vec3.h"
#include "render/lens_distortion.h"

namespace candela {

// How the image's pixels map to directions: through K (and a lens distortion), through K and a
// fisheye lens (render/fisheye.h), as an equirectangular panorama of every direction about the
// camera (render/panorama.h), or orthographically: K maps a pixel to a point of the camera's
// plane, from which its ray runs along +z.
enum class CameraProjection : uint32_t {
  Perspective = 0,
  Equirectangular = 1,
  Fisheye = 2,
  Orthographic = 3
};

struct Camera {
  uint32_t width = 512, height = 512;  // of the render: the image, or a window of it (below)
  // The whole image's, over which an equirectangular camera's angles span, whatever part of it a
  // render takes (a window, or the pilot's sparse pixels).
  uint32_t panoramaWidth = 512, panoramaHeight = 512;
  CameraProjection projection = CameraProjection::Perspective;
  // Pixel (u, v, 1) -> camera-space direction with z = 1 (distorted); orthographic: -> the point
  // (x, y) of the camera's plane z = 0 (with a 1 for z).
  Mat3 inverseK;
  LensDistortion distortion;  // a fisheye's coefficients are its k1 to k4
  Mat3 cameraToWorld;  // OpenCV camera axes -> world
  Vec3 position;       // camera centre in world space
  float apertureRadius = 0;
  float focusDistance = 1;  // along camera +z
  // Where the camera moves while the shutter is open (SceneView::cameraPoses): the time of the
  // exposure at which a sample at image row py (in pixels) and shutter number u in [0, 1) is
  // taken is py * shutterRowSlope + u * shutterRowShare. A global shutter has slope 0 and share 1;
  // a rolling one reads its rows from the top, each open for a share of the exposure.
  float shutterRowSlope = 0, shutterRowShare = 1;
  // Pixel (x, y) of the render is pixel (stride x + stride / 2, stride y + stride / 2) of this
  // camera's image: a sparse sample of its pixels (the light-path pilot's,
  // backends/render_pilot.h); 1 for every render of the image itself.
  uint32_t pixelStride = 1;
  // Or pixel (windowX + x, windowY + y): a window of the image (a crop, CameraDesc::crop, or
  // backends/seen_emitters.h's) whose pixels take the samples they have in the whole image,
  // `imageWidth` wide (0: the render is the whole image).
  uint32_t windowX = 0, windowY = 0, imageWidth = 0;
};

// The index of the render's pixel (x, y) among those of the image it belongs to, which keys its
// samples: a window's pixels draw what the whole image's render draws there.
CANDELA_HDI uint64_t samplePixelIndex(const Camera& camera, uint32_t x, uint32_t y) {
  const uint32_t width = camera.imageWidth > 0 ? camera.imageWidth : camera.width;
  return uint64_t(camera.windowY + y) * width + camera.windowX + x;
}

}  // namespace candela
