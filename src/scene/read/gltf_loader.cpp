// glTF loading through tinygltf, every index and bound checked here; see gltf_loader.h.
#include "scene/read/gltf_loader.h"

#include <cmath>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <vector>

#include "scene/read/gltf_accessor.h"
#include "scene/read/gltf_animation.h"
#include "scene/read/gltf_file.h"
#include "scene/read/gltf_instancing.h"
#include "scene/read/gltf_materials.h"
#include "scene/read/gltf_nodes.h"
#include "scene/read/gltf_uri.h"
#include "scene/read/gltf_variants.h"
#include "scene/scene_error.h"

namespace candela {
namespace {

class MeshBuilder {
 public:
  // `variant`: the index of the KHR_materials_variants variant that picks the materials (-1:
  // the primitives' own), among `variantCount`.
  // `rig` poses the vertices (at `rest`); with `keep` it keeps the primitives, for an animation.
  MeshBuilder(const tinygltf::Model& model, const std::string& label, const std::string& folder,
              const std::map<int, std::string>& embedded, TextureLoader& textures, int variant,
              size_t variantCount, GltfRig& rig, const GltfPose& rest, bool keep)
      : model_(model),
        label_(label),
        materials_(model, label, folder, embedded, textures, &mesh_.warnings),
        variant_(variant),
        variantCount_(variantCount),
        rig_(rig),
        rest_(rest),
        keep_(keep) {}

  void addNode(int index, const tinygltf::Node& node) {
    const std::string where = "nodes[" + std::to_string(index) + "]";
    if (node.mesh < 0) return;
    if (node.skin >= int(model_.skins.size()))
      throw SceneError(label_ + ": " + where + ".skin: skin " + std::to_string(node.skin) +
                       " does not exist (" + std::to_string(model_.skins.size()) + " skins)");
    // An instanced node's placements under it (none: the node's own transform alone).
    std::vector<std::optional<GltfMatrix>> instances{std::nullopt};
    if (node.extensions.count("EXT_mesh_gpu_instancing")) {
      instances.clear();
      const GltfMatrix identity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
      for (const GltfMatrix& m : meshPlacements(model_, index, node, identity, label_))
        instances.push_back(m);
    }
    int skin = node.skin;
    if (skin >= 0 && instances.front()) {
      warn("skins of instanced meshes are not applied: they keep their rest pose (" + where + ")");
      skin = -1;
    }
    for (const std::optional<GltfMatrix>& instance : instances)
      addMesh(node.mesh, index, instance, skin, where + ".mesh");
  }

