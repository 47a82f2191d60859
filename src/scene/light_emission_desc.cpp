// What lights emit, and where: see light_emission_desc.h.
#include "scene/light_emission_desc.h"

#include <cmath>

#include "render/light_sample.h"
#include "scene/along_up.h"
#include "scene/dvec3.h"
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
  if (d.rectangle && !isFinite(rectangleLightRadiance(d)))
    return "its surface's radiance, " + factors + " over a rectangle of " +
           formatNumber(d.rectangle->size.x) + " by " + formatNumber(d.rectangle->size.y) +
           ", is beyond single precision; expected a larger size or a smaller intensity";
  return "";
}

RectangleAxes rectangleAxes(const LightDesc& d) {
  const DVec3 n = dvec3(lightAxis(d));
  const Vec3 up = d.rectangle->up                        ? *d.rectangle->up
                  : alongUp(lightAxis(d), Vec3(0, 1, 0)) ? Vec3(0, 0, 1)
                                                         : Vec3(0, 1, 0);
  const DVec3 height = unit(dvec3(up) - dot(dvec3(up), n) * n);  // up made perpendicular to n
  return {toVec3(cross(height, n)), toVec3(height), toVec3(n)};
}

void rectangleCorners(const LightDesc& d, Vec3 corners[4]) {
  const RectangleAxes axes = rectangleAxes(d);
  const double w = 0.5 * double(d.rectangle->size.x), h = 0.5 * double(d.rectangle->size.y);
  const DVec3 c = dvec3(d.position), u = dvec3(axes.width), v = dvec3(axes.height);
  const double signs[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (int k = 0; k < 4; ++k)
    corners[k] = toVec3(c + (signs[k][0] * w) * u + (signs[k][1] * h) * v);
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
  light.hiddenFromCamera = !d.visible;
  return light;
}

SpotCone spotCone(const LightDesc& d) {
  SpotCone cone;
  if (!d.spot) return cone;
  const SpotDesc& spot = *d.spot;
  cone.axis = lightAxis(d);
  const double cutoff = double(spot.cutoffDegrees) * (kPi / 180.0);
  const double beam = double(spot.beamDegrees) * (kPi / 180.0);
  cone.cosCutoff = float(std::cos(cutoff));
  cone.cosBeam = float(std::cos(beam));
  cone.cutoff = float(cutoff);
  cone.invTransition = cutoff > beam ? float(1.0 / (cutoff - beam)) : 0.0f;
  return cone;
}

LightProfile lightProfile(const LightDesc& d) {
  LightProfile p;
  if (!d.profile) return p;
  const Vec3 axis = lightAxis(d);
  const DVec3 n = dvec3(axis);
  const Vec3 up = d.profile->up && !alongUp(axis, *d.profile->up) ? *d.profile->up
                  : alongUp(axis, Vec3(0, 1, 0))                  ? Vec3(0, 0, 1)
                                                                  : Vec3(0, 1, 0);
  const DVec3 c0 = unit(dvec3(up) - dot(dvec3(up), n) * n);
  p.texture = d.profile->texture;
  p.scale = d.profile->scale;
  p.cosFirst = float(std::cos(double(d.profile->firstDegrees) * kPi / 180));
  p.cosLast = float(std::cos(double(d.profile->lastDegrees) * kPi / 180));
  p.axis = axis;
  p.c0 = toVec3(c0);
  p.c90 = toVec3(cross(c0, n));
  return p;
}

}  // namespace candela
