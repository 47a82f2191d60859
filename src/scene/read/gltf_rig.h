// What places a glTF mesh's vertices: its nodes, its morph targets' weights and its skins. Each
// primitive's own positions and normals are first moved by its morph targets, weighted, then
// placed by its node's transform (times its EXT_mesh_gpu_instancing placement) or, where the node
// has a skin, by the skin's joints: each vertex by the weighted sum of its joints' transforms times
// their inverse bind matrices (glTF ignores a skinned mesh's node transform). Loading poses a
// file once, at rest (every node's own transform and weights); an object that plays one of the
// file's animations poses it again at each time it is seen (scene/mesh_motion.h).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/vec3.h"
#include "scene/read/gltf_animation.h"
#include "scene/read/gltf_nodes.h"
#include "scene/read/tiny_gltf_config.h"

namespace candela {

// One primitive's vertices as the file gives them, and where they land in the mesh.
struct GltfRigPrimitive {
  int node = -1;                          // the node that places it
  std::optional<GltfMatrix> instance;     // its EXT_mesh_gpu_instancing placement under the node
  std::vector<float> positions, normals;  // its own, 3 numbers a vertex (normals may be none)
  // Per morph target, what it adds to each vertex's position and normal (either may be none).
  std::vector<std::vector<float>> targetPositions, targetNormals;
  int skin = -1;  // the node's skin, or -1
  // Per vertex, `influences` joints (indices into the skin's joints) and their weights, summing
  // to 1.
  int influences = 0;
  std::vector<uint32_t> joints;
  std::vector<float> jointWeights;
  uint32_t base = 0;        // its first vertex in the mesh
  int32_t normalBase = -1;  // its first normal in the mesh, -1: it has none
};

// Every node's transform (in the object's frame) and its mesh's morph target weights, at one time.
struct GltfPose {
  std::vector<GltfMatrix> worlds;              // per node
  std::vector<std::vector<double>> weights;    // per node: one per target of its mesh
  std::vector<std::vector<GltfMatrix>> skins;  // per skin: each joint's world times inverse bind
};

class GltfRig {
 public:
  // The file's nodes, skins and default weights, for the object that holds node `root` (-1: the
  // file's scene).
  GltfRig(const tinygltf::Model& model, const std::string& label, int root);

  // Where the nodes stand and what weights their meshes take at time t (seconds) of `animation`,
  // or at rest where it is null.
  GltfPose pose(const GltfAnimation* animation, double t) const;

  // Reads the skin weights of a primitive with a skin (JOINTS_n and WEIGHTS_n) into *primitive,
  // each vertex's made to sum to 1, and returns how many vertices have none (they stay with their
  // node, as if it had no skin). Throws SceneError "<where>.attributes...: <reason>" for a joint
  // past the skin's, a negative weight or attributes that do not match, and "<label>: skins[i]...:
  // <reason>" for a skin whose joints or inverse bind matrices do not exist or do not match.
  size_t readInfluences(const tinygltf::Model& model, const tinygltf::Primitive& source,
                        const std::string& where, GltfRigPrimitive* primitive) const;

  // Writes the primitive's vertices, posed, from positions[p.base] and its normals from
  // normals[p.normalBase] (each made unit; *usable, where given, says which could be).
  void place(const GltfRigPrimitive& p, const GltfPose& pose, std::vector<Vec3>* positions,
             std::vector<Vec3>* normals, std::vector<bool>* usable = nullptr) const;

  // Whether the primitive's faces are seen from behind at rest: a transform of negative
  // determinant mirrors them, and glTF reverses their winding to keep their outsides out.
  bool mirrored(const GltfRigPrimitive& p, const GltfPose& pose) const;

  // Whether `animation` moves any vertex of `primitives`: a node that places one (but the
  // root, whose motion the object's own placement follows), a joint of their skins or one of its
  // parents, or their morph weights.
  bool movedBy(const GltfAnimation& animation) const;

  // The primitives, kept for an object that plays an animation.
  std::vector<GltfRigPrimitive> primitives;
  // The file's animations as loading read them, in its order, for the objects that play one: each
  // with its name, and the reason it cannot be played where it cannot (SceneError's message).
  struct Animation {
    std::string name;
    std::optional<GltfAnimation> played;
    std::string fault;
  };
  std::vector<Animation> animations;

 private:
  struct Skin {
    std::vector<int> joints;
    std::vector<GltfMatrix> inverseBinds;
    std::string fault;  // why it cannot be read (SceneError's message), or empty
  };
  static Skin readSkin(const tinygltf::Model& model, const std::string& where,
                       const tinygltf::Skin& skin);
  tinygltf::Model skeleton_;  // the file's nodes and scenes alone: what places them
  std::string label_;
  int root_;
  std::vector<int> parents_;                      // per node, -1: none
  std::vector<std::vector<double>> restWeights_;  // per node
  std::vector<Skin> skins_;
};

}  // namespace candela
