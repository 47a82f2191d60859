// The light-path pilot; see light_path_pilot.h.
#include "backends/light_path_pilot.h"

#include <algorithm>
#include <cstddef>
#include <vector>

#include "core/rng.h"

namespace candela {

namespace {

// The smallest stride at which the camera's image has at most kPilotPixels pixels.
uint32_t pilotStride(uint32_t width, uint32_t height) {
  uint32_t s = 1;
  while (uint64_t(width / s) * (height / s) > kPilotPixels) ++s;
  return s;
}

struct PilotImages {
  RenderResult a, b;  // two seeds
};

// Variance of a pixel's value (over the two seeds' difference) relative to the squared mean,
// each pixel's share capped at the kPilotTrimmedShare quantile of the pixels' shares.
double relativeVariance(const PilotImages& p) {
  const std::vector<float>& a = p.a.image.pixels;
  const std::vector<float>& b = p.b.image.pixels;
  const size_t pixels = a.size() / 3;
  double sum = 0;
  std::vector<double> squares(pixels, 0.0);
  for (size_t i = 0; i < a.size(); ++i) {
    sum += double(a[i]) + double(b[i]);
    const double d = double(a[i]) - double(b[i]);
    squares[i / 3] += d * d;
  }
  if (pixels == 0) return 0;
  // The capped sum does not depend on the order, so the quantile is found in place.
  const size_t at = std::min(pixels - 1, size_t(double(pixels) * (1.0 - kPilotTrimmedShare)));
  std::nth_element(squares.begin(), squares.begin() + ptrdiff_t(at), squares.end());
  const double cap = squares[at];
  double capped = 0;
  for (const double s : squares) capped += std::min(s, cap);
  const double n = double(a.size());
  const double mean = sum / (2 * n);
  return capped / (2 * n) / (mean * mean);
}

double raysPerPixel(const PilotImages& p) {
  const double pixels = double(p.a.image.width) * p.a.image.height;
  return double(p.a.rays.total() + p.b.rays.total()) / (2 * pixels);
}

}  // namespace

LightPathChoice chooseLightPaths(Renderer& renderer, const SceneData& scene,
                                 const RenderOptions& options) {
  LightPathChoice choice;
  if (scene.settings.lightPaths != LightPaths::Auto) {
    choice.lightPaths = scene.settings.lightPaths == LightPaths::On;
    return choice;
  }
  if (scene.view().lightPathLights == 0) return choice;
  const uint32_t width = scene.camera.width, height = scene.camera.height;
  const uint32_t stride = pilotStride(width, height);
  const uint64_t pixels = uint64_t(width / stride) * (height / stride);
  if (pixels == 0) return choice;  // a sliver of an image, too thin to sample
  const uint32_t spp = uint32_t((kPilotPixels + pixels - 1) / pixels);
  const double renderSamples = double(width) * height * scene.settings.spp;
  if (spp > scene.settings.spp || 4.0 * double(pixels) * spp > kPilotShare * renderSamples)
    return choice;

  RenderOptions pilot;
  pilot.threads = options.threads;
  pilot.cancel = options.cancel;
  pilot.sceneLabel = options.sceneLabel;
  pilot.samples = {0, spp};
  pilot.adjust.pixelStride = stride;
  pilot.adjust.reseed = true;
  PilotImages with, without;
  for (int k = 0; k < 2; ++k) {
    pilot.adjust.seed = mix64(scene.settings.seed + 0x9e3779b97f4a7c15ull * uint64_t(k + 1));
    for (bool lightPaths : {true, false}) {
      pilot.adjust.lightPaths = lightPaths;
      RenderResult r = renderer.render(pilot);
      choice.seconds += r.seconds;
      choice.rays += r.rays;
      if (r.cancelled) return choice;  // the render itself stops at once
      PilotImages& images = lightPaths ? with : without;
      (k == 0 ? images.a : images.b) = std::move(r);
    }
  }
  const double raysWith = raysPerPixel(with), raysWithout = raysPerPixel(without);
  const double costWith = raysWith + (kLightPathRayCost - 1) * (raysWith - raysWithout);
  choice.piloted = true;
  choice.withLightPaths = relativeVariance(with) * costWith;
  choice.withoutLightPaths = relativeVariance(without) * raysWithout;
  // Off only where clearly cheaper: a NaN (an image without light) keeps them on.
  choice.lightPaths = !(choice.withoutLightPaths < choice.withLightPaths);
  return choice;
}

RenderResult renderChoosingLightPaths(Renderer& renderer, const SceneData& scene,
                                      RenderOptions options, LightPathChoice* choice) {
  const LightPathChoice chosen = chooseLightPaths(renderer, scene, options);
  options.adjust.lightPaths = options.adjust.lightPaths && chosen.lightPaths;
  RenderResult result = renderer.render(options);
  result.seconds += chosen.seconds;
  if (choice) *choice = chosen;
  return result;
}

}  // namespace candela
