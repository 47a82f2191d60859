// Materials in a scene file: the named library, material objects, and what a sphere or an object
// says about its material.
//
// A sphere or object names its material in one of three ways (docs/scene-format.md):
//   "material": "red_wall"                       a material defined under top-level "materials"
//   "material": {"type": "glass", "ior": 1.33}   inline
//   "material": "glass", "ior": 1.33             the seed shorthand: type name, fields beside it
// and "color" alone means a diffuse material of that colour. Fields beside "material" that the
// chosen form does not use are errors.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "scene/read/json_reader.h"
#include "scene/read/texture_reader.h"
#include "scene/scene_desc.h"

namespace candela {

// A material as read: the material and, where it is a mix, the materials it mixes
// (Material::mixParts index `parts`; a part that is a mix has its own parts after it).
struct MaterialRead {
  Material material;
  std::vector<Material> parts;
};

using MaterialLibrary = std::map<std::string, MaterialRead>;

// The top-level "materials": an object (name -> material object), the path of a JSON file of one
// (relative to the scene's folder; the file's textures relative to its own), or an array of both,
// whose names must differ. A mix may name any of them for a part, in any order; one that contains
// itself is refused.
MaterialLibrary readMaterialLibrary(const JsonValue& value, TextureLoader& textures);

// The material that `owner` (a sphere or object) gives through its "material", "color" and "ior"
// keys; nothing when it gives none. A "color" (of any type but glass and emissive) may be a
// texture (texture_reader.h), loaded through `textures`.
std::optional<MaterialRead> readMaterialReference(JsonObject& owner, const MaterialLibrary& library,
                                                  TextureLoader& textures);

}  // namespace candela
