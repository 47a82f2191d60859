// lightEmissionProblem and spotCone; see light_emission_desc.h.
#include "scene/light_emission_desc.h"

#include <cmath>

#include "scene/scene_error.h"

namespace candela {

std::string lightEmissionProblem(const LightDesc& d) {
  const std::string factors =
      "intensity " + formatNumber(d.intensity) + " times color " + formatVec3(d.color);
  if (!isFinite(lightPower(d)))
    return std::string(d.type == LightType::Directional ? "its irradiance, " : "its power, ") +
           factors +
           ", is beyond single precision; expected a smaller intensity "
           "or color";
  if (d.type == LightType::Sphere && !isFinite(sphereLightRadiance(d)))
    return "its surface's radiance, " + factors + " over a sphere of radius " +
           formatNumber(d.radius) +
           ", is beyond single precision; expected a larger radius or a "
           "smaller intensity";
  return "";
}

SpotCone spotCone(const LightDesc& d) {
  SpotCone cone;
  if (!d.spot) return cone;
  const SpotDesc& spot = *d.spot;
  cone.axis = normalize(spot.lookAt ? *spot.lookAt - d.position : d.direction);
  const double cutoff = double(spot.cutoffDegrees) * (kPi / 180.0);
  const double beam = double(spot.beamDegrees) * (kPi / 180.0);
  cone.cosCutoff = float(std::cos(cutoff));
  cone.cosBeam = float(std::cos(beam));
  cone.cutoff = float(cutoff);
  cone.invTransition = cutoff > beam ? float(1.0 / (cutoff - beam)) : 0.0f;
  return cone;
}

}  // namespace candela
