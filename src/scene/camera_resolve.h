// Turns the camera as written (fov or K; rotation, look_at or OpenCV extrinsics; thin lens)
// into the renderer's Camera: K^-1 for pixel -> camera-space ray, and an OpenCV-axes
// camera-to-world rotation (+x right, +y down, +z forward).
#pragma once

#include "scene/scene_desc.h"
#include "render/camera.h"

namespace candela {

// The description must be validated; throws SceneError only for a singular K.
Camera resolveCamera(const CameraDesc& desc, const std::string& fileLabel);

// Pixel coordinates (u right, v down, pixel centres at +0.5) of a world point seen by the
// camera, for tests and tools. Returns false when the point is behind the camera.
bool projectToPixel(const Camera& camera, const Mat3& K, const Vec3& world, float* u, float* v);

// The intrinsic matrix K of a camera description (from fov or as given).
Mat3 intrinsicMatrix(const CameraDesc& desc);

}  // namespace candela
