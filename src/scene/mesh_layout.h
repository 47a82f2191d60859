// How flattening lays out a mesh's vertices: the renderer keeps one normal and one uv per vertex
// (both run parallel to positions), so a position that the file pairs with several normals (a
// crease) or several uvs (a texture seam) is split into one vertex per combination. The layout
// depends only on the mesh and on whether its normals and uvs are used, so the objects that place
// one mesh share it (scene/flatten.cpp), and a scene of many placed meshes knows its arrays'
// sizes before it writes them.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/shapes.h"
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

  uint32_t vertexCount(const MeshDesc& mesh) const {
    return uint32_t(mesh.positions.size() + splitSources.size());
  }
};

MeshLayout layOutMesh(const MeshDesc& mesh, bool withNormals, bool withUvs);

}  // namespace candela
