// Reading glTF accessors; see gltf_accessor.h.
#include "scene/read/gltf_accessor.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "scene/scene_error.h"

namespace candela {
namespace {

const char* typeName(int components) {
  switch (components) {
    case 1:
      return "SCALAR";
    case 2:
      return "VEC2";
    case 3:
      return "VEC3";
    default:
      return "VEC4";
  }
}

// The bytes of an accessor's elements: where the first starts, the distance between them and
// each one's size, once they are known to lie within the buffer.
struct ElementBytes {
  const uint8_t* first = nullptr;
  size_t stride = 0;
  size_t count = 0;
};

const tinygltf::Accessor& accessorAt(const tinygltf::Model& model, int index,
                                     const std::string& where) {
  if (index < 0 || size_t(index) >= model.accessors.size())
    throw SceneError(where + ": accessor " + std::to_string(index) + " does not exist (" +
                     std::to_string(model.accessors.size()) + " accessors)");
  return model.accessors[size_t(index)];
}

ElementBytes elementBytes(const tinygltf::Model& model, int index, int components,
                          size_t componentSize, const std::string& where) {
  const std::string what = where + ": accessor " + std::to_string(index);
  const tinygltf::Accessor& a = accessorAt(model, index, where);
  if (a.sparse.isSparse) throw SceneError(what + " is sparse; candela reads only plain accessors");
  if (a.bufferView < 0 || size_t(a.bufferView) >= model.bufferViews.size())
    throw SceneError(what + " has no buffer view (bufferView " + std::to_string(a.bufferView) +
                     ")");
  const tinygltf::BufferView& view = model.bufferViews[size_t(a.bufferView)];
  if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size())
    throw SceneError(what + ": buffer view " + std::to_string(a.bufferView) + " names buffer " +
                     std::to_string(view.buffer) + ", which does not exist");
  const tinygltf::Buffer& buffer = model.buffers[size_t(view.buffer)];
  const size_t elementSize = componentSize * size_t(components);
  const size_t stride = view.byteStride > 0 ? size_t(view.byteStride) : elementSize;
  if (stride < elementSize)
    throw SceneError(what + ": byteStride " + std::to_string(view.byteStride) +
                     " is smaller than an element (" + std::to_string(elementSize) + " bytes)");
  ElementBytes bytes;
  bytes.count = a.count;
  bytes.stride = stride;
  // Every bound in 64 bits: offsets and counts come from the file.
  const uint64_t viewEnd = uint64_t(view.byteOffset) + uint64_t(view.byteLength);
  if (viewEnd > buffer.data.size())
    throw SceneError(what + ": buffer view " + std::to_string(a.bufferView) + " ends at byte " +
                     std::to_string(viewEnd) + " of buffer " + std::to_string(view.buffer) +
                     ", which holds " + std::to_string(buffer.data.size()));
  if (a.count == 0) return bytes;
  const uint64_t needed =
      uint64_t(a.byteOffset) + uint64_t(stride) * (uint64_t(a.count) - 1) + uint64_t(elementSize);
  if (a.count > (uint64_t(1) << 32) || needed > uint64_t(view.byteLength))
    throw SceneError(
        what + ": " + std::to_string(a.count) + " elements of " + std::to_string(elementSize) +
        " bytes from byte " + std::to_string(a.byteOffset) + " do not fit buffer view " +
        std::to_string(a.bufferView) + " (" + std::to_string(view.byteLength) + " bytes)");
  bytes.first = buffer.data.data() + view.byteOffset + a.byteOffset;
  return bytes;
}

void requireType(const tinygltf::Accessor& a, int index, int components, const std::string& where) {
  const int expected = components == 1   ? TINYGLTF_TYPE_SCALAR
                       : components == 2 ? TINYGLTF_TYPE_VEC2
                       : components == 3 ? TINYGLTF_TYPE_VEC3
                                         : TINYGLTF_TYPE_VEC4;
  if (a.type != expected)
    throw SceneError(where + ": accessor " + std::to_string(index) + " is not of type " +
                     typeName(components));
}

// glTF's name of a component type, as its tables write them ("normalized SHORT").
std::string componentTypeName(int type, bool normalized) {
  const char* name = type == TINYGLTF_COMPONENT_TYPE_BYTE             ? "BYTE"
                     : type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE  ? "UNSIGNED_BYTE"
                     : type == TINYGLTF_COMPONENT_TYPE_SHORT          ? "SHORT"
                     : type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? "UNSIGNED_SHORT"
                     : type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT   ? "UNSIGNED_INT"
                     : type == TINYGLTF_COMPONENT_TYPE_FLOAT          ? "FLOAT"
                                                                      : nullptr;
  if (!name) return "componentType " + std::to_string(type);
  return std::string(normalized && type != TINYGLTF_COMPONENT_TYPE_FLOAT ? "normalized " : "") +
         name;
}

// What `encodings` allow, in glTF's words.
std::string encodingNames(unsigned encodings) {
  if (encodings & kPlainIntegers)
    return "FLOAT, or BYTE, UNSIGNED_BYTE, SHORT or UNSIGNED_SHORT, normalized or not";
  const bool hasSigned = encodings & kSignedNormalized,
             hasUnsigned = encodings & kUnsignedNormalized;
  return std::string("FLOAT") + (!hasSigned && !hasUnsigned ? ""
                                 : !hasSigned   ? " or normalized UNSIGNED_BYTE or UNSIGNED_SHORT"
                                 : !hasUnsigned ? " or normalized BYTE or SHORT"
                                                : " or normalized BYTE, UNSIGNED_BYTE, SHORT or "
                                                  "UNSIGNED_SHORT");
}

// One integer component as glTF reads it: as it is, or normalized (unsigned into [0, 1]; signed
// into [-1, 1], the most negative value held at -1).
float decodeInteger(const uint8_t* bytes, int type, bool normalized) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      const float c = float(int8_t(bytes[0]));
      return normalized ? std::max(c / 127.0f, -1.0f) : c;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return normalized ? float(bytes[0]) / 255.0f : float(bytes[0]);
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      int16_t v = 0;
      std::memcpy(&v, bytes, 2);
      return normalized ? std::max(float(v) / 32767.0f, -1.0f) : float(v);
    }
    default: {
      uint16_t v = 0;
      std::memcpy(&v, bytes, 2);
      return normalized ? float(v) / 65535.0f : float(v);
    }
  }
}

}  // namespace

