// Reading and checking the animation block; see animation_reader.h.
#include "scene/read/animation_reader.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>

#include "scene/along_up.h"
#include "scene/animation.h"
#include "scene/camera_resolve.h"
#include "scene/light_emission_desc.h"
#include "scene/read/camera_reader.h"
#include "scene/read/did_you_mean.h"
#include "scene/read/entity_reader.h"

namespace candela {
namespace {

struct PropertyName {
  const char* name;
  AnimProperty property;
};

const std::vector<PropertyName>& propertiesOf(AnimTarget target) {
  static const std::vector<PropertyName> camera = {
      {"position", AnimProperty::Position}, {"rotation", AnimProperty::Rotation},
      {"look_at", AnimProperty::LookAt},    {"up", AnimProperty::Up},
      {"fov", AnimProperty::Fov},           {"aperture_radius", AnimProperty::ApertureRadius},
      {"focus_distance", AnimProperty::FocusDistance}};
  static const std::vector<PropertyName> sphere = {
      {"position", AnimProperty::Position},     {"radius", AnimProperty::Radius},
      {"color", AnimProperty::Color},           {"roughness", AnimProperty::Roughness},
      {"anisotropy", AnimProperty::Anisotropy}, {"scattering", AnimProperty::Scattering}};
  static const std::vector<PropertyName> object = {
      {"position", AnimProperty::Position},    {"rotation", AnimProperty::Rotation},
      {"scale", AnimProperty::Scale},          {"color", AnimProperty::Color},
      {"roughness", AnimProperty::Roughness},  {"anisotropy", AnimProperty::Anisotropy},
      {"scattering", AnimProperty::Scattering}};
  static const std::vector<PropertyName> light = {{"position", AnimProperty::Position},
                                                  {"intensity", AnimProperty::Intensity},
                                                  {"color", AnimProperty::Color},
                                                  {"radius", AnimProperty::Radius},
                                                  {"direction", AnimProperty::Direction},
                                                  {"look_at", AnimProperty::LookAt},
                                                  {"angle", AnimProperty::Angle},
                                                  {"size", AnimProperty::Size},
                                                  {"up", AnimProperty::Up}};
  switch (target) {
    case AnimTarget::Camera: return camera;
    case AnimTarget::Sphere: return sphere;
    case AnimTarget::Object: return object;
    case AnimTarget::Light: break;
  }
  return light;
}

// What a track may name: "camera" and every id, in file order (for did-you-mean ties).
struct Targets {
  std::vector<std::string> names{"camera"};
  std::map<std::string, std::pair<AnimTarget, uint32_t>> byId;

