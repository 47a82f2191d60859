// SceneData: owns the flattened arrays and the BVH of a scene; view() is what renderers see.
#pragma once

#include <vector>

#include "scene/scene_desc.h"
#include "scene/scene_view.h"

namespace candela {

struct BvhStats {
  uint32_t nodeCount = 0;
  uint32_t leafCount = 0;
  uint32_t maxDepth = 0;
  double buildSeconds = 0;
};

struct SceneData {
  std::vector<Material> materials;
  std::vector<Sphere> spheres;
  std::vector<Vec3> positions;
  std::vector<OctNormal> normals;
  std::vector<Triangle> triangles;
  std::vector<Light> lights;
  std::vector<BvhNode> nodes;
  std::vector<uint32_t> primIndices;
  Vec3 environment{0.0f};
  Camera camera;
  RenderSettings settings;
  BvhStats bvh;

  SceneView view() const;
  // World-space bounds of all geometry (empty scene: min > max).
  void bounds(Vec3* lo, Vec3* hi) const;
};

// Transforms meshes to world space, resolves the camera, adds sphere lights as emissive
// spheres and builds the BVH; triangles are then numbered in the BVH's leaf order. The
// description must already be validated.
SceneData flattenScene(const SceneDesc& desc);
// The same for a description whose meshes the caller no longer needs: they are released once
// flattened, before the BVH is built, so the two copies of the geometry and the build's arrays
// never coexist (the 8.5M-triangle bench scene: peak RSS 1.12 -> 0.82 GB). Everything but
// `objects[i].mesh` is left intact.
SceneData flattenScene(SceneDesc&& desc);

// flattenScene without the BVH (nodes and primIndices left empty) and with triangles in the
// order of the description: for refitting a tree built for a description of the same structure.
SceneData flattenSceneContents(const SceneDesc& desc);

// Replaces the camera, settings, environment, materials, lights and spheres of `scene` (which
// flattenScene made from a description with the same geometry as `desc`) by those of `desc`,
// keeping mesh vertices, triangles and the BVH. scene/frame_scene.h decides when that is valid.
void refreshSceneValues(SceneData& scene, const SceneDesc& desc);

}  // namespace candela
