#include "scene/mesh_layout.h"

#include <algorithm>
#include <unordered_map>
#include <utility>

namespace candela {

bool readsTextures(const Material& m) {
  return m.colorTexture.index >= 0 || m.emissionTexture.index >= 0 || m.alpha.texture.index >= 0 ||
         m.normalMap.index >= 0 || m.roughnessTexture.index >= 0 || m.mixWeightTexture.index >= 0 ||
         m.coatTexture.index >= 0 || m.sheenTexture.index >= 0 ||
         m.coatRoughnessTexture.index >= 0 || m.sheenRoughnessTexture.index >= 0 ||
         m.coatNormalMap.index >= 0 || m.transmittanceTexture.index >= 0;
}

bool readsUvs(const Material& m) { return readsTextures(m) || m.anisotropy != 0.0f; }

bool usesNormals(const ObjectDesc& obj) { return obj.smooth && !obj.mesh->normals.empty(); }

bool anyMaterialOf(const ObjectDesc& obj, bool (*test)(const Material&)) {
  const auto any = [test](const std::vector<Material>& v) {
    return std::any_of(v.begin(), v.end(), test);
  };
  if (obj.material) return test(*obj.material) || any(obj.mixParts);
  return any(obj.mesh->materials) || any(obj.mesh->mixParts);
}

bool usesUvs(const ObjectDesc& obj) {
  return !obj.mesh->uvs.empty() && (obj.uvPass || anyMaterialOf(obj, readsUvs));
}

void layOutForPasses(SceneDesc& desc, const std::vector<Aov>& aovs) {
  if (hasAov(aovs, Aov::Uv))
    for (ObjectDesc& object : desc.objects) object.uvPass = true;
  if (hasAov(aovs, Aov::ObjectCoordinates)) desc.objectCoordinatesPass = true;
}

bool usesVertexColors(const ObjectDesc& obj) {
  return obj.vertexColors && !obj.mesh->colors.empty();
}

MeshLayout layOutMesh(const MeshDesc& mesh, bool withNormals, bool withUvs) {
  using Corner = MeshLayout::Corner;
  MeshLayout layout;
  layout.withNormals = withNormals;
  layout.withUvs = withUvs;
  layout.triangles.resize(mesh.triangles.size());
  const uint32_t own = uint32_t(mesh.positions.size());
  if (withNormals || withUvs) layout.corners.assign(own, Corner{-2, -2});
  struct SplitHash {
    size_t operator()(const std::pair<uint32_t, uint64_t>& k) const {
      return std::hash<uint64_t>()(k.second * 0x9e3779b97f4a7c15ull ^ k.first);
    }
  };
  std::unordered_map<std::pair<uint32_t, uint64_t>, uint32_t, SplitHash> splits;
  const auto vertexFor = [&](uint32_t v, int32_t n, int32_t t) -> uint32_t {
    if (!withNormals && !withUvs) return v;
    const Corner c{withNormals ? n : -1, withUvs ? t : -1};
    Corner& slot = layout.corners[v];
    if (slot == Corner{-2, -2}) slot = c;
    if (slot == c) return v;
    const auto key = std::make_pair(v, (uint64_t(uint32_t(c.n)) << 32) | uint32_t(c.t));
    const auto [it, inserted] = splits.try_emplace(key, own + uint32_t(layout.splitSources.size()));
    if (inserted) {
      layout.splitSources.push_back(v);
      layout.corners.push_back(c);
    }
    return it->second;
  };
  for (size_t i = 0; i < mesh.triangles.size(); ++i) {
    const MeshTriangle& t = mesh.triangles[i];
    Triangle& w = layout.triangles[i];
    for (int k = 0; k < 3; ++k) w.v[k] = vertexFor(t.v[k], t.n[k], t.t[k]);
    w.material = t.material;
  }
  return layout;
}

}  // namespace candela
