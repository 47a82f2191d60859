// Reading spheres, objects and lights; see entity_reader.h.
#include "scene/read/entity_reader.h"

#include <filesystem>

namespace candela {
namespace {

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
  sphere.material = readMaterialReference(fields, library, textures).value_or(Material{});
  fields.finish();
  return sphere;
}

ObjectDesc readObject(const JsonValue& value, const MaterialLibrary& library,
                      const std::string& baseDir, TextureLoader& textures) {
  JsonObject fields(
      value, {"id", "file", "position", "rotation", "scale", "material", "color", "ior", "smooth"});
  ObjectDesc object;
  object.where = value.path();
  object.id = readId(fields);
  const JsonValue file = fields.require("file");
  const std::string name = file.string();
  if (name.empty()) file.failExpected("the path of an OBJ or PLY file");
  const std::filesystem::path path(name);
  object.file = path.is_absolute() ? name : (std::filesystem::path(baseDir) / path).string();
  if (std::optional<JsonValue> position = fields.get("position"))
    object.position = position->vec3();
  if (std::optional<JsonValue> rotation = fields.get("rotation"))
    object.rotation = rotation->vec3();
  if (std::optional<JsonValue> scale = fields.get("scale")) object.scale = readScale(*scale);
  if (std::optional<JsonValue> smooth = fields.get("smooth")) readSmooth(*smooth, object);
  object.material = readMaterialReference(fields, library, textures);
  fields.finish();
  return object;
}

LightDesc readLight(const JsonValue& value) {
  JsonObject fields(value, {"id", "type", "position", "intensity", "color", "radius"});
  LightDesc light;
  light.where = value.path();
  light.id = readId(fields);
  if (std::optional<JsonValue> type = fields.get("type"))
    light.type = type->choice({"point", "sphere"}) == 0 ? LightType::Point : LightType::Sphere;
  light.position = fields.require("position").vec3();
  light.intensity = fields.require("intensity").nonNegativeNumber();
  if (std::optional<JsonValue> color = fields.get("color")) light.color = color->colour();
  if (light.type == LightType::Sphere)
    light.radius = fields.require("radius").positiveNumber();
  else
    fields.reject("radius", "not used by a point light (only \"sphere\" lights have a radius)");
  fields.finish();
  return light;
}

}  // namespace candela
