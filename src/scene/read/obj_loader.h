// Wavefront OBJ (+ MTL) file -> MeshDesc, in object space.
//
// Polygons are triangulated (quads split along the shorter diagonal by tinyobjloader, larger
// polygons fanned when convex and ear-clipped when not, see polygon_triangulation.h), keeping the
// file's vertex order, so a face's outside stays the side its vertices wind counter-clockwise
// around. Vertex normals are kept where all three corners of a triangle have one; otherwise the
// triangle's normal indices are -1 (face normal); likewise for texture coordinates (`vt`, u and v;
// a third component is ignored). Each MTL material becomes a Material by the mapping of
// docs/scene-format.md (diffuse by Kd and map_Kd, plastic or conductor by Ks and Ns, emissive by
// Ke and map_Ke), masked by d, Tr and map_d (textures through `textures`, relative to the MTL
// file; see mtlMaterials in obj_loader.cpp); faces without one (no usemtl, no MTL file, or a name
// the MTL does not define) use an extra diffuse 0.8 entry. A missing MTL file is not an error:
// its faces fall back to that entry.
//
// Errors throw SceneError, with `label` (how the caller shows the path) naming the file:
//   cannot open "<label>" (<reason>)
//   <label>:<line>: <reason>            malformed statements, see obj_scanner.h
//   <label>: <reason>                   faults without a line, e.g. a file with no faces
//   <mtl file>:<line>: <reason>         bad texture or alpha statements in an MTL file
#pragma once

#include <string>

#include "scene/read/texture_reader.h"
#include "scene/scene_desc.h"
#include "scene/scene_error.h"

namespace candela {

// A group an object asks for by name (its "obj_group") that the file does not have: the scene
// reports it at the object's "obj_group".
class ObjGroupError : public SceneError {
 public:
  using SceneError::SceneError;
};

// The OBJ file's faces, or with `group` those after the `g` or `o` statements of that name, their
// vertices alone (throws ObjGroupError naming the file's groups where none has that name).
MeshDesc loadObjFile(const std::string& path, const std::string& label, TextureLoader& textures,
                     const std::string& group = "");

}  // namespace candela
