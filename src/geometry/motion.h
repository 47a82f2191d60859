// Primitives that move while the shutter is open (motion blur): where a moving vertex or sphere
// stands at a ray's time, between the poses GeometryView keeps at motionTimes (linearly within
// each step: the steps are short enough that a turning mesh keeps its size, docs/scene-format.md).
#pragma once

#include <cstdint>

#include "core/oct_normal.h"
#include "core/vec3.h"
#include "geometry/geometry_view.h"

namespace candela {

// What vertexMotions and sphereMotions hold for what does not move.
constexpr uint32_t kStill = 0xffffffffu;

// Where `time` falls among the poses: between pose `step` and the next, `t` of the way.
struct MotionStep {
  uint32_t step = 0;
  float t = 0.0f;
};

// A time outside [0, 1] (a wide pixel filter's sample beyond the first or last row under a
// rolling shutter) takes the nearer end's pose, as the camera does (render/camera_motion.h). The
// times are even steps but for a whole frame here and there (scene/animation.h's shutterTimes),
// so the step that an even spacing predicts is at most one or two off.
CANDELA_HDI MotionStep motionStepAt(const GeometryView& scene, float time) {
  const float* times = scene.motionTimes;
  const uint32_t last = scene.motionTimeCount - 2;  // the last step's first pose
  time = time < 0.0f ? 0.0f : (time > 1.0f ? 1.0f : time);
  const float guess = time * float(last + 1);
  MotionStep s;
  s.step = guess < float(last) ? uint32_t(guess) : last;
  while (s.step > 0 && time < times[s.step]) --s.step;
  while (s.step < last && time >= times[s.step + 1]) ++s.step;
  const float span = times[s.step + 1] - times[s.step];
  s.t = span > 0.0f ? (time - times[s.step]) / span : 0.0f;
  if (s.t > 1.0f) s.t = 1.0f;
  return s;
}

CANDELA_HDI bool triangleMoves(const GeometryView& scene, const Triangle& tri) {
  return scene.vertexMotionCount != 0 && scene.vertexMotions[tri.v[0]] != kStill;
}

CANDELA_HDI bool sphereMoves(const GeometryView& scene, uint32_t sphere) {
  return scene.sphereMotionCount != 0 && scene.sphereMotions[sphere] != kStill;
}

// Vertex v's position at `s` (v must move).
CANDELA_HDI Vec3 movingPosition(const GeometryView& scene, uint32_t v, MotionStep s) {
  const Vec3* poses = scene.motionPositions + scene.vertexMotions[v] + s.step;
  return poses[0] + (poses[1] - poses[0]) * s.t;
}

// Vertex v's shading normal at `s`, unit length (v must move and have a normal).
CANDELA_HDI Vec3 movingNormal(const GeometryView& scene, uint32_t v, MotionStep s) {
  const OctNormal* poses = scene.motionNormals + scene.vertexMotions[v] + s.step;
  const Vec3 a = decodeOctNormal(poses[0]), b = decodeOctNormal(poses[1]);
  const Vec3 n = a + (b - a) * s.t;
  const float len2 = lengthSquared(n);
  return len2 > 0.0f ? n / sqrtf(len2) : a;
}

// The corners of triangle `tri` at step `s` (motionStepAt of the time), moving or not.
CANDELA_HDI void triangleCornersAt(const GeometryView& scene, const Triangle& tri, MotionStep s,
                                   Vec3 (&p)[3]) {
  if (!triangleMoves(scene, tri)) {
    for (int k = 0; k < 3; ++k) p[k] = scene.positions[tri.v[k]];
    return;
  }
  for (int k = 0; k < 3; ++k) p[k] = movingPosition(scene, tri.v[k], s);
}

// The corners of moving triangle `tri` at `time`: out of line on the CPU, where only scenes with
// motion call it (core/device.h).
CANDELA_HD_CPU_CALL void movingCornersAt(const GeometryView& scene, const Triangle& tri, float time,
                                         Vec3 (&p)[3]) {
  triangleCornersAt(scene, tri, motionStepAt(scene, time), p);
}

CANDELA_HDI_ALWAYS void triangleCornersAt(const GeometryView& scene, const Triangle& tri,
                                          float time, Vec3 (&p)[3]) {
  if (!triangleMoves(scene, tri)) {
    for (int k = 0; k < 3; ++k) p[k] = scene.positions[tri.v[k]];
    return;
  }
  movingCornersAt(scene, tri, time, p);
}

// Sphere `sphere` at step `s`, moving or not.
CANDELA_HDI Sphere sphereAt(const GeometryView& scene, uint32_t sphere, MotionStep s) {
  if (!sphereMoves(scene, sphere)) return scene.spheres[sphere];
  const Sphere* poses = scene.motionSpheres + scene.sphereMotions[sphere] + s.step;
  Sphere at = scene.spheres[sphere];
  at.center = poses[0].center + (poses[1].center - poses[0].center) * s.t;
  at.radius = poses[0].radius + (poses[1].radius - poses[0].radius) * s.t;
  return at;
}

CANDELA_HDI Sphere sphereAt(const GeometryView& scene, uint32_t sphere, float time) {
  return sphereAt(scene, sphere,
                  sphereMoves(scene, sphere) ? motionStepAt(scene, time) : MotionStep());
}

}  // namespace candela
