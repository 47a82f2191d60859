// lightEmissionProblem, sunOneMinusCos, directionalLight and spotCone; see light_emission_desc.h.
#include "scene/light_emission_desc.h"

#include <cmath>

#include "render/light_sample.h"
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
  if (d.type == LightType::Directional && d.angleDegrees > 0) {
    const Light l = directionalLight(d);
    // A disc too small for single precision (omc 0) is a delta light, whose irradiance is checked
    // above.
    if (l.sunOneMinusCos > 0.0f && !isFinite(sunRadiance(l)))
      return "its disc's radiance, " + factors + " over a disc " + formatNumber(d.angleDegrees) +
             " degrees across, is beyond single precision; expected a larger angle or a smaller "
             "intensity";
  }
  if (d.type == LightType::Sphere && !isFinite(sphereLightRadiance(d)))
    return "its surface's radiance, " + factors + " over a sphere of radius " +
           formatNumber(d.radius) +
           ", is beyond single precision; expected a larger radius or a "
           "smaller intensity";
  return "";
}

float sunOneMinusCos(const LightDesc& d) {
  const double halfRadius = double(d.angleDegrees) * (kPi / 180.0) / 4.0;
  const double s = std::sin(halfRadius);
  return float(2.0 * s * s);
}

Light directionalLight(const LightDesc& d) {
  Light light;
  light.type = LightType::Directional;
  light.direction = unitVector(d.direction);
  light.power = lightPower(d);  // the irradiance
  light.sunOneMinusCos = sunOneMinusCos(d);
  return light;
}

SpotCone spotCone(const LightDesc& d) {
  SpotCone cone;
  if (!d.spot) return cone;
  const SpotDesc& spot = *d.spot;
  cone.axis = unitVector(spot.lookAt ? *spot.lookAt - d.position : d.direction);
  const double cutoff = double(spot.cutoffDegrees) * (kPi / 180.0);
  const double beam = double(spot.beamDegrees) * (kPi / 180.0);
  cone.cosCutoff = float(std::cos(cutoff));
  cone.cosBeam = float(std::cos(beam));
  cone.cutoff = float(cutoff);
  cone.invTransition = cutoff > beam ? float(1.0 / (cutoff - beam)) : 0.0f;
  return cone;
}

}  // namespace candela
