// Picking glTF materials by variant; see gltf_variants.h.
#include "scene/read/gltf_variants.h"

#include "scene/read/did_you_mean.h"

namespace candela {
namespace {

const char* kExtension = "KHR_materials_variants";

}  // namespace

std::vector<std::string> gltfVariantNames(const tinygltf::Model& model, const std::string& label) {
  const auto e = model.extensions.find(kExtension);
  if (e == model.extensions.end()) return {};
  const std::string where = label + ": extensions." + kExtension + ".variants";
  const tinygltf::Value& variants = e->second.Get("variants");
  if (!variants.IsArray()) throw SceneError(where + ": expected an array of variants");
  std::vector<std::string> names;
  for (size_t i = 0; i < variants.ArrayLen(); ++i) {
    const tinygltf::Value& name = variants.Get(int(i)).Get("name");
    if (!name.IsString())
      throw SceneError(where + "[" + std::to_string(i) + "].name: expected a string");
    names.push_back(name.Get<std::string>());
  }
  return names;
}

int gltfVariantIndex(const std::vector<std::string>& names, const std::string& name) {
  for (size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return int(i);
  if (names.empty())
    throw GltfVariantError("the file has no variants (KHR_materials_variants), so none is \"" +
                           name + "\"");
  std::string list;
  for (size_t i = 0; i < names.size(); ++i) list += (i == 0 ? "\"" : ", \"") + names[i] + "\"";
  const std::string close = closestMatch(name, names);
  throw GltfVariantError("the file has no variant \"" + name + "\"" +
                         (close.empty() ? "" : " (did you mean \"" + close + "\"?)") +
                         "; its variants: " + list);
}

int gltfVariantMaterial(const tinygltf::Primitive& p, int variant, size_t variantCount,
                        size_t materialCount, const std::string& label, const std::string& where) {
  const auto e = p.extensions.find(kExtension);
  if (variant < 0 || e == p.extensions.end()) return p.material;
  const std::string at = label + ": " + where + ".extensions." + kExtension + ".mappings";
  const tinygltf::Value& mappings = e->second.Get("mappings");
  if (!mappings.IsArray()) throw SceneError(at + ": expected an array of mappings");
  for (size_t m = 0; m < mappings.ArrayLen(); ++m) {
    const std::string mappingAt = at + "[" + std::to_string(m) + "]";
    const tinygltf::Value& mapping = mappings.Get(int(m));
    const tinygltf::Value& material = mapping.Get("material");
    const tinygltf::Value& variants = mapping.Get("variants");
    if (!material.IsInt() || material.GetNumberAsInt() < 0 ||
        size_t(material.GetNumberAsInt()) >= materialCount)
      throw SceneError(mappingAt + ".material: expected a material from 0 to " +
                       std::to_string(int(materialCount) - 1));
    if (!variants.IsArray())
      throw SceneError(mappingAt + ".variants: expected an array of variants' indices");
    for (size_t v = 0; v < variants.ArrayLen(); ++v) {
      const tinygltf::Value& index = variants.Get(int(v));
      if (!index.IsInt() || index.GetNumberAsInt() < 0 ||
          size_t(index.GetNumberAsInt()) >= variantCount)
        throw SceneError(mappingAt + ".variants[" + std::to_string(v) + "]: expected a variant " +
                         "from 0 to " + std::to_string(int(variantCount) - 1));
      if (index.GetNumberAsInt() == variant) return material.GetNumberAsInt();
    }
  }
  return p.material;
}

}  // namespace candela
