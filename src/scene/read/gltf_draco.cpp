// Decoding Draco-compressed glTF primitives; see gltf_draco.h.
#include "scene/read/gltf_draco.h"

#include <cstdint>
#include <cstring>
#include <memory>
#include <vector>

#ifdef CANDELA_HAS_DRACO
#include <draco/compression/decode.h>
#endif

#include "scene/read/gltf_json_edit.h"
#include "scene/scene_error.h"

namespace candela {

#ifdef CANDELA_HAS_DRACO
namespace {

int componentsOf(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR:
      return 1;
    case TINYGLTF_TYPE_VEC2:
      return 2;
    case TINYGLTF_TYPE_VEC3:
      return 3;
    case TINYGLTF_TYPE_VEC4:
      return 4;
    default:
      return 0;
  }
}

// `bytes` as a new buffer of the model, read whole by a new buffer view; its index.
int appendView(tinygltf::Model& model, std::vector<unsigned char> bytes) {
  tinygltf::Buffer buffer;
  buffer.data = std::move(bytes);
  tinygltf::BufferView view;
  view.buffer = int(model.buffers.size());
  view.byteOffset = 0;
  view.byteLength = buffer.data.size();
  model.buffers.push_back(std::move(buffer));
  model.bufferViews.push_back(view);
  return int(model.bufferViews.size() - 1);
}

// Accessor `index` of the model, refused unless it exists.
tinygltf::Accessor& accessorAt(tinygltf::Model& model, int index, const std::string& where) {
  if (index < 0 || size_t(index) >= model.accessors.size())
    throw SceneError(where + ": accessor " + std::to_string(index) + " does not exist (" +
                     std::to_string(model.accessors.size()) + " accessors)");
  return model.accessors[size_t(index)];
}

// The Draco stream of buffer view `index`, decoded; refused unless the view lies in its buffer.
std::unique_ptr<draco::Mesh> decodeStream(const tinygltf::Model& model, int index,
                                          const std::string& where) {
  if (index < 0 || size_t(index) >= model.bufferViews.size())
    throw SceneError(where + ".bufferView: buffer view " + std::to_string(index) +
                     " does not exist (" + std::to_string(model.bufferViews.size()) +
                     " buffer views)");
  const tinygltf::BufferView& view = model.bufferViews[size_t(index)];
  if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size() ||
      uint64_t(view.byteOffset) + uint64_t(view.byteLength) >
          model.buffers[size_t(view.buffer)].data.size())
    throw SceneError(where + ".bufferView: buffer view " + std::to_string(index) +
                     " lies outside its buffer");
  draco::DecoderBuffer stream;
  stream.Init(reinterpret_cast<const char*>(model.buffers[size_t(view.buffer)].data.data() +
                                            view.byteOffset),
              view.byteLength);
  draco::Decoder decoder;
  auto decoded = decoder.DecodeMeshFromBuffer(&stream);
  if (!decoded.ok())
    throw SceneError(where + ": Draco cannot decode buffer view " + std::to_string(index) + " (" +
                     decoded.status().error_msg_string() + ")");
  return std::move(decoded).value();
}