  explicit Targets(const SceneDesc& scene) {
    add(scene.spheres, AnimTarget::Sphere);
    add(scene.objects, AnimTarget::Object);
    add(scene.lights, AnimTarget::Light);
  }
  template <typename Entities>
  void add(const Entities& entities, AnimTarget kind) {
    for (uint32_t i = 0; i < entities.size(); ++i) {
      if (entities[i].id.empty()) continue;
      names.push_back(entities[i].id);
      byId[entities[i].id] = {kind, i};
    }
  }
};

std::string describeTarget(AnimTarget target, const std::string& id) {
  switch (target) {
    case AnimTarget::Camera: return "the camera";
    case AnimTarget::Sphere: return "sphere " + candela::quoted(id);
    case AnimTarget::Object: return "object " + candela::quoted(id);
    case AnimTarget::Light: break;
  }
  return "light " + candela::quoted(id);
}

void readTarget(const JsonValue& value, const Targets& targets, AnimTrack& track,
                std::string* id) {
  *id = value.string();
  if (*id == "camera") {
    track.target = AnimTarget::Camera;
    return;
  }
  const auto found = targets.byId.find(*id);
  if (found == targets.byId.end()) {
    const std::string suggestion = closestMatch(*id, targets.names);
    value.fail("no sphere, object or light has id " + candela::quoted(*id) +
               (suggestion.empty() ? "" : " (did you mean " + candela::quoted(suggestion) + "?)"));
  }
  track.target = found->second.first;
  track.index = found->second.second;
}

void readProperty(const JsonValue& value, const std::string& targetName, AnimTrack& track) {
  const std::string name = value.string();
  std::vector<std::string> names;
  for (const PropertyName& p : propertiesOf(track.target)) {
    if (name == p.name) {
      track.property = p.property;
      return;
    }
    names.push_back(p.name);
  }
  const std::string suggestion = closestMatch(name, names);
  if (!suggestion.empty())
    value.fail(targetName + " has no animatable property " + candela::quoted(name) + ", did you mean " +
               candela::quoted(suggestion) + "?");
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "" : ", ") + candela::quoted(n);
  value.fail(targetName + " has no animatable property " + candela::quoted(name) + ", expected one of " +
             list);
}

Vec3 readValue(const JsonValue& value, AnimProperty property, const CameraDesc& camera) {
  switch (property) {
    case AnimProperty::Position:
    case AnimProperty::Rotation:
    case AnimProperty::LookAt:
    case AnimProperty::Up: return value.vec3();
    case AnimProperty::Fov:
      return Vec3(readFov(value, camera.projection));
    case AnimProperty::ApertureRadius:
    case AnimProperty::Intensity: return Vec3(value.nonNegativeNumber());
    case AnimProperty::FocusDistance:
    case AnimProperty::Radius: return Vec3(value.positiveNumber());
    case AnimProperty::Color:
    case AnimProperty::Scattering:
      return value.colour();
    case AnimProperty::Roughness:
    case AnimProperty::Anisotropy:
      return Vec3(value.unitNumber(property == AnimProperty::Roughness
                                       ? "a roughness in [0, 1]"
                                       : "an anisotropy in [0, 1]"));
    case AnimProperty::Scale: return readScale(value);
    case AnimProperty::Direction:
      return readDirection(value);
    case AnimProperty::Angle:
      return Vec3(readSunAngle(value));
    case AnimProperty::Size: {
      const Vec2 size = readRectangleSize(value);
      return Vec3(size.x, size.y, 0.0f);
    }
  }
  return Vec3(0.0f);
}

void readKeys(const JsonValue& value, AnimTrack& track, const CameraDesc& camera) {
  const std::string expectation = "a non-empty array of [frame, value] keys";
  const std::vector<JsonValue> keys = value.elements(expectation);
  if (keys.empty()) value.failExpected(expectation);
  for (const JsonValue& key : keys) {
    if (!key.json().is_array() || key.json().size() != 2)
      key.failExpected("a key [frame, value]");
    const std::vector<JsonValue> parts = key.elements();
    AnimKey k;
    k.frame = uint32_t(parts[0].integer(0, UINT32_MAX, "a non-negative integer frame"));
    k.value = readValue(parts[1], track.property, camera);
    if (!track.keys.empty()) {
      const AnimKey& previous = track.keys.back();
      if (k.frame <= previous.frame)
        key.fail("frames must increase, got " + std::to_string(k.frame) + " after " +
                 std::to_string(previous.frame));
      // Interpolating through zero would flatten the mesh (and divide its normals by zero).
      if (track.property == AnimProperty::Scale)
        for (int i = 0; i < 3; ++i)
          if ((k.value[i] > 0) != (previous.value[i] > 0))
            parts[1].fail("scale changes sign between keys, so the mesh would pass through "
                          "zero size");
    }
    track.keys.push_back(k);
  }
}

// How a camera with fixed extrinsics got them.
std::string posedBy(const CameraDesc& c) {
  return c.gltfFile.empty() ? "a camera given by \"extrinsics\""
                            : "a camera taken from a glTF file (\"gltf\")";
}

// Refuses a property that the target's style does not use.
void checkUsed(const JsonValue& property, const AnimTrack& track, const SceneDesc& scene) {
  const auto unused = [&](const std::string& why) {
    property.fail(candela::quoted(property.string()) + " is not used by " + why);
  };
  if (track.target == AnimTarget::Camera) {
    const CameraDesc& c = scene.camera;
    switch (track.property) {
      case AnimProperty::Fov:
        if (c.intrinsics) unused("a camera given by \"intrinsics\"");
        if (c.projection == CameraProjection::Equirectangular) unused("an equirectangular camera");
        if (c.projection == CameraProjection::Orthographic) unused("an orthographic camera");
        break;
      case AnimProperty::ApertureRadius:
      case AnimProperty::FocusDistance:
        if (c.projection == CameraProjection::Equirectangular) unused("an equirectangular camera");
        break;
      case AnimProperty::Position:
        if (c.extrinsicsR) unused(posedBy(c));
        break;
      case AnimProperty::Rotation:
        if (c.extrinsicsR) unused(posedBy(c));
        if (c.lookAt) unused("a camera aimed with \"look_at\"");
        break;
      case AnimProperty::LookAt:
      case AnimProperty::Up:
        if (!c.lookAt) unused("a camera without \"look_at\"");
        break;
      default: break;
    }
  } else if (track.target == AnimTarget::Light) {
    const LightDesc& light = scene.lights[track.index];
    const bool directional = light.type == LightType::Directional;
    const bool aimed = light.spot || light.rectangle || light.profile;
    const std::string name = light.type == LightType::Sphere ? "a sphere light"
                             : directional                   ? "a directional light"
                             : light.spot                    ? "a spot light"
                             : light.rectangle               ? "a rectangle light"
                                                             : "a point light";
    switch (track.property) {
      case AnimProperty::Color:
        if (light.rectangle && light.rectangle->texture.index >= 0)
          unused(name + " whose \"color\" is a texture");
        break;
      case AnimProperty::Radius:
        if (light.type != LightType::Sphere)
          unused(name + " (only \"sphere\" lights have a radius)");
        break;
      case AnimProperty::Position:
        if (directional) unused(name + " (it shines from infinitely far)");
        break;
      case AnimProperty::Direction:
        if (!directional && !aimed)
          unused(name +
                 " (only \"spot\", \"rectangle\" and \"directional\" lights, and point lights "
                 "with a \"profile\", have a direction)");
        if (light.lookAt) unused(name + " aimed with \"look_at\"");
        break;
      case AnimProperty::Angle:
        if (!directional) unused(name + " (only \"directional\" lights have a disc's angle)");
        break;
      case AnimProperty::LookAt:
        if (!light.lookAt)
          unused(name + " (only a spot or rectangle light aimed with \"look_at\" has one)");
        break;
      case AnimProperty::Size:
      case AnimProperty::Up:
        if (!light.rectangle) unused(name + " (only \"rectangle\" lights have a size and an up)");
        break;
      default:
        break;
    }
  } else if (track.property == AnimProperty::Color || track.property == AnimProperty::Roughness ||
             track.property == AnimProperty::Anisotropy ||
             track.property == AnimProperty::Scattering) {
    const Material* m = track.target == AnimTarget::Sphere
                                ? &scene.spheres[track.index].material
                                : (scene.objects[track.index].material
                                       ? &*scene.objects[track.index].material
                                       : nullptr);
    if (m && m->type == MaterialType::Emissive) unused("an emissive material");
    if (m && m->type == MaterialType::Mix) unused("a \"mix\" material");
    if (m && m->alpha.thinSheetIor > 0.0f) unused("a \"thin_glass\" material");
    if (track.property == AnimProperty::Color) {
      if (m && !isBlack(m->absorption))
        unused("glass with a \"transmission_depth\" (its colour sets what it absorbs, once)");
      return;
    }
    if (!m) unused("an object whose materials are its file's (give it a \"material\")");
    if (track.property == AnimProperty::Scattering) {
      if (m->type != MaterialType::Glass) unused("a material other than \"glass\"");
      return;
    }
    if (m->type == MaterialType::Diffuse || m->type == MaterialType::Translucent)
      unused("a \"diffuse\" material");
    if (track.property == AnimProperty::Anisotropy) {
      if (m->type == MaterialType::Plastic) unused("a \"plastic\" material");
      return;
    }
    if (m->roughnessTexture.index >= 0) unused("a material whose roughness is a texture");
  }
}

// The thin-lens fields must make sense together whichever of them is animated.
void checkLens(const JsonValue& value, const AnimationDesc& animation, const SceneDesc& scene) {
  const AnimTrack* aperture = nullptr;
  const AnimTrack* focus = nullptr;
  for (const AnimTrack& t : animation.tracks) {
    if (t.target != AnimTarget::Camera) continue;
    if (t.property == AnimProperty::ApertureRadius) aperture = &t;
    if (t.property == AnimProperty::FocusDistance) focus = &t;
  }
  const CameraDesc& c = scene.camera;
  if (focus && !aperture && c.apertureRadius == 0)
    failAt(value.file(), memberPath(focus->where, "property"),
           "\"focus_distance\" is not used by a pinhole camera (aperture_radius 0)");
  if (aperture && !focus && !c.focusDistance && !c.lookAt)
    failAt(value.file(), memberPath(aperture->where, "property"),
           "an animated \"aperture_radius\" needs \"focus_distance\" or \"look_at\" on the "
               "camera, or a focus_distance track");
}

// The camera must make finite rays at every frame (scene/camera_resolve.h), and a look_at camera
// must have a view direction, not parallel to up: checked for every frame when the camera is
// animated, so that no frame of a sequence is written before a bad one is found.
void checkCameraAtEveryFrame(const JsonValue& value, const AnimationDesc& animation,
                             const SceneDesc& scene) {
  AnimationDesc cameraTracks;
  for (const AnimTrack& t : animation.tracks)
    if (t.target == AnimTarget::Camera) cameraTracks.tracks.push_back(t);
  if (cameraTracks.tracks.empty()) return;
  const auto check = [&](const CameraDesc& c, const std::string& at) {
    if (c.lookAt) {
      const Vec3 f = *c.lookAt - c.position;
      if (isBlack(f)) value.fail(at + "the camera looks at its own position");
      if (alongUp(f, c.up)) value.fail(at + "the camera looks along its up direction");
    }
    if (const std::optional<CameraProblem> problem =
            cameraProblem(c, samplesBeyondEdge(scene.render.filter)))
      value.fail(at + problem->path + " " + problem->message);
  };
  cameraTracks.shutterOpen = animation.shutterOpen;
  cameraTracks.shutterClose = animation.shutterClose;
  for (uint32_t frame = 0; frame < animation.frames; ++frame) {
    check(cameraAtFrame(scene.camera, cameraTracks, frame),
          "at frame " + std::to_string(frame) + " ");
    // A motion-blurred frame's camera must be one at every time of its exposure too.
    for (double time : shutterTimes(cameraTracks, frame)) {
      char at[64];
      std::snprintf(at, sizeof(at), "at time %g (frame %u's exposure) ", time, frame);
      check(cameraAtTime(scene.camera, cameraTracks, time), at);
    }
  }
}

// The shutter (docs/scene-format.md, *Motion blur*): a fraction of the frame interval centred on
// the frame, or its opening and closing as offsets from the frame, in frames.
void readShutter(const JsonValue& value, AnimationDesc& animation) {
  if (value.json().is_array()) {
    const std::string expectation =
        "[open, close] with -1 <= open <= close <= 1 and close - open <= 1 (frames)";
    if (value.json().size() != 2) value.failExpected(expectation);
    std::vector<float> times;
    for (const JsonValue& time : value.elements()) times.push_back(time.number());
    if (!(times[0] >= -1.0f && times[1] <= 1.0f && times[0] <= times[1] &&
          times[1] - times[0] <= 1.0f))
      value.failExpected(expectation);
    animation.shutterOpen = times[0];
    animation.shutterClose = times[1];
    return;
  }
  const float open =
      value.unitNumber("a number in [0, 1] (the share of the frame interval, centred on the frame)",
                       " or [open, close]");
  animation.shutterOpen = -0.5f * open;
  animation.shutterClose = 0.5f * open;
}

// A light's aim must make a direction at every frame (and every time of a blurred frame's
// exposure): a spot or rectangle light aimed with look_at must not reach that point as either
// moves, an animated direction must not pass through zero between its keys, and a rectangle
// light's up must not run along its aim. The fault is put on the light's last track of position,
// look_at, direction or up.
void checkAimsAtEveryFrame(const AnimationDesc& animation, const SceneDesc& scene,
                           const std::string& file) {
  for (uint32_t i = 0; i < scene.lights.size(); ++i) {
    const LightDesc& light = scene.lights[i];
    if (!light.spot && !light.rectangle && light.type != LightType::Directional) continue;
    const AnimTrack* aim = nullptr;
    for (const AnimTrack& t : animation.tracks)
      if (t.target == AnimTarget::Light && t.index == i &&
          (t.property == AnimProperty::Position || t.property == AnimProperty::LookAt ||
           t.property == AnimProperty::Direction || t.property == AnimProperty::Up))
        aim = &t;
    if (!aim) continue;
    const auto check = [&](const LightDesc& at, const std::string& when) {
      if (at.lookAt) {
        if (isBlack(*at.lookAt - at.position))
          failAt(file, aim->where,
                 when + " the " + (at.spot ? "spot" : "rectangle") +
                     " light looks at its own position");
      } else if (isBlack(at.direction)) {  // any other has a unitVector
        failAt(file, aim->where, when + " the light's direction is zero");
      }
      if (at.rectangle && at.rectangle->up && alongUp(lightAxis(at), *at.rectangle->up))
        failAt(file, aim->where, when + " the rectangle light points along its up");
    };
    for (uint32_t frame = 0; frame < animation.frames; ++frame) {
      check(lightAtFrame(light, i, animation, frame), "at frame " + std::to_string(frame));
      // A motion-blurred frame's light must make one at every time of its exposure too.
      for (double time : shutterTimes(animation, frame)) {
        char when[64];
        std::snprintf(when, sizeof(when), "at time %g (frame %u's exposure)", time, frame);
        check(lightAtTime(light, i, animation, time), when);
      }
    }
  }
}

// A rolling shutter (docs/scene-format.md, *Motion blur*): {"row_exposure": e}, each row's share
// of an open shutter's exposure, e in [0, 1) (0 by default: each row an instant).
void readRollingShutter(const JsonValue& value, AnimationDesc& animation) {
  JsonObject fields(value, {"row_exposure"});
  animation.rowExposure = 0;
  if (std::optional<JsonValue> e = fields.get("row_exposure")) {
    const std::string expectation = "a number in [0, 1) (each row's share of the exposure)";
    animation.rowExposure = e->unitNumber(expectation);
    if (animation.rowExposure == 1.0f) e->failExpected(expectation);
  }
  fields.finish();
  if (!(animation.shutterClose > animation.shutterOpen))
    fields.fail("a rolling shutter needs an open \"shutter\" to read its rows over");
}

}  // namespace

