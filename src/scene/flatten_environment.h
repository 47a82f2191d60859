// The environment of a flattened scene: the kernel's Environment, its map's texels and the
// distribution that samples them (render/environment.h).
#pragma once

#include <cstdint>
#include <vector>

#include "core/vec3.h"
#include "render/environment.h"
#include "render/scene_data.h"
#include "scene/scene_desc.h"

namespace candela {

// Sets scene.environment and the env* arrays from `desc` (its light index is left to
// addEmitterLights); arrays already made from the same map are kept.
void flattenEnvironment(const EnvironmentDesc& desc, SceneData& scene);

// The environment map is sampled by a distribution over cells, each texel split into k x k of
// them, bilinear within each as the lookup is: k is 4, 2 or 1, the largest that keeps a w x h map
// within 4 M cells. Finer cells let a sun a few texels wide be sampled by its bilinear shape
// (docs/performance.md, *Environment sampling*).
uint32_t environmentCellsPerTexel(uint32_t w, uint32_t h);

// The sampling grid of a w x h map (render/environment.h, cellToMap): k w columns and k h rows,
// or, where texels are not split, w columns and h + 1 rows shifted by half a texel, so that the
// texel centres are cell corners.
EnvironmentGrid environmentGrid(uint32_t w, uint32_t h);

// The brightness (RGB sum) of the map's bilinear lookup (render/environment.h) at the corners of
// the grid's cells: rows + 1 rows of columns + 1, the last column the first again (the map
// wraps). Each cell lies within one of the lookup's bilinear patches, so the bilinear
// interpolation of its corners is the lookup over it.
std::vector<float> environmentCornerBrightness(const Vec3* texels, uint32_t w, uint32_t h,
                                               const EnvironmentGrid& grid);

// The sum of the RGB radiance of the environment, averaged over directions.
double environmentMeanRadiance(const SceneData& scene);

}  // namespace candela
