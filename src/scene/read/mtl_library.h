// The MTL side of an OBJ file: the material libraries that its `mtllib` statements name.
//
// tinyobjloader parses the MTL text; this reads the files (relative to the OBJ's folder), notes
// which materials set Kd, since tinyobjloader reports a material without Kd as black where the
// format wants the default diffuse 0.8, and keeps the statements candela reads itself (textures
// and alpha), with their file and line for messages.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "scene/read/obj_scanner.h"

namespace candela {

// One MTL statement: where it is and what follows its keyword (trimmed).
struct MtlStatement {
  std::string file;    // the MTL file as messages show it
  std::string folder;  // the MTL file's folder, against which texture names are resolved
  size_t line = 0;     // 1-based
  std::string arguments;
};

// The statements of one material that candela reads itself; the last of each kind counts.
struct MtlTextures {
  std::optional<MtlStatement> mapKd, mapKe, d, tr, mapD, norm;
  // The PBR extension's roughness: a number, or a texture of them.
  std::optional<MtlStatement> pr, mapPr;
  // The PBR extension's metalness: a number, or a texture of them.
  std::optional<MtlStatement> pm, mapPm;
  // The PBR extension's anisotropy and its rotation (a fraction of a full turn), as Blender's
  // exporter writes them.
  std::optional<MtlStatement> aniso, anisor;
  // The PBR extension's clear coat (its weight, as Blender's exporter writes its Coat Weight) and
  // that coat's roughness.
  std::optional<MtlStatement> pc, pcr;
  // The PBR extension's sheen (Blender's exporter writes its Sheen Weight).
  std::optional<MtlStatement> ps;
  // A bump map (`bump`, `map_Bump` or `map_bump`, as written in bumpKeyword): heights, read
  // where the material has no `norm`.
  std::optional<MtlStatement> bump;
  std::string bumpKeyword;
};

struct MtlLibrary {
  std::string text;                // every readable file, concatenated
  std::set<std::string> kdNames;   // materials with a Kd statement
  std::map<std::string, MtlTextures> statements;  // by material name
  std::vector<std::string> files;  // the files read, as paths from the OBJ file's folder
  struct Unread {
    NamedAtLine library;  // as the OBJ file names it, and where
    std::string why;
  };
  std::vector<Unread> unread;  // the files that could not be read
};

// The files `names` (from the OBJ's `mtllib` statements). Files that cannot be read are skipped
// (and listed in `unread`): their materials fall back to the default. `objLabel` is the OBJ file
// as messages show it; MTL files are shown beside it.
MtlLibrary readMtlLibrary(const std::string& objPath, const std::string& objLabel,
                          const std::vector<NamedAtLine>& names);

}  // namespace candela
