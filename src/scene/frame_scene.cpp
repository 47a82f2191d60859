// Reuse or rebuild of a frame's flattened scene; see frame_scene.h.
#include "scene/frame_scene.h"

#include <chrono>
#include <cstdint>
#include <cstring>
#include <vector>

#include "geometry/bvh_refit.h"
#include "scene/flatten.h"
#include "scene/key_writer.h"

namespace candela {
namespace {

// FNV-1a over a vector's bytes: equal meshes give equal hashes; a collision would need two
// different meshes with the same counts in one animation.
template <typename T>
uint64_t hashOf(const std::vector<T>& items) {
  uint64_t h = 1469598103934665603ull;
  const unsigned char* p = reinterpret_cast<const unsigned char*>(items.data());
  for (size_t i = 0, n = items.size() * sizeof(T); i < n; ++i) h = (h ^ p[i]) * 1099511628211ull;
  return h ^ items.size();
}

// Both keys list the same things; the structure key leaves out what a refit can follow.
std::string sceneKey(const SceneDesc& desc, bool withTransforms) {
  KeyWriter key;
  key.add(desc.ownBvh);
  key.add(desc.spheres.size());
  for (const SphereDesc& s : desc.spheres) {
    if (withTransforms) {
      key.add(s.position);
      key.add(s.radius);
    }
  }
  key.add(desc.lights.size());
  for (const LightDesc& l : desc.lights) {
    key.add(l.type);
    if (l.type == LightType::Sphere && withTransforms) {  // sphere lights are spheres of the BVH
      key.add(l.position);
      key.add(l.radius);
    }
  }
  key.add(desc.objects.size());
  for (const ObjectDesc& o : desc.objects) {
    if (withTransforms) {
      key.add(o.position);
      key.add(o.rotation);
      key.add(o.scale);
    }
    key.add(o.smooth);
    key.add(o.material.has_value());  // decides how many materials the object appends
    key.add(o.mesh.materials.size());
    key.add(hashOf(o.mesh.positions));
    key.add(hashOf(o.mesh.normals));
    key.add(hashOf(o.mesh.uvs));
    key.add(hashOf(o.mesh.triangles));
  }
  key.add(desc.textures.size());
  for (const std::shared_ptr<const TextureDesc>& t : desc.textures) key.add(t->contentHash);
  return key.take();
}

}  // namespace

std::string geometryKey(const SceneDesc& desc) { return sceneKey(desc, true); }
std::string structureKey(const SceneDesc& desc) { return sceneKey(desc, false); }

const SceneData& FrameScene::prepare(const SceneDesc& desc, const FlowMotion* flow) {
  const auto start = std::chrono::steady_clock::now();
  std::string geometry = geometryKey(desc), structure = structureKey(desc);
  if (!geometryKey_.empty() && geometry == geometryKey_) {
    refreshSceneValues(data_, desc);
    change_ = SceneChange::Values;
  } else {
    bool refitted = false;
    PreviousLights previous = takeLights(data_);  // its tree serves if the lights did not move
    if (!structureKey_.empty() && structure == structureKey_ && desc.ownBvh == OwnBvh::None) {
      // No own BVH to refit (Embree refits its own): the same triangles, moved.
      data_ = flattenSceneContents(desc, &data_);
      addEmitterLights(data_, &previous);
      refitted = true;
    } else if (!structureKey_.empty() && structure == structureKey_ && !data_.nodes.empty()) {
      SceneData moved = flattenSceneContents(desc, &data_);
      moved.nodes = std::move(data_.nodes);
      moved.primIndices = std::move(data_.primIndices);
      // The same triangles (the structure is unchanged), in the leaf order of the kept tree.
      moved.triangles = std::move(data_.triangles);
      moved.bvh = data_.bvh;
      refitBvh(moved.nodes, moved.primIndices, moved.spheres.data(),
               uint32_t(moved.spheres.size()), moved.positions.data(), moved.triangles.data());
      refitted = bvhSahCost(moved.nodes) <= kRefitCostLimit * builtCost_;
      if (refitted) addEmitterLights(moved, &previous);  // else flattenScene below makes them
      data_ = std::move(moved);
    }
    if (!refitted) {
      data_ = flattenScene(desc);
      builtCost_ = bvhSahCost(data_.nodes);
    }
    change_ = refitted ? SceneChange::Motion : SceneChange::Structure;
    geometryKey_ = std::move(geometry);
    structureKey_ = std::move(structure);
  }
  if (flow) {
    applyFlowMotion(data_, *flow);
  } else {
    clearFlowMotion(data_);
  }
  seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return data_;
}

}  // namespace candela
