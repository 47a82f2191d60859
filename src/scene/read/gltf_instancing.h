// EXT_mesh_gpu_instancing (Blender's "GPU Instances", gltfpack's -mi): a node whose mesh is drawn
// once per instance, each placed by the T R S of its TRANSLATION, ROTATION and SCALE accessors'
// elements under the node's own transform. candela copies the mesh once per instance.
#pragma once

#include <string>
#include <vector>

#include "scene/read/gltf_nodes.h"
#include "scene/read/tiny_gltf_config.h"

namespace candela {

// Every copy of a node beyond this many vertices is refused, so that a small file cannot ask for
// any amount of memory (a mesh of 10,000 vertices 26,000 times).
constexpr uint64_t kMostInstancedVertices = uint64_t(1) << 28;

// Where node `index` (placed at `world`) draws its mesh: `world` alone without the extension, else
// world * T R S of each instance. Throws SceneError "<label>: nodes[i].extensions.
// EXT_mesh_gpu_instancing...: <reason>" for accessors that do not exist, differ in count, hold
// numbers glTF does not allow there or that are not finite, or copies past
// kMostInstancedVertices.
std::vector<GltfMatrix> meshPlacements(const tinygltf::Model& model, int index,
                                       const tinygltf::Node& node, const GltfMatrix& world,
                                       const std::string& label);

}  // namespace candela
