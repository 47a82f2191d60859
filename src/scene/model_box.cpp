#include "scene/model_box.h"

namespace candela {

Bounds3 meshBox(const MeshDesc& mesh) {
  if (mesh.positions.empty()) return Bounds3(Vec3(0.0f));
  Bounds3 box;
  for (const Vec3& p : mesh.positions) box.grow(p);
  return box;
}

const MeshDesc& modelMesh(const ObjectDesc& obj) {
  return obj.restMesh ? *obj.restMesh : *obj.mesh;
}

Bounds3 sphereModelBox() { return Bounds3(Vec3(-1.0f), Vec3(1.0f)); }

std::optional<Bounds3> lightModelBox(const LightDesc& light) {
  if (light.type == LightType::Sphere) return sphereModelBox();
  if (light.rectangle) return Bounds3(Vec3(-0.5f, -0.5f, 0.0f), Vec3(0.5f, 0.5f, 0.0f));
  return std::nullopt;
}

}  // namespace candela
