// Where a glTF file's scene places its nodes: each node's transform (its matrix, or translation,
// rotation and scale) times its parents', visited from the nodes of the file's default scene (its
// first where it names none; in a file without scenes, every node that is no other's child).
// Throws SceneError "<label>: <reason>" for a node that does not exist, is reached twice (a node
// has one parent) or has a transform that is not finite.
#pragma once

#include <array>
#include <functional>
#include <string>

#include "scene/read/tiny_gltf_config.h"

namespace candela {

using GltfMatrix = std::array<double, 16>;  // column-major, as glTF writes it

void forEachPlacedNode(const tinygltf::Model& model, const std::string& label,
                       const std::function<void(int index, const tinygltf::Node& node,
                                                const GltfMatrix& world)>& visit);

}  // namespace candela
