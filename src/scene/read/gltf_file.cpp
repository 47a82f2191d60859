// Parsing glTF files; see gltf_file.h.
#include "scene/read/gltf_file.h"

#include <cstdint>
#include <exception>
#include <filesystem>
#include <set>

#include "image/image_io.h"
#include "scene/read/gltf_draco.h"
#include "scene/read/gltf_json_edit.h"
#include "scene/read/gltf_meshopt.h"
#include "scene/read/text_file.h"
#include "scene/scene_error.h"

namespace candela {
namespace {

// The extensions a file may require that candela reads; it refuses a file requiring any other.
const std::set<std::string> kReadableRequired = {
    "KHR_texture_transform", "KHR_materials_emissive_strength",
    "KHR_materials_ior",     "KHR_materials_transmission",
    "KHR_materials_volume",  "KHR_materials_dispersion",
    "KHR_mesh_quantization", "EXT_mesh_gpu_instancing"};

// The extensions read through an optional library: the Debian package that has it, and whether
// this build does.
struct Decoder {
  const char* extension;
  const char* package;
  bool (*built)();
};
const Decoder kDecoders[] = {
    {"KHR_draco_mesh_compression", "libdraco-dev", gltfDracoDecoding},
    {"EXT_meshopt_compression", "libmeshoptimizer-dev", gltfMeshoptDecoding},
    {"EXT_texture_webp", "libwebp-dev", webpDecoding}};

// Throws SceneError naming the file's required extension `required` unless this build reads it.
void requireReadable(const std::string& required, const std::string& label) {
  const std::string at = label + ": extensionsRequired: the file requires " + required;
  for (const Decoder& d : kDecoders)
    if (required == d.extension) {
      if (d.built()) return;
      throw SceneError(at + ", and this build of candela reads no such files (built without " +
                       d.package + ")");
    }
  if (!kReadableRequired.count(required)) throw SceneError(at + ", which candela does not read");
}

// What tinygltf's image callback fills: the bytes of each image held in the file (a data URI or a
// buffer view), by image index, for the texture loader to decode (images named by URI are read
// from their files instead), and the model being read, against which a buffer view's bytes are
// checked: tinygltf hands them over without looking at the buffer's size.
struct ImageBytes {
  const tinygltf::Model* model = nullptr;
  std::map<int, std::string>* embedded = nullptr;
};

bool keepImageBytes(tinygltf::Image* image, const int index, std::string* error, std::string*, int,
                    int, const unsigned char* bytes, int size, void* user) {
  auto& images = *static_cast<ImageBytes*>(user);
  if (image->bufferView >= 0) {
    const tinygltf::Model& model = *images.model;
    const tinygltf::BufferView& view = model.bufferViews[size_t(image->bufferView)];
    const tinygltf::Buffer& buffer = model.buffers[size_t(view.buffer)];
    if (uint64_t(view.byteOffset) + uint64_t(view.byteLength) > buffer.data.size() ||
        view.byteLength > size_t(INT32_MAX)) {
      *error += "images[" + std::to_string(index) + "]: buffer view " +
                std::to_string(image->bufferView) + " ends past its buffer (" +
                std::to_string(buffer.data.size()) + " bytes)\n";
      return false;
    }
  }
  (*images.embedded)[index].assign(reinterpret_cast<const char*>(bytes), size_t(size));
  image->image.clear();
  return true;
}

std::string firstLine(const std::string& text) {
  std::string line = text.substr(0, text.find('\n'));
  while (!line.empty() && (line.back() == ' ' || line.back() == '\r')) line.pop_back();
  return line;
}

}  // namespace

std::unique_ptr<GltfFile> readGltfFile(const std::string& path, const std::string& label) {
  std::string bytes, reason;
  if (!readTextFile(path, &bytes, &reason))
    throw SceneError("cannot open \"" + label + "\" (" + reason + ")");
  leaveOutDracoIndices(&bytes);
  giveMeshoptPlaceholdersAByte(&bytes);
  auto file = std::make_unique<GltfFile>();
  file->folder = std::filesystem::path(path).parent_path().string();
  tinygltf::Model& model = file->model;
  ImageBytes images{&model, &file->embedded};
  std::string error, warning;
  bool parsed = false;
  try {
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(keepImageBytes, &images);
    const bool binary = bytes.size() >= 4 && bytes.compare(0, 4, "glTF") == 0;
    if (bytes.size() >= (size_t(1) << 31))
      throw SceneError(label + ": the file is larger than 2 GiB");
    parsed = binary
                 ? loader.LoadBinaryFromMemory(&model, &error, &warning,
                                               reinterpret_cast<const unsigned char*>(bytes.data()),
                                               unsigned(bytes.size()), file->folder)
                 : loader.LoadASCIIFromString(&model, &error, &warning, bytes.data(),
                                              unsigned(bytes.size()), file->folder);
  } catch (const SceneError&) {
    throw;
  } catch (const std::exception& e) {
    error = std::string("not a readable glTF file (") + e.what() + ")";
  }
  if (!parsed) {
    // A file that requires what this build cannot decode may be valid only to a decoder (Draco's
    // indices without a buffer view, meshopt's placeholder buffers): that is the better message.
    editGltfJson(&bytes, [&](nlohmann::json& doc, bool) {
      if (doc.contains("extensionsRequired") && doc["extensionsRequired"].is_array())
        for (const nlohmann::json& required : doc["extensionsRequired"])
          if (required.is_string()) requireReadable(required.get<std::string>(), label);
      return false;
    });
    throw SceneError(label + ": " +
                     (error.empty() ? std::string("not a readable glTF file") : firstLine(error)));
  }
  for (const std::string& required : model.extensionsRequired) requireReadable(required, label);
  decodeMeshoptViews(model, label);
  decodeDracoPrimitives(model, label);
  return file;
}

}  // namespace candela
