// Stanford PLY file -> MeshDesc, in object space: the mesh format of 3D scanning (the Stanford
// repository's own files, photogrammetry and Meshlab exports), ASCII or binary of either byte
// order (ply_header.h).
//
// Read: the `vertex` element's x, y, z, its normals nx, ny, nz where it has all three, and its
// texture coordinates as u, v (or s, t, texture_u, texture_v, texture_s, texture_t), which mean
// what an OBJ's `vt` does; the `face` element's list `vertex_indices` (or `vertex_index`), each
// face triangulated as an OBJ face is (a quad along its shorter diagonal, a larger polygon by
// polygon_triangulation.h), keeping its winding; vertex colours as red, green, blue (or
// diffuse_red..., or r, g, b), display colours (sRGB) of an integer type's range or floats from 0
// to 1, made linear (MeshDesc::colors). Every other element and property is skipped. A PLY file
// has no materials: its faces are diffuse 0.8, or 1 under vertex colours (which tint it), unless
// the object gives a material.
//
// Errors throw SceneError naming the file: "<label>:<line>: <reason>" in the header and in an
// ASCII body, "<label>: <reason>" in a binary one, the reason naming the element and its number
// ("face 12: vertex index 900 out of range (800 vertices)").
#pragma once

#include <string>

#include "scene/scene_desc.h"

namespace candela {

MeshDesc loadPlyFile(const std::string& path, const std::string& label);

// Whether a mesh file is read as PLY: its name ends in ".ply", in any case.
bool isPlyPath(const std::string& path);

}  // namespace candela
