// Pass files beside an image; see pass_files.h.
#include "apps/cli/pass_files.h"

#include <array>
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "image/image_io.h"
#include "scene/camera_crop.h"
#include "scene/camera_resolve.h"
#include "scene/flatten.h"
#include "scene/instance_poses.h"

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

// The camera's and the poses' files beside `image` (encodeCamera, encodePoses).
std::string cameraPath(const std::string& image) { return siblingPath(image, "camera", ".json"); }
std::string posesPath(const std::string& image) { return siblingPath(image, "poses", ".json"); }

// The names --aov takes beside the passes, for files of the scene's description.
struct DescriptionFile {
  const char* name;
  const char* what;
  bool PassFiles::*wanted;
};
constexpr DescriptionFile kDescriptionFiles[] = {
    {"camera", "the camera's matrices", &PassFiles::camera},
    {"poses", "each instance's pose", &PassFiles::poses}};

// The shortest text that reads back to `value` as a float.
std::string floatText(float value) {
  return nlohmann::basic_json<nlohmann::ordered_map, std::vector, std::string, bool, std::int64_t,
                              std::uint64_t, float>(value)
      .dump();
}

// A matrix, a row a line, under a key indented by `indent`: [\n    [a, b, c],\n    ...\n  ].
template <class Rows>
std::string matrixText(const Rows& rows, const std::string& indent) {
  std::string text = "[";
  for (size_t i = 0; i < rows.size(); ++i) {
    text += (i ? ",\n" : "\n") + indent + "  [";
    for (size_t j = 0; j < rows[i].size(); ++j) text += (j ? ", " : "") + floatText(rows[i][j]);
    text += "]";
  }
  return text + "\n" + indent + "]";
}

// Whether pass `aov` of `image` goes into a sibling .pfm: every pass of a .png or .pfm but a
// .png's alpha, which is the PNG's own (an .exr holds them all).
bool inSiblingFile(const std::string& image, Aov aov) {
  return !isExrPath(image) && !(aov == Aov::Alpha && !isFloatImagePath(image));
}

}  // namespace

PassFiles parsePassFiles(const std::string& list) {
  PassFiles files;
  std::vector<std::string> passes;
  for (const std::string& name : splitPassList(list)) {
    bool described = false;
    for (const DescriptionFile& file : kDescriptionFiles)
      if (name == file.name) files.*file.wanted = described = true;
    if (!described) passes.push_back(name);
  }
  try {
    files.aovs = aovsFromNames(passes);
  } catch (const std::invalid_argument& e) {
    std::string known = "; and beside the image ";
    for (const DescriptionFile& file : kDescriptionFiles)
      known += std::string(&file == kDescriptionFiles ? "" : " and ") + file.name + " (" +
               file.what + ")";
    throw std::invalid_argument(e.what() + known);
  }
  return files;
}

std::vector<std::string> passFilePaths(const std::string& image, const PassFiles& files) {
  std::vector<std::string> paths;
  for (Aov aov : files.aovs)
    if (inSiblingFile(image, aov)) paths.push_back(siblingPath(image, aovName(aov), ".pfm"));
  if (hasAov(files.aovs, Aov::Instance)) paths.push_back(instanceNamesPath(image));
  if (files.camera) paths.push_back(cameraPath(image));
  if (files.poses) paths.push_back(posesPath(image));
  return paths;
}

std::string encodeInstanceNames(const SceneDesc& desc) {
  nlohmann::ordered_json table = nlohmann::ordered_json::object();
  for (const auto& [number, name] : instanceNames(desc)) table[std::to_string(number)] = name;
  return table.dump(2) + "\n";
}

std::string encodeCamera(const SceneDesc& desc) {
  const CameraMatrices c = cameraMatrices(desc.camera, desc.file);
  std::array<std::array<float, 3>, 3> intrinsics;
  for (int i = 0; i < 3; ++i)
    intrinsics[i] = {c.intrinsics.m[i][0], c.intrinsics.m[i][1], c.intrinsics.m[i][2]};
  std::string text =
      "{\n  \"width\": " + std::to_string(c.width) + ",\n  \"height\": " + std::to_string(c.height);
  if (desc.camera.crop) text += ",\n  \"crop\": " + cropText(*desc.camera.crop);
  if (c.projection != CameraProjection::Perspective)
    text += ",\n  \"projection\": \"" + std::string(projectionName(c.projection)) + "\"";
  if (c.projection != CameraProjection::Equirectangular)
    text += ",\n  \"intrinsics\": " + matrixText(intrinsics, "  ");
  text += ",\n  \"extrinsics\": " + matrixText(affineRows(c.rotation, c.translation), "  ");
  if (c.apertureRadius > 0.0f)
    text += ",\n  \"aperture_radius\": " + floatText(c.apertureRadius) +
            ",\n  \"focus_distance\": " + floatText(c.focusDistance);
  if (!c.distortion.empty()) {
    text += ",\n  \"distortion\": [";
    for (size_t i = 0; i < c.distortion.size(); ++i)
      text += (i > 0 ? ", " : "") + floatText(c.distortion[i]);
    text += "]";
  }
  return text + "\n}\n";
}

std::string encodePoses(const SceneDesc& desc) {
  const CameraMatrices camera = cameraMatrices(desc.camera, desc.file);
  std::string text = "{";
  for (const InstancePose& pose : instancePoses(desc)) {
    const InstancePose seen = poseInCamera(pose, camera);
    text += std::string(text.size() > 1 ? ",\n" : "\n") + "  \"" + std::to_string(pose.number) +
            "\": {\n    \"name\": " + nlohmann::json(pose.name).dump() +
            ",\n    \"object_to_world\": " +
            matrixText(affineRows(pose.linear, pose.position), "    ") +
            ",\n    \"object_to_camera\": " +
            matrixText(affineRows(seen.linear, seen.position), "    ");
    if (const std::optional<Bounds3>& box = pose.modelBox)
      text += ",\n    \"model_box\": " +
              matrixText(std::array<std::array<float, 3>, 2>{{{box->lo.x, box->lo.y, box->lo.z},
                                                              {box->hi.x, box->hi.y, box->hi.z}}},
                         "    ");
    text += "\n  }";
  }
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
      const ImageLayer* alpha = nullptr;
      for (size_t i = 0; i < layers.size(); ++i)
        if (files.aovs[i] == Aov::Alpha && !inSiblingFile(image, Aov::Alpha)) alpha = &layers[i];
      out.emplace_back(image, encodeImage(image, result.image, desc.output, alpha));
      for (size_t i = 0; i < layers.size(); ++i) {
        if (!inSiblingFile(image, files.aovs[i])) continue;
        const std::string path = siblingPath(image, aovName(files.aovs[i]), ".pfm");
        out.emplace_back(path, encodeLayerPfm(path, layers[i]));
      }
    }
  }
  if (hasAov(files.aovs, Aov::Instance))
    out.emplace_back(instanceNamesPath(image), encodeInstanceNames(desc));
  if (files.camera) out.emplace_back(cameraPath(image), encodeCamera(desc));
  if (files.poses) out.emplace_back(posesPath(image), encodePoses(desc));
  return out;
}

}  // namespace candela::cli
