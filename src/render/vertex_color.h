// The colour a mesh's vertices give a point of a triangle (SceneView::vertexColors), interpolated
// by its barycentrics: 1 on spheres and in scenes without vertex colours.
#pragma once

#include "core/device.h"
#include "core/vec3.h"
#include "geometry/ray.h"
#include "render/scene_view.h"

namespace candela {

CANDELA_HDI Vec3 vertexColor(const SceneView& scene, const Hit& hit) {
  if (scene.vertexColorCount == 0 || hit.prim < scene.sphereCount) return Vec3(1.0f);
  const Triangle& tri = scene.triangles[hit.prim - scene.sphereCount];
  const float b0 = 1.0f - hit.b1 - hit.b2;
  return b0 * scene.vertexColors[tri.v[0]] + hit.b1 * scene.vertexColors[tri.v[1]] +
         hit.b2 * scene.vertexColors[tri.v[2]];
}

}  // namespace candela
