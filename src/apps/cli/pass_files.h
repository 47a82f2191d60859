// Where a render's passes (--aov) are written: inside a multi-layer .exr beside R, G, B, or, for
// a .png or .pfm image, as sibling .pfm files named after it, out.png -> out.depth.pfm (but a
// .png's alpha, which is its own alpha channel; an .exr's is its A); with the
// instance pass, the names of its numbers beside it, out.instances.json; with `camera`, the
// camera's matrices, out.camera.json; with `poses`, each instance's pose, out.poses.json
// (docs/aovs.md).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "image/image_layer.h"
#include "render/aov_layers.h"
#include "render/render_result.h"
#include "scene/scene_desc.h"

namespace candela::cli {

// What --aov asks for beside the image: render passes, and the files of the scene's camera and
// instance poses.
struct PassFiles {
  std::vector<Aov> aovs;
  bool camera = false;
  bool poses = false;
};

// --aov's comma-separated list: "camera" and "poses" are those files, every other name a pass.
// Throws std::invalid_argument naming an unknown name and listing the known ones.
PassFiles parsePassFiles(const std::string& list);

// The sibling files of `image` for `files`: a .pfm per pass (none for an .exr, which holds them),
// then, with the instance pass, the instance names' .json, then the camera's and the poses'.
std::vector<std::string> passFilePaths(const std::string& image, const PassFiles& files);

// The instance names' table: {"1": "floor", "2": "spheres[1]", ...}, as scene.instances in Python
// (scene/flatten.h, instanceNames).
std::string encodeInstanceNames(const SceneDesc& desc);

// The camera of `desc` as a camera object of the scene format (scene/camera_resolve.h,
// cameraMatrices): {"width", "height", "intrinsics": K, "extrinsics": [R t; 0 1]}, and the lens's
// "aperture_radius" and "focus_distance" where it has one.
std::string encodeCamera(const SceneDesc& desc);

// Each instance's pose (scene/instance_poses.h) by number: {"1": {"name", "object_to_world",
// "object_to_camera"}, ...}, the matrices 4 x 4, the second the camera's extrinsics times the
// first.
std::string encodePoses(const SceneDesc& desc);

// The bytes of `image` and of its sibling files, as (path, bytes), the image first: what a
// render of `scene`, flattened from `desc`, with `files` writes. Throws ImageWriteError.
std::vector<std::pair<std::string, std::string>> encodeWithPasses(const std::string& image,
                                                                  const RenderResult& result,
                                                                  const SceneData& scene,
                                                                  const PassFiles& files,
                                                                  const SceneDesc& desc);

}  // namespace candela::cli
