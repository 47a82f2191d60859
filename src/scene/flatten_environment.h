// The environment of a flattened scene: the kernel's Environment, its map's texels and the
// distribution that samples them (render/environment.h).
#pragma once

#include <cstdint>
#include <vector>

#include "core/vec3.h"
#include "render/scene_data.h"
#include "scene/scene_desc.h"

namespace candela {

// Sets scene.environment and the env* arrays from `desc` (its light index is left to
// addEmitterLights); arrays already made from the same map are kept.
void flattenEnvironment(const EnvironmentDesc& desc, SceneData& scene);

// The environment map is sampled by a piecewise-constant distribution over cells, each texel
// split into k x k of them: k is 4, 2 or 1, the largest that keeps a w x h map within 4 M cells.
// Finer cells let a sun a few texels wide be sampled by its bilinear shape rather than by its
// texels' means (docs/performance.md, *Environment sampling*).
uint32_t environmentCellsPerTexel(uint32_t w, uint32_t h);

// The brightness (RGB sum) of each of the (k w) x (k h) cells, row-major: the exact mean over it
// of the map's bilinear lookup (render/environment.h), so positive wherever a lookup in it is.
std::vector<double> environmentCellBrightness(const Vec3* texels, uint32_t w, uint32_t h,
                                              uint32_t k);

// The sum of the RGB radiance of the environment, averaged over directions.
double environmentMeanRadiance(const SceneData& scene);

}  // namespace candela
