// The optical flow passes: where a camera sample's first hit moves on the image from this frame to
// the next, and to the previous (docs/aovs.md).
#pragma once

#include "core/vec2.h"
#include "render/aov.h"
#include "render/fisheye.h"
#include "render/panorama.h"
#include "render/scene_view.h"

namespace candela {

// The pixel `c` (camera-space point or direction) falls on through `camera`'s lens, when it
// lies in front of the camera (an orthographic camera's: a point, anywhere).
CANDELA_HDI bool projectToPixel(const FlowCamera& camera, const Vec3& c, Vec2* pixel) {
  if (camera.projection == CameraProjection::Orthographic) {
    const Vec3 h = camera.K * Vec3(c.x, c.y, 1.0f);
    *pixel = Vec2(h.x, h.y);
    return true;
  }
  if (camera.projection == CameraProjection::Equirectangular) {
    *pixel = panoramaPixel(c, camera.width, camera.height);
    return true;
  }
  if (camera.projection == CameraProjection::Fisheye) {
    const Vec2 n = fisheyePoint(camera.distortion, c);
    const Vec3 h = camera.K * Vec3(n.x, n.y, 1.0f);
    *pixel = Vec2(h.x, h.y);
    return true;
  }
  if (!(c.z > 0.0f)) return false;
  Vec3 n = c / c.z;
  if (camera.distortion.enabled) {
    const Vec2 bent = distortNormalized(camera.distortion, n.x, n.y);
    n = Vec3(bent.x, bent.y, 1.0f);
  }
  const Vec3 h = camera.K * n;
  *pixel = Vec2(h.x, h.y);
  return true;
}

// One direction of the flow: this frame's and the other frame's cameras, and each material's
// instance's motion to the other frame (by material), with where the vertices of meshes that
// move apart stand there.
struct FlowTarget {
  const FlowFrames* frames;
  const InstanceMotion* motions;
  const Vec3* vertices;
};

CANDELA_HDI FlowTarget forwardFlow(const SceneView& scene) {
  return {&scene.flow, scene.materialMotions, scene.flowVertices};
}

CANDELA_HDI FlowTarget backwardFlow(const SceneView& scene) {
  return {&scene.backwardFlow, scene.backwardMotions, scene.backwardFlowVertices};
}

// The flow of one sample in pixels towards `target`'s other frame (the next: forward flow; the
// previous: backward flow): the first hit carried by its instance's motion and projected by the
// other frame's camera, minus its projection by this frame's; a sample that saw the background
// follows its ray's direction, a point at infinity, so only the cameras' turning moves it. False
// where either projection is undefined (the point behind a camera, the background of an
// orthographic camera).
CANDELA_HDI bool sampleFlow(const SceneView& scene, const FlowTarget& target, const FirstHit& first,
                            const Vec3& rayDirection, Vec2* flow) {
  const FlowCamera& now = target.frames->now;
  const FlowCamera& next = target.frames->next;
  Vec3 fromNow, fromNext;
  if (first.hit) {
    const InstanceMotion& m = target.motions[first.material];
    fromNow = now.worldToCamera * (first.position - now.position);
    Vec3 moved = m.linear * first.position + m.offset;
    if (m.perVertex && first.prim >= scene.sphereCount) {
      // The same point of the triangle, between its vertices where they stand next.
      const Triangle& t = scene.triangles[first.prim - scene.sphereCount];
      moved = (1.0f - first.b1 - first.b2) * target.vertices[t.v[0]] +
              first.b1 * target.vertices[t.v[1]] + first.b2 * target.vertices[t.v[2]];
    }
    fromNext = next.worldToCamera * (moved - next.position);
  } else {
    // A point at infinity is no one pixel of an orthographic camera, which sees it everywhere.
    if (now.projection == CameraProjection::Orthographic ||
        next.projection == CameraProjection::Orthographic)
      return false;
    fromNow = now.worldToCamera * rayDirection;
    fromNext = next.worldToCamera * rayDirection;
  }
  Vec2 a, b;
  if (!projectToPixel(now, fromNow, &a) || !projectToPixel(next, fromNext, &b)) return false;
  *flow = Vec2(b.x - a.x, b.y - a.y);
  // A panorama wraps around: across its seam a point moves the short way.
  if (now.projection == CameraProjection::Equirectangular) {
    const float w = float(now.width);
    if (flow->x > 0.5f * w) flow->x -= w;
    if (flow->x < -0.5f * w) flow->x += w;
  }
  return true;
}

}  // namespace candela
