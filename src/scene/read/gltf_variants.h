// KHR_materials_variants (Shopify's and Blender's product variants: one shoe, many colourways): a
// file names variants, and each primitive maps some of them to materials of its own. The variant
// an object asks for (its "gltf_variant") picks each primitive's material; a primitive it does not
// map, or an object that asks for none, keeps the primitive's material.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "scene/read/tiny_gltf_config.h"
#include "scene/scene_error.h"

namespace candela {

// A variant the file does not have: the scene reports it at the object's "gltf_variant".
class GltfVariantError : public SceneError {
 public:
  using SceneError::SceneError;
};

// The file's variants' names, in order (none without the extension). Throws SceneError
// "<label>: extensions.KHR_materials_variants...: <reason>" for a list glTF does not allow.
std::vector<std::string> gltfVariantNames(const tinygltf::Model& model, const std::string& label);

// The index of variant `name` among `names`; throws GltfVariantError naming the file's variants
// (and the likely one meant) where it has none of that name.
int gltfVariantIndex(const std::vector<std::string>& names, const std::string& name);

// The material primitive `p` takes under variant `variant` (-1: none): the mapping's that lists
// it, else the primitive's own. Throws SceneError "<label>: <where>.extensions.
// KHR_materials_variants.mappings[i]...: <reason>" for a mapping glTF does not allow.
int gltfVariantMaterial(const tinygltf::Primitive& p, int variant, size_t variantCount,
                        size_t materialCount, const std::string& label, const std::string& where);

}  // namespace candela
