// Point, spot and directional lights that move while the shutter is open (motion blur): where
// such a light stands, and where its cone and profile point (or a directional light shines), at a
// ray's time, between the poses that SceneView::lightPoses keeps at the geometry's motionTimes
// (geometry/motion.h). Lights with a surface move as their shapes do.
#pragma once

#include "core/vec3.h"
#include "geometry/motion.h"
#include "render/light.h"

namespace candela {

// A light's pose at one of motionTimes: a point light's place and the unit axes of its spot cone
// (`axis`) and of its profile (render/light_profile.h), which turn with it; a directional light's
// direction (`axis`).
struct LightPose {
  Vec3 position;
  Vec3 axis;
  Vec3 profileAxis, profileC0, profileC90;
};

// The unit vector a + (b - a) t (a where that is zero).
CANDELA_HDI Vec3 blendedAxis(const Vec3& a, const Vec3& b, float t) {
  const Vec3 v = a + (b - a) * t;
  const float len2 = lengthSquared(v);
  return len2 > 0.0f ? v / sqrtf(len2) : a;
}

// Room for a posed copy of a light (posedLight) that is filled only where the light moves: a
// Light's own constructor would set every field on each call of the hot paths that may need one.
union PosedLightSlot {
  Light light;
  CANDELA_HDI PosedLightSlot() {}
};

// Moving light `l` (l.moves) at `time`, out of line on the CPU where only scenes with motion call
// it (core/device.h). Its place moves linearly between two poses and its axes turn with them, the
// profile's kept perpendicular.
CANDELA_HD_CPU_CALL Light posedLight(const GeometryView& scene, const LightPose* poses,
                                     const Light& l, float time) {
  const MotionStep s = motionStepAt(scene, time);
  const LightPose& a = poses[l.shape + s.step];
  const LightPose& b = poses[l.shape + s.step + 1];
  Light at = l;
  if (l.type == LightType::Directional) {
    at.direction = blendedAxis(a.axis, b.axis, s.t);
    return at;
  }
  at.position = a.position + (b.position - a.position) * s.t;
  at.spot.axis = blendedAxis(a.axis, b.axis, s.t);
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
