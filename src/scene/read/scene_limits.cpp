// The scene's single-precision limits; see scene_limits.h.
#include "scene/read/scene_limits.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "scene/animation.h"
#include "scene/light_emission_desc.h"
#include "scene/read/json_reader.h"
#include "scene/scene_error.h"

namespace candela {
namespace {

// The tracks of `animation` that animate entity `index` of kind `target`.
AnimationDesc tracksOf(const SceneDesc& scene, AnimTarget target, uint32_t index) {
  AnimationDesc tracks;
  if (scene.animation)
    for (const AnimTrack& t : scene.animation->tracks)
      if (t.target == target && t.index == index) tracks.tracks.push_back(t);
  return tracks;
}

// Calls check(frame) for every frame where `tracks` animate the entity, or once (frame 0) where
// nothing does.
template <typename Check>
void atEveryFrame(const SceneDesc& scene, const AnimationDesc& tracks, const Check& check) {
  const uint32_t frames = tracks.tracks.empty() ? 1 : scene.animation->frames;
  for (uint32_t frame = 0; frame < frames; ++frame) check(frame);
}

// How a message names the frame: "at frame N, " for an animated entity, else nothing.
std::string atFrame(const AnimationDesc& tracks, uint32_t frame) {
  return tracks.tracks.empty() ? std::string() : "at frame " + std::to_string(frame) + ", ";
}

// Value `property` of the entity at `frame`: its track's, else `still`.
Vec3 propertyAt(const AnimationDesc& tracks, AnimProperty property, uint32_t frame,
                const Vec3& still) {
  for (const AnimTrack& t : tracks.tracks)
    if (t.property == property) return evaluateTrack(t, frame);
  return still;
}

double maxAbs(const Vec3& v) {
  return std::max({std::fabs(double(v.x)), std::fabs(double(v.y)), std::fabs(double(v.z))});
}

void failBeyond(const SceneDesc& scene, const std::string& where, const std::string& at,
                const std::string& what, double reach) {
  failAt(scene.file, where,
         at + what + " reaches " + formatNumber(reach) +
             " from the origin; expected geometry within " +
             formatNumber(float(kMaxWorldCoordinate)) +
             " (single precision cannot intersect it further out)");
}

}  // namespace

void checkLightEmission(const SceneDesc& scene) {
  for (uint32_t i = 0; i < scene.lights.size(); ++i) {
    const LightDesc& light = scene.lights[i];
    const AnimationDesc tracks = tracksOf(scene, AnimTarget::Light, i);
    atEveryFrame(scene, tracks, [&](uint32_t frame) {
      const std::string problem = lightEmissionProblem(lightAtFrame(light, i, tracks, frame));
      if (!problem.empty()) failAt(scene.file, light.where, atFrame(tracks, frame) + problem);
    });
  }
}

void checkWorldExtent(const SceneDesc& scene) {
  for (uint32_t i = 0; i < scene.spheres.size(); ++i) {
    const SphereDesc& sphere = scene.spheres[i];
    const AnimationDesc tracks = tracksOf(scene, AnimTarget::Sphere, i);
    atEveryFrame(scene, tracks, [&](uint32_t frame) {
      const Vec3 position = propertyAt(tracks, AnimProperty::Position, frame, sphere.position);
      const double radius = propertyAt(tracks, AnimProperty::Radius, frame, Vec3(sphere.radius)).x;
      const double reach = maxAbs(position) + radius;
      if (!(reach <= kMaxWorldCoordinate))
        failBeyond(scene, sphere.where, atFrame(tracks, frame), "the sphere", reach);
    });
  }
  // Sphere and rectangle lights are geometry too: a sphere, two triangles.
  for (uint32_t i = 0; i < scene.lights.size(); ++i) {
    const LightDesc& light = scene.lights[i];
    if (light.type != LightType::Sphere && !light.rectangle) continue;
    const AnimationDesc tracks = tracksOf(scene, AnimTarget::Light, i);
    atEveryFrame(scene, tracks, [&](uint32_t frame) {
      const LightDesc at = lightAtFrame(light, i, tracks, frame);
      const double halfDiagonal =
          at.rectangle ? 0.5 * std::hypot(double(at.rectangle->size.x), at.rectangle->size.y) : 0;
      const double reach = maxAbs(at.position) + double(at.radius) + halfDiagonal;
      if (!(reach <= kMaxWorldCoordinate))
        failBeyond(scene, light.where, atFrame(tracks, frame), "the light", reach);
    });
  }
  // Rotation keeps lengths: a mesh's farthest vertex from its origin bounds every turn. Objects
  // that place one mesh share its radius.
  std::map<const MeshDesc*, double> meshRadii;
  for (uint32_t i = 0; i < scene.objects.size(); ++i) {
    const ObjectDesc& object = scene.objects[i];
    const auto [found, fresh] = meshRadii.emplace(object.mesh.get(), 0.0);
    if (fresh)
      for (const Vec3& p : object.mesh->positions) {
        const double x = p.x, y = p.y, z = p.z;
        found->second = std::max(found->second, std::sqrt(x * x + y * y + z * z));
      }
    const double meshRadius = found->second;
    const AnimationDesc tracks = tracksOf(scene, AnimTarget::Object, i);
    atEveryFrame(scene, tracks, [&](uint32_t frame) {
      const Vec3 position = propertyAt(tracks, AnimProperty::Position, frame, object.position);
      const Vec3 scale = propertyAt(tracks, AnimProperty::Scale, frame, object.scale);
      const double reach = maxAbs(position) + maxAbs(scale) * meshRadius;
      if (!(reach <= kMaxWorldCoordinate))
        failBeyond(scene, object.where, atFrame(tracks, frame), "its mesh, scaled and placed,",
                   reach);
    });
  }
}

}  // namespace candela
