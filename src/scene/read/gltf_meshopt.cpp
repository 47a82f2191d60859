// Decoding meshopt-compressed glTF buffer views; see gltf_meshopt.h.
#include "scene/read/gltf_meshopt.h"

#include <cstdint>
#include <vector>

#ifdef CANDELA_HAS_MESHOPT
#include <meshoptimizer.h>
#endif

#include "scene/read/gltf_json_edit.h"
#include "scene/scene_error.h"

namespace candela {

#ifdef CANDELA_HAS_MESHOPT
namespace {

const char* kExtension = "EXT_meshopt_compression";

// A stream decodes to at most this many times its own size (meshopt's vertex codec, at best 2 bits
// per 16 bytes, stays below 64), so that a file cannot ask for any amount of memory.
constexpr uint64_t kMostExpansion = 256;

uint64_t integerOf(const tinygltf::Value& e, const char* key, int64_t fallback,
                   const std::string& where) {
  if (!e.Has(key)) {
    if (fallback < 0) throw SceneError(where + "." + key + ": expected a number, got none");
    return uint64_t(fallback);
  }
  const tinygltf::Value& v = e.Get(key);
  if (!v.IsNumber() || v.GetNumberAsDouble() < 0 || v.GetNumberAsDouble() > 9e15 ||
      v.GetNumberAsDouble() != double(int64_t(v.GetNumberAsDouble())))
    throw SceneError(where + "." + key + ": expected a whole number from 0");
  return uint64_t(v.GetNumberAsDouble());
}

std::string stringOf(const tinygltf::Value& e, const char* key, const char* fallback,
                     const std::string& where) {
  if (!e.Has(key)) {
    if (!fallback) throw SceneError(where + "." + key + ": expected a string, got none");
    return fallback;
  }
  if (!e.Get(key).IsString()) throw SceneError(where + "." + key + ": expected a string");
  return e.Get(key).Get<std::string>();
}

// View `view`'s stream (extension object `e`) decoded: a new buffer that the view reads whole.
void decodeView(tinygltf::Model& model, tinygltf::BufferView& view, const tinygltf::Value& e,
                const std::string& where) {
  if (!e.IsObject()) throw SceneError(where + ": expected an object");
  const uint64_t buffer = integerOf(e, "buffer", -1, where);
  const uint64_t offset = integerOf(e, "byteOffset", 0, where);
  const uint64_t length = integerOf(e, "byteLength", -1, where);
  const uint64_t stride = integerOf(e, "byteStride", -1, where);
  const uint64_t count = integerOf(e, "count", -1, where);
  const std::string mode = stringOf(e, "mode", nullptr, where);
  const std::string filter = stringOf(e, "filter", "NONE", where);
  if (buffer >= model.buffers.size())
    throw SceneError(where + ".buffer: buffer " + std::to_string(buffer) + " does not exist (" +
                     std::to_string(model.buffers.size()) + " buffers)");
  const std::vector<unsigned char>& source = model.buffers[size_t(buffer)].data;
  if (offset + length > source.size())
    throw SceneError(where + ": bytes " + std::to_string(offset) + " to " +
                     std::to_string(offset + length) + " lie past the end of buffer " +
                     std::to_string(buffer) + " (" + std::to_string(source.size()) + " bytes)");
  // What meshoptimizer's decoders assume of their arguments (they assert it).
  if (mode == "ATTRIBUTES") {
    if (stride == 0 || stride > 256 || stride % 4 != 0)
      throw SceneError(where +
                       ".byteStride: expected a multiple of 4 from 4 to 256 for "
                       "ATTRIBUTES, got " +
                       std::to_string(stride));
  } else if (mode == "TRIANGLES" || mode == "INDICES") {
    if (stride != 2 && stride != 4)
      throw SceneError(where + ".byteStride: expected 2 or 4 for " + mode + ", got " +
                       std::to_string(stride));
    if (mode == "TRIANGLES" && count % 3 != 0)
      throw SceneError(where + ".count: expected a multiple of 3 for TRIANGLES, got " +
                       std::to_string(count));
  } else {
    throw SceneError(where + ".mode: expected ATTRIBUTES, TRIANGLES or INDICES, got \"" + mode +
                     "\"");
  }
  const bool filtered = filter != "NONE";
  if (filtered && mode != "ATTRIBUTES")
    throw SceneError(where + ".filter: only ATTRIBUTES take a filter, got \"" + filter + "\"");
  if (filter == "OCTAHEDRAL" && stride != 4 && stride != 8)
    throw SceneError(where + ".byteStride: expected 4 or 8 for OCTAHEDRAL, got " +
                     std::to_string(stride));
  if (filter == "QUATERNION" && stride != 8)
    throw SceneError(where + ".byteStride: expected 8 for QUATERNION, got " +
                     std::to_string(stride));
  if (filtered && filter != "OCTAHEDRAL" && filter != "QUATERNION" && filter != "EXPONENTIAL")
    throw SceneError(where +
                     ".filter: expected NONE, OCTAHEDRAL, QUATERNION or EXPONENTIAL, "
                     "got \"" +
                     filter + "\"");
  const uint64_t size = count * stride;
  if (count > (uint64_t(1) << 32) || size > kMostExpansion * length + 65536)
    throw SceneError(where + ": " + std::to_string(count) + " elements of " +
                     std::to_string(stride) + " bytes cannot come from a stream of " +
                     std::to_string(length) + " bytes");
  std::vector<unsigned char> decoded(static_cast<size_t>(size));
  const unsigned char* stream = source.data() + offset;
  const int status =
      mode == "ATTRIBUTES"
          ? meshopt_decodeVertexBuffer(decoded.data(), count, stride, stream, length)
      : mode == "TRIANGLES"
          ? meshopt_decodeIndexBuffer(decoded.data(), count, stride, stream, length)
          : meshopt_decodeIndexSequence(decoded.data(), count, stride, stream, length);
  if (status != 0)
    throw SceneError(where + ": the " + mode + " stream does not decode (meshoptimizer's error " +
                     std::to_string(status) + ")");
  if (filter == "OCTAHEDRAL") meshopt_decodeFilterOct(decoded.data(), count, stride);
  if (filter == "QUATERNION") meshopt_decodeFilterQuat(decoded.data(), count, stride);
  if (filter == "EXPONENTIAL") meshopt_decodeFilterExp(decoded.data(), count, stride);
  tinygltf::Buffer plain;
  plain.data = std::move(decoded);
  view.buffer = int(model.buffers.size());
  view.byteOffset = 0;
  view.byteLength = plain.data.size();
  model.buffers.push_back(std::move(plain));
}

}  // namespace

bool gltfMeshoptDecoding() { return true; }

void giveMeshoptPlaceholdersAByte(std::string* file) {
  if (gltfJsonText(*file).find(kExtension) == std::string_view::npos) return;
  editGltfJson(file, [](nlohmann::json& doc, bool binary) {
    if (!doc.contains("buffers") || !doc["buffers"].is_array()) return false;
    // The placeholders: buffers without a URI (but a .glb's first, its binary chunk) that only
    // compressed views read, tagged "fallback" or not (the extension allows both).
    std::vector<bool> readPlainly(doc["buffers"].size(), false);
    if (doc.contains("bufferViews") && doc["bufferViews"].is_array())
      for (const nlohmann::json& view : doc["bufferViews"]) {
        if (!view.is_object() || !view.contains("buffer") || !view["buffer"].is_number_unsigned())
          continue;
        const size_t b = view["buffer"].get<size_t>();
        const bool compressed = view.contains("extensions") && view["extensions"].is_object() &&
                                view["extensions"].contains(kExtension);
        if (b < readPlainly.size() && !compressed) readPlainly[b] = true;
      }
    bool changed = false;
    for (size_t i = 0; i < doc["buffers"].size(); ++i) {
      nlohmann::json& b = doc["buffers"][i];
      if (!b.is_object() || b.contains("uri") || readPlainly[i] || (binary && i == 0)) continue;
      b["uri"] = "data:application/octet-stream;base64,AA==";  // one byte: tinygltf takes no
      b["byteLength"] = 1;                                     // empty data URI
      changed = true;
    }
    return changed;
  });
}

void decodeMeshoptViews(tinygltf::Model& model, const std::string& label) {
  for (size_t i = 0; i < model.bufferViews.size(); ++i) {
    const auto e = model.bufferViews[i].extensions.find(kExtension);
    if (e == model.bufferViews[i].extensions.end()) continue;
    decodeView(model, model.bufferViews[i], e->second,
               label + ": bufferViews[" + std::to_string(i) + "].extensions." + kExtension);
  }
}

#else  // without meshoptimizer

bool gltfMeshoptDecoding() { return false; }

void giveMeshoptPlaceholdersAByte(std::string*) {}

void decodeMeshoptViews(tinygltf::Model&, const std::string&) {}

#endif

}  // namespace candela
