// SceneData: owns the flattened arrays and the BVH of a scene; view() is what renderers see.
//
// scene/flatten.h makes it from a scene description.
#pragma once

#include <cstdint>
#include <vector>

#include "core/padded_allocator.h"
#include "render/mesh_instances.h"
#include "render/scene_change.h"
#include "render/scene_view.h"

namespace candela {

struct BvhStats {
  uint32_t nodeCount = 0;
  uint32_t leafCount = 0;
  uint32_t maxDepth = 0;
  double buildSeconds = 0;
};

// The vector that holds an array of type T. Arrays of Vec3 are padded (core/padded_allocator.h):
// the Embree engine shares the positions, which it reads 16 bytes at a time.
template <class T>
struct OwnedArray {
  using type = std::vector<T>;
};
template <>
struct OwnedArray<Vec3> {
  using type = PaddedVector<Vec3>;
};

#define CANDELA_OWNED_ARRAY(Type, name, count, rewrittenBy) OwnedArray<Type>::type name;

struct SceneData {
  CANDELA_SCENE_ARRAYS(CANDELA_OWNED_ARRAY)
  uint32_t firstTriangleLight = 0;
  bool loneDeltaLight = false;
  uint32_t firstHitDeltaLights = 0;  // SceneView::firstHitDeltaLights
  // The lights that start light subpaths, when the view allows (render/light_path.h), and
  // whether any of them has a surface.
  uint32_t lightsStartingPaths = 0;
  bool areaLightsStartPaths = false;
  float infiniteLightShare = 0.0f;
  bool sunDiscs = false;
  Environment environment;
  // A hash of the bounds and powers of the lights the light tree was built over (0: no tree): a
  // frame with the same hash keeps the tree (scene/flatten_lights.cpp), and the GPU its copy
  // (RewrittenBy).
  uint64_t lightTreeHash = 0;
  // The content hash of the map the env* arrays were made from (0: none): a frame with an equal
  // map keeps them, and so does the GPU (RewrittenBy). And the map's mean texel over directions
  // (sin theta weighted), host only.
  uint64_t environmentMapHash = 0;
  Vec3 environmentMapMean;
  // Of the content hashes of the textures in the pool: a frame with the same textures keeps the
  // pool, and so does the GPU (RewrittenBy).
  uint64_t texturePoolHash = 0;
  // The mean linear colour of each emission texture (host only; -1 where not taken yet): what a
  // textured emitter's power weighs. Taken when a material first emits by the texture, and kept
  // with the pool.
  std::vector<Vec3> textureMeans;
  Camera camera;
  RenderSettings settings;
  FlowFrames flow;
  FlowFrames backwardFlow;
  BvhStats bvh;
  // Host only: the instance number (docs/aovs.md) of the entity each material belongs to; every
  // sphere, object and sphere light appends materials of its own, so a material names one.
  std::vector<uint32_t> materialInstances;
  // Host only: the objects that repeat a mesh, for an engine that traces them as instances.
  MeshInstances meshInstances;
  // Host only: where each object's vertices begin in positions, in file order (the flow pass
  // places those of a mesh that moves apart: scene/flow_motion.h).
  std::vector<uint32_t> objectFirstVertex;

  SceneView view() const;
  // Moves the arrays of keyed group `group` (RewrittenBy::EnvironmentMap or TexturePool), its
  // key and what the host keeps beside them (the map's mean and distribution size, the texture
  // means) from `from` into this scene; `from` is left without them (key 0), so no later frame
  // takes them again.
  void takeGroup(SceneData& from, RewrittenBy group);
  // Empties the arrays of keyed group `group` and zeroes its key and host extras.
  void clearGroup(RewrittenBy group);
  // World-space bounds of all geometry (empty scene: min > max).
  void bounds(Vec3* lo, Vec3* hi) const;
};

#undef CANDELA_OWNED_ARRAY

}  // namespace candela