  MeshDesc finish() {
    if (mesh_.triangles.empty())
      throw SceneError(label_ + ": expected at least one triangle, got none");
    mesh_.holdsCameras = !model_.cameras.empty();
    mesh_.holdsLights = !model_.lights.empty();
    if (!mesh_.colors.empty()) mesh_.colors.resize(mesh_.positions.size(), Vec3(1.0f));
    if (!model_.animations.empty() && !keep_)
      warn(
          "the file's animations do not move the object (it plays one with "
          "\"gltf_animation\"; a camera taken from the file may follow one too)");
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

  void addMesh(int index, int node, const std::optional<GltfMatrix>& instance, int skin,
               const std::string& where) {
    if (index < 0 || size_t(index) >= model_.meshes.size())
      throw SceneError(label_ + ": " + where + ": mesh " + std::to_string(index) +
                       " does not exist (" + std::to_string(model_.meshes.size()) + " meshes)");
    const tinygltf::Mesh& m = model_.meshes[size_t(index)];
    for (size_t p = 0; p < m.primitives.size(); ++p)
      addPrimitive(m.primitives[p], node, instance, skin,
                   "meshes[" + std::to_string(index) + "].primitives[" + std::to_string(p) + "]");
  }

  void addPrimitive(const tinygltf::Primitive& primitive, int node,
                    const std::optional<GltfMatrix>& instance, int skin, const std::string& where) {
    const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
        mode != TINYGLTF_MODE_TRIANGLE_FAN) {
      warn("points and lines are not rendered (" + where + " is one)");
      return;
    }
    const std::string at = label_ + ": " + where;
    const auto attribute = [&](const char* name) {
      const auto found = primitive.attributes.find(name);
      return found == primitive.attributes.end() ? -1 : found->second;
    };
    const int positionAccessor = attribute("POSITION");
    if (positionAccessor < 0) throw SceneError(at + ".attributes: expected a POSITION");
    GltfRigPrimitive rigged;
    rigged.node = node;
    rigged.instance = instance;
    rigged.skin = skin;
    std::vector<float>& positions = rigged.positions;
    std::vector<float>& normals = rigged.normals;
    positions =
        readFloatAccessor(model_, positionAccessor, 3, kAnyEncoding, at + ".attributes.POSITION");
    const size_t vertices = positions.size() / 3;
    std::vector<float> uvs;
    if (attribute("NORMAL") >= 0)
      normals = readFloatAccessor(model_, attribute("NORMAL"), 3, kFloats | kSignedNormalized,
                                  at + ".attributes.NORMAL");
    if (attribute("TEXCOORD_0") >= 0)
      uvs = readFloatAccessor(model_, attribute("TEXCOORD_0"), 2, kAnyEncoding,
                              at + ".attributes.TEXCOORD_0");
    const std::vector<float> colors = readColors(attribute("COLOR_0"), at + ".attributes.COLOR_0");
    if ((!normals.empty() && normals.size() / 3 != vertices) ||
        (!uvs.empty() && uvs.size() / 2 != vertices) ||
        (!colors.empty() && colors.size() / 3 != vertices))
      throw SceneError(at + ".attributes: NORMAL, TEXCOORD_0 and COLOR_0 must have as many " +
                       "elements as POSITION (" + std::to_string(vertices) + ")");
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
    const int fileMaterial = gltfVariantMaterial(primitive, variant_, variantCount_,
                                                 model_.materials.size(), label_, where);
    const uint32_t material = materialIndex(fileMaterial, where + ".material");
    if (!colors.empty() && mesh_.materials[material].type == MaterialType::Emissive)
      warn(where + ".attributes.COLOR_0: vertex colours do not tint an unlit material (materials[" +
           std::to_string(fileMaterial) + "])");  // candela's emitters take none

    if (!colors.empty()) {
      mesh_.colors.resize(mesh_.positions.size(), Vec3(1.0f));  // earlier vertices without
      for (size_t v = 0; v < vertices; ++v)
        mesh_.colors.push_back(Vec3(colors[3 * v], colors[3 * v + 1], colors[3 * v + 2]));
    }
    readTargets(primitive, at, &rigged);
    if (skin >= 0 && rig_.readInfluences(model_, primitive, at, &rigged) > 0)
      warn("vertices without skin weights stay with their node (" + where + ")");
    const Placed placed = appendVertices(rigged, uvs);
    appendTriangles(mode, indices, placed, material);
    if (keep_) rig_.primitives.push_back(std::move(rigged));
  }

  // A primitive's morph targets: what each adds to its positions and normals (their texture
  // coordinates and colours are not read).
  void readTargets(const tinygltf::Primitive& primitive, const std::string& at,
                   GltfRigPrimitive* rigged) {
    const size_t vertices = rigged->positions.size() / 3;
    for (size_t k = 0; k < primitive.targets.size(); ++k) {
      const std::string where = at + ".targets[" + std::to_string(k) + "]";
      const std::map<std::string, int>& target = primitive.targets[k];
      const auto read = [&](const char* name, unsigned encodings, bool wanted) {
        const auto found = target.find(name);
        if (found == target.end() || !wanted) return std::vector<float>();
        std::vector<float> values =
            readFloatAccessor(model_, found->second, 3, encodings, where + "." + name);
        if (values.size() != 3 * vertices)
          throw SceneError(where + "." + name + ": expected as many elements as POSITION (" +
                           std::to_string(vertices) + "), got " +
                           std::to_string(values.size() / 3));
        return values;
      };
      rigged->targetPositions.push_back(read("POSITION", kAnyEncoding, true));
      rigged->targetNormals.push_back(
          read("NORMAL", kFloats | kSignedNormalized, !rigged->normals.empty()));
      for (const auto& [name, accessor] : target)
        if (name != "POSITION" && name != "NORMAL" && name != "TANGENT")
          warn("morph targets' " + name + " is not applied (" + where + ")");
    }
  }

