// Editing a glTF file's JSON before tinygltf parses it, for what tinygltf refuses that glTF's
// compression extensions allow (gltf_draco.h, gltf_meshopt.h): the JSON of a .gltf's text or of a
// .glb's first chunk handed to `edit`, and the file rebuilt around it where `edit` changed it.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace candela {

// The JSON text of `file` (a .gltf's text or a .glb's bytes): the whole text, or a .glb's first
// chunk (empty where the .glb's header or chunk is malformed; the parser then says what is wrong).
std::string_view gltfJsonText(const std::string& file);

// Gives *file (a .gltf's text or a .glb's bytes) its JSON as `edit(json, binary)` leaves it where
// `edit` returns true; leaves it as it is where `edit` returns false or the JSON cannot be read.
// `binary`: the file is a .glb.
void editGltfJson(std::string* file, const std::function<bool(nlohmann::json&, bool)>& edit);

}  // namespace candela
