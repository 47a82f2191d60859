// Editing a glTF file's JSON; see gltf_json_edit.h.
#include "scene/read/gltf_json_edit.h"

#include <cstdint>
#include <cstring>

namespace candela {

namespace {

// A .glb: a 12-byte header, the JSON chunk (its length, "JSON", the text) and what follows.
bool isGlb(const std::string& file) { return file.size() >= 20 && file.compare(0, 4, "glTF") == 0; }

}  // namespace

std::string_view gltfJsonText(const std::string& file) {
  if (!isGlb(file)) return file;
  uint32_t length = 0;
  std::memcpy(&length, file.data() + 12, 4);
  if (file.compare(16, 4, "JSON") != 0 || length > file.size() - 20) return {};
  return std::string_view(file).substr(20, length);
}

void editGltfJson(std::string* file, const std::function<bool(nlohmann::json&, bool)>& edit) {
  const bool binary = isGlb(*file);
  const std::string_view text = gltfJsonText(*file);
  nlohmann::json doc = nlohmann::json::parse(text, nullptr, false);
  if (doc.is_discarded() || !doc.is_object() || !edit(doc, binary)) return;
  std::string json = doc.dump();
  if (!binary) {
    *file = std::move(json);
    return;
  }
  while (json.size() % 4) json += ' ';
  const size_t rest = 20 + text.size();  // where what follows the JSON chunk starts
  const uint32_t total = uint32_t(20 + json.size() + (file->size() - rest)),
                 length = uint32_t(json.size());
  std::string header = file->substr(0, 8);
  header.append(reinterpret_cast<const char*>(&total), 4);
  header.append(reinterpret_cast<const char*>(&length), 4);
  header += "JSON";
  file->replace(0, rest, header + json);
}

}  // namespace candela
