// What the optical flow pass (docs/aovs.md) knows of the next frame: how each instance moves and
// how both frames' cameras project.
#pragma once

#include "core/mat3.h"
#include "core/vec3.h"
#include "render/camera.h"
#include "render/lens_distortion.h"

namespace candela {

// An instance's motion to the next frame: a world point p of it moves to linear * p + offset, or,
// for a mesh whose vertices move apart (`perVertex`), to where its triangle's vertices go
// (SceneView::flowVertices).
struct InstanceMotion {
  Mat3 linear = Mat3::diagonal(Vec3(1.0f));
  Vec3 offset{0.0f};
  bool perVertex = false;
};

// A camera's projection: world point p -> pixel of K * the distorted (x / z, y / z, 1) of
// worldToCamera * (p - position) (OpenCV camera axes; pixel (0, 0) is the image's top-left corner).
struct FlowCamera {
  CameraProjection projection = CameraProjection::Perspective;  // a panorama has no K
  uint32_t width = 0, height = 0;                               // a panorama's
  Mat3 K;
  LensDistortion distortion;
  Mat3 worldToCamera;
  Vec3 position{0.0f};
};

// The two frames of the flow pass; `enabled` only in renders that write it.
struct FlowFrames {
  FlowCamera now, next;
  bool enabled = false;
};

}  // namespace candela
