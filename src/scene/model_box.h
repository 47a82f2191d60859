// The box an instance's model spans in its own frame: the object_coordinates pass maps it to
// [0, 1]^3 and the poses file gives it, so that a pass value maps back to a point of the model
// (docs/aovs.md, *Instance poses*).
#pragma once

#include <optional>

#include "geometry/aabb.h"
#include "scene/scene_desc.h"

namespace candela {

// The box of a mesh's positions as its file has them; the origin's point for a mesh without any.
Bounds3 meshBox(const MeshDesc& mesh);

// An object's model: its mesh as its file binds it, however an animation poses it
// (ObjectDesc::restMesh); its box is the object's.
const MeshDesc& modelMesh(const ObjectDesc& obj);

// A sphere's and a sphere light's: the unit sphere's, [-1, 1]^3.
Bounds3 sphereModelBox();

// A light's: a sphere light's as above, a rectangle light's square [-1/2, 1/2]^2 (z 0); none for
// the lights that have no extent (point, spot and directional).
std::optional<Bounds3> lightModelBox(const LightDesc& light);

}  // namespace candela
