// Reading materials; see material_reader.h.
#include "scene/read/material_reader.h"

#include <vector>

#include "scene/read/did_you_mean.h"

namespace candela {
namespace {

const std::vector<std::string> kTypeNames = {"diffuse", "mirror", "glass", "emissive"};
const MaterialType kTypes[] = {MaterialType::Diffuse, MaterialType::Mirror, MaterialType::Glass,
                               MaterialType::Emissive};
// The types the seed shorthand may name: the first three of the above.
constexpr size_t kShorthandCount = 3;

std::string notUsedBy(size_t type) {
  return std::string("not used by ") + (kTypes[type] == MaterialType::Emissive ? "an " : "a ") +
         quoted(kTypeNames[type]) + " material";
}

// The fields of a material of type kTypes[type], read from `fields`: the material object itself,
// or for the shorthand the sphere or object that carries them.
Material readFields(JsonObject& fields, size_t type, TextureLoader& textures) {
  Material material;
  material.type = kTypes[type];
  switch (material.type) {
    case MaterialType::Diffuse:
    case MaterialType::Mirror:
    case MaterialType::Glass: {
      const float defaultColor = material.type == MaterialType::Diffuse ? 0.8f : 1.0f;
      const std::optional<JsonValue> color = fields.get("color");
      if (color && material.type == MaterialType::Diffuse)
        material.color = readTexturedColour(*color, textures, &material.colorTexture);
      else
        material.color = color ? color->colour() : Vec3(defaultColor);
      if (material.type == MaterialType::Glass) {
        if (std::optional<JsonValue> ior = fields.get("ior")) material.ior = ior->positiveNumber();
      } else {
        fields.reject("ior", notUsedBy(type));
      }
      fields.reject("radiance", notUsedBy(type));
      break;
    }
    case MaterialType::Emissive:
      material.radiance = fields.require("radiance").colour();
      fields.reject("color", notUsedBy(type));
      fields.reject("ior", notUsedBy(type));
      break;
  }
  return material;
}

[[noreturn]] void failUnknownMaterial(const JsonValue& value, const std::string& name,
                                      const MaterialLibrary& library) {
  std::vector<std::string> candidates(kTypeNames.begin(), kTypeNames.begin() + kShorthandCount);
  for (const auto& entry : library) candidates.push_back(entry.first);
  const std::string suggestion = closestMatch(name, candidates);
  if (!suggestion.empty())
    value.fail("unknown material " + quoted(name) + ", did you mean " + quoted(suggestion) + "?");
  std::string hint =
      "expected \"diffuse\", \"mirror\", \"glass\" or a name defined under "
      "\"materials\"";
  if (name == "emissive")
    hint +=
        "; an emissive material is written as an object: {\"type\": \"emissive\", "
        "\"radiance\": ...}";
  value.fail("unknown material " + quoted(name) + ", " + hint);
}

}  // namespace

MaterialLibrary readMaterialLibrary(const JsonValue& value, TextureLoader& textures) {
  if (!value.json().is_object()) value.failExpected("an object (material name -> material)");
  MaterialLibrary library;
  for (const auto& item : value.json().items()) {
    if (isCommentKey(item.key())) continue;
    const JsonValue material(item.value(), value.file(), memberPath(value.path(), item.key()));
    library[item.key()] = readMaterial(material, textures);
  }
  return library;
}

Material readMaterial(const JsonValue& value, TextureLoader& textures) {
  JsonObject fields(value, {"type", "color", "ior", "radiance"}, "a material object");
  const size_t type = fields.require("type").choice(kTypeNames);
  Material material = readFields(fields, type, textures);
  fields.finish();
  return material;
}

std::optional<Material> readMaterialReference(JsonObject& owner, const MaterialLibrary& library,
                                              TextureLoader& textures) {
  const std::optional<JsonValue> reference = owner.get("material");
  if (!reference) {
    owner.reject("ior", "not used without a \"glass\" material");
    if (std::optional<JsonValue> color = owner.get("color")) {
      Material diffuse;
      diffuse.color = readTexturedColour(*color, textures, &diffuse.colorTexture);
      return diffuse;
    }
    return std::nullopt;
  }
  if (reference->json().is_object()) {
    const std::string reason = "not used beside an inline material (put it inside \"material\")";
    owner.reject("color", reason);
    owner.reject("ior", reason);
    return readMaterial(*reference, textures);
  }
  if (!reference->json().is_string())
    reference->failExpected("a material name or a material object");

  const std::string name = reference->string();
  // A named material wins over the shorthand of the same name: the scene's author defined it on
  // purpose, and a library entry called "glass" would otherwise be unreachable.
  const auto named = library.find(name);
  if (named != library.end()) {
    const std::string reason = "not used with the named material " + quoted(name);
    owner.reject("color", reason);
    owner.reject("ior", reason);
    return named->second;
  }
  for (size_t type = 0; type < kShorthandCount; ++type)
    if (name == kTypeNames[type]) return readFields(owner, type, textures);
  failUnknownMaterial(*reference, name, library);
}

}  // namespace candela
