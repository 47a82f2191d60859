// The warning for reflectances above 1; see reflectance_check.h.
#include "scene/read/reflectance_check.h"

#include <string>

#include "scene/scene_error.h"

namespace candela {
namespace {

constexpr int kNamed = 4;  // entities named one by one before the rest are counted

bool reflectsMoreThanItReceives(const Material& m) {
  const bool reflective = m.type == MaterialType::Diffuse || m.type == MaterialType::Conductor ||
                          m.type == MaterialType::Plastic || m.type == MaterialType::Glass;
  return reflective && (m.color.x > 1.0f || m.color.y > 1.0f || m.color.z > 1.0f);
}

}  // namespace

void warnReflectanceAboveOne(SceneDesc& scene) {
  int count = 0;
  const auto check = [&](const std::string& where, const Material& m) {
    if (!reflectsMoreThanItReceives(m) || ++count > kNamed) return;
    scene.warnings.push_back(scene.file + ": " + where + ": its material's color " +
                             formatVec3(m.color) +
                             " is above 1, a surface that reflects more light than it receives; "
                             "colours are linear reflectances in [0, 1] (8-bit values divided "
                             "by 255)");
  };
  for (const SphereDesc& sphere : scene.spheres) check(sphere.where, sphere.material);
  for (const ObjectDesc& object : scene.objects)
    if (object.material) check(object.where, *object.material);
  if (count > kNamed)
    scene.warnings.push_back(scene.file + ": " + std::to_string(count - kNamed) +
                             " more spheres or objects whose material's color is above 1");
}

}  // namespace candela