std::vector<float> readFloatAccessor(const tinygltf::Model& model, int index, int components,
                                     unsigned encodings, const std::string& where) {
  const tinygltf::Accessor& a = accessorAt(model, index, where);
  requireType(a, index, components, where);
  const int type = a.componentType;
  const bool isFloat = type == TINYGLTF_COMPONENT_TYPE_FLOAT;
  const bool isSigned =
      type == TINYGLTF_COMPONENT_TYPE_BYTE || type == TINYGLTF_COMPONENT_TYPE_SHORT;
  const bool isUnsigned = type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                          type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
  const unsigned encoding = isFloat                    ? kFloats
                            : !isSigned && !isUnsigned ? 0u
                            : !a.normalized            ? kPlainIntegers
                            : isSigned                 ? kSignedNormalized
                                                       : kUnsignedNormalized;
  if (!(encoding & encodings))
    throw SceneError(where + ": accessor " + std::to_string(index) + " holds " +
                     componentTypeName(type, a.normalized) + "; expected " +
                     encodingNames(encodings));
  const size_t size =
      isFloat                                                                                 ? 4
      : type == TINYGLTF_COMPONENT_TYPE_BYTE || type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ? 1
                                                                                              : 2;
  const ElementBytes bytes = elementBytes(model, index, components, size, where);
  std::vector<float> values(bytes.count * size_t(components));
  for (size_t i = 0; i < bytes.count; ++i) {
    const uint8_t* element = bytes.first + i * bytes.stride;
    for (int c = 0; c < components; ++c) {
      const uint8_t* component = element + size * size_t(c);
      float value = 0.0f;
      if (isFloat) {
        std::memcpy(&value, component, 4);
        if (!std::isfinite(value))
          throw SceneError(where + ": accessor " + std::to_string(index) + ", element " +
                           std::to_string(i) + ": expected finite numbers, got " +
                           std::to_string(value));
      } else {
        value = decodeInteger(component, type, a.normalized);
      }
      values[i * size_t(components) + size_t(c)] = value;
    }
  }
  return values;
}

std::vector<uint32_t> readIndexAccessor(const tinygltf::Model& model, int index,
                                        const std::string& where) {
  const tinygltf::Accessor& a = accessorAt(model, index, where);
  requireType(a, index, 1, where);
  size_t size = 0;
  switch (a.componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      size = 1;
      break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      size = 2;
      break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      size = 4;
      break;
    default:
      throw SceneError(where + ": accessor " + std::to_string(index) +
                       ": expected indices of unsigned bytes, shorts or ints (componentType " +
                       std::to_string(a.componentType) + ")");
  }
  const ElementBytes bytes = elementBytes(model, index, 1, size, where);
  std::vector<uint32_t> indices(bytes.count);
  for (size_t i = 0; i < bytes.count; ++i) {
    const uint8_t* element = bytes.first + i * bytes.stride;
    if (size == 1) {
      indices[i] = element[0];
    } else if (size == 2) {
      uint16_t v = 0;
      std::memcpy(&v, element, 2);
      indices[i] = v;
    } else {
      std::memcpy(&indices[i], element, 4);
    }
  }
  return indices;
}

}  // namespace candela