  // A primitive's vertex colours (COLOR_0, linear RGB or RGBA, whose alpha is not used) as RGB,
  // or none for `index` -1.
  std::vector<float> readColors(int index, const std::string& where) {
    if (index < 0) return {};
    const bool rgba = size_t(index) < model_.accessors.size() &&
                      model_.accessors[size_t(index)].type == TINYGLTF_TYPE_VEC4;
    const std::vector<float> read =
        readFloatAccessor(model_, index, rgba ? 4 : 3, kFloats | kUnsignedNormalized, where);
    std::vector<float> rgb;
    rgb.reserve(read.size());
    for (size_t i = 0; i < read.size(); ++i) {
      if (rgba && i % 4 == 3) continue;
      if (!(read[i] >= 0.0f && read[i] <= 1.0f))
        throw SceneError(where + ": accessor " + std::to_string(index) + ", element " +
                         std::to_string(i / (rgba ? 4 : 3)) + ": expected colours from 0 to 1, " +
                         "got " + formatNumber(read[i]));
      rgb.push_back(read[i]);
    }
    return rgb;
  }

  // Where a primitive's vertices landed in mesh_, and which of its normals are usable.
  struct Placed {
    uint32_t base = 0;
    int32_t normalBase = -1, uvBase = -1;  // -1: it has none
    std::vector<bool> usableNormal;
    bool mirrored = false;  // by a transform of negative determinant
  };

  // Positions and normals as the rig poses them at rest (scene/read/gltf_rig.h), uvs turned to
  // candela's v.
  Placed appendVertices(GltfRigPrimitive& rigged, const std::vector<float>& uvs) {
    Placed placed;
    placed.base = uint32_t(mesh_.positions.size());
    rigged.base = placed.base;
    mesh_.positions.resize(mesh_.positions.size() + rigged.positions.size() / 3);
    if (!rigged.normals.empty()) {
      placed.normalBase = int32_t(mesh_.normals.size());
      rigged.normalBase = placed.normalBase;
      mesh_.normals.resize(mesh_.normals.size() + rigged.normals.size() / 3);
    }
    rig_.place(rigged, rest_, &mesh_.positions, &mesh_.normals, &placed.usableNormal);
    placed.mirrored = rig_.mirrored(rigged, rest_);
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
  int variant_;
  size_t variantCount_;
  GltfRig& rig_;
  const GltfPose& rest_;
  bool keep_;
};

}  // namespace

bool isGltfPath(const std::string& path) {
  std::string lower = std::filesystem::path(path).extension().string();
  for (char& c : lower) c = char(std::tolower(static_cast<unsigned char>(c)));
  return lower == ".gltf" || lower == ".glb";
}

MeshDesc loadGltfFile(const std::string& path, const std::string& label, TextureLoader& textures,
                      const std::string& variant, const std::string& nodeName,
                      std::shared_ptr<GltfRig>* rig) {
  const std::unique_ptr<GltfFile> file = readGltfFile(path, label);
  const int root = nodeName.empty() ? -1 : gltfNodeIndex(file->model, nodeName);
  const std::vector<std::string> variants = gltfVariantNames(file->model, label);
  auto posing = std::make_shared<GltfRig>(file->model, label, root);
  const GltfPose rest = posing->pose(nullptr, 0.0);
  MeshBuilder builder(file->model, label, file->folder, file->embedded, textures,
                      variant.empty() ? -1 : gltfVariantIndex(variants, variant), variants.size(),
                      *posing, rest, rig != nullptr);
  forEachPlacedNode(
      file->model, label,
      [&](int index, const tinygltf::Node& node, const GltfMatrix&) {
        builder.addNode(index, node);
      },
      {}, root);
  MeshDesc mesh = builder.finish();
  // Every animation, read once: listed with its length, and kept for the objects that play one.
  // One that no object plays may be broken: it is only listed.
  for (size_t i = 0; i < file->model.animations.size(); ++i) {
    GltfRig::Animation animation{file->model.animations[i].name, std::nullopt, ""};
    try {
      animation.played.emplace(file->model, i, label);
    } catch (const SceneError& error) {
      animation.fault = error.what();
    }
    mesh.animations.emplace_back(animation.name,
                                 animation.played ? animation.played->length() : -1.0);
    if (rig) posing->animations.push_back(std::move(animation));
  }
  if (rig) *rig = std::move(posing);
  for (const tinygltf::Buffer& buffer : file->model.buffers)
    if (!buffer.uri.empty() && !isDataUri(buffer.uri))
      mesh.bufferFiles.push_back(gltfUriPath(buffer.uri, file->folder));
  return mesh;
}

}  // namespace candela
