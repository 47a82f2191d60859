// Where a render's passes (--aov) are written: inside a multi-layer .exr beside R, G, B, or, for
// a .png or .pfm image, as sibling .pfm files named after it, out.png -> out.depth.pfm
// (docs/aovs.md).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "image/image_layer.h"
#include "image/output_desc.h"
#include "render/aov_layers.h"
#include "render/render_result.h"

namespace candela::cli {

// The sibling files of `image` for `aovs`; none for an .exr, which holds them.
std::vector<std::string> passFilePaths(const std::string& image, const std::vector<Aov>& aovs);

// The bytes of `image` and of its sibling files, as (path, bytes), the image first: what a
// render of `scene` with `aovs` writes. Throws ImageWriteError.
std::vector<std::pair<std::string, std::string>> encodeWithPasses(
    const std::string& image, const RenderResult& result, const SceneData& scene,
    const std::vector<Aov>& aovs, const OutputDesc& output);

}  // namespace candela::cli
