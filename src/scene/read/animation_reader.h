// The `animation` block of a scene file -> AnimationDesc.
//
// Runs after the camera, spheres, objects and lights are read, because a track is checked against
// what it animates: its target ("camera" or an id), a property that target has and that its
// style uses (no "fov" on a camera given by intrinsics, no "radius" on a point light), a value of
// the right shape and range for that property, and keys in increasing frame order. A camera
// aimed with look_at is also checked at every frame: it must never look at its own position or
// along its up direction.
#pragma once

#include "scene/read/json_reader.h"
#include "scene/scene_desc.h"

namespace candela {

AnimationDesc readAnimation(const JsonValue& value, const SceneDesc& scene);

}  // namespace candela
