// Next-event estimation towards point and directional lights, emitting spheres and triangles and
// the environment.
//
// A point light of power P seen from distance d contributes irradiance (P / 4 pi) cos / d^2; a
// directional light of irradiance E, E cos.
// A sphere is sampled uniformly by the solid angle of the cone it subtends, a triangle by the
// solid angle it subtends or, where that is ill-conditioned, by area; either pdf can be evaluated
// again when a BSDF-sampled ray hits the emitter, for multiple importance sampling (emitterPdf).
#pragma once

#include <cmath>

#include "core/check.h"
#include "core/frame.h"
#include "core/sampling.h"
#include "geometry/motion.h"
#include "geometry/spherical_triangle.h"
#include "render/scene_view.h"
#include "render/surface_color.h"

namespace candela {

struct LightSample {
  Vec3 wi;           // unit direction from the shading point towards the light
  float distance;    // to the sampled light point
  // Incident radiance (area light), intensity / d^2 (point light) or irradiance (directional).
  Vec3 radiance;
  float pdf;     // solid-angle density; 1 for delta lights
  bool isDelta;  // delta lights cannot be hit by BSDF sampling (render/light.h, isDeltaLight)
};

// 1 - cos(theta_max) of the cone a sphere subtends, accurate also for tiny, far spheres.
CANDELA_HDI float sphereConeOneMinusCos(float sin2ThetaMax) {
  return sin2ThetaMax < 0.00068523f ? 0.5f * sin2ThetaMax  // 1 - sqrt(1 - x) ~ x / 2
                                    : 1.0f - sqrtf(1.0f - sin2ThetaMax);
}

// Solid-angle pdf with which sampleLight picks a direction towards the sphere light whose
// surface is `s` from p; 0 when p is inside it (which then shows it no emitting surface).
CANDELA_HDI float sphereLightPdf(const Sphere& s, const Vec3& p) {
  const float dist2 = lengthSquared(s.center - p);
  const float r2 = s.radius * s.radius;
  if (dist2 <= r2) return 0.0f;
  return uniformConePdf(sphereConeOneMinusCos(r2 / dist2));
}

// The light whose shape is primitive `prim`, or -1. Triangle lights come last among the lights,
// in ascending triangle order, so they are found by bisection.
CANDELA_HDI int32_t lightOfPrimitive(const SceneView& scene, uint32_t prim) {
  if (prim < scene.sphereCount) return scene.spheres[prim].light;
  const uint32_t triangle = prim - scene.sphereCount;
  uint32_t lo = scene.firstTriangleLight, hi = scene.lightCount;
  while (lo < hi) {
    const uint32_t mid = (lo + hi) / 2;
    if (scene.lights[mid].shape < triangle) {
      lo = mid + 1;
    } else {
      hi = mid;
    }
  }
  return lo < scene.lightCount && scene.lights[lo].shape == triangle ? int32_t(lo) : -1;
}

// The primitive index of an area light's shape (spheres first, then triangles), which the shadow
// ray towards a point sampled on it skips; 0xffffffff (none) for a light without a shape.
CANDELA_HDI uint32_t lightPrimitive(const SceneView& scene, const Light& l) {
  switch (l.type) {
    case LightType::Sphere:
      return l.shape;
    case LightType::Triangle:
      return scene.sphereCount + l.shape;
    case LightType::Point:
    case LightType::Environment:
    case LightType::Directional:
      break;
  }
  return 0xffffffffu;
}

CANDELA_HDI bool samplePointLight(const SceneView& scene, const Light& l, const Vec3& p,
                                  LightSample* s) {
  const Vec3 toLight = l.position - p;
  const float dist2 = lengthSquared(toLight);
  if (dist2 <= 0.0f) return false;
  s->distance = sqrtf(dist2);
  s->wi = toLight / s->distance;
  s->radiance = l.power * (kInv4Pi / dist2);
  if (hasCone(l.spot) || l.profile.texture >= 0) {
    const float share =
        coneFalloff(l.spot, -s->wi) * profileFactor(scene.texturePool(), l.profile, -s->wi);
    if (!(share > 0.0f)) return false;
    s->radiance *= share;
  }
  s->pdf = 1.0f;
  s->isDelta = true;
  return true;
}

// sin^2 of the angular radius of directional light l's disc, from 1 - cos, without cos's
// rounding (which for the sun's 0.27 degrees would cost 0.3%).
CANDELA_HDI float sunSin2(const Light& l) { return l.sunOneMinusCos * (2.0f - l.sunOneMinusCos); }

// The radiance of directional light l's disc: its irradiance E over the projected solid angle
// pi sin^2 of the disc (E = L pi sin^2 for a surface facing it).
CANDELA_HDI Vec3 sunRadiance(const Light& l) { return l.power / (kPi * sunSin2(l)); }

// Whether the unit direction wi (towards the light) lies within directional light l's disc.
CANDELA_HDI bool inSunDisc(const Light& l, const Vec3& wi) {
  // The sine of the angle from the axis, not its cosine, which float holds too coarsely near 1.
  return -dot(wi, l.direction) > 0.0f && lengthSquared(cross(wi, l.direction)) <= sunSin2(l);
}

// A directional light shines along its direction from infinitely far, on every point alike:
// from that one direction, or from a disc of directions around it, uniformly over its solid angle
// (pdf uniformConePdf(sunOneMinusCos)).
CANDELA_HDI bool sampleDirectionalLight(const Light& l, float u1, float u2, LightSample* s) {
  s->distance = kInfinity;
  if (l.sunOneMinusCos == 0.0f) {
    s->wi = -l.direction;
    s->radiance = l.power;
    s->pdf = 1.0f;
    s->isDelta = true;
    return true;
  }
  // sampleUniformCone with sin theta taken from 1 - cos theta, exact for the smallest discs.
  const float oneMinusCos = u1 * l.sunOneMinusCos;
  const float sinTheta = sqrtf(oneMinusCos * (2.0f - oneMinusCos));
  const float phi = 2.0f * kPi * u2;
  const Vec3 local(cosf(phi) * sinTheta, sinf(phi) * sinTheta, 1.0f - oneMinusCos);
  s->wi = normalize(Frame(-l.direction).toWorld(local));
  s->radiance = sunRadiance(l);
  s->pdf = uniformConePdf(l.sunOneMinusCos);
  s->isDelta = false;
  return true;
}

// A point on sphere light `l` seen from p, uniform over the cone the sphere subtends there, with
// the radiance of its texture (if any) at that point; the sphere where it stands at `time`.
CANDELA_HDI bool sampleSphereLight(const SceneView& scene, const Light& l, const Vec3& p,
                                   float time, float u1, float u2, LightSample* s) {
  CANDELA_DCHECK(l.shape < scene.sphereCount);
  const Sphere sphere = sphereAt(scene, l.shape, time);
  const Vec3 toCenter = sphere.center - p;
  const float dist2 = lengthSquared(toCenter);
  const float r2 = sphere.radius * sphere.radius;
  if (dist2 <= r2) return false;
  const float dc = sqrtf(dist2);
  const float oneMinusCosMax = sphereConeOneMinusCos(r2 / dist2);
  const Vec3 local = sampleUniformCone(u1, u2, oneMinusCosMax);
  const Vec3 axis = toCenter / dc;
  s->wi = normalize(Frame(axis).toWorld(local));
  // Distance to the near intersection with the sphere along wi (clamped at the tangent).
  const float cosTheta = local.z;
  const float sin2Theta = maxf(0.0f, 1.0f - cosTheta * cosTheta);
  const float b = dc * cosTheta;
  const float disc = maxf(0.0f, r2 - dc * dc * sin2Theta);
  s->distance = b - sqrtf(disc);
  s->radiance =
      sphereRadiance(scene, scene.materials[sphere.material], sphere, p + s->wi * s->distance);
  s->pdf = uniformConePdf(oneMinusCosMax);
  s->isDelta = false;
  return s->distance > 0.0f;
}

// Whether triangle (p0, p1, p2) is sampled by the solid angle it subtends at p, which is then
// `*solidAngle`; else by area. Sampling by solid angle costs about as much as the rest of a
// shadow ray and pays only where the triangle fills much of the view (docs/performance.md): so
// only where area / distance^2 to its centroid is at least kSolidAngleSamplingFrom, and the
// solid angle is well conditioned (geometry/spherical_triangle.h).
constexpr float kSolidAngleSamplingFrom = 1.0f;
CANDELA_HDI bool sampledBySolidAngle(const Vec3& p0, const Vec3& p1, const Vec3& p2, float area,
                                     const Vec3& p, float* solidAngle) {
  const float d2 = lengthSquared((p0 + p1 + p2) * (1.0f / 3.0f) - p);
  if (!(area >= kSolidAngleSamplingFrom * d2)) return false;
  *solidAngle = sphericalTriangleArea(normalize(p0 - p), normalize(p1 - p), normalize(p2 - p));
  return *solidAngle >= kMinSphericalSolidAngle && *solidAngle <= kMaxSphericalSolidAngle;
}

// A point on triangle light `l`: uniform over the solid angle it subtends at p where
// sampledBySolidAngle says so (pdf 1 / solid angle), else uniform by area (pdf
// d^2 / (cos_light area)), where the triangle stands at `time`. The triangle emits from its
// outside (render/bsdf.h's convention for ng), and from its back too where its material is
// two-sided.
CANDELA_HDI bool sampleTriangleLight(const SceneView& scene, const Light& l, const Vec3& p,
                                     float time, float u1, float u2, LightSample* s) {
  CANDELA_DCHECK(l.shape < scene.triangleCount);
  const Triangle& tri = scene.triangles[l.shape];
  const Material& m = scene.materials[tri.material];
  Vec3 corners[3];
  triangleCornersAt(scene, tri, time, corners);
  const Vec3 &p0 = corners[0], &p1 = corners[1], &p2 = corners[2];
  Vec3 n = cross(p1 - p0, p2 - p0);
  const float side = dot(n, p - p0);
  // p behind the plane sees the triangle's back: a two-sided one's emits (n then turned towards
  // p), a one-sided one's nothing.
  if (m.twoSided && side < 0.0f) {
    n = -n;
  } else if (!(side > 0.0f)) {
    return false;
  }
  const float twiceArea = length(n);
  if (!(twiceArea > 0.0f)) return false;
  float solidAngle = 0.0f;
  const bool spherical = sampledBySolidAngle(p0, p1, p2, 0.5f * twiceArea, p, &solidAngle);
  float b[3];
  if (spherical) {
    float unused;
    if (!sampleSphericalTriangle(p0, p1, p2, p, u1, u2, b, &unused)) return false;
  } else {
    sampleUniformTriangle(u1, u2, b);
  }
  const Vec3 toLight = (b[0] * p0 + b[1] * p1 + b[2] * p2) - p;
  const float dist2 = lengthSquared(toLight);
  if (!(dist2 > 0.0f)) return false;
  s->distance = sqrtf(dist2);
  s->wi = toLight / s->distance;
  const float cosLight = -dot(s->wi, n) / twiceArea;
  if (!(cosLight > 0.0f)) return false;
  s->radiance = triangleRadiance(scene, m, tri, b[1], b[2]);
  s->pdf = spherical ? 1.0f / solidAngle : dist2 / (cosLight * 0.5f * twiceArea);
  s->isDelta = false;
  return true;
}

// The solid-angle pdf with which the environment light samples world direction wi: a map by its
// distribution (the density over the map divided by the Jacobian 2 pi^2 sin(theta)), a constant
// environment uniformly over the sphere.
CANDELA_HDI_ALWAYS float environmentPdf(const SceneView& scene, const Vec3& wi) {
  const Environment& e = scene.environment;
  if (e.width == 0) return kInv4Pi;
  const Vec3 d = e.fromWorld * wi;
  float u, v;
  directionToMap(d, &u, &v);
  const float sinTheta = sqrtf(d.x * d.x + d.z * d.z);
  if (!(sinTheta > 0.0f)) return 0.0f;
  uint32_t column, row;
  float s, t;
  mapToCell(e, u, v, &column, &row, &s, &t);
  const float pdfMap =
      environmentDistribution(scene).cellPdf(column, row, s, t) * mapDensityPerGridDensity(e, row);
  return pdfMap / (2.0f * kPi * kPi * sinTheta);
}

CANDELA_HDI bool sampleEnvironmentLight(const SceneView& scene, float u1, float u2,
                                        LightSample* s) {
  const Environment& e = scene.environment;
  if (e.width == 0) {
    const float z = 1.0f - 2.0f * u1, r = sqrtf(maxf(0.0f, 1.0f - z * z)), phi = 2.0f * kPi * u2;
    s->wi = Vec3(r * cosf(phi), r * sinf(phi), z);
    s->pdf = kInv4Pi;
    s->radiance = e.radiance;
  } else {
    uint32_t column, row;
    float cellS, cellT, pdfGrid;
    if (!environmentDistribution(scene).sampleCell(u1, u2, &column, &row, &cellS, &cellT, &pdfGrid))
      return false;
    float u, v, sinTheta;
    cellToMap(e, column, row, cellS, cellT, &u, &v);
    const Vec3 d = mapToDirection(u, v, &sinTheta);
    if (!(sinTheta > 0.0f)) return false;
    s->wi = normalize(e.toWorld * d);
    s->pdf = pdfGrid * mapDensityPerGridDensity(e, row) / (2.0f * kPi * kPi * sinTheta);
    s->radiance = e.radiance * lookupMap(scene.envTexels, e.width, e.height, u, v);
  }
  s->distance = kInfinity;
  s->isDelta = false;
  return true;
}

// A sample of light `l` as seen from p at `time` (where a light with a moving shape then stands),
// from the uniform numbers (u1, u2) (a delta light uses neither); false when the light shows p
// nothing.
CANDELA_HDI bool sampleLight(const SceneView& scene, const Light& l, const Vec3& p, float time,
                             float u1, float u2, LightSample* s) {
  switch (l.type) {
    case LightType::Point:
      if (l.moves)
        return samplePointLight(scene, posedLight(scene, scene.lightPoses, l, time), p, s);
      return samplePointLight(scene, l, p, s);
    case LightType::Sphere:
      return sampleSphereLight(scene, l, p, time, u1, u2, s);
    case LightType::Triangle:
      return sampleTriangleLight(scene, l, p, time, u1, u2, s);
    case LightType::Environment:
      return sampleEnvironmentLight(scene, u1, u2, s);
    case LightType::Directional:
      if (l.moves)
        return sampleDirectionalLight(posedLight(scene, scene.lightPoses, l, time), u1, u2, s);
      return sampleDirectionalLight(l, u1, u2, s);
  }
  return false;
}

// The solid-angle pdf with which sampleLight, from point `from` at `time`, samples the direction
// `wi` that reached area light `l` at distance t, where the surface's geometric normal is ng.
CANDELA_HDI float emitterPdf(const SceneView& scene, const Light& l, const Vec3& from, float time,
                             const Vec3& wi, float t, const Vec3& ng) {
  switch (l.type) {
    case LightType::Sphere:
      return sphereLightPdf(sphereAt(scene, l.shape, time), from);
    case LightType::Triangle: {
      Vec3 corners[3];
      triangleCornersAt(scene, scene.triangles[l.shape], time, corners);
      const Vec3 &p0 = corners[0], &p1 = corners[1], &p2 = corners[2];
      const float area = 0.5f * length(cross(p1 - p0, p2 - p0));
      float solidAngle = 0.0f;
      if (sampledBySolidAngle(p0, p1, p2, area, from, &solidAngle)) return 1.0f / solidAngle;
      const float cosLight = fabsf(dot(wi, ng));
      return cosLight > 0.0f && area > 0.0f ? t * t / (cosLight * area) : 0.0f;
    }
    case LightType::Point:
    case LightType::Environment:
    case LightType::Directional:
      break;
  }
  return 0.0f;
}

}  // namespace candela