// The primitive `p`'s compressed geometry (extension object `e`) decoded into new buffers, its
// accessors pointed at them.
void decodePrimitive(tinygltf::Model& model, tinygltf::Primitive& p, const tinygltf::Value& e,
                     const std::string& where) {
  const tinygltf::Value& viewValue = e.Get("bufferView");
  const tinygltf::Value& attributes = e.Get("attributes");
  if (!viewValue.IsInt() || !attributes.IsObject())
    throw SceneError(where + ": expected a bufferView and attributes");
  if (p.mode != TINYGLTF_MODE_TRIANGLES && p.mode != TINYGLTF_MODE_TRIANGLE_STRIP)
    throw SceneError(where + ": a compressed primitive holds triangles (mode 4 or 5), not mode " +
                     std::to_string(p.mode));
  const std::unique_ptr<draco::Mesh> mesh = decodeStream(model, viewValue.GetNumberAsInt(), where);
  const uint32_t points = mesh->num_points();
  for (const std::string& name : attributes.Keys()) {
    const std::string at = where + ".attributes." + name;
    const tinygltf::Value& id = attributes.Get(name);
    const auto named = p.attributes.find(name);
    if (named == p.attributes.end())
      throw SceneError(at + ": the primitive has no attribute " + name);
    if (!id.IsInt() || id.GetNumberAsInt() < 0)
      throw SceneError(at + ": expected a Draco attribute id (an integer from 0)");
    const draco::PointAttribute* source =
        mesh->GetAttributeByUniqueId(uint32_t(id.GetNumberAsInt()));
    if (!source)
      throw SceneError(at + ": the Draco stream has no attribute " +
                       std::to_string(id.GetNumberAsInt()));
    tinygltf::Accessor& accessor = accessorAt(model, named->second, at);
    const int n = componentsOf(accessor.type);
    if (n == 0 || source->num_components() != n)
      throw SceneError(at + ": the Draco attribute has " +
                       std::to_string(int(source->num_components())) +
                       " components, its accessor " + std::to_string(n));
    std::vector<unsigned char> bytes(size_t(points) * size_t(n) * sizeof(float));
    float value[4];
    for (uint32_t i = 0; i < points; ++i) {
      if (!source->ConvertValue<float>(source->mapped_index(draco::PointIndex(i)), int8_t(n),
                                       value))
        throw SceneError(at + ": Draco cannot read its values as numbers");
      std::memcpy(&bytes[size_t(i) * size_t(n) * sizeof(float)], value, size_t(n) * sizeof(float));
    }
    accessor.bufferView = appendView(model, std::move(bytes));
    accessor.byteOffset = 0;
    accessor.count = points;
    accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    accessor.normalized = false;
    accessor.sparse.isSparse = false;
  }
  // Draco's faces are a triangle list, whatever the primitive's mode said.
  std::vector<unsigned char> bytes(size_t(mesh->num_faces()) * 3 * sizeof(uint32_t));
  for (uint32_t f = 0; f < mesh->num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      const uint32_t index = mesh->face(draco::FaceIndex(f))[k].value();
      std::memcpy(&bytes[(size_t(f) * 3 + size_t(k)) * sizeof(uint32_t)], &index, sizeof index);
    }
  if (p.indices < 0) {
    tinygltf::Accessor indices;
    indices.type = TINYGLTF_TYPE_SCALAR;
    model.accessors.push_back(indices);
    p.indices = int(model.accessors.size() - 1);
  }
  tinygltf::Accessor& indices = accessorAt(model, p.indices, where + " indices");
  indices.count = size_t(mesh->num_faces()) * 3;
  indices.bufferView = appendView(model, std::move(bytes));
  indices.byteOffset = 0;
  indices.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
  indices.type = TINYGLTF_TYPE_SCALAR;
  indices.sparse.isSparse = false;
  p.mode = TINYGLTF_MODE_TRIANGLES;
}

}  // namespace

bool gltfDracoDecoding() { return true; }

void leaveOutDracoIndices(std::string* file) {
  if (gltfJsonText(*file).find("KHR_draco_mesh_compression") == std::string_view::npos) return;
  editGltfJson(file, [](nlohmann::json& doc, bool) {
    bool changed = false;
    if (!doc.contains("meshes") || !doc["meshes"].is_array()) return false;
    for (nlohmann::json& mesh : doc["meshes"]) {
      if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array())
        continue;
      for (nlohmann::json& p : mesh["primitives"])
        if (p.is_object() && p.contains("extensions") && p["extensions"].is_object() &&
            p["extensions"].contains("KHR_draco_mesh_compression") && p.contains("indices")) {
          p.erase("indices");
          changed = true;
        }
    }
    return changed;
  });
}

void decodeDracoPrimitives(tinygltf::Model& model, const std::string& label) {
  const char* extension = "KHR_draco_mesh_compression";
  for (size_t m = 0; m < model.meshes.size(); ++m)
    for (size_t i = 0; i < model.meshes[m].primitives.size(); ++i) {
      tinygltf::Primitive& p = model.meshes[m].primitives[i];
      const auto e = p.extensions.find(extension);
      if (e == p.extensions.end()) continue;
      decodePrimitive(model, p, e->second,
                      label + ": meshes[" + std::to_string(m) + "].primitives[" +
                          std::to_string(i) + "].extensions." + extension);
    }
}

#else  // without Draco a file that requires it is refused (gltf_file.cpp); one that only uses it
       // carries the geometry uncompressed as well, which is read

bool gltfDracoDecoding() { return false; }

void leaveOutDracoIndices(std::string*) {}

void decodeDracoPrimitives(tinygltf::Model&, const std::string&) {}

#endif

}  // namespace candela
