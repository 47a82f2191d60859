// Pass files beside an image; see pass_files.h.
#include "apps/cli/pass_files.h"

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>
#include <nlohmann/json.hpp>

#include "image/image_io.h"
#include "scene/camera_resolve.h"
#include "scene/flatten.h"

namespace fs = std::filesystem;

namespace candela::cli {

namespace {

std::string siblingPath(const std::string& image, const char* pass, const char* extension) {
  const fs::path path(image);
  return (path.parent_path() / (path.stem().string() + "." + pass + extension)).string();
}

// The instance names' table beside `image` (encodeInstanceNames).
std::string instanceNamesPath(const std::string& image) {
  return siblingPath(image, "instances", ".json");
}

// The camera file beside `image` (encodeCamera).
std::string cameraPath(const std::string& image) { return siblingPath(image, "camera", ".json"); }

constexpr const char* kCameraFile = "camera";

// The shortest text that reads back to `value` as a float.
std::string floatText(float value) {
  return nlohmann::basic_json<nlohmann::ordered_map, std::vector, std::string, bool, std::int64_t,
                              std::uint64_t, float>(value)
      .dump();
}

// A matrix, a row a line: [\n    [a, b, c],\n    ...\n  ].
std::string matrixText(const std::vector<std::vector<float>>& rows) {
  std::string text = "[";
  for (size_t i = 0; i < rows.size(); ++i) {
    text += i ? ",\n    [" : "\n    [";
    for (size_t j = 0; j < rows[i].size(); ++j) text += (j ? ", " : "") + floatText(rows[i][j]);
    text += "]";
  }
  return text + "\n  ]";
}

}  // namespace

PassFiles parsePassFiles(const std::string& list) {
  PassFiles files;
  std::vector<std::string> passes;
  for (const std::string& name : splitPassList(list)) {
    if (name == kCameraFile)
      files.camera = true;
    else
      passes.push_back(name);
  }
  try {
    files.aovs = aovsFromNames(passes);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(e.what() + std::string(", and ") + kCameraFile +
                                " (the camera's matrices)");
  }
  return files;
}

std::vector<std::string> passFilePaths(const std::string& image, const PassFiles& files) {
  std::vector<std::string> paths;
  if (!isExrPath(image))
    for (Aov aov : files.aovs) paths.push_back(siblingPath(image, aovName(aov), ".pfm"));
  if (hasAov(files.aovs, Aov::Instance)) paths.push_back(instanceNamesPath(image));
  if (files.camera) paths.push_back(cameraPath(image));
  return paths;
}

std::string encodeInstanceNames(const SceneDesc& desc) {
  nlohmann::ordered_json table = nlohmann::ordered_json::object();
  for (const auto& [number, name] : instanceNames(desc)) table[std::to_string(number)] = name;
  return table.dump(2) + "\n";
}

std::string encodeCamera(const SceneDesc& desc) {
  const CameraMatrices c = cameraMatrices(desc.camera, desc.file);
  std::vector<std::vector<float>> intrinsics, extrinsics;
  for (int i = 0; i < 3; ++i) {
    const float* k = c.intrinsics.m[i];
    const float* r = c.rotation.m[i];
    intrinsics.push_back({k[0], k[1], k[2]});
    extrinsics.push_back({r[0], r[1], r[2], c.translation[i]});
  }
  extrinsics.push_back({0.0f, 0.0f, 0.0f, 1.0f});
  std::string text = "{\n  \"width\": " + std::to_string(c.width) +
                     ",\n  \"height\": " + std::to_string(c.height) +
                     ",\n  \"intrinsics\": " + matrixText(intrinsics) +
                     ",\n  \"extrinsics\": " + matrixText(extrinsics);
  if (c.apertureRadius > 0.0f)
    text += ",\n  \"aperture_radius\": " + floatText(c.apertureRadius) +
            ",\n  \"focus_distance\": " + floatText(c.focusDistance);
  return text + "\n}\n";
}

std::vector<std::pair<std::string, std::string>> encodeWithPasses(const std::string& image,
                                                                  const RenderResult& result,
                                                                  const SceneData& scene,
                                                                  const PassFiles& files,
                                                                  const SceneDesc& desc) {
  std::vector<std::pair<std::string, std::string>> out;
  if (files.aovs.empty()) {
    out.emplace_back(image, encodeImage(image, result.image, desc.output));
  } else {
    const std::vector<ImageLayer> layers = makeAovLayers(scene, files.aovs, result.aovs);
    if (isExrPath(image)) {
      out.emplace_back(image, encodeLayeredExr(image, result.image, layers));
    } else {
      out.emplace_back(image, encodeImage(image, result.image, desc.output));
      const std::vector<std::string> paths = passFilePaths(image, files);
      for (size_t i = 0; i < layers.size(); ++i)
        out.emplace_back(paths[i], encodeLayerPfm(paths[i], layers[i]));
    }
  }
  if (hasAov(files.aovs, Aov::Instance))
    out.emplace_back(instanceNamesPath(image), encodeInstanceNames(desc));
  if (files.camera) out.emplace_back(cameraPath(image), encodeCamera(desc));
  return out;
}

}  // namespace candela::cli
