// Editing a glTF file's JSON; see gltf_json_edit.h.
#include "scene/read/gltf_json_edit.h"

#include <cstdint>
#include <cstring>

namespace candela {

std::string editGltfJson(const std::string& file,
                         const std::function<bool(nlohmann::json&, bool)>& edit) {
  // A .glb: a 12-byte header, the JSON chunk (its length, "JSON", the text) and what follows.
  const bool binary = file.size() >= 20 && file.compare(0, 4, "glTF") == 0;
  uint32_t jsonLength = 0;
  if (binary) std::memcpy(&jsonLength, file.data() + 12, 4);
  if (binary && (file.compare(16, 4, "JSON") != 0 || jsonLength > file.size() - 20)) return file;
  nlohmann::json doc =
      nlohmann::json::parse(binary ? file.substr(20, jsonLength) : file, nullptr, false);
  if (doc.is_discarded() || !doc.is_object() || !edit(doc, binary)) return file;
  std::string json = doc.dump();
  if (!binary) return json;
  while (json.size() % 4) json += ' ';
  const std::string rest = file.substr(20 + size_t(jsonLength));
  const uint32_t total = uint32_t(20 + json.size() + rest.size()), length = uint32_t(json.size());
  std::string out = file.substr(0, 8);
  out.append(reinterpret_cast<const char*>(&total), 4);
  out.append(reinterpret_cast<const char*>(&length), 4);
  out += "JSON";
  out += json;
  out += rest;
  return out;
}

}  // namespace candela
