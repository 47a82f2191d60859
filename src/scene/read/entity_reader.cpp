// Reading spheres, objects and lights; see entity_reader.h.
#include "scene/read/entity_reader.h"

#include <cmath>
#include <sstream>
#include <utility>

#include "scene/along_up.h"
#include "scene/light_emission_desc.h"
#include "scene/read/gltf_lights.h"
#include "scene/read/gltf_loader.h"
#include "scene/read/ies_profile.h"
#include "scene/read/ply_loader.h"
#include "scene/read/resolve_path.h"
#include "scene/read/texel_check.h"
#include "scene/read/texture_reader.h"
#include "scene/read/transform_reader.h"
#include "scene/scene_error.h"
#include "scene/shape_meshes.h"

namespace candela {
namespace {

// The shapes' names, quoted: "a", "b" or "c".
std::string shapeList() {
  const std::vector<std::string>& names = shapeNames();
  std::string list;
  for (size_t i = 0; i < names.size(); ++i)
    list += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + quoted(names[i]);
  return list;
}

// An optional "id": a non-empty string other than "camera", which animation tracks use to name
// the camera. Uniqueness across the scene is the loader's check.
std::string readId(JsonObject& fields) {
  const std::optional<JsonValue> id = fields.get("id");
  if (!id) return "";
  const std::string text = id->string();
  if (text.empty()) id->failExpected("a non-empty string");
  if (text == "camera") id->failExpected("an id other than \"camera\", which names the camera");
  return text;
}

// `smooth`: true (the file's normals), false (flat faces), or a crease angle in degrees.
void readSmooth(const JsonValue& smooth, ObjectDesc& object) {
  const std::string expected = "true, false or a crease angle in degrees (above 0, up to 180)";
  if (smooth.json().is_boolean()) {
    object.smooth = smooth.boolean();
    return;
  }
  if (!smooth.json().is_number()) smooth.failExpected(expected);
  const double degrees = smooth.json().get<double>();
  if (!(degrees > 0 && degrees <= 180)) smooth.failExpected(expected);
  object.creaseDegrees = float(degrees);
}

// A spot or rectangle light's aim: "direction" (into light.direction) or "look_at".
void readAim(JsonObject& fields, const std::string& name, LightDesc& light) {
  fields.exclusive("direction", "look_at");
  if (std::optional<JsonValue> aim = fields.get("direction")) {
    light.direction = readDirection(*aim);
  } else if (std::optional<JsonValue> lookAt = fields.get("look_at")) {
    light.lookAt = lookAt->vec3();
    if (isBlack(*light.lookAt - light.position))
      lookAt->fail("the " + name + " looks at its own position");
  } else {
    fields.fail("missing \"direction\" or \"look_at\" (where the " + name + " points)");
  }
}

// A spot light's cone ("cutoff_angle", "beam_width").
SpotDesc readSpot(JsonObject& fields) {
  SpotDesc spot;
  const std::string cutoffRange = "an angle in degrees above 0, up to 180";
  if (std::optional<JsonValue> cutoff = fields.get("cutoff_angle")) {
    spot.cutoffDegrees = cutoff->number(cutoffRange);
    if (!(spot.cutoffDegrees > 0 && spot.cutoffDegrees <= 180)) cutoff->failExpected(cutoffRange);
  }
  spot.beamDegrees = 0.75f * spot.cutoffDegrees;
  if (std::optional<JsonValue> beam = fields.get("beam_width")) {
    std::ostringstream range;
    range << "an angle in degrees from 0 to the cutoff_angle, " << spot.cutoffDegrees;
    const std::string beamRange = range.str();
    spot.beamDegrees = beam->number(beamRange);
    if (!(spot.beamDegrees >= 0 && spot.beamDegrees <= spot.cutoffDegrees))
      beam->failExpected(beamRange);
  }
  return spot;
}

}  // namespace

Vec3 readScale(const JsonValue& value) {
  const std::string expectation = "a non-zero number";
  if (value.json().is_number()) {
    const float s = value.number(expectation);
    if (s == 0) value.failExpected(expectation);
    return Vec3(s);
  }
  if (!value.json().is_array() || value.json().size() != 3)
    value.failExpected("a non-zero number or an array of 3 non-zero numbers");
  Vec3 scale;
  const std::vector<JsonValue> elements = value.elements();
  for (int i = 0; i < 3; ++i) {
    scale[i] = elements[i].number(expectation);
    if (scale[i] == 0) elements[i].failExpected(expectation);
  }
  return scale;
}

float readSunAngle(const JsonValue& value) {
  const std::string range = "an apparent diameter in degrees from 0, below 180";
  const float degrees = value.number(range);
  if (!(degrees >= 0 && degrees < 180)) value.failExpected(range);
  return degrees;
}

Vec3 readDirection(const JsonValue& value) {
  const Vec3 v = value.vec3();
  if (isBlack(v)) value.failExpected("a direction of non-zero length");
  return unitVector(v);
}

SphereDesc readSphere(const JsonValue& value, const MaterialLibrary& library,
                      TextureLoader& textures) {
  JsonObject fields(value, {"id", "position", "center", "radius", "material", "color", "ior"});
  SphereDesc sphere;
  sphere.where = value.path();
  sphere.id = readId(fields);
  fields.exclusive("position", "center");
  std::optional<JsonValue> position = fields.get("position");
  if (!position) position = fields.get("center");
  if (!position) fields.fail("missing required key \"position\"");
  sphere.position = position->vec3();
  sphere.radius = fields.require("radius").positiveNumber();
  if (std::optional<MaterialRead> read = readMaterialReference(fields, library, textures)) {
    sphere.material = read->material;
    sphere.mixParts = std::move(read->parts);
  }
  // Its inside would need a light sampled from within (render/light_sample.h samples the cone a
  // sphere subtends from outside).
  if (sphere.material.twoSided) {
    const std::string why =
        "a two-sided emitter on a sphere, which emits outwards only; expected a material without "
        "\"two_sided\" or \"emission_two_sided\" (two-sided emitters are mesh faces and "
        "rectangle lights)";
    fields.require("material").fail(why);
  }
  // Traversal lets rays through mesh faces alone (geometry/alpha_mask.h).
  if (isMasked(sphere.material.alpha)) {
    const std::string why =
        sphere.material.alpha.thinSheetIor > 0.0f
            ? "a \"thin_glass\" material on a sphere; expected it on mesh faces (a thin sheet, "
              "such as a window pane), or \"glass\" for a solid sphere"
            : "a material with an \"alpha\" on a sphere; expected it on mesh faces (spheres are "
              "not masked)";
    fields.require("material").fail(why);
  }
  fields.finish();
  return sphere;
}

namespace {

// An object's "gltf_variant" and "gltf_node", which pick a glTF file's materials and nodes, its
// "gltf_animation", which it plays, and its "obj_group", which picks an OBJ file's group; `name`
// is its file as written.
void readGltfSelection(JsonObject& fields, const std::string& name, ObjectDesc& object) {
  if (std::optional<JsonValue> variant = fields.get("gltf_variant")) {
    object.gltfVariant = variant->string();
    if (object.gltfVariant.empty()) variant->failExpected("the name of one of the file's variants");
    if (!object.shape.empty())
      variant->fail("a glTF file's variant, and the object is a " + object.shape);
    if (!isGltfPath(object.file))
      variant->fail("a glTF file's variant, and \"" + name + "\" is not a glTF file");
    if (object.material)
      variant->fail("not used: the object's material replaces the file's, whatever the variant");
  }
  if (std::optional<JsonValue> node = fields.get("gltf_node")) {
    object.gltfNode = node->string();
    if (object.gltfNode.empty()) node->failExpected("the name of one of the file's nodes");
    if (!object.shape.empty())
      node->fail("a glTF file's node, and the object is a " + object.shape);
    if (!isGltfPath(object.file))
      node->fail("a glTF file's node, and \"" + name + "\" is not a glTF file");
  }
  if (std::optional<JsonValue> animation = fields.get("gltf_animation")) {
    if (!object.shape.empty())
      animation->fail("a glTF file's animation, and the object is a " + object.shape);
    if (!isGltfPath(object.file))
      animation->fail("a glTF file's animation, and \"" + name + "\" is not a glTF file");
    object.gltfAnimated = true;
    // A name or a number, or {"name" or "index", "start", "speed", "loop"}: its clock.
    std::optional<JsonValue> pick = animation;
    std::optional<JsonObject> clock;
    if (animation->json().is_object()) {
      clock.emplace(*animation, std::vector<std::string>{"name", "index", "start", "speed", "loop"},
                    "an animation's name or number, from 0, or an object of its \"name\" or "
                    "\"index\", \"start\", \"speed\" and \"loop\"");
      clock->exclusive("name", "index");
      pick = clock->has("name") ? clock->get("name") : clock->get("index");
      if (!pick) clock->fail("expected its \"name\" or its \"index\"");
      if (std::optional<JsonValue> start = clock->get("start"))
        object.gltfClock.start = start->number("the time in the animation, in seconds, at frame 0");
      if (std::optional<JsonValue> speed = clock->get("speed")) {
        object.gltfClock.speed =
            speed->number("how fast the animation plays (1: as the file says)");
        if (!(object.gltfClock.speed != 0.0))
          speed->failExpected("a speed other than 0 (negative plays it backwards)");
      }
      if (std::optional<JsonValue> loop = clock->get("loop"))
        object.gltfClock.loop = loop->boolean();
      clock->finish();
    }
    const std::string expectation = "an animation's name or number, from 0";
    if (pick->json().is_string()) {
      object.gltfAnimationName = pick->string();
      if (object.gltfAnimationName.empty()) pick->failExpected(expectation);
    } else {
      object.gltfAnimationNumber = int(pick->integer(0, 1u << 30, expectation));
    }
  }
  if (std::optional<JsonValue> group = fields.get("obj_group")) {
    object.objGroup = group->string();
    if (object.objGroup.empty())
      group->failExpected("the name of one of the file's groups (\"g\") or objects (\"o\")");
    if (!object.shape.empty())
      group->fail("an OBJ file's group, and the object is a " + object.shape);
    if (isGltfPath(object.file) || isPlyPath(object.file))
      group->fail("an OBJ file's group, and \"" + name + "\" is not an OBJ file");
  }
}

}  // namespace

ObjectDesc readObject(const JsonValue& value, const MaterialLibrary& library,
                      const std::string& baseDir, TextureLoader& textures) {
  JsonObject fields(value, {"id", "file", "shape", "position", "rotation", "scale", "transform",
                            "material", "color", "ior", "smooth", "vertex_colors", "gltf_variant",
                            "gltf_node", "gltf_animation", "obj_group"});
  ObjectDesc object;
  object.where = value.path();
  object.id = readId(fields);
  std::string name;  // the file as written
  fields.exclusive("file", "shape");
  if (std::optional<JsonValue> shape = fields.get("shape")) {
    if (shape->json().is_string() && shape->string() == "sphere")
      shape->fail("expected " + shapeList() +
                  "; a sphere goes in \"spheres\", exact, with a \"radius\"");
    object.shape = shapeNames()[shape->choice(shapeNames())];
  } else {
    if (!fields.has("file"))
      fields.fail("missing required key \"file\" (an OBJ, PLY or glTF file) or \"shape\" (" +
                  shapeList() + ")");
    const JsonValue file = fields.require("file");
    name = file.string();
    if (name.empty()) file.failExpected("the path of an OBJ, PLY or glTF file");
    object.file = resolvePath(name, baseDir);
  }
  for (const char* key : {"position", "rotation", "scale"}) fields.exclusive("transform", key);
  if (std::optional<JsonValue> transform = fields.get("transform")) {
    const Placement placement = readTransform(*transform);
    object.position = placement.position;
    object.rotation = placement.rotation;
    object.scale = placement.scale;
  }
  if (std::optional<JsonValue> position = fields.get("position"))
    object.position = position->vec3();
  if (std::optional<JsonValue> rotation = fields.get("rotation"))
    object.rotation = rotation->vec3();
  if (std::optional<JsonValue> scale = fields.get("scale")) object.scale = readScale(*scale);
  if (std::optional<JsonValue> smooth = fields.get("smooth")) readSmooth(*smooth, object);
  if (std::optional<JsonValue> colors = fields.get("vertex_colors"))
    object.vertexColors = colors->boolean();
  if (std::optional<MaterialRead> read = readMaterialReference(fields, library, textures)) {
    object.material = read->material;
    object.mixParts = std::move(read->parts);
  }
  readGltfSelection(fields, name, object);
  fields.finish();
  return object;
}

namespace {

// A rectangle light's "size" (a number for a square, or [width, height]) and "up" (any vector not
// along its axis).
RectangleDesc readRectangle(JsonObject& fields, const LightDesc& light) {
  RectangleDesc rectangle;
  const JsonValue size = fields.require("size");
  rectangle.size = readRectangleSize(size);
  if (std::optional<JsonValue> up = fields.get("up")) {
    rectangle.up = up->vec3();
    if (alongUp(lightAxis(light), *rectangle.up))
      up->failExpected("a direction that is not parallel to where the light points");
  }
  if (std::optional<JsonValue> twoSided = fields.get("two_sided"))
    rectangle.twoSided = twoSided->boolean();
  return rectangle;
}

}  // namespace

Vec2 readRectangleSize(const JsonValue& value) {
  const std::string expectation = "a positive number or [width, height], each positive";
  if (value.json().is_number()) {
    const float side = value.positiveNumber();
    return Vec2(side, side);
  }
  if (!value.json().is_array() || value.json().size() != 2) value.failExpected(expectation);
  const std::vector<JsonValue> elements = value.elements();
  return Vec2(elements[0].positiveNumber(), elements[1].positiveNumber());
}

namespace {

// A point or spot light's "profile", an IES file relative to the scene file's folder, and its
// "up" (the direction of the profile's C0 plane), after the light's aim.
ProfileDesc readProfile(const JsonValue& value, JsonObject& fields, TextureLoader& textures,
                        const LightDesc& light) {
  const std::string written = value.string();
  if (written.empty()) value.failExpected("the path of an IES file");
  ProfileDesc profile;
  try {
    const TextureLoader::LoadedProfile loaded =
        textures.loadProfile(textures.resolve(written), written);
    profile.texture = loaded.index;
    profile.firstDegrees = float(loaded.first);
    profile.lastDegrees = float(loaded.last);
  } catch (const SceneError& e) {
    value.fail(e.what());
  }
  profile.scale = float(1.0 / profileTextureMean(textures.texture(profile.texture),
                                                 profile.firstDegrees, profile.lastDegrees));
  if (std::optional<JsonValue> up = fields.get("up")) {
    profile.up = up->vec3();
    if (alongUp(lightAxis(light), *profile.up))
      up->failExpected("a direction that is not parallel to where the light points");
  }
  return profile;
}

}  // namespace

LightDesc readLight(const JsonValue& value, TextureLoader& textures) {
  JsonObject fields(value, {"id", "type", "position", "intensity", "color", "radius", "direction",
                            "look_at", "cutoff_angle", "beam_width", "angle", "size", "up",
                            "two_sided", "visible", "profile"});
  LightDesc light;
  light.where = value.path();
  light.id = readId(fields);
  enum Kind { kPoint, kSphere, kSpot, kDirectional, kRectangle };
  size_t kind = kPoint;
  if (std::optional<JsonValue> type = fields.get("type"))
    kind = type->choice({"point", "sphere", "spot", "directional", "rectangle"});
  static const char* const names[] = {"point light", "sphere light", "spot light",
                                      "directional light", "rectangle light"};
  const std::string notUsed = std::string("not used by a ") + names[kind];
  light.type = kind == kSphere        ? LightType::Sphere
               : kind == kDirectional ? LightType::Directional
               : kind == kRectangle   ? LightType::Triangle
                                      : LightType::Point;
  if (kind == kDirectional)
    fields.reject("position", notUsed + " (it shines from infinitely far along its \"direction\")");
  else
    light.position = fields.require("position").vec3();
  light.intensity = fields.require("intensity").nonNegativeNumber();
  const std::optional<JsonValue> color = fields.get("color");
  if (color && color->json().is_object() && !color->json().contains("temperature") &&
      kind != kRectangle)
    color->fail(
        "a texture, which only \"rectangle\" lights take; expected a colour or "
        "{\"temperature\": kelvin}");
  TextureRef texture;
  if (color) light.color = readLightColour(*color, textures, &texture);
  if (kind == kSphere)
    light.radius = fields.require("radius").positiveNumber();
  else
    fields.reject("radius", notUsed + " (only \"sphere\" lights have a radius)");
  if (kind != kDirectional)
    fields.reject("angle", notUsed + " (only \"directional\" lights have a disc's angle)");
  if (kind == kSpot || kind == kRectangle) {
    readAim(fields, names[kind], light);
  } else if (kind == kDirectional) {
    fields.reject("look_at", notUsed + " (it shines along its \"direction\", from infinitely far)");
    light.direction = readDirection(fields.require("direction"));
    if (std::optional<JsonValue> angle = fields.get("angle"))
      light.angleDegrees = readSunAngle(*angle);
  } else if (kind == kPoint && fields.has("profile")) {
    // A profile's axis: straight down unless it says otherwise.
    light.direction = Vec3(0.0f, -1.0f, 0.0f);
    if (fields.has("direction") || fields.has("look_at")) readAim(fields, names[kind], light);
  } else {
    fields.reject("direction", notUsed +
                                   " (only \"spot\", \"rectangle\" and \"directional\" lights, "
                                   "and point lights with a \"profile\", have a direction)");
    fields.reject("look_at", notUsed +
                                 " (only \"spot\" and \"rectangle\" lights, and point "
                                 "lights with a \"profile\", point at a place)");
  }
  if (kind == kPoint || kind == kSpot) {
    if (std::optional<JsonValue> profile = fields.get("profile"))
      light.profile = readProfile(*profile, fields, textures, light);
  } else {
    fields.reject("profile", notUsed + " (only \"point\" and \"spot\" lights have a profile)");
  }
  const bool seen =
      kind == kSphere || kind == kRectangle || (kind == kDirectional && light.angleDegrees > 0.0f);
  if (seen) {
    if (std::optional<JsonValue> visible = fields.get("visible"))
      light.visible = visible->boolean();
  } else {
    fields.reject("visible", notUsed + (kind == kDirectional
                                            ? " without an \"angle\" (a sun of no disc is "
                                              "never seen)"
                                            : " (only \"sphere\", \"rectangle\" and "
                                              "\"directional\" lights with a disc are seen)"));
  }
  if (kind == kSpot) {
    light.spot = readSpot(fields);
  } else {
    for (const char* key : {"cutoff_angle", "beam_width"})
      fields.reject(key, notUsed + " (only \"spot\" lights have a cone)");
  }
  if (kind == kRectangle) {
    light.rectangle = readRectangle(fields, light);
    light.rectangle->texture = texture;
    if (texture.index >= 0) {
      const std::string beyond =
          firstTexelBeyondFloat(textures.texture(texture.index), rectangleLightRadiance(light));
      if (!beyond.empty())
        color->fail("the texture's " + beyond + " times the light's radiance " +
                    formatVec3(rectangleLightRadiance(light)) +
                    " is beyond single precision; expected a smaller intensity");
    }
  } else {
    fields.reject("size", notUsed + " (only \"rectangle\" lights have a size)");
    if (!light.profile)
      fields.reject("up", notUsed +
                              " (only \"rectangle\" lights and lights with a \"profile\" "
                              "have an up)");
    fields.reject("two_sided", notUsed + " (only \"rectangle\" lights have two sides)");
  }
  fields.finish();
  return light;
}

bool namesGltfLights(const JsonValue& value) {
  return value.json().is_object() && value.json().contains("gltf");
}

std::vector<LightDesc> readGltfLightEntry(const JsonValue& value, const std::string& baseDir) {
  for (const auto& item : value.json().items())
    if (item.key() != "gltf" && !isCommentKey(item.key()))
      JsonValue(item.value(), value.file(), memberPath(value.path(), item.key()))
          .fail("not used beside \"gltf\" (the file gives each of its lights' values)");
  JsonObject fields(value, {"gltf"});
  const JsonValue gltf = fields.require("gltf");
  const std::string written = gltf.string();
  if (written.empty()) gltf.failExpected("the path of a glTF file");
  const std::string file = resolvePath(written, baseDir);
  std::vector<LightDesc> lights;
  try {
    lights = readGltfLights(file, written);
  } catch (const SceneError& e) {
    gltf.fail(e.what());
  }
  for (LightDesc& light : lights) {
    light.where = gltf.path() + ": " + light.where;
    light.gltfFile = file;
  }
  fields.finish();
  return lights;
}

}  // namespace candela
