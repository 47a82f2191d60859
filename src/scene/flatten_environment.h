// The environment of a flattened scene: the kernel's Environment, its map's texels and the
// distribution that samples them (render/environment.h).
#pragma once

#include "render/scene_data.h"
#include "scene/scene_desc.h"

namespace candela {

// Sets scene.environment and the env* arrays from `desc` (its light index is left to
// addEmitterLights); arrays already made from the same map are kept.
void flattenEnvironment(const EnvironmentDesc& desc, SceneData& scene);

// The sum of the RGB radiance of the environment, averaged over directions.
double environmentMeanRadiance(const SceneData& scene);

}  // namespace candela
