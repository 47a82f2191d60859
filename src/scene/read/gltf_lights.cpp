// Reading a glTF file's lights; see gltf_lights.h.
#include "scene/read/gltf_lights.h"

#include <cmath>
#include <memory>

#include "core/constants.h"
#include "scene/dvec3.h"
#include "scene/read/gltf_file.h"
#include "scene/read/gltf_nodes.h"
#include "scene/scene_error.h"

namespace candela {
namespace {

constexpr double kDegreesPerRadian = 180.0 / kPiDouble;
constexpr double kLumensPerWatt = 683.0;

// A number as a float, or the error "<where>: expected <what>, got <value>".
float finiteFloat(double value, const std::string& where, const std::string& what) {
  const float f = float(value);
  if (!std::isfinite(f))
    throw SceneError(where + ": expected " + what + ", got " + formatNumber(value));
  return f;
}

// The index of the light a node carries, or -1.
int lightOfNode(const tinygltf::Node& node, size_t lightCount, const std::string& where) {
  const auto found = node.extensions.find("KHR_lights_punctual");
  if (found == node.extensions.end()) return -1;
  const tinygltf::Value& extension = found->second;
  const std::string at = where + ".extensions.KHR_lights_punctual";
  if (!extension.IsObject() || !extension.Has("light") || !extension.Get("light").IsNumber())
    throw SceneError(at + ".light: expected the index of a light");
  const double index = extension.Get("light").GetNumberAsDouble();
  if (!(index >= 0 && index < double(lightCount) && index == std::floor(index)))
    throw SceneError(at + ".light: light " + formatNumber(index) + " does not exist (" +
                     std::to_string(lightCount) + " lights)");
  return int(index);
}

// What a glTF light is, whatever node places it.
LightDesc lightOf(const tinygltf::Light& l, const std::string& where) {
  LightDesc light;
  if (l.type == "directional")
    light.type = LightType::Directional;
  else if (l.type != "point" && l.type != "spot")
    throw SceneError(where + ".type: expected \"point\", \"spot\" or \"directional\", got \"" +
                     l.type + "\"");
  if (!(l.intensity >= 0))
    throw SceneError(where + ".intensity: expected a non-negative number, got " +
                     formatNumber(l.intensity));
  const double watts = l.type == "directional" ? l.intensity / kLumensPerWatt
                                               : 4.0 * kPiDouble * l.intensity / kLumensPerWatt;
  light.intensity = finiteFloat(watts, where + ".intensity", "a number within single precision");
  if (!l.color.empty()) {
    if (l.color.size() != 3)
      throw SceneError(where + ".color: expected 3 numbers, got " + std::to_string(l.color.size()));
    for (int c = 0; c < 3; ++c) {
      if (!(l.color[size_t(c)] >= 0))
        throw SceneError(where + ".color: expected non-negative numbers, got " +
                         formatNumber(l.color[size_t(c)]));
      light.color[c] = finiteFloat(l.color[size_t(c)], where + ".color", "finite numbers");
    }
  }
  if (l.type == "spot") {
    const double inner = l.spot.innerConeAngle, outer = l.spot.outerConeAngle;
    if (!(outer > 0 && outer <= kPiDouble / 2))
      throw SceneError(where + ".spot.outerConeAngle: expected an angle above 0, up to pi/2, got " +
                       formatNumber(outer));
    if (!(inner >= 0 && inner < outer))
      throw SceneError(where + ".spot.innerConeAngle: expected an angle from 0 to below the " +
                       "outerConeAngle, " + formatNumber(outer) + ", got " + formatNumber(inner));
    light.spot = SpotDesc{float(outer * kDegreesPerRadian), float(inner * kDegreesPerRadian)};
  }
  return light;
}

}  // namespace

std::vector<LightDesc> readGltfLights(const std::string& path, const std::string& label) {
  const std::unique_ptr<GltfFile> file = readGltfFile(path, label);
  const tinygltf::Model& model = file->model;
  std::vector<LightDesc> lights;
  forEachPlacedNode(model, label, [&](int index, const tinygltf::Node& node, const GltfMatrix& w) {
    const std::string where = label + ": nodes[" + std::to_string(index) + "]";
    const int which = lightOfNode(node, model.lights.size(), where);
    if (which < 0) return;
    LightDesc light =
        lightOf(model.lights[size_t(which)],
                label + ": extensions.KHR_lights_punctual.lights[" + std::to_string(which) + "]");
    light.where = where;
    const DVec3 position{w[12], w[13], w[14]};
    // A glTF light shines along its node's -z, whatever the node's scale.
    const DVec3 direction = unit(DVec3{-w[8], -w[9], -w[10]});
    if (!(std::fabs(position.x) < 1e30 && std::fabs(position.y) < 1e30 &&
          std::fabs(position.z) < 1e30))
      throw SceneError(where + ": the light's place is beyond reach");
    if (!std::isfinite(dot(direction, direction)))
      throw SceneError(where + ": the node's transform flattens the light");
    if (light.type != LightType::Directional) light.position = toVec3(position);
    if (light.type == LightType::Directional || light.spot) light.direction = toVec3(direction);
    lights.push_back(light);
  });
  if (lights.empty())
    throw SceneError(label + ": the file's scene places no lights (KHR_lights_punctual)");
  return lights;
}

}  // namespace candela
