// Where each instance of the scene is, for vision datasets (docs/aovs.md, *Instance poses*): the
// placement taking its model into world space, numbered as the instance pass numbers it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/mat3.h"
#include "core/vec3.h"
#include "geometry/aabb.h"
#include "scene/camera_resolve.h"
#include "scene/scene_desc.h"

namespace candela {

// p_world = linear p_model + position. An object's model is its mesh as its OBJ file has it
// (linear = R diag(scale)); a sphere's and a sphere light's, the unit sphere at the origin
// (linear = radius I); a rectangle light's, the unit square [-1/2, 1/2]^2 of the xy plane, which
// shines along +z; a point light's, the origin (linear = I).
struct InstancePose {
  uint32_t number = 0;
  std::string name;  // as instanceNames gives it
  Mat3 linear;
  Vec3 position;
  // The box the model spans in its own frame (scene/model_box.h), over which the
  // object_coordinates pass runs from 0 to 1; none for a point, spot or directional light.
  std::optional<Bounds3> modelBox;
};

// A light's model's linear part: a sphere light's and a rectangle light's as above; for a spot or
// directional light, a rotation whose third column (the model's +z) is where it shines, the first
// two completing a right-handed frame (core/frame.h); a point light's, the identity.
Mat3 lightModel(const LightDesc& light);

// Every instance's pose, in the order of its number.
std::vector<InstancePose> instancePoses(const SceneDesc& desc);

// The same pose in the camera's frame: from the model to OpenCV's camera axes, [R t] times it.
InstancePose poseInCamera(const InstancePose& pose, const CameraMatrices& camera);

}  // namespace candela
