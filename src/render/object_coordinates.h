// The object_coordinates pass's value at a hit (docs/aovs.md): where the point lies in its
// object's own frame, normalised to [0, 1] over the object's box, so that it names the same
// point of the object however the object is placed, moved or posed (a normalised object
// coordinate space, NOCS, as Kubric's object_coordinates).
#pragma once

#include "geometry/surface.h"
#include "render/scene_view.h"

namespace candela {

// A sphere's from its unit sphere's box, [-1, 1]^3; a triangle's between its vertices'
// (SceneView::objectCoordinates, laid out only where the pass is rendered; 0 elsewhere).
CANDELA_HDI Vec3 objectCoordinatesAt(const SceneView& scene, const Hit& hit,
                                     const SurfacePoint& sp) {
  if (hit.prim < scene.sphereCount) return 0.5f * (sp.ng + Vec3(1.0f));
  if (scene.objectCoordinateCount == 0) return Vec3(0.0f);
  const Triangle& t = scene.triangles[hit.prim - scene.sphereCount];
  const float b0 = 1.0f - hit.b1 - hit.b2;
  return b0 * scene.objectCoordinates[t.v[0]] + hit.b1 * scene.objectCoordinates[t.v[1]] +
         hit.b2 * scene.objectCoordinates[t.v[2]];
}

}  // namespace candela
