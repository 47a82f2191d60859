// Values of glTF material extensions; see gltf_extension_values.h.
#include "scene/read/gltf_extension_values.h"

#include <cmath>
#include <utility>

#include "scene/scene_error.h"

namespace candela {

const tinygltf::Value* extension(const tinygltf::ExtensionMap& extensions, const char* name) {
  const auto found = extensions.find(name);
  return found != extensions.end() && found->second.IsObject() ? &found->second : nullptr;
}

double extensionNumber(const tinygltf::Value* object, const char* key, double fallback,
                       const std::string& where) {
  if (!object || !object->Has(key)) return fallback;
  const tinygltf::Value& value = object->Get(key);
  const double number = value.IsNumber() ? value.GetNumberAsDouble() : NAN;
  if (!std::isfinite(number)) throw SceneError(where + "." + key + ": expected a finite number");
  return number;
}

Vec3 extensionColour(const tinygltf::Value* object, const char* key, Vec3 fallback, float most,
                     const std::string& where) {
  if (!object || !object->Has(key)) return fallback;
  const tinygltf::Value& c = object->Get(key);
  Vec3 colour;
  for (int i = 0; i < 3; ++i) {
    const tinygltf::Value& v = c.IsArray() && c.ArrayLen() == 3 ? c.Get(i) : tinygltf::Value();
    colour[i] = v.IsNumber() ? float(v.GetNumberAsDouble()) : NAN;
    if (!(colour[i] >= 0.0f && colour[i] <= most && std::isfinite(colour[i])))
      throw SceneError(where + "." + key + ": expected three " +
                       (std::isfinite(most) ? "numbers in [0, " + formatNumber(most) + "]"
                                            : std::string("finite, non-negative numbers")));
  }
  return colour;
}

float unitFactor(double value, const std::string& where) {
  if (!(value >= 0.0 && value <= 1.0))
    throw SceneError(where + ": expected a number between 0 and 1, got " +
                     formatNumber(float(value)));
  return float(value);
}

float extensionFactor(const tinygltf::Value* object, const char* key, double fallback,
                      const std::string& where) {
  return unitFactor(extensionNumber(object, key, fallback, where), where + "." + key);
}

Shading mixOf(Shading first, Shading second, float weight, const TextureRef& map,
              uint32_t channel) {
  Shading mix;
  mix.material.type = MaterialType::Mix;
  mix.material.mixWeight = weight;
  mix.material.mixWeightTexture = map;
  mix.material.mixWeightChannel = channel;
  mix.parts = {std::move(first), std::move(second)};
  return mix;
}

}  // namespace candela
