// Reuse or rebuild of a frame's flattened scene; see frame_scene.h.
#include "scene/frame_scene.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "geometry/bvh_refit.h"
#include "scene/content_hash.h"
#include "scene/flatten.h"
#include "scene/key_writer.h"
#include "scene/light_emission_desc.h"
#include "scene/mesh_layout.h"

namespace candela {
namespace {

// The geometry of `desc` as bytes, in full (*geometry) and less the transforms (*structure): the
// two list the same things, each mesh hashed once for both.
void writeKeys(const SceneDesc& desc, std::string* geometry, std::string* structure) {
  KeyWriter full, shape;
  const auto both = [&](const auto& value) {
    full.add(value);
    shape.add(value);
  };
  both(desc.ownBvh);
  both(desc.objectCoordinatesPass);
  both(desc.spheres.size());
  for (const SphereDesc& s : desc.spheres) {
    full.add(s.position);
    full.add(s.radius);
    both(s.mixParts.size());  // decides how many materials the sphere appends
  }
  both(desc.lights.size());
  for (const LightDesc& l : desc.lights) {
    both(l.type);
    if (l.type == LightType::Sphere) {  // sphere lights are spheres of the BVH
      full.add(l.position);
      full.add(l.radius);
    }
    if (l.rectangle) {  // and rectangle lights two of its triangles
      Vec3 corners[4];
      rectangleCorners(l, corners);
      for (const Vec3& corner : corners) full.add(corner);
    }
  }
  both(desc.objects.size());
  struct MeshHashes {
    uint64_t topology = 0, pose = 0;
  };
  std::unordered_map<const MeshDesc*, MeshHashes> meshHashes;
  for (const ObjectDesc& o : desc.objects) {
    full.add(o.position);
    full.add(o.rotation);
    full.add(o.scale);
    both(o.smooth);
    both(usesUvs(o));  // with the mesh, decides the object's vertices (scene/mesh_layout.h)
    both(usesVertexColors(o));
    both(o.material.has_value());  // decides how many materials the object appends
    both(o.mixParts.size());
    both(o.mesh->materials.size());
    both(o.mesh->mixParts.size());
    // Objects that name one file share its mesh: it is hashed once. Its triangles, texture
    // coordinates and colours are its structure; where its vertices stand (a glTF animation's
    // pose) is a motion, which a refit follows as it follows a transform.
    const auto [hashes, fresh] = meshHashes.try_emplace(o.mesh.get(), MeshHashes{});
    if (fresh) {
      const MeshDesc& m = *o.mesh;
      hashes->second.topology = hashVector(m.colors, hashVector(m.triangles, hashVector(m.uvs)));
      hashes->second.pose = hashVector(m.normals, hashVector(m.positions));
    }
    both(hashes->second.topology);
    both(o.mesh->positions.size());
    both(o.mesh->normals.size());
    full.add(hashes->second.pose);
  }
  both(desc.textures.size());
  for (const std::shared_ptr<const TextureDesc>& t : desc.textures) both(textureHash(*t));
  *geometry = full.take();
  *structure = shape.take();
}

}  // namespace

const SceneData& FrameScene::prepare(const SceneDesc& desc, const FlowMotion* flow,
                                     const FlowMotion* backwardFlow) {
  const auto start = std::chrono::steady_clock::now();
  std::string geometry, structure;
  writeKeys(desc, &geometry, &structure);
  // A frame whose spheres, objects or lights move while the shutter is open is flattened and
  // built afresh, and so is the frame after it: no keys, nothing to reuse.
  const auto posed = [](const auto& shape) { return !shape.shutterPoses.empty(); };
  if (std::any_of(desc.spheres.begin(), desc.spheres.end(), posed) ||
      std::any_of(desc.objects.begin(), desc.objects.end(), posed) ||
      std::any_of(desc.lights.begin(), desc.lights.end(), posed)) {
    geometry.clear();
    structure.clear();
  }
  if (!geometryKey_.empty() && geometry == geometryKey_) {
    refreshSceneValues(data_, desc);
    change_ = SceneChange::Values;
  } else {
    bool refitted = false;
    const bool sameStructure = !structureKey_.empty() && structure == structureKey_;
    // data_ is taken apart below: should anything throw, the next frame must not reuse it.
    geometryKey_.clear();
    structureKey_.clear();
    PreviousLights previous = takeLights(data_);  // its tree serves if the lights did not move
    if (sameStructure && desc.ownBvh == OwnBvh::None) {
      // No own BVH to refit (Embree refits its own): the same triangles, moved.
      data_ = flattenSceneContents(desc, &data_);
      addEmitterLights(data_, &previous);
      refitted = true;
    } else if (sameStructure && !data_.nodes.empty()) {
      SceneData moved = flattenSceneContents(desc, &data_);
      // The same triangles (the structure is unchanged), in the leaf order of the kept tree; the
      // file order stays at hand for a rebuild.
      std::vector<Triangle> fileOrder = std::move(moved.triangles);
      moved.triangles = std::move(data_.triangles);
      moved.nodes = std::move(data_.nodes);
      moved.primIndices = std::move(data_.primIndices);
      moved.bvh = data_.bvh;
      refitBvh(moved.nodes, moved.primIndices, moved.spheres.data(),
               uint32_t(moved.spheres.size()), moved.positions.data(), moved.triangles.data());
      refitted = bvhCostGrowth(moved.nodes, builtCosts_) <= kRefitCostLimit;
      if (refitted) {
        addEmitterLights(moved, &previous);
      } else {  // the refitted tree degraded: a new one over the same contents
        moved.triangles = std::move(fileOrder);
        addBvhAndLights(moved, desc.ownBvh, &previous);
      }
      data_ = std::move(moved);
    } else {
      data_ = flattenScene(desc, &data_, &previous);
    }
    if (!refitted) builtCosts_ = bvhCostProfile(data_.nodes);
    change_ = refitted ? SceneChange::Motion : SceneChange::Structure;
    geometryKey_ = std::move(geometry);
    structureKey_ = std::move(structure);
  }
  clearFlowMotion(data_);
  if (flow) applyFlowMotion(data_, *flow);
  if (backwardFlow) applyFlowMotion(data_, *backwardFlow, FlowDirection::Backward);
  seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return data_;
}

}  // namespace candela
