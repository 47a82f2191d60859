// Validation pass over Wavefront OBJ text, ahead of tinyobjloader.
//
// tinyobjloader is lenient: it reads "abc" as 0, keeps face indices that point past the vertex
// list, ignores statements it does not know, stops at a comment after a face, and reports what it
// does refuse without a line number. This pass checks every statement first and throws SceneError
// "<label>:<line>: <reason>" for the first fault (lines are 1-based; \n, \r\n and a lone \r all
// end a line). It returns the text tinyobjloader should parse: only the statements candela uses
// (v, vn, vt, f, usemtl, mtllib; the others become empty lines, since tinyobjloader would parse
// some of them unchecked: "vw" and "t" numbers out of range, "t" tag counts that allocate hundreds
// of kilobytes a line), with data lines normalised (single spaces, trailing comments removed),
// faces of more than four corners cut into triangles (polygon_triangulation.h) and every line
// ending in \n.
#pragma once

#include <string>
#include <vector>

namespace candela {

// A name and the first line (1-based) that gives it.
struct NamedAtLine {
  std::string name;
  size_t line = 0;
};

struct ObjScan {
  std::string text;                            // for tinyobjloader
  std::vector<NamedAtLine> materialLibraries;  // `mtllib` file names, unique, in order of use
  std::vector<NamedAtLine> materialUses;       // `usemtl` names, unique, in order of use
  // Vertices, and those with a colour ("v x y z r g b"), and the first line of one without.
  size_t vertices = 0, colouredVertices = 0, firstUncolouredLine = 0;
};

ObjScan scanObj(const std::string& text, const std::string& label);

}  // namespace candela
