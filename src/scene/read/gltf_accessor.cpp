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
    case 16:
      return "MAT4";
    default:
      return "VEC4";
  }
}

// Where elements lie in a buffer: the first one's bytes and the distance between them, once they
// are known to lie within it.
struct ElementBytes {
  const uint8_t* first = nullptr;
  size_t stride = 0;
};

// Accessors without a buffer view are zeros (glTF); so that a file cannot ask for any amount of
// them, their count is bounded.
constexpr uint64_t kMaxZeroElements = uint64_t(1) << 24;

const tinygltf::Accessor& accessorAt(const tinygltf::Model& model, int index,
                                     const std::string& where) {
  if (index < 0 || size_t(index) >= model.accessors.size())
    throw SceneError(where + ": accessor " + std::to_string(index) + " does not exist (" +
                     std::to_string(model.accessors.size()) + " accessors)");
  return model.accessors[size_t(index)];
}

// The bytes of `count` elements of `elementSize` from `byteOffset` in buffer view `viewIndex`,
// the view's byteStride apart where `strided` (else packed, as a sparse accessor's parts are).
// `what` names the reader in errors ("...: accessor 3", "...: accessor 3: sparse.values").
ElementBytes viewBytes(const tinygltf::Model& model, int viewIndex, int64_t byteOffset,
                       uint64_t count, size_t elementSize, bool strided, const std::string& what) {
  if (viewIndex < 0 || size_t(viewIndex) >= model.bufferViews.size())
    throw SceneError(what + ": buffer view " + std::to_string(viewIndex) + " does not exist (" +
                     std::to_string(model.bufferViews.size()) + " buffer views)");
  const tinygltf::BufferView& view = model.bufferViews[size_t(viewIndex)];
  if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size())
    throw SceneError(what + ": buffer view " + std::to_string(viewIndex) + " names buffer " +
                     std::to_string(view.buffer) + ", which does not exist");
  const tinygltf::Buffer& buffer = model.buffers[size_t(view.buffer)];
  const size_t stride = strided && view.byteStride > 0 ? size_t(view.byteStride) : elementSize;
  if (stride < elementSize)
    throw SceneError(what + ": byteStride " + std::to_string(view.byteStride) +
                     " is smaller than an element (" + std::to_string(elementSize) + " bytes)");
  // Every bound in 64 bits: offsets and counts come from the file.
  const uint64_t viewEnd = uint64_t(view.byteOffset) + uint64_t(view.byteLength);
  if (viewEnd > buffer.data.size())
    throw SceneError(what + ": buffer view " + std::to_string(viewIndex) + " ends at byte " +
                     std::to_string(viewEnd) + " of buffer " + std::to_string(view.buffer) +
                     ", which holds " + std::to_string(buffer.data.size()));
  if (byteOffset < 0)
    throw SceneError(what + ": byteOffset " + std::to_string(byteOffset) + " is negative");
  ElementBytes bytes;
  bytes.stride = stride;
  if (count == 0) return bytes;
  const uint64_t needed =
      uint64_t(byteOffset) + uint64_t(stride) * (count - 1) + uint64_t(elementSize);
  if (count > (uint64_t(1) << 32) || needed > uint64_t(view.byteLength))
    throw SceneError(
        what + ": " + std::to_string(count) + " elements of " + std::to_string(elementSize) +
        " bytes from byte " + std::to_string(byteOffset) + " do not fit buffer view " +
        std::to_string(viewIndex) + " (" + std::to_string(view.byteLength) + " bytes)");
  bytes.first = buffer.data.data() + view.byteOffset + uint64_t(byteOffset);
  return bytes;
}

// The bytes of an index's component type (UNSIGNED_BYTE, _SHORT or _INT), 0 for any other.
size_t unsignedSize(int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return 1;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      return 4;
    default:
      return 0;
  }
}

// An unsigned integer of `size` (1, 2 or 4) bytes, little-endian as glTF stores it.
uint32_t readUnsigned(const uint8_t* bytes, size_t size) {
  if (size == 1) return bytes[0];
  if (size == 2) {
    uint16_t v = 0;
    std::memcpy(&v, bytes, 2);
    return v;
  }
  uint32_t v = 0;
  std::memcpy(&v, bytes, 4);
  return v;
}

