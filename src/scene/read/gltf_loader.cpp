// glTF loading through tinygltf, every index and bound checked here; see gltf_loader.h.
#include "scene/read/gltf_loader.h"

#include <array>
#include <cmath>
#include <exception>
#include <filesystem>
#include <map>
#include <set>
#include <vector>

#include "scene/read/gltf_accessor.h"
#include "scene/read/gltf_materials.h"
#include "scene/read/gltf_uri.h"
#include "scene/read/text_file.h"
#include "scene/scene_error.h"

namespace candela {
namespace {

// The extensions a file may require that candela reads; it refuses a file requiring any other.
const std::set<std::string> kReadableRequired = {
    "KHR_texture_transform", "KHR_materials_emissive_strength",
    "KHR_materials_ior",     "KHR_materials_transmission",
    "KHR_materials_volume",  "KHR_materials_dispersion"};

using Matrix = std::array<double, 16>;  // column-major, as glTF writes it

Matrix identity() { return {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}; }

Matrix multiply(const Matrix& a, const Matrix& b) {
  Matrix m{};
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      for (int k = 0; k < 4; ++k) m[4 * c + r] += a[4 * k + r] * b[4 * c + k];
  return m;
}

// A node's own transform: its matrix, or translation * rotation * scale.
Matrix localTransform(const tinygltf::Node& node, const std::string& where) {
  auto finite = [&](const std::vector<double>& values, size_t count, const char* key) {
    if (!values.empty() && values.size() != count)
      throw SceneError(where + "." + key + ": expected " + std::to_string(count) + " numbers");
    for (double v : values)
      if (!std::isfinite(v)) throw SceneError(where + "." + key + ": expected finite numbers");
  };
  finite(node.matrix, 16, "matrix");
  finite(node.translation, 3, "translation");
  finite(node.rotation, 4, "rotation");
  finite(node.scale, 3, "scale");
  if (node.matrix.size() == 16) {
    Matrix m;
    std::copy(node.matrix.begin(), node.matrix.end(), m.begin());
    return m;
  }
  Matrix m = identity();
  if (node.rotation.size() == 4) {
    double x = node.rotation[0], y = node.rotation[1], z = node.rotation[2], w = node.rotation[3];
    const double n = std::sqrt(x * x + y * y + z * z + w * w);
    if (!(n > 0)) throw SceneError(where + ".rotation: expected a unit quaternion, got 0");
    x /= n, y /= n, z /= n, w /= n;
    m = {1 - 2 * (y * y + z * z),
         2 * (x * y + z * w),
         2 * (x * z - y * w),
         0,
         2 * (x * y - z * w),
         1 - 2 * (x * x + z * z),
         2 * (y * z + x * w),
         0,
         2 * (x * z + y * w),
         2 * (y * z - x * w),
         1 - 2 * (x * x + y * y),
         0,
         0,
         0,
         0,
         1};
  }
  if (node.scale.size() == 3)
    for (int c = 0; c < 3; ++c)
      for (int r = 0; r < 3; ++r) m[4 * c + r] *= node.scale[size_t(c)];
  if (node.translation.size() == 3)
    for (int r = 0; r < 3; ++r) m[12 + r] = node.translation[size_t(r)];
  return m;
}

// The nodes the file's scene places, outermost first.
std::vector<int> rootNodes(const tinygltf::Model& model, const std::string& label) {
  if (!model.scenes.empty()) {
    const int scene = model.defaultScene >= 0 ? model.defaultScene : 0;
    if (size_t(scene) >= model.scenes.size())
      throw SceneError(label + ": scene: scene " + std::to_string(scene) + " does not exist (" +
                       std::to_string(model.scenes.size()) + " scenes)");
    return model.scenes[size_t(scene)].nodes;
  }
  std::vector<bool> child(model.nodes.size(), false);
  for (const tinygltf::Node& node : model.nodes)
    for (int c : node.children)
      if (c >= 0 && size_t(c) < child.size()) child[size_t(c)] = true;
  std::vector<int> roots;
  for (size_t i = 0; i < child.size(); ++i)
    if (!child[i]) roots.push_back(int(i));
  return roots;
}

class MeshBuilder {
 public:
  MeshBuilder(const tinygltf::Model& model, const std::string& label, const std::string& folder,
              const std::map<int, std::string>& embedded, TextureLoader& textures)
      : model_(model),
        label_(label),
        materials_(model, label, folder, embedded, textures, &mesh_.warnings) {}

