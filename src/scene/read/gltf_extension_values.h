// Reading the values of a glTF material's extension objects (numbers, factors in [0, 1],
// colours), each refused with its JSON path where glTF does not allow it, and the mix that the
// material readers (scene/read/gltf_materials.h) build of two parts.
#pragma once

#include <string>

#include "core/texture.h"
#include "core/vec3.h"
#include "scene/read/gltf_materials.h"
#include "scene/read/tiny_gltf_config.h"

namespace candela {

// The extension `name` of a material's extensions, where it is an object; else null.
const tinygltf::Value* extension(const tinygltf::ExtensionMap& extensions, const char* name);

// A number of an extension's object (null: none), `fallback` where absent; refused unless finite.
double extensionNumber(const tinygltf::Value* object, const char* key, double fallback,
                       const std::string& where);

// Three numbers of an extension's object, `fallback` where absent; refused unless each is in
// [0, most] (most infinite: finite and non-negative).
Vec3 extensionColour(const tinygltf::Value* object, const char* key, Vec3 fallback, float most,
                     const std::string& where);

// `value`, refused unless in [0, 1].
float unitFactor(double value, const std::string& where);

// A factor in [0, 1] of an extension's object, `fallback` where absent.
float extensionFactor(const tinygltf::Value* object, const char* key, double fallback,
                      const std::string& where);

// The mix of `first` and `second`, the second's share `weight` (or the texture's channel).
Shading mixOf(Shading first, Shading second, float weight, const TextureRef& map, uint32_t channel);

}  // namespace candela
