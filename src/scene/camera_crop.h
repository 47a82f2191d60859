// A crop of a camera's image (CameraDesc::crop): which pixels a render takes, each drawing the
// samples it has in the whole image's render (docs/scene-format.md, *Crops*).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "scene/scene_desc.h"

namespace candela {

// Why `crop` is no part of a width x height image ("reaches past ..."), or nothing where it is.
std::optional<std::string> cropProblem(const CameraCrop& crop, uint32_t width, uint32_t height);

// The size of the image a render of `camera` makes: its crop's, or the whole image's.
uint32_t renderedWidth(const CameraDesc& camera);
uint32_t renderedHeight(const CameraDesc& camera);

// "[x, y, width, height]", as the scene format writes it.
std::string cropText(const CameraCrop& crop);

}  // namespace candela
