// Reading a glTF accessor's elements, every bound checked: the accessor, its buffer view and its
// buffer must exist and hold all the elements the accessor says they do (a file may claim
// anything). An accessor without a buffer view is zeros, and a sparse one substitutes the
// elements it names, as glTF defines them. Errors throw SceneError with `where`, the JSON path of
// what names the accessor
// ("meshes[0].primitives[1].attributes.POSITION"), and the reason.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "scene/read/tiny_gltf_config.h"

namespace candela {

// The encodings of numbers an accessor may use, as glTF's tables allow them per attribute (and
// KHR_mesh_quantization widens them for positions, normals and texture coordinates). Flags.
enum AccessorEncoding : unsigned {
  kFloats = 1u,
  kUnsignedNormalized = 2u,  // normalized UNSIGNED_BYTE and _SHORT: c / 255, c / 65535
  kSignedNormalized = 4u,    // normalized BYTE and SHORT: max(c / 127, -1), max(c / 32767, -1)
  kPlainIntegers = 8u,       // BYTE, UNSIGNED_BYTE, SHORT and UNSIGNED_SHORT as they are
};
constexpr unsigned kAnyEncoding =
    kFloats | kUnsignedNormalized | kSignedNormalized | kPlainIntegers;

// The `components`-wide elements of accessor `index` as floats, one after another, decoded from
// any of the `encodings` (AccessorEncoding flags).
std::vector<float> readFloatAccessor(const tinygltf::Model& model, int index, int components,
                                     unsigned encodings, const std::string& where);

// The scalar unsigned integers (UNSIGNED_BYTE, _SHORT or _INT) of accessor `index`: indices.
std::vector<uint32_t> readIndexAccessor(const tinygltf::Model& model, int index,
                                        const std::string& where);

}  // namespace candela
