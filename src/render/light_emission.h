// Where a light subpath leaves a light with a surface (render/light_path.h): a point uniform over
// the light's area, with the radiance that leaves it. Next-event estimation samples the same
// lights from a shading point instead (render/light_sample.h).
#pragma once

#include <cmath>

#include "core/constants.h"
#include "core/sampling.h"
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

// The density by area with which sampleEmissionPoint picks a point of area light `l` on one
// side: one over its emitting area (a sphere's whole surface, a triangle's one side, or both
// sides of a two-sided one).
CANDELA_HDI float emissionAreaPdf(const SceneView& scene, const Light& l) {
  if (l.type == LightType::Sphere) {
    const float r = scene.spheres[l.shape].radius;
    return 1.0f / (4.0f * kPi * r * r);
  }
  const Triangle& tri = scene.triangles[l.shape];
  const Vec3& p0 = scene.positions[tri.v[0]];
  const float twiceArea =
      length(cross(scene.positions[tri.v[1]] - p0, scene.positions[tri.v[2]] - p0));
  const float sides = scene.materials[tri.material].twoSided ? 2.0f : 1.0f;
  return twiceArea > 0.0f ? 2.0f / (sides * twiceArea) : 0.0f;
}

// A point uniform over the emitting surface of area light `l` (a sphere, or a triangle's side:
// of a two-sided one, either side alike) for (u1, u2) in [0, 1)^2.
CANDELA_HDI EmissionPoint sampleEmissionPoint(const SceneView& scene, const Light& l, float u1,
                                              float u2) {
  EmissionPoint e;
  if (l.type == LightType::Sphere) {
    const Sphere& s = scene.spheres[l.shape];
    e.n = sampleUniformCone(u1, u2, 2.0f);  // the whole sphere of directions
    e.p = spherePoint(s, e.n * s.radius, &e.error);
    e.radiance = sphereRadiance(scene, scene.materials[s.material], s, e.p);
    return e;
  }
  const Triangle& tri = scene.triangles[l.shape];
  const Material& m = scene.materials[tri.material];
  const Vec3& p0 = scene.positions[tri.v[0]];
  const Vec3& p1 = scene.positions[tri.v[1]];
  const Vec3& p2 = scene.positions[tri.v[2]];
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
