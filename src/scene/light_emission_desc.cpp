// lightEmissionProblem; see light_emission_desc.h.
#include "scene/light_emission_desc.h"

#include "scene/scene_error.h"

namespace candela {

std::string lightEmissionProblem(const LightDesc& d) {
  const std::string factors =
      "intensity " + formatNumber(d.intensity) + " times color " + formatVec3(d.color);
  if (!isFinite(lightPower(d)))
    return "its power, " + factors +
           ", is beyond single precision; expected a smaller intensity "
           "or color";
  if (d.type == LightType::Sphere && !isFinite(sphereLightRadiance(d)))
    return "its surface's radiance, " + factors + " over a sphere of radius " +
           formatNumber(d.radius) +
           ", is beyond single precision; expected a larger radius or a "
           "smaller intensity";
  return "";
}

}  // namespace candela
