// How flattening lays out a mesh's vertices: the renderer keeps one normal and one uv per vertex
// (both run parallel to positions), so a position that the file pairs with several normals (a
// crease) or several uvs (a texture seam) is split into one vertex per combination. The layout
// depends only on the mesh and on whether an object uses its normals and uvs, so the objects that
// place one mesh share it (scene/flatten.cpp), and a scene of many placed meshes knows its arrays'
// sizes before it writes them.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/shapes.h"
#include "render/aov_layers.h"
#include "scene/scene_desc.h"

namespace candela {

struct MeshLayout {
  // The file's normal and uv index of an emitted vertex (-1: none; -2: a vertex no face uses).
  struct Corner {
    int32_t n, t;
    bool operator==(const Corner& o) const { return n == o.n && t == o.t; }
  };
  // The mesh vertex that each vertex beyond the mesh's own (a split) copies, in order.
  std::vector<uint32_t> splitSources;
  // Of every emitted vertex, the mesh's own and then the splits; empty when neither normals nor
  // uvs are used.
  std::vector<Corner> corners;
  // The mesh's triangles over the emitted vertices, numbered from 0, each with its mesh material.
  std::vector<Triangle> triangles;
  // Whether the vertices carry the file's normals and uvs (layOutMesh's choices).
  bool withNormals = false, withUvs = false;

  uint32_t vertexCount(const MeshDesc& mesh) const {
    return uint32_t(mesh.positions.size() + splitSources.size());
  }
};

MeshLayout layOutMesh(const MeshDesc& mesh, bool withNormals, bool withUvs);

// Whether a material looks anything up by uv: a texture, an alpha mask's or a normal map.
bool readsTextures(const Material& m);
// Whether a material needs uvs: it reads textures or orients its anisotropy by them.
bool readsUvs(const Material& m);
// Whether `test` holds for a material that shades an object: its own or else its mesh's, or a
// part of their mixes.
bool anyMaterialOf(const ObjectDesc& obj, bool (*test)(const Material&));
// Whether an object uses its mesh's normals: it is smooth and the file has them.
bool usesNormals(const ObjectDesc& obj);
// Whether an object uses its mesh's uvs: the file has them and one of the object's materials reads
// them (a texture or an alpha mask's), or the uv pass shows them (ObjectDesc::uvPass). Uvs that
// nothing reads would split vertices at every seam for nothing (Sponza's file: 69,013 vertices for
// 39,999 positions).
bool usesUvs(const ObjectDesc& obj);
// Marks `desc` for the passes of `aovs` that need more laid out than the image does: the uv pass
// every object's uvs (ObjectDesc::uvPass), the object_coordinates pass each vertex's place in its
// object (SceneDesc::objectCoordinatesPass).
void layOutForPasses(SceneDesc& desc, const std::vector<Aov>& aovs);
// Whether an object's vertices carry its mesh's colours: the file has them and the object does
// not leave them ("vertex_colors": false).
bool usesVertexColors(const ObjectDesc& obj);

}  // namespace candela
