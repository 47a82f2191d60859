// A camera that moves while the shutter is open (docs/scene-format.md, *Motion blur*): its pose at
// a few times across the exposure, and the pose of any time between, position linearly and
// orientation along the shortest arc, each sample of a pixel at a time of its own.
#pragma once

#include <cstdint>

#include "core/quaternion.h"
#include "render/camera.h"

namespace candela {

// The camera's pose at `time`, from 0 (the shutter opens) to 1 (it closes).
struct CameraPose {
  Quaternion rotation;  // of the camera-to-world matrix (OpenCV camera axes)
  Vec3 position;
  float time = 0;
};

// `camera` at shutter time `u` between `poses` (count >= 2, times increasing from 0 to 1): the
// pose of the segment that holds u, interpolated. A time outside [0, 1] (a wide pixel filter's
// sample beyond the image's first or last row, under a rolling shutter) is the nearer end's.
CANDELA_HDI Camera cameraAtShutterTime(const Camera& camera, const CameraPose* poses,
                                       uint32_t count, float u) {
  u = u < 0.0f ? 0.0f : (u > 1.0f ? 1.0f : u);
  uint32_t i = 0;
  while (i + 2 < count && u >= poses[i + 1].time) ++i;
  const CameraPose& a = poses[i];
  const CameraPose& b = poses[i + 1];
  const float span = b.time - a.time;
  const float t = span > 0.0f ? (u - a.time) / span : 0.0f;
  Camera posed = camera;
  posed.position = a.position + (b.position - a.position) * t;
  posed.cameraToWorld = rotationMatrix(slerp(a.rotation, b.rotation, t));
  return posed;
}

}  // namespace candela
