// The warning for reflectances above 1; see reflectance_check.h.
#include "scene/read/reflectance_check.h"

#include <string>

#include "scene/scene_error.h"

namespace candela {
namespace {

constexpr int kNamed = 4;  // entities named one by one before the rest are counted

bool reflectsMoreThanItReceives(const Material& m) {
  const bool reflective = m.type == MaterialType::Diffuse || m.type == MaterialType::Translucent ||
                          m.type == MaterialType::Conductor || m.type == MaterialType::Plastic ||
                          m.type == MaterialType::Glass;
  // A texture's tint is 1 and its texels' largest unknown here: each part alone, then.
  const bool textured = m.colorTexture.index >= 0 || m.transmittanceTexture.index >= 0;
  return reflective && (textured ? maxComponent(max(m.color, m.transmittance))
                                 : maxComponent(m.color + m.transmittance)) > 1.0f;
}

// What m's colour (and a translucent surface's transmittance) say, for the warning.
std::string scattered(const Material& m) {
  if (maxComponent(m.color) > 1.0f || isBlack(m.transmittance))
    return "color " + formatVec3(m.color) +
           " is above 1, a surface that reflects more light than it receives";
  return "color " + formatVec3(m.color) + " and transmittance " + formatVec3(m.transmittance) +
         " sum above 1, a surface that scatters more light than it receives";
}

}  // namespace

void warnReflectanceAboveOne(SceneDesc& scene) {
  int count = 0;
  const auto check = [&](const std::string& where, const Material& m, const char* whose) {
    if (!reflectsMoreThanItReceives(m) || ++count > kNamed) return;
    scene.warnings.push_back(scene.file + ": " + where + ": " + whose + " " + scattered(m) +
                             "; colours are linear reflectances in [0, 1] (8-bit values divided "
                             "by 255)");
  };
  // A mix's parts are named by the surface that has them.
  const auto checkAll = [&](const std::string& where, const Material& m,
                            const std::vector<Material>& parts) {
    const int before = count;
    check(where, m, "its material's");
    for (const Material& part : parts)
      if (count == before) check(where, part, "a part of its mix material's");
  };
  for (const SphereDesc& sphere : scene.spheres)
    checkAll(sphere.where, sphere.material, sphere.mixParts);
  for (const ObjectDesc& object : scene.objects)
    if (object.material) checkAll(object.where, *object.material, object.mixParts);
  if (count > kNamed)
    scene.warnings.push_back(scene.file + ": " + std::to_string(count - kNamed) +
                             " more spheres or objects whose material's color is above 1");
}

}  // namespace candela
