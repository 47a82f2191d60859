// Reading a glTF accessor's elements, every bound checked: the accessor, its buffer view and its
// buffer must exist and hold all the elements the accessor says they do (a file may claim
// anything). Errors throw SceneError with `where`, the JSON path of what names the accessor
// ("meshes[0].primitives[1].attributes.POSITION"), and the reason.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "scene/read/tiny_gltf_config.h"

namespace candela {

// The `components`-wide float elements of accessor `index`, one after another: FLOAT components,
// or (where `normalizedIntegers`) normalized unsigned bytes and shorts scaled into [0, 1], as
// glTF allows for texture coordinates and colours.
std::vector<float> readFloatAccessor(const tinygltf::Model& model, int index, int components,
                                     bool normalizedIntegers, const std::string& where);

// The scalar unsigned integers (UNSIGNED_BYTE, _SHORT or _INT) of accessor `index`: indices.
std::vector<uint32_t> readIndexAccessor(const tinygltf::Model& model, int index,
                                        const std::string& where);

}  // namespace candela
