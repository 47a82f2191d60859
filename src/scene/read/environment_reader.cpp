// Reading the environment; see environment_reader.h.
#include "scene/read/environment_reader.h"

#include <cmath>
#include <exception>
#include <filesystem>
#include <memory>
#include <optional>

#include "image/image_io.h"

namespace candela {
namespace {

// The first texel that is not a finite, non-negative radiance, as "texel (x, y) is ...", or "".
std::string badTexel(const ImageRGB& image) {
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 0; x < image.width; ++x) {
      const Vec3 t = image.at(x, y);
      for (int c = 0; c < 3; ++c) {
        const float v = t[c];
        const char* what =
            std::isnan(v) ? "NaN" : (std::isinf(v) ? "infinite" : (v < 0 ? "negative" : nullptr));
        if (what) return "texel (" + std::to_string(x) + ", " + std::to_string(y) + ") is " + what;
      }
    }
  return "";
}

}  // namespace

EnvironmentDesc readEnvironment(const JsonValue& value, const std::string& baseDir) {
  JsonObject fields(value, {"color", "map", "strength", "rotation"});
  EnvironmentDesc environment;
  std::optional<JsonValue> map = fields.get("map");
  if (!map) {
    fields.reject("strength", "not used by a constant environment (only with a \"map\")");
    fields.reject("rotation", "not used by a constant environment (only with a \"map\")");
    environment.color = fields.require("color").colour();
    fields.finish();
    return environment;
  }
  const std::string written = map->string();
  const std::filesystem::path path(written);
  environment.map = path.is_absolute() ? written : (std::filesystem::path(baseDir) / path).string();
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
  const std::string bad = badTexel(image);
  if (!bad.empty())
    map->fail(written + ": " + bad + "; expected finite, non-negative radiance in every texel");
  environment.image = std::make_shared<const ImageRGB>(std::move(image));
  return environment;
}

}  // namespace candela