  void addNodes(const std::vector<int>& roots) {
    std::vector<bool> reached(model_.nodes.size(), false);
    std::vector<std::pair<int, Matrix>> pending;
    for (auto it = roots.rbegin(); it != roots.rend(); ++it) pending.push_back({*it, identity()});
    while (!pending.empty()) {
      const auto [index, parent] = pending.back();
      pending.pop_back();
      if (index < 0 || size_t(index) >= model_.nodes.size())
        throw SceneError(label_ + ": node " + std::to_string(index) + " does not exist (" +
                         std::to_string(model_.nodes.size()) + " nodes)");
      const std::string where = "nodes[" + std::to_string(index) + "]";
      if (reached[size_t(index)])
        throw SceneError(label_ + ": " + where +
                         " is reached twice (a node may have one parent and appear once)");
      reached[size_t(index)] = true;
      const tinygltf::Node& node = model_.nodes[size_t(index)];
      const Matrix world = multiply(parent, localTransform(node, label_ + ": " + where));
      if (node.skin >= 0) warn("skins are not applied: skinned meshes keep their rest pose");
      if (node.mesh >= 0) addMesh(node.mesh, world, where + ".mesh");
      for (auto c = node.children.rbegin(); c != node.children.rend(); ++c)
        pending.push_back({*c, world});
    }
  }

  MeshDesc finish() {
    if (mesh_.triangles.empty())
      throw SceneError(label_ + ": expected at least one triangle, got none");
    if (!model_.cameras.empty()) warn("the file's cameras are not used (the scene's camera is)");
    if (!model_.animations.empty())
      warn("the file's animations are not played (the scene's keyframes move the object)");
    if (model_.extensions.count("KHR_lights_punctual"))
      warn("the file's lights (KHR_lights_punctual) are not used (the scene's lights are)");
    return std::move(mesh_);
  }

 private:
  void warn(const std::string& message) {
    if (warned_.insert(message).second) mesh_.warnings.push_back(label_ + ": " + message);
  }

  uint32_t materialIndex(int index, const std::string& where) {
    if (index >= int(model_.materials.size()))
      throw SceneError(label_ + ": " + where + ": material " + std::to_string(index) +
                       " does not exist (" + std::to_string(model_.materials.size()) +
                       " materials)");
    if (index < 0) index = -1;
    const auto found = materialOf_.find(index);
    if (found != materialOf_.end()) return found->second;
    const uint32_t made = uint32_t(mesh_.materials.size());
    mesh_.materials.push_back(materials_.read(index, &mesh_.mixParts));
    materialOf_.emplace(index, made);
    return made;
  }

  void addMesh(int index, const Matrix& world, const std::string& where) {
    if (index < 0 || size_t(index) >= model_.meshes.size())
      throw SceneError(label_ + ": " + where + ": mesh " + std::to_string(index) +
                       " does not exist (" + std::to_string(model_.meshes.size()) + " meshes)");
    const tinygltf::Mesh& m = model_.meshes[size_t(index)];
    for (size_t p = 0; p < m.primitives.size(); ++p)
      addPrimitive(m.primitives[p], world,
                   "meshes[" + std::to_string(index) + "].primitives[" + std::to_string(p) + "]");
  }

