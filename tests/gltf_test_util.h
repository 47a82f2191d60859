// Writing small glTF files for tests: a document (nlohmann::json) and one binary buffer that
// accessors are appended to, saved as .gltf (the buffer as a data URI, or as a .bin beside it) or
// as one binary .glb.
#pragma once

#include <cstdint>
#include <cstring>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "scene/read/gltf_loader.h"
#include "scene/read/texture_reader.h"
#include "scene/scene_error.h"

namespace candela::test {

inline std::string base64(const std::string& bytes) {
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    uint32_t v = uint32_t(uint8_t(bytes[i])) << 16;
    if (i + 1 < bytes.size()) v |= uint32_t(uint8_t(bytes[i + 1])) << 8;
    if (i + 2 < bytes.size()) v |= uint32_t(uint8_t(bytes[i + 2]));
    out += digits[(v >> 18) & 63];
    out += digits[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? digits[(v >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? digits[v & 63] : '=';
  }
  return out;
}

struct GltfFile {
  nlohmann::json doc = {{"asset", {{"version", "2.0"}}}};
  std::string buffer;
  // Buffers after the first (`buffer`'s), written as they are (a meshopt fallback: no bytes).
  std::vector<nlohmann::json> moreBuffers;

  // Appends `values` as a buffer view and an accessor of `count` elements of `type`; returns the
  // accessor's index. `stride` 0: tightly packed.
  template <typename T>
  int addAccessor(const std::vector<T>& values, int componentType, const char* type, size_t count,
                  size_t stride = 0, bool normalized = false) {
    while (buffer.size() % 4) buffer += '\0';
    const size_t offset = buffer.size();
    buffer.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
    nlohmann::json view = {
        {"buffer", 0}, {"byteOffset", offset}, {"byteLength", values.size() * sizeof(T)}};
    if (stride) view["byteStride"] = stride;
    doc["bufferViews"].push_back(view);
    nlohmann::json accessor = {{"bufferView", doc["bufferViews"].size() - 1},
                               {"componentType", componentType},
                               {"count", count},
                               {"type", type}};
    if (normalized) accessor["normalized"] = true;
    doc["accessors"].push_back(accessor);
    return int(doc["accessors"].size() - 1);
  }
  int addFloats(const std::vector<float>& values, const char* type, size_t components) {
    return addAccessor(values, 5126, type, values.size() / components);
  }
  // An image of the file: its bytes in the buffer (a buffer view), as a .glb holds them.
  int addImage(const std::string& png) {
    while (buffer.size() % 4) buffer += '\0';
    doc["bufferViews"].push_back(
        {{"buffer", 0}, {"byteOffset", buffer.size()}, {"byteLength", png.size()}});
    buffer += png;
    doc["images"].push_back(
        {{"bufferView", doc["bufferViews"].size() - 1}, {"mimeType", "image/png"}});
    return int(doc["images"].size() - 1);
  }

  // The .gltf text, its buffer a data URI (or `binName`, to be written beside it).
  std::string gltf(const std::string& binName = "") const {
    nlohmann::json d = doc;
    d["buffers"] = {
        {{"byteLength", buffer.size()},
         {"uri",
          binName.empty() ? "data:application/octet-stream;base64," + base64(buffer) : binName}}};
    for (const nlohmann::json& more : moreBuffers) d["buffers"].push_back(more);
    return d.dump();
  }
  std::string glb() const {
    nlohmann::json d = doc;
    d["buffers"] = {{{"byteLength", buffer.size()}}};
    for (const nlohmann::json& more : moreBuffers) d["buffers"].push_back(more);
    std::string json = d.dump(), bin = buffer;
    while (json.size() % 4) json += ' ';
    while (bin.size() % 4) bin += '\0';
    std::string out = "glTF";
    const auto u32 = [&](uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
    u32(2);
    u32(uint32_t(12 + 8 + json.size() + 8 + bin.size()));
    u32(uint32_t(json.size()));
    out += "JSON";
    out += json;
    u32(uint32_t(bin.size()));
    out += std::string("BIN\0", 4);
    out += bin;
    return out;
  }
};

// A square (x, y in [-1, 1], z = 0, two triangles) whose morph target stretches it along x to
// twice its width; its one animation takes the target's weight from 0 to 1 over one second.
inline GltfFile stretchingSquare() {
  GltfFile f;
  const int p = f.addFloats({-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0}, "VEC3", 3);
  const int dp = f.addFloats({-1, 0, 0, 1, 0, 0, 1, 0, 0, -1, 0, 0}, "VEC3", 3);
  const int indices = f.addAccessor(std::vector<uint16_t>{0, 1, 2, 0, 2, 3}, 5123, "SCALAR", 6);
  const int times = f.addFloats({0, 1}, "SCALAR", 1), weights = f.addFloats({0, 1}, "SCALAR", 1);
  nlohmann::json primitive = {{"attributes", {{"POSITION", p}}}, {"indices", indices}};
  primitive["targets"] = nlohmann::json::array({{{"POSITION", dp}}});
  f.doc["meshes"] = {{{"primitives", nlohmann::json::array({primitive})}}};
  f.doc["nodes"] = {{{"mesh", 0}}};
  f.doc["animations"] = {
      {{"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "weights"}}}}}},
       {"samplers", {{{"input", times}, {"output", weights}}}}}};
  return f;
}

// The mesh of the glTF file at `path`, named `label` in messages (its textures not kept).
inline MeshDesc loadGltfMesh(const std::string& path, const std::string& label) {
  std::vector<std::shared_ptr<const TextureDesc>> textures;
  TextureLoader loader(textures, ".");
  return loadGltfFile(path, label, loader);
}

// The error loading it gives, or "(no error)".
inline std::string gltfLoadError(const std::string& path, const std::string& label) {
  try {
    loadGltfMesh(path, label);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace candela::test
