// The "camera" section of a scene file -> CameraDesc, validated but not resolved.
//
// Values are kept as written (fov or K, Euler rotation or look_at/up or OpenCV extrinsics) so that
// animation can change them per frame; scene/camera_resolve.h turns them into a Camera. Checked
// here: types and ranges, keys that exclude each other (fov/intrinsics, rotation/look_at,
// extrinsics/position/rotation/look_at, spp/rays), a look_at that differs from the position and
// an up that is not parallel to the view, a proper rotation in the extrinsics, and a
// focus_distance wherever an open aperture has no look_at to focus on.
#pragma once

#include <string>

#include "scene/read/json_reader.h"
#include "scene/scene_desc.h"

namespace candela {

// The most pixels an image may have (16384 x 16384): its float sums alone take 3 GiB.
constexpr uint64_t kMaxPixels = uint64_t(1) << 28;

// A field of view in degrees for a camera of `projection`: above 0 and below 180 for a
// perspective camera (whose angle reaches 90 degrees each way at infinity), up to 360 for an
// equidistant fisheye.
float readFov(const JsonValue& value, CameraProjection projection);

// The camera's spp (the scene's samples per pixel) goes to `render`; a glTF file it names
// ("gltf") is resolved against `baseDir`, the scene file's folder.
CameraDesc readCamera(const JsonValue& value, RenderSettings& render, const std::string& baseDir);

// A camera taken from a glTF file with "gltf_animation": its pose at each frame k of the scene's
// animation is that of its node at time k / fps seconds of the file's animation, given as camera
// tracks of position and rotation (one key a frame) in place of its fixed pose. Throws SceneError
// "<file>: camera.gltf_animation: ..." for a scene without an animation block, an animation the
// file does not have or cannot play, or a pose that makes no camera at some frame.
void followGltfAnimation(SceneDesc& scene);

}  // namespace candela
