// Flattening the environment; see flatten_environment.h.
#include "scene/flatten_environment.h"

#include <algorithm>
#include <array>
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

// The mean over directions of the N numbers value(x, y) gives (a std::array<double, N>) on a
// w x h map: each cell weighted by the solid angle of its row.
template <size_t N, typename Value>
std::array<double, N> meanOverDirections(uint32_t w, uint32_t h, const Value& value) {
  std::array<double, N> sum{};
  double weights = 0.0;
  for (uint32_t y = 0; y < h; ++y) {
    const double weight = rowSinTheta(y, h);
    for (uint32_t x = 0; x < w; ++x) {
      const std::array<double, N> v = value(x, y);
      for (size_t k = 0; k < N; ++k) sum[k] += v[k] * weight;
      weights += weight;
    }
  }
  for (double& s : sum) s /= weights;
  return sum;
}

// MIS compensation (Karlik et al. 2019, as pbrt-v4's ImageInfiniteLight): the environment is
// only ever sampled beside BSDF sampling, whose rays find the whole sphere, so light samples are
// better spent where the map is brighter than its mean over directions: each brightness becomes
// its excess over that mean. A map with no excess (a uniform one) keeps its brightness.
void compensateForMis(std::vector<double>& brightness, uint32_t w, uint32_t h) {
  const double mean = meanOverDirections<1>(w, h, [&](uint32_t x, uint32_t y) {
    return std::array<double, 1>{brightness[size_t(y) * w + x]};
  })[0];
  if (!std::any_of(brightness.begin(), brightness.end(), [&](double b) { return b > mean; }))
    return;
  for (double& b : brightness) b = std::max(0.0, b - mean);
}

}  // namespace

uint32_t environmentCellsPerTexel(uint32_t w, uint32_t h) {
  constexpr uint64_t kMaxCells = uint64_t(1) << 22;  // 8 bytes each: 32 MB
  for (uint32_t k = 4; k > 1; k /= 2)
    if (uint64_t(k * k) * w * h <= kMaxCells) return k;
  return 1;
}

// Where k is even a cell lies within one bilinear patch (texel centres are the patches'
// corners), over which the mean of the lookup is its value at the cell's centre; a whole texel's
// mean (k = 1) is the mean of its quarters'.
std::vector<double> environmentCellBrightness(const Vec3* texels, uint32_t w, uint32_t h,
                                              uint32_t k) {
  const uint32_t split = k < 2 ? 2 : k, sw = split * w, sh = split * h;
  const auto lookup = [&](uint32_t x, uint32_t y) {
    return componentSum(
        lookupMap(texels, w, h, (float(x) + 0.5f) / float(sw), (float(y) + 0.5f) / float(sh)));
  };
  const uint32_t cw = k * w, ch = k * h;
  std::vector<double> f(size_t(cw) * ch);
  for (uint32_t y = 0; y < ch; ++y)
    for (uint32_t x = 0; x < cw; ++x)
      f[size_t(y) * cw + x] = k >= 2 ? lookup(x, y)
                                     : 0.25 * (lookup(2 * x, 2 * y) + lookup(2 * x + 1, 2 * y) +
                                               lookup(2 * x, 2 * y + 1) +
                                               lookup(2 * x + 1, 2 * y + 1));
  return f;
}

namespace {

// The map's mean texel over directions.
Vec3 meanTexel(const Vec3* texels, uint32_t w, uint32_t h) {
  const std::array<double, 3> mean = meanOverDirections<3>(w, h, [&](uint32_t x, uint32_t y) {
    const Vec3& t = texels[size_t(y) * w + x];
    return std::array<double, 3>{t.x, t.y, t.z};
  });
  return Vec3(float(mean[0]), float(mean[1]), float(mean[2]));
}

}  // namespace

void flattenEnvironment(const EnvironmentDesc& desc, SceneData& s) {
  Environment e;
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
    e.sampleColumns = s.environment.sampleColumns;
    e.sampleRows = s.environment.sampleRows;
    s.environment = e;
    return;
  }
  s.environment = e;
  s.environmentMapHash = hash;
  const uint32_t w = image.width, h = image.height;
  s.envTexels.resize(size_t(w) * h);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) s.envTexels[size_t(y) * w + x] = image.at(x, y);
  s.environmentMapMean = meanTexel(s.envTexels.data(), w, h);

  const uint32_t k = environmentCellsPerTexel(w, h), cw = k * w, ch = k * h;
  std::vector<double> f = environmentCellBrightness(s.envTexels.data(), w, h, k);
  compensateForMis(f, cw, ch);
  for (uint32_t y = 0; y < ch; ++y)
    for (uint32_t x = 0; x < cw; ++x) f[size_t(y) * cw + x] *= rowSinTheta(y, ch);
  s.environment.sampleColumns = cw;
  s.environment.sampleRows = ch;
  Distribution2DArrays d;
  buildDistribution2D(f, cw, ch, &d);
  s.envConditionalCdf = std::move(d.conditional);
  s.envMarginalCdf = std::move(d.marginal);
  s.envConditionalGuide = std::move(d.conditionalGuide);
  s.envMarginalGuide = std::move(d.marginalGuide);
}

double environmentMeanRadiance(const SceneData& s) {
  const Environment& e = s.environment;
  return componentSum(e.width == 0 ? e.radiance : e.radiance * s.environmentMapMean);
}

}  // namespace candela
