// An object that plays a glTF file's animation ("gltf_animation"): what the animation moves below
// the object's node (the whole file without one) moves the object's mesh. Nodes that place its
// meshes, the joints of its skins and its morph weights are sampled at each time asked (as
// gltf_animation.h samples them), and the mesh is posed anew (gltf_rig.h).
#pragma once

#include <memory>
#include <string>

#include "scene/read/gltf_rig.h"
#include "scene/scene_desc.h"

namespace candela {

// The motion of `mesh`, as `rig` (with its primitives and the file's animations) poses it, under
// the animation that `object` names; null where it moves none of its vertices. Throws SceneError
// "<label>: <reason>" where the file has no such animation or cannot play it.
std::shared_ptr<const MeshMotion> gltfMeshMotion(const ObjectDesc& object, const std::string& label,
                                                 std::shared_ptr<const MeshDesc> mesh,
                                                 std::shared_ptr<const GltfRig> rig);

}  // namespace candela
