// What a light of the description emits, in the float arithmetic the kernel's arrays hold it in:
// its power, for a sphere light the radiance of its surface (the power spread over the sphere's
// area 4 pi r^2 and the pi of a Lambertian emitter's cosine), for a spot light its cone, and for
// a directional light its disc.
#pragma once

#include <cmath>
#include <string>

#include "core/constants.h"
#include "render/light.h"
#include "render/spot_cone.h"
#include "scene/dvec3.h"
#include "scene/scene_desc.h"

namespace candela {

inline Vec3 lightPower(const LightDesc& d) { return d.color * d.intensity; }

inline Vec3 sphereLightRadiance(const LightDesc& d) {
  return lightPower(d) / (4.0f * kPi * kPi * d.radius * d.radius);
}

// A rectangle light's power spread over its area, from one side (or both, where it is two-sided),
// with a Lambertian emitter's pi.
inline Vec3 rectangleLightRadiance(const LightDesc& d) {
  const RectangleDesc& r = *d.rectangle;
  const double sides = r.twoSided ? 2.0 : 1.0;
  return lightPower(d) / float(kPi * sides * double(r.size.x) * double(r.size.y));
}

// Why a light's power or surface radiance is beyond single precision, as "its power, ... ,
// is ...", or "" when both are finite. Each factor is finite (the reader sees to that); their
// product need not be, and a light of infinite radiance would light nothing (the renderer drops
// samples that are not finite).
std::string lightEmissionProblem(const LightDesc& d);

// The unit vector along v, normalised in double: float's squares of its components would
// overflow beyond 1.8e19 and vanish below 1e-19, so any non-zero v has one; zero for zero.
inline Vec3 unitVector(const Vec3& v) {
  const DVec3 d = dvec3(v);
  if (!(dot(d, d) > 0)) return Vec3(0.0f);
  return toVec3(unit(d));
}

// Where a spot or rectangle light points: at its look_at, else along its direction (unit).
inline Vec3 lightAxis(const LightDesc& d) {
  return unitVector(d.lookAt ? *d.lookAt - d.position : d.direction);
}

// The axes of a rectangle light, unit vectors of a right-handed frame: its width's, its height's
// (up, or the default's, made perpendicular to the axis), and where it shines.
struct RectangleAxes {
  Vec3 width, height, normal;
};
RectangleAxes rectangleAxes(const LightDesc& d);

// A rectangle light's corners, counter-clockwise seen from where it shines.
void rectangleCorners(const LightDesc& d, Vec3 corners[4]);

// A directional light's 1 - cos of its disc's angular radius, 2 sin^2(radius / 2) in double (0:
// a delta light, as is a disc too small for single precision).
float sunOneMinusCos(const LightDesc& d);

// The kernel's directional light of description d: its direction, irradiance and disc.
Light directionalLight(const LightDesc& d);

// The share of a point light's power that the cone lets out: the falloff's mean over the sphere,
// (1 + (sin beam - sin cutoff) / (cutoff - beam)) / 2, or (1 - cos cutoff) / 2 for a hard edge.
inline double coneFluxShare(double beam, double cutoff) {
  if (!(cutoff > beam)) return 0.5 * (1.0 - std::cos(cutoff));
  return 0.5 * (1.0 + (std::sin(beam) - std::sin(cutoff)) / (cutoff - beam));
}

// The kernel's cone of a spot light (none for other lights), aimed from d.position.
SpotCone spotCone(const LightDesc& d);

// A point or spot light's profile (render/light_profile.h) at its aim: the C0 direction its up
// made perpendicular to its axis, C90 counter-clockwise from it seen from behind the axis.
LightProfile lightProfile(const LightDesc& d);

}  // namespace candela
