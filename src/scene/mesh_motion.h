// A mesh whose vertices move with time: an object that plays a glTF file's animation of the nodes
// below its own, its morph targets and its skins (scene/read/gltf_mesh_motion.h).
#pragma once

#include <memory>

namespace candela {

struct MeshDesc;

class MeshMotion {
 public:
  virtual ~MeshMotion() = default;
  // The mesh at `seconds` into the animation: the same triangles, texture coordinates and
  // materials, its vertices and normals where the animation has them then.
  virtual std::shared_ptr<const MeshDesc> meshAt(double seconds) const = 0;
};

}  // namespace candela
