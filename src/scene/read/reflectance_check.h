// The warning for a material that reflects more light than it receives: a colour above 1 on a
// diffuse, mirror, conductor, plastic or glass surface, most often an 8-bit colour (255, 128, 0)
// written where the format takes linear reflectances in [0, 1].
#pragma once

#include "scene/scene_desc.h"

namespace candela {

// Adds to scene.warnings one line per sphere or object whose own material's colour has a
// component above 1 (the first few, then how many more); meshes' MTL materials are not checked.
void warnReflectanceAboveOne(SceneDesc& scene);

}  // namespace candela