AnimationDesc readAnimation(const JsonValue& value, const SceneDesc& scene) {
  JsonObject fields(value, {"frames", "fps", "tracks", "shutter", "rolling_shutter"});
  AnimationDesc animation;
  animation.frames =
      uint32_t(fields.require("frames").integer(1, kMaxFrames, "a positive integer"));
  if (std::optional<JsonValue> fps = fields.get("fps")) animation.fps = fps->positiveNumber();
  if (std::optional<JsonValue> shutter = fields.get("shutter")) readShutter(*shutter, animation);
  if (std::optional<JsonValue> rolling = fields.get("rolling_shutter"))
    readRollingShutter(*rolling, animation);

  const Targets targets(scene);
  std::map<std::pair<std::string, int>, std::string> animated;  // (target, property) -> track
  if (std::optional<JsonValue> tracks = fields.get("tracks")) {
    for (const JsonValue& element : tracks->elements()) {
      JsonObject t(element, {"target", "property", "keys"});
      AnimTrack track;
      track.where = element.path();
      std::string id;
      readTarget(t.require("target"), targets, track, &id);
      const std::string targetName = describeTarget(track.target, id);
      const JsonValue property = t.require("property");
      readProperty(property, targetName, track);
      checkUsed(property, track, scene);
      const auto previous = animated.emplace(std::make_pair(id, int(track.property)), track.where);
      if (!previous.second)
        element.fail(targetName + "'s " + property.string() + " is already animated by " +
                     previous.first->second);
      readKeys(t.require("keys"), track, scene.camera);
      t.finish();
      animation.tracks.push_back(std::move(track));
    }
  }
  fields.finish();
  checkLens(value, animation, scene);
  checkCameraAtEveryFrame(value, animation, scene);
  checkAimsAtEveryFrame(animation, scene, value.file());
  return animation;
}

}  // namespace candela
