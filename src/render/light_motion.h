// Point and spot lights that move while the shutter is open (motion blur): where such a light
// stands, and where its cone and profile point, at a ray's time, between the poses that
// SceneView::lightPoses keeps at the geometry's motionTimes (geometry/motion.h). Lights with a
// surface move as their shapes do.
#pragma once

#include "core/vec3.h"
#include "geometry/motion.h"
#include "render/light.h"

namespace candela {

// A point light's pose at one of motionTimes: its place and the unit axes of its spot cone and of
// its profile (render/light_profile.h), which turn with it.
struct LightPose {
  Vec3 position;
  Vec3 spotAxis;
  Vec3 profileAxis, profileC0, profileC90;
};

// The unit vector a + (b - a) t (a where that is zero).
CANDELA_HDI Vec3 blendedAxis(const Vec3& a, const Vec3& b, float t) {
  const Vec3 v = a + (b - a) * t;
  const float len2 = lengthSquared(v);
  return len2 > 0.0f ? v / sqrtf(len2) : a;
}

// Moving point light `l` (l.moves) at `time`, out of line on the CPU where only scenes with
// motion call it (core/device.h). Its place moves linearly between two poses and its axes turn
// with them, the profile's kept perpendicular.
CANDELA_HD_CPU_CALL Light posedPointLight(const GeometryView& scene, const LightPose* poses,
                                          const Light& l, float time) {
  const MotionStep s = motionStepAt(scene, time);
  const LightPose& a = poses[l.shape + s.step];
  const LightPose& b = poses[l.shape + s.step + 1];
  Light at = l;
  at.position = a.position + (b.position - a.position) * s.t;
  at.spot.axis = blendedAxis(a.spotAxis, b.spotAxis, s.t);
  if (l.profile.texture >= 0) {
    const Vec3 axis = blendedAxis(a.profileAxis, b.profileAxis, s.t);
    const Vec3 c0 = blendedAxis(a.profileC0, b.profileC0, s.t);
    at.profile.axis = axis;
    at.profile.c0 = normalize(c0 - axis * dot(c0, axis));
    const Vec3 c90 = blendedAxis(a.profileC90, b.profileC90, s.t);
    at.profile.c90 = dot(cross(axis, at.profile.c0), c90) >= 0.0f ? cross(axis, at.profile.c0)
                                                                  : cross(at.profile.c0, axis);
  }
  return at;
}

}  // namespace candela
