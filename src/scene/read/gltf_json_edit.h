// Editing a glTF file's JSON before tinygltf parses it, for what tinygltf refuses that glTF's
// compression extensions allow (gltf_draco.h, gltf_meshopt.h): the JSON of a .gltf's text or of a
// .glb's first chunk handed to `edit`, and the file rebuilt around it where `edit` changed it.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <string>

namespace candela {

// `file` (a .gltf's text or a .glb's bytes) with its JSON as `edit(json, binary)` leaves it when
// `edit` returns true; `file` itself when it returns false, or where the JSON cannot be read (the
// parser then says what is wrong). `binary`: the file is a .glb.
std::string editGltfJson(const std::string& file,
                         const std::function<bool(nlohmann::json&, bool)>& edit);

}  // namespace candela
