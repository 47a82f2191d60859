// Evaluating animation tracks; see animation.h.
#include "scene/animation.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "render/bsdf.h"
#include "render/material_prepare.h"

namespace candela {
namespace {

void applyToCamera(CameraDesc& camera, AnimProperty property, const Vec3& v) {
  switch (property) {
    case AnimProperty::Position: camera.position = v; break;
    case AnimProperty::Rotation: camera.rotation = v; break;
    case AnimProperty::LookAt: camera.lookAt = v; break;
    case AnimProperty::Up: camera.up = v; break;
    case AnimProperty::Fov: camera.fov = v.x; break;
    case AnimProperty::ApertureRadius: camera.apertureRadius = v.x; break;
    case AnimProperty::FocusDistance: camera.focusDistance = v.x; break;
    default: break;  // not a camera property; the loader refuses such tracks
  }
}

// A material's roughness at a frame, with what it derives from it (a plastic's coat tables).
void setRoughness(Material& material, float roughness) {
  material.roughness = roughness;
  prepareMaterial(&material);
}

void applyToSphere(SphereDesc& sphere, AnimProperty property, const Vec3& v) {
  switch (property) {
    case AnimProperty::Position: sphere.position = v; break;
    case AnimProperty::Radius: sphere.radius = v.x; break;
    case AnimProperty::Color: sphere.material.color = v; break;
    case AnimProperty::Roughness:
      setRoughness(sphere.material, v.x);
      break;
    case AnimProperty::Anisotropy:
      sphere.material.anisotropy = v.x;
      break;
    case AnimProperty::Scattering:
      sphere.material.scattering = v;
      break;
    default: break;
  }
}

void applyToObject(ObjectDesc& object, AnimProperty property, const Vec3& v) {
  switch (property) {
    case AnimProperty::Position: object.position = v; break;
    case AnimProperty::Rotation: object.rotation = v; break;
    case AnimProperty::Scale: object.scale = v; break;
    case AnimProperty::Color:
      if (!object.material) object.material = Material{};  // diffuse, as a static "color"
      object.material->color = v;
      break;
    case AnimProperty::Roughness:
      if (object.material) setRoughness(*object.material, v.x);  // the loader refuses none
      break;
    case AnimProperty::Anisotropy:
      if (object.material) object.material->anisotropy = v.x;
      break;
    case AnimProperty::Scattering:
      if (object.material) object.material->scattering = v;
      break;
    default: break;
  }
}

void applyToLight(LightDesc& light, AnimProperty property, const Vec3& v) {
  switch (property) {
    case AnimProperty::Position: light.position = v; break;
    case AnimProperty::Intensity: light.intensity = v.x; break;
    case AnimProperty::Color: light.color = v; break;
    case AnimProperty::Radius: light.radius = v.x; break;
    case AnimProperty::Direction:
      light.direction = v;
      break;
    case AnimProperty::Angle:
      light.angleDegrees = v.x;
      break;
    case AnimProperty::LookAt:
      light.lookAt = v;
      break;
    case AnimProperty::Up:
      if (light.rectangle) light.rectangle->up = v;
      break;
    case AnimProperty::Size:
      if (light.rectangle) light.rectangle->size = Vec2(v.x, v.y);
      break;
    default: break;
  }
}

// The index k of the keys a and b = keys[k + 1] around `time`, strictly inside the keyed range:
// keys[k].frame <= time < keys[k + 1].frame, by bisection.
size_t keyBefore(const std::vector<AnimKey>& keys, double time) {
  const auto after = std::upper_bound(keys.begin(), keys.end(), time,
                                      [](double t, const AnimKey& key) { return t < key.frame; });
  return size_t(after - keys.begin()) - 1;
}

}  // namespace

Vec3 evaluateTrack(const AnimTrack& track, uint32_t frame) {
  const std::vector<AnimKey>& keys = track.keys;
  if (frame <= keys.front().frame) return keys.front().value;
  if (frame >= keys.back().frame) return keys.back().value;
  const size_t k = keyBefore(keys, double(frame));
  const AnimKey& a = keys[k];
  const AnimKey& b = keys[k + 1];
  const float t = float(frame - a.frame) / float(b.frame - a.frame);
  return a.value + (b.value - a.value) * t;  // exactly a.value at t = 0
}

Vec3 evaluateTrackAt(const AnimTrack& track, double time) {
  const double whole = std::floor(time);
  if (time == whole && whole >= 0.0 && whole <= double(kMaxFrames))
    return evaluateTrack(track, uint32_t(whole));  // a frame's value, to the bit
  const std::vector<AnimKey>& keys = track.keys;
  if (time <= double(keys.front().frame)) return keys.front().value;
  if (time >= double(keys.back().frame)) return keys.back().value;
  const size_t k = keyBefore(keys, time);
  const AnimKey& a = keys[k];
  const AnimKey& b = keys[k + 1];
  const float t = float((time - a.frame) / double(b.frame - a.frame));
  return a.value + (b.value - a.value) * t;
}

CameraDesc cameraAtTime(const CameraDesc& camera, const AnimationDesc& animation, double time) {
  CameraDesc result = camera;
  for (const AnimTrack& track : animation.tracks)
    if (track.target == AnimTarget::Camera)
      applyToCamera(result, track.property, evaluateTrackAt(track, time));
  return result;
}

namespace {

// Whether `track` moves what an open shutter blurs: the camera, an object's placement, a sphere.
bool blurs(const AnimTrack& track) {
  switch (track.target) {
    case AnimTarget::Camera:
      return true;
    case AnimTarget::Object:
      return track.property == AnimProperty::Position || track.property == AnimProperty::Rotation ||
             track.property == AnimProperty::Scale;
    case AnimTarget::Sphere:
      return track.property == AnimProperty::Position || track.property == AnimProperty::Radius;
    case AnimTarget::Light:
      return track.property == AnimProperty::Position ||
             track.property == AnimProperty::Direction || track.property == AnimProperty::LookAt ||
             track.property == AnimProperty::Up || track.property == AnimProperty::Radius ||
             track.property == AnimProperty::Size;
  }
  return false;
}

bool same(const Vec3& a, const Vec3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

}  // namespace

std::vector<double> shutterTimes(const AnimationDesc& animation, uint32_t frame) {
  if (!(animation.shutterClose > animation.shutterOpen) ||
      (std::none_of(animation.tracks.begin(), animation.tracks.end(), blurs) &&
       !animation.meshesMove))
    return {};
  const double open = double(frame) + animation.shutterOpen;
  const double close = double(frame) + animation.shutterClose;
  std::vector<double> times;
  for (uint32_t i = 0; i <= kShutterSegments; ++i)
    times.push_back(i == kShutterSegments ? close : open + (close - open) * i / kShutterSegments);
  for (double whole = std::floor(open) + 1; whole < close; ++whole) times.push_back(whole);
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  return times;
}

CameraDesc cameraAtFrame(const CameraDesc& camera, const AnimationDesc& animation,
                         uint32_t frame) {
  return cameraAtTime(camera, animation, double(frame));  // a whole time: each track's frame value
}

ShutterBlur shutterBlur(const SceneDesc& scene) {
  ShutterBlur blur;
  if (!scene.animation) return blur;
  std::set<uint32_t> objects, spheres, lights;
  for (const AnimTrack& track : scene.animation->tracks) {
    if (!blurs(track)) continue;
    if (track.target == AnimTarget::Camera) blur.camera = true;
    if (track.target == AnimTarget::Object) objects.insert(track.index);
    if (track.target == AnimTarget::Sphere) spheres.insert(track.index);
    if (track.target == AnimTarget::Light) lights.insert(track.index);
  }
  for (uint32_t i = 0; i < scene.objects.size(); ++i)
    if (scene.objects[i].meshMotion) objects.insert(i);
  blur.objects = uint32_t(objects.size());
  blur.spheres = uint32_t(spheres.size());
  blur.lights = uint32_t(lights.size());
  return blur;
}

LightDesc lightAtFrame(const LightDesc& light, uint32_t index, const AnimationDesc& animation,
                       uint32_t frame) {
  return lightAtTime(light, index, animation, double(frame));  // a whole time: each key's value
}

LightDesc lightAtTime(const LightDesc& light, uint32_t index, const AnimationDesc& animation,
                      double time) {
  LightDesc result = light;
  for (const AnimTrack& track : animation.tracks)
    if (track.target == AnimTarget::Light && track.index == index)
      applyToLight(result, track.property, evaluateTrackAt(track, time));
  return result;
}

namespace {

bool samePose(const SpherePose& a, const SpherePose& b) {
  return same(a.position, b.position) && a.radius == b.radius;
}

bool samePose(const ObjectPose& a, const ObjectPose& b) {
  return same(a.position, b.position) && same(a.rotation, b.rotation) && same(a.scale, b.scale) &&
         a.mesh == b.mesh;
}

// Whether two meshes of one motion have their vertices and normals in the same places.
bool samePlaces(const MeshDesc& a, const MeshDesc& b) {
  const auto equal = [](const std::vector<Vec3>& u, const std::vector<Vec3>& v) {
    return u.size() == v.size() &&
           std::equal(u.begin(), u.end(), v.begin(),
                      [](const Vec3& x, const Vec3& y) { return same(x, y); });
  };
  return equal(a.positions, b.positions) && equal(a.normals, b.normals);
}

// Gives the objects of `result` whose meshes move (ObjectDesc::meshMotion) their meshes at each
// of `times` (in frames) in their shutter poses, beside the placements their tracks give them
// there; an object whose mesh and placement stay put while the shutter is open gets none.
void poseMovingMeshes(const AnimationDesc& animation, const std::vector<double>& times,
                      SceneDesc& result) {
  for (ObjectDesc& object : result.objects) {
    if (!object.meshMotion) continue;
    std::vector<ObjectPose> poses = object.shutterPoses;
    if (poses.empty())
      poses.assign(times.size(), ObjectPose{object.position, object.rotation, object.scale});
    bool moves = !object.shutterPoses.empty();
    for (size_t k = 0; k < times.size(); ++k) {
      poses[k].mesh = object.meshMotion->meshAt(times[k] / double(animation.fps));
      moves = moves || !samePlaces(*poses[k].mesh, *poses[0].mesh);
    }
    object.shutterPoses = moves ? std::move(poses) : std::vector<ObjectPose>();
  }
}

bool samePose(const LightDesc& a, const LightDesc& b) {
  const auto sameUp = [](const LightDesc& x, const LightDesc& y) {
    const std::optional<Vec3> none;
    const std::optional<Vec3>& u = x.rectangle ? x.rectangle->up : none;
    const std::optional<Vec3>& v = y.rectangle ? y.rectangle->up : none;
    return u.has_value() == v.has_value() && (!u || same(*u, *v));
  };
  const bool sameSize = !a.rectangle || (a.rectangle->size.x == b.rectangle->size.x &&
                                         a.rectangle->size.y == b.rectangle->size.y);
  return same(a.position, b.position) && same(a.direction, b.direction) &&
         a.lookAt.has_value() == b.lookAt.has_value() &&
         (!a.lookAt || same(*a.lookAt, *b.lookAt)) && a.radius == b.radius && sameSize &&
         sameUp(a, b);
}

// Shape `index` of `shapes` (the scene's spheres or objects, which tracks name as `target`) at each
// of `times` (in frames), its tracks in `animation` applied by `apply`: the poses `poseOf` takes
// of it, or none where they are all one.
template <class Shape, class Apply, class PoseOf>
auto shutterPosesOf(const std::vector<Shape>& shapes, uint32_t index, AnimTarget target,
                    const AnimationDesc& animation, const std::vector<double>& times,
                    const Apply& apply, const PoseOf& poseOf) {
  std::vector<decltype(poseOf(shapes[index]))> poses;
  for (double time : times) {
    Shape at = shapes[index];
    for (const AnimTrack& t : animation.tracks)
      if (t.target == target && t.index == index) apply(at, t.property, evaluateTrackAt(t, time));
    poses.push_back(poseOf(at));
  }
  if (std::all_of(poses.begin(), poses.end(),
                  [&](const auto& pose) { return samePose(pose, poses.front()); }))
    poses.clear();
  return poses;
}

// Gives the spheres, objects and lights of `result` that the tracks of `animation` move across
// `times` (in frames) their poses there; those that stay put get none.
void poseMovingShapes(const AnimationDesc& animation, const std::vector<double>& times,
                      const SceneDesc& scene, SceneDesc& result) {
  for (const AnimTrack& track : animation.tracks) {
    if (!blurs(track)) continue;
    if (track.target == AnimTarget::Sphere) {
      SphereDesc& sphere = result.spheres[track.index];
      if (sphere.shutterPoses.empty())
        sphere.shutterPoses =
            shutterPosesOf(scene.spheres, track.index, AnimTarget::Sphere, animation, times,
                           applyToSphere, [](const SphereDesc& s) {
                             return SpherePose{s.position, s.radius};
                           });
    } else if (track.target == AnimTarget::Object) {
      ObjectDesc& object = result.objects[track.index];
      if (object.shutterPoses.empty())
        object.shutterPoses =
            shutterPosesOf(scene.objects, track.index, AnimTarget::Object, animation, times,
                           applyToObject, [](const ObjectDesc& o) {
                             return ObjectPose{o.position, o.rotation, o.scale};
                           });
    } else if (track.target == AnimTarget::Light) {
      LightDesc& light = result.lights[track.index];
      if (light.shutterPoses.empty())
        light.shutterPoses =
            shutterPosesOf(scene.lights, track.index, AnimTarget::Light, animation, times,
                           applyToLight, [](const LightDesc& l) { return l; });
    }
  }
}

}  // namespace

SceneDesc sceneAtFrame(const SceneDesc& scene, uint32_t frame) {
  SceneDesc result = scene;
  result.animation.reset();
  result.render.seed = scene.render.seed + frame;
  if (!scene.animation) return result;
  for (ObjectDesc& object : result.objects)
    if (object.meshMotion)
      object.mesh = object.meshMotion->meshAt(frame / double(scene.animation->fps));
  for (const AnimTrack& track : scene.animation->tracks) {
    const Vec3 v = evaluateTrack(track, frame);
    switch (track.target) {
      case AnimTarget::Camera: applyToCamera(result.camera, track.property, v); break;
      case AnimTarget::Sphere: applyToSphere(result.spheres[track.index], track.property, v); break;
      case AnimTarget::Object: applyToObject(result.objects[track.index], track.property, v); break;
      case AnimTarget::Light: applyToLight(result.lights[track.index], track.property, v); break;
    }
  }
  const std::vector<double> times = shutterTimes(*scene.animation, frame);
  if (times.empty()) return result;
  const double span = times.back() - times.front();
  for (double time : times) result.shutterTimes.push_back(float((time - times.front()) / span));
  if (std::any_of(scene.animation->tracks.begin(), scene.animation->tracks.end(),
                  [](const AnimTrack& t) { return t.target == AnimTarget::Camera; }))
    for (size_t k = 0; k < times.size(); ++k)
      result.shutterCameras.push_back(
          {result.shutterTimes[k], cameraAtTime(scene.camera, *scene.animation, times[k])});
  result.shutterRowExposure = scene.animation->rowExposure;
  poseMovingShapes(*scene.animation, times, scene, result);
  poseMovingMeshes(*scene.animation, times, result);
  return result;
}

}  // namespace candela
