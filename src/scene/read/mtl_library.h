// The MTL side of an OBJ file: the material libraries that its `mtllib` statements name.
//
// tinyobjloader parses the MTL text; this reads the files (relative to the OBJ's folder) and notes
// which materials set Kd, since tinyobjloader reports a material without Kd as black where the
// format wants the default diffuse 0.8.
#pragma once

#include <set>
#include <string>
#include <vector>

namespace candela {

struct MtlLibrary {
  std::string text;                // every readable file, concatenated
  std::set<std::string> kdNames;   // materials with a Kd statement
  std::vector<std::string> files;  // the files read, as paths from the OBJ file's folder
};

// Files that cannot be read are skipped: their materials fall back to the default.
MtlLibrary readMtlLibrary(const std::string& objPath, const std::vector<std::string>& names);

}  // namespace candela
