// Vertex normals for the faces of a mesh that its file gives none (an OBJ without `vn`: most
// scanned meshes), so that a curved surface tessellated coarsely shades smoothly.
#pragma once

#include "scene/scene_desc.h"

namespace candela {

// A copy of `mesh` in which every triangle without normals has one at each corner: the average of
// the unit normals of the triangles around that corner's position, weighted by their angles there
// (Thuermer and Wuethrich 1998, as Mitsuba 3 computes an OBJ's missing normals), over the
// triangles whose normal is within `creaseDegrees` (0 to 180) of the corner's own triangle's, so
// that edges sharper than it stay sharp. Positions are matched by value, so a file that repeats a
// vertex along a seam (the Utah teapot's patches) shades across it. Only triangles without normals
// take part; the file's own normals are kept, and a triangle of no area stays flat. The cost is
// linear in the faces where all the faces at a position lie within the crease of each other (a
// smooth surface, and every surface at 180 degrees); a position of more than 4096 faces that
// spread wider than the crease gives each of its corners its own face's normal.
MeshDesc withComputedNormals(const MeshDesc& mesh, float creaseDegrees);

}  // namespace candela
