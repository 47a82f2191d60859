// Pass files beside an image; see pass_files.h.
#include "apps/cli/pass_files.h"

#include <filesystem>
#include <nlohmann/json.hpp>

#include "image/image_io.h"
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

}  // namespace

std::vector<std::string> passFilePaths(const std::string& image, const std::vector<Aov>& aovs) {
  std::vector<std::string> paths;
  if (!isExrPath(image))
    for (Aov aov : aovs) paths.push_back(siblingPath(image, aovName(aov), ".pfm"));
  if (hasAov(aovs, Aov::Instance)) paths.push_back(instanceNamesPath(image));
  return paths;
}

std::string encodeInstanceNames(const SceneDesc& desc) {
  nlohmann::ordered_json table = nlohmann::ordered_json::object();
  for (const auto& [number, name] : instanceNames(desc)) table[std::to_string(number)] = name;
  return table.dump(2) + "\n";
}

std::vector<std::pair<std::string, std::string>> encodeWithPasses(const std::string& image,
                                                                  const RenderResult& result,
                                                                  const SceneData& scene,
                                                                  const std::vector<Aov>& aovs,
                                                                  const SceneDesc& desc) {
  if (aovs.empty()) return {{image, encodeImage(image, result.image, desc.output)}};
  const std::vector<ImageLayer> layers = makeAovLayers(scene, aovs, result.aovs);
  std::vector<std::pair<std::string, std::string>> files;
  if (isExrPath(image)) {
    files.emplace_back(image, encodeLayeredExr(image, result.image, layers));
  } else {
    files.emplace_back(image, encodeImage(image, result.image, desc.output));
    const std::vector<std::string> paths = passFilePaths(image, aovs);
    for (size_t i = 0; i < layers.size(); ++i)
      files.emplace_back(paths[i], encodeLayerPfm(paths[i], layers[i]));
  }
  if (hasAov(aovs, Aov::Instance))
    files.emplace_back(instanceNamesPath(image), encodeInstanceNames(desc));
  return files;
}

}  // namespace candela::cli