  void addPrimitive(const tinygltf::Primitive& primitive, const Matrix& world,
                    const std::string& where) {
    const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
        mode != TINYGLTF_MODE_TRIANGLE_FAN) {
      warn("points and lines are not rendered (" + where + " is one)");
      return;
    }
    if (!primitive.targets.empty()) warn("morph targets are not applied (" + where + ")");
    if (primitive.attributes.count("COLOR_0"))
      warn("vertex colours (COLOR_0) are not rendered (" + where + ")");
    const std::string at = label_ + ": " + where;
    const auto attribute = [&](const char* name) {
      const auto found = primitive.attributes.find(name);
      return found == primitive.attributes.end() ? -1 : found->second;
    };
    const int positionAccessor = attribute("POSITION");
    if (positionAccessor < 0) throw SceneError(at + ".attributes: expected a POSITION");
    const std::vector<float> positions =
        readFloatAccessor(model_, positionAccessor, 3, false, at + ".attributes.POSITION");
    const size_t vertices = positions.size() / 3;
    std::vector<float> normals, uvs;
    if (attribute("NORMAL") >= 0)
      normals = readFloatAccessor(model_, attribute("NORMAL"), 3, false, at + ".attributes.NORMAL");
    if (attribute("TEXCOORD_0") >= 0)
      uvs = readFloatAccessor(model_, attribute("TEXCOORD_0"), 2, true,
                              at + ".attributes.TEXCOORD_0");
    if ((!normals.empty() && normals.size() / 3 != vertices) ||
        (!uvs.empty() && uvs.size() / 2 != vertices))
      throw SceneError(at + ".attributes: NORMAL and TEXCOORD_0 must have as many elements as " +
                       "POSITION (" + std::to_string(vertices) + ")");
    std::vector<uint32_t> indices;
    if (primitive.indices >= 0) {
      indices = readIndexAccessor(model_, primitive.indices, at + ".indices");
      for (size_t i = 0; i < indices.size(); ++i)
        if (indices[i] >= vertices)
          throw SceneError(at + ".indices: index " + std::to_string(i) + " is " +
                           std::to_string(indices[i]) + ", past the " + std::to_string(vertices) +
                           " vertices");
    } else {
      indices.resize(vertices);
      for (size_t i = 0; i < vertices; ++i) indices[i] = uint32_t(i);
    }
    if (mesh_.positions.size() + vertices >= (size_t(1) << 31))
      throw SceneError(at + ": the file has more than 2^31 vertices");
    const uint32_t material = materialIndex(primitive.material, where + ".material");

    const Placed placed = appendVertices(positions, normals, uvs, world);
    appendTriangles(mode, indices, placed, material);
  }

  // Where a primitive's vertices landed in mesh_, and which of its normals are usable.
  struct Placed {
    uint32_t base = 0;
    int32_t normalBase = -1, uvBase = -1;  // -1: it has none
    std::vector<bool> usableNormal;
    bool mirrored = false;  // by a transform of negative determinant
  };

  // Positions by the node's transform, normals by its inverse transpose (the cofactors, times
  // the determinant's sign), uvs turned to candela's v.
  Placed appendVertices(const std::vector<float>& positions, const std::vector<float>& normals,
                        const std::vector<float>& uvs, const Matrix& world) {
    Placed placed;
    placed.base = uint32_t(mesh_.positions.size());
    for (size_t v = 0; v < positions.size() / 3; ++v) {
      const double x = positions[3 * v], y = positions[3 * v + 1], z = positions[3 * v + 2];
      Vec3 p;
      for (int r = 0; r < 3; ++r)
        p[r] = float(world[size_t(r)] * x + world[size_t(4 + r)] * y + world[size_t(8 + r)] * z +
                     world[size_t(12 + r)]);
      mesh_.positions.push_back(p);
    }
    const auto at3 = [&](int c, int r) { return world[size_t(4 * c + r)]; };
    double cof[3][3];
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        cof[r][c] = at3((c + 1) % 3, (r + 1) % 3) * at3((c + 2) % 3, (r + 2) % 3) -
                    at3((c + 2) % 3, (r + 1) % 3) * at3((c + 1) % 3, (r + 2) % 3);
    const double det = at3(0, 0) * cof[0][0] + at3(1, 0) * cof[0][1] + at3(2, 0) * cof[0][2];
    placed.mirrored = det < 0;
    if (!normals.empty()) placed.normalBase = int32_t(mesh_.normals.size());
    for (size_t v = 0; v < normals.size() / 3; ++v) {
      Vec3 n;
      for (int r = 0; r < 3; ++r)
        n[r] = float(cof[r][0] * normals[3 * v] + cof[r][1] * normals[3 * v + 1] +
                     cof[r][2] * normals[3 * v + 2]);
      if (placed.mirrored) n = -n;
      const float length = std::sqrt(dot(n, n));
      placed.usableNormal.push_back(length > 0.0f && std::isfinite(length));
      mesh_.normals.push_back(placed.usableNormal.back() ? n / length : Vec3(0.0f, 0.0f, 1.0f));
    }
    if (!uvs.empty()) placed.uvBase = int32_t(mesh_.uvs.size());
    for (size_t v = 0; v < uvs.size() / 2; ++v)
      mesh_.uvs.push_back(Vec2(uvs[2 * v], 1.0f - uvs[2 * v + 1]));
    return placed;
  }

