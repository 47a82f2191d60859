// Pass files beside an image; see pass_files.h.
#include "apps/cli/pass_files.h"

#include <filesystem>

#include "image/image_io.h"

namespace fs = std::filesystem;

namespace candela::cli {

namespace {

std::string siblingPath(const std::string& image, const char* pass) {
  const fs::path path(image);
  return (path.parent_path() / (path.stem().string() + "." + pass + ".pfm")).string();
}

}  // namespace

std::vector<std::string> passFilePaths(const std::string& image, const std::vector<Aov>& aovs) {
  std::vector<std::string> paths;
  if (isExrPath(image)) return paths;
  for (Aov aov : aovs) paths.push_back(siblingPath(image, aovName(aov)));
  return paths;
}

std::vector<std::pair<std::string, std::string>> encodeWithPasses(
    const std::string& image, const RenderResult& result, const SceneData& scene,
    const std::vector<Aov>& aovs, const OutputDesc& output) {
  if (aovs.empty()) return {{image, encodeImage(image, result.image, output)}};
  const std::vector<ImageLayer> layers = makeAovLayers(scene, aovs, result.aovs);
  if (isExrPath(image)) return {{image, encodeLayeredExr(image, result.image, layers)}};
  std::vector<std::pair<std::string, std::string>> files = {
      {image, encodeImage(image, result.image, output)}};
  const std::vector<std::string> paths = passFilePaths(image, aovs);
  for (size_t i = 0; i < layers.size(); ++i)
    files.emplace_back(paths[i], encodeLayerPfm(paths[i], layers[i]));
  return files;
}

}  // namespace candela::cli
