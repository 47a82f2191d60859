// Reading the environment; see environment_reader.h.
#include "scene/read/environment_reader.h"

#include <cmath>
#include <exception>
#include <memory>
#include <optional>

#include "image/image_io.h"
#include "scene/content_hash.h"
#include "scene/read/resolve_path.h"
#include "scene/read/texel_check.h"
#include "scene/scene_error.h"
#include "scene/sky_model.h"

namespace candela {
namespace {

// The sky's map: 1024 x 512 texels, a texel 0.35 degrees across, so that the horizon, where the
// sky meets the ground, blends over no more.
constexpr uint32_t kSkyMapWidth = 1024;

// {"sun": direction towards the sun, "turbidity": t, "ground": radiance}.
SkyParams readSky(const JsonValue& value) {
  JsonObject fields(value, {"sun", "turbidity", "ground"},
                    "a sky object {\"sun\": [x, y, z], \"turbidity\": t, \"ground\": colour}");
  SkyParams sky;
  const JsonValue sun = fields.require("sun");
  const Vec3 towards = sun.vec3();
  const double length = std::sqrt(double(towards.x) * towards.x + double(towards.y) * towards.y +
                                  double(towards.z) * towards.z);
  if (!(length > 0.0) || !std::isfinite(length))
    sun.failExpected("a direction towards the sun, not [0, 0, 0]");
  sky.sun = Vec3(float(towards.x / length), float(towards.y / length), float(towards.z / length));
  if (sky.sun.y < 0.0f)
    sun.failExpected("a sun at or above the horizon (y >= 0); the model has no night");
  if (std::optional<JsonValue> turbidity = fields.get("turbidity")) {
    sky.turbidity = turbidity->number();
    if (!(sky.turbidity >= kSkyTurbidityMin && sky.turbidity <= kSkyTurbidityMax))
      turbidity->failExpected("a turbidity from " + formatNumber(kSkyTurbidityMin) + " to " +
                              formatNumber(kSkyTurbidityMax) + " (the model's fitted range)");
  }
  if (std::optional<JsonValue> ground = fields.get("ground")) sky.ground = ground->colour();
  fields.finish();
  return sky;
}

// Makes `image` (what `what`, "map" or "sky", gave) the environment's map, unless its brightest
// texel times the colour and strength is beyond single precision.
void keepMap(ImageRGB image, const std::string& what, const JsonValue& value,
             EnvironmentDesc& environment) {
  const std::string overflow =
      firstTexelBeyondFloat(image, environment.color * environment.strength);
  if (!overflow.empty())
    value.fail("the " + what + "'s " + overflow + ", times color " + formatVec3(environment.color) +
               " and strength " + formatNumber(environment.strength) +
               " is beyond single precision; expected a smaller strength or color");
  environment.mapHash = hashImage(image);
  environment.image = std::make_shared<const ImageRGB>(std::move(image));
}

}  // namespace

EnvironmentDesc readEnvironment(const JsonValue& value, const std::string& baseDir) {
  JsonObject fields(value, {"color", "map", "sky", "strength", "rotation", "visible"});
  EnvironmentDesc environment;
  if (std::optional<JsonValue> visible = fields.get("visible"))
    environment.visible = visible->boolean();
  fields.exclusive("map", "sky");
  if (std::optional<JsonValue> sky = fields.get("sky")) {
    fields.reject("rotation", "not used by a \"sky\" (its \"sun\" gives the sun's direction)");
    environment.color = Vec3(1.0f);
    if (std::optional<JsonValue> color = fields.get("color")) environment.color = color->colour();
    if (std::optional<JsonValue> strength = fields.get("strength"))
      environment.strength = strength->nonNegativeNumber();
    fields.finish();
    keepMap(skyMap(readSky(*sky), kSkyMapWidth, kSkyMapWidth / 2), "sky", value, environment);
    return environment;
  }
  std::optional<JsonValue> map = fields.get("map");
  if (!map) {
    fields.reject("strength",
                  "not used by a constant environment (only with a \"map\" or \"sky\")");
    fields.reject("rotation", "not used by a constant environment (only with a \"map\")");
    environment.color = fields.require("color").colour();
    fields.finish();
    return environment;
  }
  const std::string written = map->string();
  environment.map = resolvePath(written, baseDir);
  environment.color = Vec3(1.0f);
  if (std::optional<JsonValue> color = fields.get("color")) environment.color = color->colour();
  if (std::optional<JsonValue> strength = fields.get("strength"))
    environment.strength = strength->nonNegativeNumber();
  if (std::optional<JsonValue> rotation = fields.get("rotation"))
    environment.rotation = rotation->vec3();
  fields.finish();

  ImageRGB image;
  try {
    image = readImage(environment.map);
  } catch (const std::exception& e) {
    map->fail(std::string("cannot read the environment map: ") + e.what());
  }
  if (image.width == 0 || image.height == 0) map->fail(written + ": the environment map is empty");
  const std::string bad = firstBadTexel(image);
  if (!bad.empty())
    map->fail(written + ": " + bad + "; expected finite, non-negative radiance in every texel");
  keepMap(std::move(image), "map", value, environment);
  return environment;
}

}  // namespace candela
