// The "render" section of a scene file -> RenderSettings (all but spp, which the camera gives)
// and OutputDesc (the 8-bit encoding).
#pragma once

#include "scene/read/json_reader.h"
#include "scene/scene_desc.h"

namespace candela {

void readRender(const JsonValue& value, RenderSettings& render, OutputDesc& output);

}  // namespace candela
