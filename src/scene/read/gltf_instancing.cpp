// Placing the instances of a glTF node's mesh; see gltf_instancing.h.
#include "scene/read/gltf_instancing.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "scene/read/gltf_accessor.h"
#include "scene/scene_error.h"

namespace candela {

std::vector<GltfMatrix> meshPlacements(const tinygltf::Model& model, int index,
                                       const tinygltf::Node& node, const GltfMatrix& world,
                                       const std::string& label) {
  const auto e = node.extensions.find("EXT_mesh_gpu_instancing");
  if (e == node.extensions.end() || node.mesh < 0) return {world};
  const std::string where =
      label + ": nodes[" + std::to_string(index) + "].extensions.EXT_mesh_gpu_instancing";
  const tinygltf::Value& attributes = e->second.Get("attributes");
  if (!attributes.IsObject()) throw SceneError(where + ".attributes: expected an object");
  // The instances' count, as the accessors declare it, bounded before anything is read.
  uint64_t declared = 0;
  for (const char* name : {"TRANSLATION", "ROTATION", "SCALE"}) {
    const tinygltf::Value& accessor = attributes.Get(name);
    if (accessor.IsInt() && accessor.GetNumberAsInt() >= 0 &&
        size_t(accessor.GetNumberAsInt()) < model.accessors.size())
      declared =
          std::max<uint64_t>(declared, model.accessors[size_t(accessor.GetNumberAsInt())].count);
  }
  uint64_t vertices = 0;
  if (size_t(node.mesh) < model.meshes.size())
    for (const tinygltf::Primitive& p : model.meshes[size_t(node.mesh)].primitives) {
      const auto position = p.attributes.find("POSITION");
      if (position != p.attributes.end() && position->second >= 0 &&
          size_t(position->second) < model.accessors.size())
        vertices += model.accessors[size_t(position->second)].count;
    }
  if (declared * vertices > kMostInstancedVertices)
    throw SceneError(where + ": " + std::to_string(declared) + " instances of a mesh of " +
                     std::to_string(vertices) + " vertices are more than candela copies (" +
                     std::to_string(kMostInstancedVertices) + " vertices)");
  // Each attribute's elements (translations and scales as floats or, quantized, integers;
  // rotations as floats or normalized integers); the instance count is theirs.
  size_t count = 0;
  bool counted = false;
  const auto read = [&](const char* name, int components, unsigned encodings) {
    if (!attributes.Has(name)) return std::vector<float>();
    const tinygltf::Value& accessor = attributes.Get(name);
    const std::string at = where + ".attributes." + name;
    if (!accessor.IsInt()) throw SceneError(at + ": expected an accessor's index");
    std::vector<float> values =
        readFloatAccessor(model, accessor.GetNumberAsInt(), components, encodings, at);
    const size_t n = values.size() / size_t(components);
    if (counted && n != count)
      throw SceneError(at + ": " + std::to_string(n) + " instances, where the other attributes " +
                       "have " + std::to_string(count));
    count = n;
    counted = true;
    return values;
  };
  const std::vector<float> t = read("TRANSLATION", 3, kAnyEncoding);
  const std::vector<float> r = read("ROTATION", 4, kFloats | kSignedNormalized);
  const std::vector<float> s = read("SCALE", 3, kAnyEncoding);
  if (!counted) return {world};  // no attributes: glTF draws the mesh once, at the node
  std::vector<GltfMatrix> placements;
  placements.reserve(count);
  for (size_t i = 0; i < count; ++i) {
    std::array<double, 3> translation{0, 0, 0}, scale{1, 1, 1};
    std::array<double, 4> rotation{0, 0, 0, 1};
    for (size_t c = 0; c < 3; ++c) {
      if (!t.empty()) translation[c] = t[3 * i + c];
      if (!s.empty()) scale[c] = s[3 * i + c];
    }
    for (size_t c = 0; c < 4 && !r.empty(); ++c) rotation[c] = r[4 * i + c];
    if (!(rotation[0] * rotation[0] + rotation[1] * rotation[1] + rotation[2] * rotation[2] +
              rotation[3] * rotation[3] >
          0))
      throw SceneError(where + ".attributes.ROTATION: instance " + std::to_string(i) +
                       ": expected a unit quaternion, got 0");
    placements.push_back(gltfMultiply(world, gltfTrs(translation, rotation, scale)));
  }
  return placements;
}

}  // namespace candela
