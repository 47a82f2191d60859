// Where a glTF file's scene places its nodes: each node's transform (its matrix, or translation,
// rotation and scale) times its parents', visited from the nodes of the file's default scene (its
// first where it names none; in a file without scenes, every node that is no other's child), or
// from one node by its name.
// Throws SceneError "<label>: <reason>" for a node that does not exist, is reached twice (a node
// has one parent) or has a transform that is not finite.
#pragma once

#include <array>
#include <functional>
#include <string>

#include "scene/read/tiny_gltf_config.h"
#include "scene/scene_error.h"

namespace candela {

using GltfMatrix = std::array<double, 16>;  // column-major, as glTF writes it

// A node's own transform in place of its matrix or T R S (an animation's, at some time): true
// where it gives one.
using GltfLocalOverride =
    std::function<bool(int index, const tinygltf::Node& node, GltfMatrix* local)>;

// With `root` (a node's index) the walk visits that node and what lies under it alone, the root
// at the identity (its own transform and its parents' left out), so that an object holds one
// node of a file in the node's own frame.
void forEachPlacedNode(const tinygltf::Model& model, const std::string& label,
                       const std::function<void(int index, const tinygltf::Node& node,
                                                const GltfMatrix& world)>& visit,
                       const GltfLocalOverride& moved = {}, int root = -1);

// A node an object asks for by name (its "gltf_node") that the file does not have, or has more than
// once: the scene reports it at the object's "gltf_node".
class GltfNodeError : public SceneError {
 public:
  using SceneError::SceneError;
};

// The index of the node named `name`; throws GltfNodeError naming the file's nodes (and the
// likely one meant) where none or several have that name.
int gltfNodeIndex(const tinygltf::Model& model, const std::string& name);

// A node's own transform: its matrix, or translation * rotation * scale. Throws SceneError
// "<where>.<key>: <reason>" for arrays of the wrong size, numbers that are not finite or a zero
// quaternion.
GltfMatrix gltfLocalTransform(const tinygltf::Node& node, const std::string& where);

// The cofactors of an affine transform's linear part, c[r][k] that of element (r, k) (so c is the
// inverse transpose times the determinant: what carries normals), and the determinant.
struct GltfCofactors {
  double c[3][3];
  double det;
  explicit GltfCofactors(const GltfMatrix& m);
};

// The inverse of an affine transform (its last row 0 0 0 1), or false where it has none.
bool gltfInvert(const GltfMatrix& m, GltfMatrix* inverse);

// a * b (column-major).
GltfMatrix gltfMultiply(const GltfMatrix& a, const GltfMatrix& b);

// T * R * S as glTF composes a node's transform (the quaternion [x, y, z, w] normalized).
GltfMatrix gltfTrs(const std::array<double, 3>& t, std::array<double, 4> q,
                   const std::array<double, 3>& s);

}  // namespace candela
