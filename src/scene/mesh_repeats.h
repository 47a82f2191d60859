// Finding the objects of a flattened scene that repeat one mesh (render/mesh_instances.h).
#pragma once

#include <cstdint>
#include <vector>

#include "render/scene_data.h"
#include "scene/mesh_layout.h"
#include "scene/scene_desc.h"

namespace candela {

// What flattening appended for one object: its mesh, and how it laid the mesh out
// (scene/mesh_layout.h: among others the mesh vertex that each split vertex copies), shared by
// the objects that place the mesh alike.
struct FlattenedObject {
  const MeshDesc* mesh = nullptr;
  const MeshLayout* layout = nullptr;
};

// Fills s.meshInstances.prototypes and each object's `prototype` (s.meshInstances.objects, one
// per entry of `objects`, already placed): objects whose meshes have equal positions and which
// flattening gave the same triangles, up to the shift of their vertex indices, and the same
// split vertices, repeat one prototype. Meshes used once get none.
void findRepeatedMeshes(SceneData& s, const std::vector<FlattenedObject>& objects);

}  // namespace candela
