// Turns the camera as written (fov or K; rotation, look_at or OpenCV extrinsics; thin lens)
// into the renderer's Camera: K^-1 for pixel -> camera-space ray, and an OpenCV-axes
// camera-to-world rotation (+x right, +y down, +z forward).
#pragma once

#include <optional>
#include <string>

#include "render/camera.h"
#include "scene/scene_desc.h"

namespace candela {

// What keeps a camera description from making a camera whose every ray is finite: the JSON path
// to blame and what is wrong there.
struct CameraProblem {
  std::string path;  // e.g. "camera.intrinsics"
  std::string message;
};

// Why `desc` makes no usable camera (K not invertible; a pose that is no rotation; pixels or lens
// points whose rays are not finite), or nullopt when it makes one.
std::optional<CameraProblem> cameraProblem(const CameraDesc& desc);

// The camera of `desc`; throws SceneError "file: path: message" for a cameraProblem.
Camera resolveCamera(const CameraDesc& desc, const std::string& fileLabel);

// The intrinsic matrix K of a camera description (from fov or as given).
Mat3 intrinsicMatrix(const CameraDesc& desc);

}  // namespace candela