// The elements of accessor `index` (`a`), each of `components` values of `componentSize` bytes,
// decoded by `decode(bytes, out, element)` into `components` Ts: from its buffer view (zeros
// without one), then its sparse substitutions, whose indices must rise and stay below its count.
template <typename T, typename Decode>
std::vector<T> readElements(const tinygltf::Model& model, const tinygltf::Accessor& a, int index,
                            int components, size_t componentSize, const Decode& decode,
                            const std::string& where) {
  const std::string what = where + ": accessor " + std::to_string(index);
  const size_t n = size_t(components), elementSize = componentSize * n;
  if (a.bufferView < 0 && a.count > kMaxZeroElements)
    throw SceneError(what + " has no buffer view and " + std::to_string(a.count) +
                     " elements; candela fills at most " + std::to_string(kMaxZeroElements) +
                     " with zeros");
  std::vector<T> values;
  if (a.bufferView >= 0) {
    const ElementBytes bytes =
        viewBytes(model, a.bufferView, int64_t(a.byteOffset), a.count, elementSize, true, what);
    values.resize(a.count * n);
    for (size_t i = 0; i < a.count; ++i) decode(bytes.first + i * bytes.stride, &values[i * n], i);
  } else {
    values.assign(a.count * n, T(0));
  }
  if (!a.sparse.isSparse) return values;
  const std::string sparse = what + ": sparse";
  const auto& s = a.sparse;
  if (s.count < 1 || uint64_t(s.count) > a.count)
    throw SceneError(sparse + ".count: expected from 1 to the accessor's count (" +
                     std::to_string(a.count) + "), got " + std::to_string(s.count));
  const int indexType = s.indices.componentType;
  const size_t indexSize = unsignedSize(indexType);
  if (indexSize == 0)
    throw SceneError(sparse + ".indices.componentType: expected UNSIGNED_BYTE, UNSIGNED_SHORT " +
                     "or UNSIGNED_INT, got " + std::to_string(indexType));
  const ElementBytes indices = viewBytes(model, s.indices.bufferView, s.indices.byteOffset,
                                         uint64_t(s.count), indexSize, false, sparse + ".indices");
  const ElementBytes substitutes =
      viewBytes(model, s.values.bufferView, s.values.byteOffset, uint64_t(s.count), elementSize,
                false, sparse + ".values");
  uint64_t previous = 0;
  for (size_t k = 0; k < size_t(s.count); ++k) {
    const uint32_t i = readUnsigned(indices.first + k * indexSize, indexSize);
    if (i >= a.count || (k > 0 && i <= previous))
      throw SceneError(sparse + ".indices: index " + std::to_string(k) + " is " +
                       std::to_string(i) + "; expected indices that rise, below " +
                       std::to_string(a.count));
    previous = i;
    decode(substitutes.first + k * elementSize, &values[size_t(i) * n], size_t(i));
  }
  return values;
}

void requireType(const tinygltf::Accessor& a, int index, int components, const std::string& where) {
  const int expected = components == 1    ? TINYGLTF_TYPE_SCALAR
                       : components == 2  ? TINYGLTF_TYPE_VEC2
                       : components == 3  ? TINYGLTF_TYPE_VEC3
                       : components == 16 ? TINYGLTF_TYPE_MAT4
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
  const auto decode = [&](const uint8_t* element, float* out, size_t i) {
    for (int c = 0; c < components; ++c) {
      const uint8_t* component = element + size * size_t(c);
      if (!isFloat) {
        out[c] = decodeInteger(component, type, a.normalized);
        continue;
      }
      std::memcpy(&out[c], component, 4);
      if (!std::isfinite(out[c]))
        throw SceneError(where + ": accessor " + std::to_string(index) + ", element " +
                         std::to_string(i) + ": expected finite numbers, got " +
                         std::to_string(out[c]));
    }
  };
  return readElements<float>(model, a, index, components, size, decode, where);
}

std::vector<uint32_t> readIndexAccessor(const tinygltf::Model& model, int index,
                                        const std::string& where) {
  const tinygltf::Accessor& a = accessorAt(model, index, where);
  requireType(a, index, 1, where);
  const size_t size = unsignedSize(a.componentType);
  if (size == 0)
    throw SceneError(where + ": accessor " + std::to_string(index) +
                     ": expected indices of unsigned bytes, shorts or ints (componentType " +
                     std::to_string(a.componentType) + ")");
  const auto decode = [&](const uint8_t* element, uint32_t* out, size_t) {
    *out = readUnsigned(element, size);
  };
  return readElements<uint32_t>(model, a, index, 1, size, decode, where);
}

}  // namespace candela
