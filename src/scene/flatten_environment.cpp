// Flattening the environment; see flatten_environment.h.
#include "scene/flatten_environment.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "core/constants.h"
#include "core/distribution2d.h"
#include "core/rotation.h"
#include "render/environment.h"
#include "render/scene_change.h"
#include "scene/content_hash.h"

namespace candela {
namespace {

// sin(theta) at the centre of row j of an h-row map.
double rowSinTheta(uint32_t j, uint32_t h) { return std::sin(kPi * (j + 0.5) / h); }

// The map's mean texel over directions: each texel weighted by the solid angle of its row. Rows
// are summed in parallel and their sums added in order, so the mean is the same on any number of
// threads.
Vec3 meanTexel(const Vec3* texels, uint32_t w, uint32_t h) {
  std::vector<double> rowSums(size_t(h) * 3);
  tbb::parallel_for(uint32_t(0), h, [&](uint32_t y) {
    const double weight = rowSinTheta(y, h);
    double sum[3] = {0.0, 0.0, 0.0};
    for (uint32_t x = 0; x < w; ++x) {
      const Vec3& t = texels[size_t(y) * w + x];
      sum[0] += t.x * weight;
      sum[1] += t.y * weight;
      sum[2] += t.z * weight;
    }
    for (int c = 0; c < 3; ++c) rowSums[size_t(y) * 3 + c] = sum[c];
  });
  double sum[3] = {0.0, 0.0, 0.0}, weights = 0.0;
  for (uint32_t y = 0; y < h; ++y) {
    for (int c = 0; c < 3; ++c) sum[c] += rowSums[size_t(y) * 3 + c];
    weights += rowSinTheta(y, h) * w;
  }
  return Vec3(float(sum[0] / weights), float(sum[1] / weights), float(sum[2] / weights));
}

// The map's v at the top of grid row y (y = rows: its bottom, 1).
double gridRowTop(const EnvironmentGrid& grid, uint32_t y) {
  const double shift = grid.shifted ? 0.5 : 0.0;
  return std::min(1.0, std::max(0.0, (y - shift) / (grid.rows - 2.0 * shift)));
}

// MIS compensation (Karlik et al. 2019, as pbrt-v4's ImageInfiniteLight): the environment is
// only ever sampled beside BSDF sampling, whose rays find the whole sphere, so light samples are
// better spent where the map is brighter than its mean over directions: each brightness becomes
// its excess over that mean. A map with no excess (a uniform one) keeps its brightness.
void compensateForMis(std::vector<float>& brightness, float mean) {
  if (!std::any_of(brightness.begin(), brightness.end(), [&](float b) { return b > mean; })) return;
  for (float& b : brightness) b = std::max(0.0f, b - mean);
}

}  // namespace

uint32_t environmentCellsPerTexel(uint32_t w, uint32_t h) {
  constexpr uint64_t kMaxCells = uint64_t(1) << 22;  // 12 bytes each: 48 MB
  for (uint32_t k = 4; k > 1; k /= 2)
    if (uint64_t(k * k) * w * h <= kMaxCells) return k;
  return 1;
}

EnvironmentGrid environmentGrid(uint32_t w, uint32_t h) {
  const uint32_t k = environmentCellsPerTexel(w, h);
  // Even k puts texel centres on cell corners as the grid is; k = 1 shifts it by half a texel.
  return {k * w, k == 1 ? h + 1 : k * h, k == 1};
}

std::vector<float> environmentCornerBrightness(const Vec3* texels, uint32_t w, uint32_t h,
                                               const EnvironmentGrid& grid) {
  const double shift = grid.shifted ? 0.5 : 0.0;
  std::vector<float> corners(size_t(grid.columns + 1) * (grid.rows + 1));
  tbb::parallel_for(uint32_t(0), grid.rows + 1, [&](uint32_t y) {
    const double v = gridRowTop(grid, y);
    for (uint32_t x = 0; x <= grid.columns; ++x) {
      const double u = (x + shift) / grid.columns;  // past 1 the lookup wraps
      corners[size_t(y) * (grid.columns + 1) + x] =
          componentSum(lookupMap(texels, w, h, float(u), float(v)));
    }
  });
  return corners;
}

void flattenEnvironment(const EnvironmentDesc& desc, SceneData& s) {
  Environment e;
  e.hiddenFromCamera = !desc.visible;
  if (!desc.image) {
    e.radiance = desc.color;
    s.environment = e;
    s.clearGroup(RewrittenBy::EnvironmentMap);
    return;
  }
  const ImageRGB& image = *desc.image;
  e.radiance = desc.color * desc.strength;
  e.toWorld = eulerRotation(desc.rotation);
  e.fromWorld = e.toWorld.transposed();
  e.width = image.width;
  e.height = image.height;
  // The texels and their distribution depend on the map alone (not on strength, tint or
  // rotation): the frames of an animation build them once.
  // A map made in memory (tests, Python) has no hash of the reader's.
  const uint64_t hash = desc.mapHash != 0 ? desc.mapHash : hashImage(image);
  if (s.environmentMapHash == hash) {
    e.grid = s.environment.grid;
    s.environment = e;
    return;
  }
  s.environment = e;
  s.environmentMapHash = hash;
  const uint32_t w = image.width, h = image.height;
  s.envTexels.resize(size_t(w) * h);
  tbb::parallel_for(uint32_t(0), h, [&](uint32_t y) {
    for (uint32_t x = 0; x < w; ++x) s.envTexels[size_t(y) * w + x] = image.at(x, y);
  });
  s.environmentMapMean = meanTexel(s.envTexels.data(), w, h);

  const EnvironmentGrid grid = environmentGrid(w, h);
  std::vector<float> corners = environmentCornerBrightness(s.envTexels.data(), w, h, grid);
  compensateForMis(corners, componentSum(s.environmentMapMean));
  // Weighted by sin(theta) at the corners, the density over the map is continuous, and so is the
  // pdf over directions, the density divided by sin(theta) there.
  for (uint32_t y = 0; y <= grid.rows; ++y) {
    const float sinTheta = float(std::sin(kPi * gridRowTop(grid, y)));
    for (uint32_t x = 0; x <= grid.columns; ++x)
      corners[size_t(y) * (grid.columns + 1) + x] *= sinTheta;
  }
  // Each row's height in units of a full row's (the shifted grid's first and last are halves).
  const double fullRows = grid.rows - (grid.shifted ? 1.0 : 0.0);
  std::vector<double> rowHeight(grid.rows);
  for (uint32_t y = 0; y < grid.rows; ++y)
    rowHeight[y] = (gridRowTop(grid, y + 1) - gridRowTop(grid, y)) * fullRows;
  s.environment.grid = grid;
  Distribution2DArrays d;
  buildBilinearDistribution2D(std::move(corners), rowHeight, grid.columns, grid.rows, &d);
  s.envConditionalCdf = std::move(d.conditional);
  s.envMarginalCdf = std::move(d.marginal);
  s.envConditionalGuide = std::move(d.conditionalGuide);
  s.envMarginalGuide = std::move(d.marginalGuide);
  s.envCellCorners = std::move(d.corners);
}

double environmentMeanRadiance(const SceneData& s) {
  const Environment& e = s.environment;
  return componentSum(e.width == 0 ? e.radiance : e.radiance * s.environmentMapMean);
}

}  // namespace candela
