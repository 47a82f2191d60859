// Turns the camera as written (fov or K; rotation, look_at or OpenCV extrinsics; thin lens)
// into the renderer's Camera: K^-1 for pixel -> camera-space ray, and an OpenCV-axes
// camera-to-world rotation (+x right, +y down, +z forward).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "render/camera.h"
#include "render/camera_motion.h"
#include "render/pixel_filter.h"
#include "scene/scene_desc.h"

namespace candela {

// What keeps a camera description from making a camera whose every ray is finite: the JSON path
// to blame and what is wrong there.
struct CameraProblem {
  std::string path;  // e.g. "camera.intrinsics"
  std::string message;
};

// How far beyond the image's edge, in pixels, the samples of its edge pixels land with `filter`.
float samplesBeyondEdge(const PixelFilter& filter);

// Why `desc` makes no usable camera (K not invertible; a pose that is no rotation; image points,
// the image widened by `beyondEdge` pixels each way, or lens points whose rays are not finite),
// or nullopt when it makes one.
std::optional<CameraProblem> cameraProblem(const CameraDesc& desc, float beyondEdge);

// The camera of `desc`; throws SceneError "file: path: message" for a cameraProblem (the image
// not widened: a loaded scene's camera was checked with its filter's reach).
Camera resolveCamera(const CameraDesc& desc, const std::string& fileLabel);

// The camera's poses across a motion-blurred frame's exposure (render/camera_motion.h), from its
// shutterCameras; empty where it has none or the camera holds still through them. Throws
// SceneError as resolveCamera does.
std::vector<CameraPose> shutterPoses(const SceneDesc& desc);

// The intrinsic matrix K of a camera description (from fov or as given).
Mat3 intrinsicMatrix(const CameraDesc& desc);

// A camera as a vision dataset records it (docs/aovs.md, *The camera file*): K with candela's
// pixel centres at +0.5, and the world-to-camera pose [R | t] in OpenCV's axes, as the contract's
// `intrinsics` and `extrinsics` take them, so that a camera given so renders the same image.
struct CameraMatrices {
  uint32_t width = 0, height = 0;
  Mat3 intrinsics;
  Mat3 rotation;             // R
  Vec3 translation;          // t: a world point p is at R p + t in camera space
  float apertureRadius = 0;  // a thin lens where above 0, focused at focusDistance along +z
  float focusDistance = 0;
  // OpenCV's distortion coefficients, as many as say the lens (5, or 8 for the rational model; a
  // fisheye's 4); none without one.
  std::vector<float> distortion;
  // Equirectangular: no K (`intrinsics` is the fov's, unused).
  CameraProjection projection = CameraProjection::Perspective;
};

// A lens's coefficients as OpenCV lists them for `projection` (distCoeffs' k1, k2, p1, p2, k3,
// k4, k5, k6, the last three only where one is not 0; cv::fisheye's k1 to k4), none where the lens
// has none; and the lens a list of them makes (as many as the list holds, the rest 0).
std::vector<float> distortionCoefficients(const LensDistortion& d, CameraProjection projection);
LensDistortion lensDistortion(const std::vector<float>& coefficients, CameraProjection projection);

// "perspective", "equirectangular", "fisheye" or "orthographic", as a scene's camera names it.
const char* projectionName(CameraProjection projection);

// The matrices of the camera `desc` makes; throws SceneError as resolveCamera does.
CameraMatrices cameraMatrices(const CameraDesc& desc, const std::string& fileLabel);

// [m p; 0 0 0 1] by rows: the 4 x 4 form the files write (the extrinsics [R t; 0 1], poses).
using AffineRows = std::array<std::array<float, 4>, 4>;
AffineRows affineRows(const Mat3& m, const Vec3& p);

}  // namespace candela
