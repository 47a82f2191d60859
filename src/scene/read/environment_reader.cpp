// Reading the environment; see environment_reader.h.
#include "scene/read/environment_reader.h"

#include <exception>
#include <memory>
#include <optional>

#include "image/image_io.h"
#include "scene/content_hash.h"
#include "scene/read/resolve_path.h"
#include "scene/read/texel_check.h"
#include "scene/scene_error.h"

namespace candela {

EnvironmentDesc readEnvironment(const JsonValue& value, const std::string& baseDir) {
  JsonObject fields(value, {"color", "map", "strength", "rotation", "visible"});
  EnvironmentDesc environment;
  if (std::optional<JsonValue> visible = fields.get("visible"))
    environment.visible = visible->boolean();
  std::optional<JsonValue> map = fields.get("map");
  if (!map) {
    fields.reject("strength", "not used by a constant environment (only with a \"map\")");
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
  const std::string overflow =
      firstTexelBeyondFloat(image, environment.color * environment.strength);
  if (!overflow.empty())
    value.fail("the map's " + overflow + ", times color " + formatVec3(environment.color) +
               " and strength " + formatNumber(environment.strength) +
               " is beyond single precision; expected a smaller strength or color");
  environment.mapHash = hashImage(image);
  environment.image = std::make_shared<const ImageRGB>(std::move(image));
  return environment;
}

}  // namespace candela
