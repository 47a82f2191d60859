// The scene of a glTF file alone; see gltf_scene.h.
#include "scene/read/gltf_scene.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>

#include "scene/dvec3.h"
#include "scene/read/gltf_accessor.h"
#include "scene/read/gltf_file.h"
#include "scene/read/gltf_instancing.h"
#include "scene/read/gltf_nodes.h"
#include "scene/scene_error.h"

namespace candela {
namespace {

constexpr uint32_t kWidth = 960, kHeight = 540;
constexpr double kFovDegrees = 40;  // across the width

// What the file's scene places: its cameras, its lights and the bounds of its meshes' vertices.
struct Staging {
  bool camera = false, lights = false;
  DVec3 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
           std::numeric_limits<double>::infinity()};
  DVec3 hi{-lo.x, -lo.y, -lo.z};
};

Staging stagingOf(const tinygltf::Model& model, const std::string& label) {
  Staging s;
  forEachPlacedNode(
      model, label, [&](int index, const tinygltf::Node& node, const GltfMatrix& world) {
        s.camera = s.camera || node.camera >= 0;
        s.lights = s.lights || node.extensions.count("KHR_lights_punctual") > 0;
        if (node.mesh < 0 || size_t(node.mesh) >= model.meshes.size()) return;  // the loader says
        std::vector<GltfMatrix> placements;
        try {
          placements = meshPlacements(model, index, node, world, label);
        } catch (const SceneError&) {
          return;  // likewise
        }
        for (const tinygltf::Primitive& primitive : model.meshes[size_t(node.mesh)].primitives) {
          const auto position = primitive.attributes.find("POSITION");
          if (position == primitive.attributes.end()) continue;
          std::vector<float> xyz;
          try {
            xyz = readFloatAccessor(model, position->second, 3, kAnyEncoding, "POSITION");
          } catch (const SceneError&) {
            continue;  // the mesh loader refuses it, with its path
          }
          for (const GltfMatrix& w : placements)
            for (size_t v = 0; v + 2 < xyz.size(); v += 3) {
              const double x = xyz[v], y = xyz[v + 1], z = xyz[v + 2];
              const DVec3 p{w[0] * x + w[4] * y + w[8] * z + w[12],
                            w[1] * x + w[5] * y + w[9] * z + w[13],
                            w[2] * x + w[6] * y + w[10] * z + w[14]};
              s.lo = {std::min(s.lo.x, p.x), std::min(s.lo.y, p.y), std::min(s.lo.z, p.z)};
              s.hi = {std::max(s.hi.x, p.x), std::max(s.hi.y, p.y), std::max(s.hi.z, p.z)};
            }
        }
      });
  return s;
}

std::array<double, 3> array3(const DVec3& v) { return {v.x, v.y, v.z}; }

}  // namespace

std::string gltfSceneText(const std::string& path, const std::string& label) {
  const std::unique_ptr<GltfFile> file = readGltfFile(path, label);
  const Staging staging = stagingOf(file->model, label);
  const std::string name = std::filesystem::path(path).filename().string();
  nlohmann::json scene;
  nlohmann::json camera = {{"width", kWidth}, {"height", kHeight}};
  if (staging.camera) {
    camera["gltf"] = name;
  } else if (staging.lo.x <= staging.hi.x) {
    // The bounds' sphere fits the narrower, vertical field of view, seen from the front (glTF's
    // +z), the right and above.
    const DVec3 centre = 0.5 * (staging.lo + staging.hi);
    const double radius =
        std::max(0.5 * std::sqrt(dot(staging.hi - staging.lo, staging.hi - staging.lo)),
                 1e-6 * std::max(1.0, std::sqrt(dot(centre, centre))));
    const double halfHeight = std::atan(std::tan(kFovDegrees * kPi / 360.0) * kHeight / kWidth);
    const DVec3 from = unit(DVec3{0.55, 0.4, 1.0});
    const DVec3 eye = centre + (1.05 * radius / std::sin(halfHeight)) * from;
    camera["fov"] = kFovDegrees;
    // Bounds beyond single precision are the mesh loader's to refuse, with their place.
    if (std::fabs(eye.x) + std::fabs(eye.y) + std::fabs(eye.z) < 1e30) {
      camera["position"] = array3(eye);
      camera["look_at"] = array3(centre);
    }
  }
  scene["camera"] = camera;
  scene["render"] = {{"max_depth", 8}, {"gamma", "srgb"}};
  scene["objects"] = nlohmann::json::array({{{"file", name}}});
  if (staging.lights) {
    scene["lights"] = nlohmann::json::array({{{"gltf", name}}});
  } else {  // a soft sun from above, left and in front, under a pale sky
    scene["environment"] = {{"color", 0.6}};
    scene["lights"] = nlohmann::json::array({{{"type", "directional"},
                                              {"direction", {0.45, -1, -0.75}},
                                              {"intensity", 2},
                                              {"angle", 4}}});
  }
  return scene.dump();
}

}  // namespace candela
