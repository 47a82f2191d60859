// The render passes by name, and their images made from a render's per-pixel sums
// (render/aov.h). The definitions are in docs/aovs.md; a new pass joins the table in
// aov_layers.cpp (in the enum's order: it is indexed by the enum) and the switch of resolvePixel.
#pragma once

#include <string>
#include <vector>

#include "image/image_layer.h"
#include "render/aov.h"
#include "render/scene_data.h"

namespace candela {

enum class Aov {
  Depth,
  Distance,
  Normal,
  NormalCamera,
  Albedo,
  Position,
  Instance,
  Material,
  Flow,
  BackwardFlow,
  Direct,
  Emission,
  Alpha,
  Uv,
  ObjectCoordinates
};

// "depth", "normal_camera", ...
const char* aovName(Aov aov);

// "depth, distance, normal, ..." for messages.
std::string knownAovNames();

// The passes named in `names`, in that order, each once. Throws std::invalid_argument naming an
// unknown pass and listing the known ones.
std::vector<Aov> aovsFromNames(const std::vector<std::string>& names);

// The names of a comma-separated list, "depth, normal", without the spaces around them.
std::vector<std::string> splitPassList(const std::string& list);

// The passes of such a list.
std::vector<Aov> parseAovList(const std::string& list);

// Whether `aovs` asks for `aov`.
bool hasAov(const std::vector<Aov>& aovs, Aov aov);

// One layer per pass in `aovs`, from `pixels` (RenderResult::aovs) of a render of `scene`.
std::vector<ImageLayer> makeAovLayers(const SceneData& scene, const std::vector<Aov>& aovs,
                                      const std::vector<AovPixel>& pixels);

}  // namespace candela
