// The "environment" section of a scene file -> EnvironmentDesc, with its map read and checked.
//
// {"color": c} is a constant sky; {"map": "sky.exr", "strength": s, "rotation": [x, y, z],
// "color": tint} an equirectangular map in EXR, PFM or Radiance HDR, relative to the scene's
// folder; {"sky": {"sun": [x, y, z], "turbidity": t, "ground": colour}, "strength": s, "color":
// tint} the analytic sky of scene/sky_model.h, made into such a map. The map must be readable,
// non-empty and hold only finite, non-negative texels: any other is one error naming the scene
// file, environment.map and what was found.
#pragma once

#include <string>

#include "scene/read/json_reader.h"
#include "scene/scene_desc.h"

namespace candela {

EnvironmentDesc readEnvironment(const JsonValue& value, const std::string& baseDir);

}  // namespace candela
