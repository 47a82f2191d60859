// Where a light subpath leaves a light with a surface (render/light_path.h): a point uniform over
// the light's area, with the radiance that leaves it. Next-event estimation samples the same
// lights from a shading point instead (render/light_sample.h).
#pragma once

#include <cmath>

#include "core/constants.h"
#include "core/sampling.h"
#include "geometry/motion.h"
#include "geometry/surface.h"
#include "render/light.h"
#include "render/scene_view.h"
#include "render/surface_color.h"

namespace candela {

// A point on a light's surface: its place (within `error` per axis), the unit normal of the
// side that emits, and the radiance that leaves it there.
struct EmissionPoint {
  Vec3 p, error, n, radiance;
};

// Whether area light `l`'s shape moves while the shutter is open (geometry/motion.h).
CANDELA_HDI bool areaLightMoves(const SceneView& scene, const Light& l) {
  return l.type == LightType::Sphere ? sphereMoves(scene, l.shape)
                                     : triangleMoves(scene, scene.triangles[l.shape]);
}

// The density by area with which sampleEmissionPoint picks a point of area light `l` on one
// side at `time`: one over its emitting area (a sphere's whole surface, a triangle's one side, or
// both sides of a two-sided one).
CANDELA_HDI float emissionAreaPdf(const SceneView& scene, const Light& l, float time) {
  if (l.type == LightType::Sphere) {
    const float r = sphereAt(scene, l.shape, time).radius;
    return 1.0f / (4.0f * kPi * r * r);
  }
  const Triangle& tri = scene.triangles[l.shape];
  Vec3 p[3];
  triangleCornersAt(scene, tri, time, p);
  const float twiceArea = length(cross(p[1] - p[0], p[2] - p[0]));
  const float sides = scene.materials[tri.material].twoSided ? 2.0f : 1.0f;
  return twiceArea > 0.0f ? 2.0f / (sides * twiceArea) : 0.0f;
}

// A point uniform over the emitting surface of area light `l` (a sphere, or a triangle's side:
// of a two-sided one, either side alike) where it stands at `time`, for (u1, u2) in [0, 1)^2.
CANDELA_HDI EmissionPoint sampleEmissionPoint(const SceneView& scene, const Light& l, float time,
                                              float u1, float u2) {
  EmissionPoint e;
  if (l.type == LightType::Sphere) {
    const Sphere s = sphereAt(scene, l.shape, time);
    e.n = sampleUniformCone(u1, u2, 2.0f);  // the whole sphere of directions
    e.p = spherePoint(s, e.n * s.radius, &e.error);
    e.radiance = sphereRadiance(scene, scene.materials[s.material], s, e.p);
    return e;
  }
  const Triangle& tri = scene.triangles[l.shape];
  const Material& m = scene.materials[tri.material];
  Vec3 corners[3];
  triangleCornersAt(scene, tri, time, corners);
  const Vec3 &p0 = corners[0], &p1 = corners[1], &p2 = corners[2];
  // A two-sided triangle's side: u1's lower half the outside, its upper half the back, each
  // half stretched over [0, 1) again for the point.
  const bool back = m.twoSided && u1 >= 0.5f;
  if (m.twoSided) u1 = back ? 2.0f * u1 - 1.0f : 2.0f * u1;
  float b[3];
  sampleUniformTriangle(u1, u2, b);
  e.p = trianglePoint(p0, p1, p2, b[1], b[2], &e.error);
  e.n = normalize(cross(p1 - p0, p2 - p0));  // the outside
  if (back) e.n = -e.n;
  e.radiance = triangleRadiance(scene, m, tri, b[1], b[2]);
  return e;
}

}  // namespace candela
