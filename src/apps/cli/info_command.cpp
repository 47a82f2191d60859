// `candela info`: loads and flattens the scene (building its BVH) and prints, one per line,
// the scene's counts, world bounds, image size, samples, its animation and the BVH statistics.
#include "apps/cli/info_command.h"

#include <cstdio>
#include <string>
#include <vector>

#include "apps/cli/scene_warnings.h"
#include "scene/animation.h"
#include "scene/camera_crop.h"
#include "scene/flatten.h"
#include "scene/light_emission_desc.h"
#include "scene/read/scene_loader.h"

namespace candela::cli {
namespace {

// What `blur` says an open shutter blurs: "the camera, 2 objects and 1 sphere"; empty for nothing.
std::string blurredList(const ShutterBlur& blur) {
  std::vector<std::string> parts;
  if (blur.camera) parts.push_back("the camera");
  const auto count = [&parts](uint32_t n, const char* noun) {
    if (n > 0) parts.push_back(std::to_string(n) + " " + noun + (n == 1 ? "" : "s"));
  };
  count(blur.objects, "object");
  count(blur.spheres, "sphere");
  count(blur.lights, "light");
  std::string list;
  for (size_t i = 0; i < parts.size(); ++i)
    list += (i == 0 ? "" : i + 1 == parts.size() ? " and " : ", ") + parts[i];
  return list;
}

// "animation:  48 frames at 24 fps, 2 tracks", and the shutter where it is open: its opening and
// closing in frames about each frame, a rolling shutter's rows, and what it blurs.
void printAnimation(const AnimationDesc& animation, const ShutterBlur& blur) {
  const size_t tracks = animation.tracks.size();
  std::printf("animation:  %u frame%s at %g fps, %zu track%s", animation.frames,
              animation.frames == 1 ? "" : "s", animation.fps, tracks, tracks == 1 ? "" : "s");
  if (animation.shutterClose > animation.shutterOpen) {
    std::printf("; shutter open from %+g to %+g frames", animation.shutterOpen,
                animation.shutterClose);
    if (animation.rowExposure < 1.0f)
      std::printf(", rolling (each row %g%% of it)", 100.0 * animation.rowExposure);
    const std::string blurred = blurredList(blur);
    std::printf("; it blurs %s", blurred.empty() ? "nothing (no track moves the camera, an object, "
                                                   "a sphere or a light)"
                                                 : blurred.c_str());
  }
  std::printf("\n");
}

// Per object of a glTF file with animations: `animations: objects[0]: "Walk" (1.2 s, played),
// "Run" (0.8 s)`, so that the names "gltf_animation" takes are at hand.
void printGltfAnimations(const SceneDesc& desc) {
  for (const ObjectDesc& object : desc.objects) {
    const auto& animations = object.mesh->animations;
    if (animations.empty()) continue;
    std::printf("animations: %s:", object.where.c_str());
    for (size_t i = 0; i < animations.size(); ++i) {
      const auto& [name, length] = animations[i];
      const bool played = object.gltfAnimated &&
                          (object.gltfAnimationName.empty() ? int(i) == object.gltfAnimationNumber
                                                            : name == object.gltfAnimationName);
      const std::string shown = name.empty() ? "#" + std::to_string(i) : "\"" + name + "\"";
      std::printf("%s %s (", i == 0 ? "" : ",", shown.c_str());
      if (length >= 0)
        std::printf("%g s", length);
      else
        std::printf("cannot be played");
      std::printf("%s)", played ? ", played" : "");
    }
    std::printf("\n");
  }
}

}  // namespace

CLI::App* addInfoCommand(CLI::App& app, InfoOptions* options) {
  CLI::App* cmd = app.add_subcommand("info", "Print a scene's contents and BVH statistics");
  cmd->add_option("scene", options->scene, "Scene file (JSON)")
      ->required()
      ->check(CLI::ExistingFile);
  return cmd;
}

int runInfo(const InfoOptions& options) {
  const SceneDesc desc = loadSceneFile(options.scene);
  printSceneWarnings(desc);
  const SceneData scene = flattenScene(desc);

  std::printf("scene:      %s\n", options.scene.c_str());
  std::printf("image:      %ux%u, %u spp%s\n", desc.camera.width, desc.camera.height,
              scene.settings.spp,
              desc.camera.crop ? (", crop " + cropText(*desc.camera.crop)).c_str() : "");
  std::printf("spheres:    %zu\n", desc.spheres.size());
  std::printf("objects:    %zu\n", desc.objects.size());
  std::printf("triangles:  %zu\n", scene.triangles.size());
  size_t points = 0, spots = 0, directional = 0, spheres = 0, faces = 0;
  bool environment = false;
  for (const Light& l : scene.lights) {
    switch (l.type) {
      case LightType::Point:
        ++(hasCone(l.spot) ? spots : points);
        break;
      case LightType::Sphere:
        ++spheres;
        break;
      case LightType::Triangle:
        ++faces;
        break;
      case LightType::Environment:
        environment = true;
        break;
      case LightType::Directional:
        ++directional;
        break;
    }
  }
  // A rectangle light is two emissive faces of the flattened scene, one light to its author.
  size_t rectangles = 0;
  for (const LightDesc& l : desc.lights)
    rectangles += l.rectangle && !isBlack(rectangleLightRadiance(l)) ? 1 : 0;
  faces -= 2 * rectangles;
  std::printf(
      "lights:     %zu (%zu point, %zu spot, %zu directional, %zu rectangle, %zu emissive spheres, "
      "%zu emissive faces%s)\n",
      scene.lights.size() - rectangles, points, spots, directional, rectangles, spheres, faces,
      environment ? ", the environment" : "");
  std::printf("materials:  %zu\n", scene.materials.size());
  if (desc.animation) printAnimation(*desc.animation, shutterBlur(desc));
  printGltfAnimations(desc);

  Vec3 lo, hi;
  scene.bounds(&lo, &hi);
  if (lo.x > hi.x || lo.y > hi.y || lo.z > hi.z)
    std::printf("bounds:     empty\n");
  else
    std::printf("bounds:     [%g, %g, %g] to [%g, %g, %g]\n", lo.x, lo.y, lo.z, hi.x, hi.y, hi.z);

  const BvhStats& bvh = scene.bvh;
  std::printf("bvh:        %u nodes, %u leaves, max depth %u, built in %.2f ms\n", bvh.nodeCount,
              bvh.leafCount, bvh.maxDepth, bvh.buildSeconds * 1e3);
  return 0;
}

}  // namespace candela::cli
