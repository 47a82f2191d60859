// Flattening the environment; see flatten_environment.h.
#include "scene/flatten_environment.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "core/constants.h"
#include "core/distribution2d.h"
#include "core/rotation.h"

namespace candela {
namespace {

// sin(theta) at the centre of row j of an h-row map.
double rowSinTheta(uint32_t j, uint32_t h) { return std::sin(kPi * (j + 0.5) / h); }

// MIS compensation (Karlik et al. 2019, as pbrt-v4's ImageInfiniteLight): the environment is
// only ever sampled beside BSDF sampling, whose rays find the whole sphere, so light samples are
// better spent where the map is brighter than its mean over directions: each brightness becomes
// its excess over that mean. A map with no excess (a uniform one) keeps its brightness.
void compensateForMis(std::vector<double>& brightness, uint32_t w, uint32_t h) {
  double sum = 0.0, weights = 0.0;
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      sum += brightness[size_t(y) * w + x] * rowSinTheta(y, h);
      weights += rowSinTheta(y, h);
    }
  const double mean = sum / weights;
  if (!std::any_of(brightness.begin(), brightness.end(), [&](double b) { return b > mean; }))
    return;
  for (double& b : brightness) b = std::max(0.0, b - mean);
}

}  // namespace

void flattenEnvironment(const EnvironmentDesc& desc, SceneData& s) {
  Environment e;
  if (!desc.image) {
    e.radiance = desc.color;
    s.environment = e;
    s.envTexels.clear();
    s.envConditionalCdf.clear();
    s.envMarginalCdf.clear();
    s.envConditionalGuide.clear();
    s.envMarginalGuide.clear();
    s.environmentMap.reset();
    return;
  }
  const ImageRGB& image = *desc.image;
  e.radiance = desc.color * desc.strength;
  e.toWorld = eulerRotation(desc.rotation);
  e.fromWorld = e.toWorld.transposed();
  e.width = image.width;
  e.height = image.height;
  s.environment = e;
  // The texels and their distribution depend on the map alone (not on strength, tint or
  // rotation): the frames of an animation build them once.
  if (s.environmentMap == desc.image) return;
  s.environmentMap = desc.image;
  const uint32_t w = image.width, h = image.height;
  s.envTexels.resize(size_t(w) * h);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) s.envTexels[size_t(y) * w + x] = image.at(x, y);

  // A texel's brightness is the brightest of it and its neighbours, which bounds the bilinear
  // lookup over its cell.
  std::vector<double> f(size_t(w) * h);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      double brightest = 0.0;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const uint32_t ny = uint32_t(std::clamp(int(y) + dy, 0, int(h) - 1));
          const uint32_t nx = (x + w + uint32_t(dx + 1) - 1) % w;
          brightest = std::max(brightest, componentSum(s.envTexels[size_t(ny) * w + nx]));
        }
      f[size_t(y) * w + x] = brightest;
    }
  compensateForMis(f, w, h);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) f[size_t(y) * w + x] *= rowSinTheta(y, h);
  Distribution2DArrays d;
  buildDistribution2D(f, w, h, &d);
  s.envConditionalCdf = std::move(d.conditional);
  s.envMarginalCdf = std::move(d.marginal);
  s.envConditionalGuide = std::move(d.conditionalGuide);
  s.envMarginalGuide = std::move(d.marginalGuide);
}

double environmentMeanRadiance(const SceneData& s) {
  const Environment& e = s.environment;
  if (e.width == 0) return componentSum(e.radiance);
  double weighted = 0.0, weights = 0.0;
  for (uint32_t y = 0; y < e.height; ++y) {
    const double sinTheta = rowSinTheta(y, e.height);
    for (uint32_t x = 0; x < e.width; ++x) {
      const Vec3 t = e.radiance * s.envTexels[size_t(y) * e.width + x];
      weighted += componentSum(t) * sinTheta;
      weights += sinTheta;
    }
  }
  return weights > 0.0 ? weighted / weights : 0.0;
}

}  // namespace candela
