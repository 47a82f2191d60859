// Flattening: a validated scene description -> the kernel's arrays (render/scene_data.h).
//
// Meshes are transformed to world space, the camera is resolved, sphere lights become emissive
// spheres, and the BVH is built; triangles are then numbered in the BVH's leaf order, and every
// emissive sphere and triangle becomes a light that its primitive names.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "render/scene_data.h"
#include "scene/flatten_lights.h"
#include "scene/scene_desc.h"

namespace candela {

// The description must already be validated.
SceneData flattenScene(const SceneDesc& desc);
// The same for a description whose meshes the caller no longer needs: they are released once
// flattened, before the BVH is built, so the two copies of the geometry and the build's arrays
// never coexist. Everything but `objects[i].mesh` is left intact.
SceneData flattenScene(SceneDesc&& desc);

// flattenScene without the BVH (nodes and primIndices left empty), with triangles in the order
// of the description and without the lights of emissive geometry (only the declared lights): for
// refitting a tree built for a description of the same structure, after which the triangles take
// the tree's order and addEmitterLights completes the lights. `previous`, where given, is the
// scene of an earlier frame, of any structure: its texture pool is moved over when the textures
// are the same (SceneData::texturePoolHash), and its environment map's arrays when the map is
// (SceneData::environmentMapHash), rather than made again.
SceneData flattenSceneContents(const SceneDesc& desc, SceneData* previous = nullptr);

// What flattenScene adds to flattenSceneContents's scene (triangles in the description's order):
// the BVH `kind`, the triangles in its leaf order, then the lights (as addEmitterLights).
void addBvhAndLights(SceneData& scene, OwnBvh kind, PreviousLights* lights);

// flattenScene taking what it can of an earlier frame: `previous`'s texture pool and map arrays
// (as flattenSceneContents) and the light tree of `lights` (as addEmitterLights), each only
// where its own key is equal, so the scene is the one flattenScene(desc) makes.
SceneData flattenScene(const SceneDesc& desc, SceneData* previous, PreviousLights* lights);

// The instance numbers of the instance pass (docs/aovs.md): spheres, then objects, then lights,
// in file order, from 1 (0 is the background). Each list's first number; the list's entries
// number on from it.
struct InstanceNumbering {
  uint32_t firstSphere = 1;
  uint32_t firstObject = 0;
  uint32_t firstLight = 0;
};
InstanceNumbering instanceNumbering(const SceneDesc& desc);

// Each instance number with its name: the JSON `id`, else the place in the file ("spheres[2]").
std::vector<std::pair<uint32_t, std::string>> instanceNames(const SceneDesc& desc);

// What the passes' layers read of a scene (render/aov_layers.h, makeAovLayers): its camera and the
// instance each material belongs to. No vertices, textures or maps are copied.
SceneData flattenPassContext(const SceneDesc& desc);

// Replaces the camera, settings, environment, materials, lights and spheres of `scene` (which
// flattenScene made from a description with the same geometry as `desc`) by those of `desc`,
// keeping mesh vertices, triangles, the BVH and the texture pool. scene/frame_scene.h decides
// when that is valid.
void refreshSceneValues(SceneData& scene, const SceneDesc& desc);

// The world-space vertices of object `obj` as flattenScene places them (its mesh's, then their
// splits: scene/mesh_layout.h), split as `laidOutAs` (the same object in the frame flattened, whose
// materials and passes decided its splits) splits them.
std::vector<Vec3> placedVertices(const ObjectDesc& obj, const ObjectDesc& laidOutAs);

}  // namespace candela
