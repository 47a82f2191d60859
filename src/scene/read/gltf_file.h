// A glTF 2.0 file (.gltf with its buffers and images beside it, or one binary .glb) parsed by
// tinygltf, text or binary as its first bytes say: the model, the bytes of the images it holds
// (data URIs and buffer views) by image index, for candela's texture loader to decode, and its
// folder, against which its URIs resolve. Throws SceneError "<label>: <reason>" for a file that
// cannot be read or parsed, or that requires an extension candela does not read.
#pragma once

#include <map>
#include <memory>
#include <string>

#include "scene/read/tiny_gltf_config.h"

namespace candela {

struct GltfFile {
  tinygltf::Model model;
  std::map<int, std::string> embedded;  // image index -> its encoded bytes
  std::string folder;
};

std::unique_ptr<GltfFile> readGltfFile(const std::string& path, const std::string& label);

}  // namespace candela
