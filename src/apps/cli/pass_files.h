// Where a render's passes (--aov) are written: inside a multi-layer .exr beside R, G, B, or, for
// a .png or .pfm image, as sibling .pfm files named after it, out.png -> out.depth.pfm; with the
// instance pass, the names of its numbers beside it, out.instances.json (docs/aovs.md).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "image/image_layer.h"
#include "render/aov_layers.h"
#include "render/render_result.h"
#include "scene/scene_desc.h"

namespace candela::cli {

// The sibling files of `image` for `aovs`: a .pfm per pass (none for an .exr, which holds them),
// then, with the instance pass, the instance names' .json.
std::vector<std::string> passFilePaths(const std::string& image, const std::vector<Aov>& aovs);

// The instance names' table: {"1": "floor", "2": "spheres[1]", ...}, as scene.instances in Python
// (scene/flatten.h, instanceNames).
std::string encodeInstanceNames(const SceneDesc& desc);

// The bytes of `image` and of its sibling files, as (path, bytes), the image first: what a
// render of `scene`, flattened from `desc`, with `aovs` writes. Throws ImageWriteError.
std::vector<std::pair<std::string, std::string>> encodeWithPasses(const std::string& image,
                                                                  const RenderResult& result,
                                                                  const SceneData& scene,
                                                                  const std::vector<Aov>& aovs,
                                                                  const SceneDesc& desc);

}  // namespace candela::cli