  // The triangles of a list, a strip or a fan of `indices` (checked against the vertices).
  void appendTriangles(int mode, const std::vector<uint32_t>& indices, const Placed& placed,
                       uint32_t material) {
    const auto add = [&](uint32_t a, uint32_t b, uint32_t c) {
      if (placed.mirrored) std::swap(b, c);  // keep the outside out
      MeshTriangle t;
      const uint32_t corner[3] = {a, b, c};
      const std::vector<bool>& usable = placed.usableNormal;
      const bool smooth = !usable.empty() && usable[a] && usable[b] && usable[c];
      for (int k = 0; k < 3; ++k) {
        t.v[k] = placed.base + corner[k];
        t.n[k] = smooth ? placed.normalBase + int32_t(corner[k]) : -1;
        t.t[k] = placed.uvBase < 0 ? -1 : placed.uvBase + int32_t(corner[k]);
      }
      t.material = material;
      mesh_.triangles.push_back(t);
    };
    const size_t n = indices.size();
    if (mode == TINYGLTF_MODE_TRIANGLES) {
      for (size_t i = 0; i + 2 < n; i += 3) add(indices[i], indices[i + 1], indices[i + 2]);
    } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
      for (size_t i = 0; i + 2 < n; ++i)  // every other one turned, to keep the strip's winding
        if (i % 2 == 0)
          add(indices[i], indices[i + 1], indices[i + 2]);
        else
          add(indices[i + 1], indices[i], indices[i + 2]);
    } else {
      for (size_t i = 1; i + 1 < n; ++i) add(indices[0], indices[i], indices[i + 1]);
    }
  }

  const tinygltf::Model& model_;
  const std::string& label_;
  MeshDesc mesh_;
  GltfMaterialReader materials_;
  std::map<int, uint32_t> materialOf_;  // glTF material (-1: the default) -> mesh_.materials
  std::set<std::string> warned_;
};

// What tinygltf's image callback fills: the bytes of each image held in the file (a data URI or a
// buffer view), by image index, for the texture loader to decode (images named by URI are read
// from their files instead), and the model being read, against which a buffer view's bytes are
// checked: tinygltf hands them over without looking at the buffer's size.
struct ImageBytes {
  const tinygltf::Model* model = nullptr;
  std::map<int, std::string> embedded;
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
  images.embedded[index].assign(reinterpret_cast<const char*>(bytes), size_t(size));
  image->image.clear();
  return true;
}

std::string firstLine(const std::string& text) {
  std::string line = text.substr(0, text.find('\n'));
  while (!line.empty() && (line.back() == ' ' || line.back() == '\r')) line.pop_back();
  return line;
}

}  // namespace

bool isGltfPath(const std::string& path) {
  std::string lower = std::filesystem::path(path).extension().string();
  for (char& c : lower) c = char(std::tolower(static_cast<unsigned char>(c)));
  return lower == ".gltf" || lower == ".glb";
}

MeshDesc loadGltfFile(const std::string& path, const std::string& label, TextureLoader& textures) {
  std::string bytes, reason;
  if (!readTextFile(path, &bytes, &reason))
    throw SceneError("cannot open \"" + label + "\" (" + reason + ")");
  const std::string folder = std::filesystem::path(path).parent_path().string();
  tinygltf::Model model;
  ImageBytes images;
  images.model = &model;
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
                                               unsigned(bytes.size()), folder)
                 : loader.LoadASCIIFromString(&model, &error, &warning, bytes.data(),
                                              unsigned(bytes.size()), folder);
  } catch (const SceneError&) {
    throw;
  } catch (const std::exception& e) {
    throw SceneError(label + ": not a readable glTF file (" + e.what() + ")");
  }
  if (!parsed)
    throw SceneError(label + ": " +
                     (error.empty() ? std::string("not a readable glTF file") : firstLine(error)));
  for (const std::string& required : model.extensionsRequired)
    if (!kReadableRequired.count(required))
      throw SceneError(label + ": extensionsRequired: the file requires " + required +
                       ", which candela does not read");
  MeshBuilder builder(model, label, folder, images.embedded, textures);
  builder.addNodes(rootNodes(model, label));
  MeshDesc mesh = builder.finish();
  for (const tinygltf::Buffer& buffer : model.buffers)
    if (!buffer.uri.empty() && !isDataUri(buffer.uri))
      mesh.bufferFiles.push_back(gltfUriPath(buffer.uri, folder));
  return mesh;
}

}  // namespace candela
