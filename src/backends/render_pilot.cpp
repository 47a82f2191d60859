// The pilot render; see render_pilot.h.
#include "backends/render_pilot.h"

#include <algorithm>
#include <tuple>
#include <utility>
#include <vector>

#include "core/rng.h"
#include "render/light_selection.h"

namespace candela {

namespace {

// relMSE's floor under each pixel's squared value, as a share of the image's squared mean
// (bench/compare.py's 0.01): a black pixel weighs 100 times one of the mean value, not without
// bound.
constexpr double kRelativeErrorFloor = 0.01;

// The smallest stride at which the camera's image has at most `most` pixels.
uint32_t pilotStride(uint32_t width, uint32_t height, uint64_t most) {
  uint32_t s = 1;
  while (uint64_t(width / s) * (height / s) > most) ++s;
  return s;
}

struct PilotImages {
  RenderResult a, b;  // two seeds
  uint32_t spp = 1;   // the samples per pixel of each
};

// The cost of an estimator that traces `more` rays a sample than one without some of its
// connections (`fewer`): the rays those add weigh kLightPathRayCost, for their shading.
double costWithConnections(double more, double fewer) {
  return more + (kLightPathRayCost - 1) * (more - fewer);
}

double raysPerSample(const PilotImages& p) {
  const double samples = double(p.a.image.width) * p.a.image.height * p.spp;
  return double(p.a.rays.total() + p.b.rays.total()) / (2 * samples);
}

}  // namespace

namespace {

// Two estimators' relative variance per sample times their costs, each pixel weighed alike by
// the weights of all four images.
std::pair<double, double> varianceTimesCost(const PilotImages& x, double costX,
                                            const PilotImages& y, double costY) {
  const std::vector<double> weights =
      relativeErrorWeights({&x.a.image, &x.b.image, &y.a.image, &y.b.image});
  return {relativeVariance(x.a.image, x.b.image, weights) * costX,
          relativeVariance(y.a.image, y.b.image, weights) * costY};
}

}  // namespace

std::vector<double> relativeErrorWeights(std::initializer_list<const ImageRGB*> images) {
  const uint32_t w = (*images.begin())->width, h = (*images.begin())->height;
  std::vector<double> mean(size_t(3) * w * h, 0.0);
  for (const ImageRGB* image : images)
    for (size_t i = 0; i < mean.size(); ++i)
      mean[i] += double(image->pixels[i]) / double(images.size());
  double total = 0;
  for (const double v : mean) total += v;
  const double m = total / double(mean.size());
  std::vector<double> weights(mean.size());
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x)
      for (uint32_t c = 0; c < 3; ++c) {
        double sum = 0;
        int count = 0;
        for (uint32_t j = y > 0 ? y - 1 : 0; j <= std::min(y + 1, h - 1); ++j)
          for (uint32_t i = x > 0 ? x - 1 : 0; i <= std::min(x + 1, w - 1); ++i, ++count)
            sum += mean[3 * (size_t(j) * w + i) + c];
        const double v = sum / count;
        weights[3 * (size_t(y) * w + x) + c] = 1.0 / (v * v + kRelativeErrorFloor * m * m);
      }
  return weights;
}

double relativeVariance(const ImageRGB& a, const ImageRGB& b, const std::vector<double>& weights) {
  double sum = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    const double d = double(a.pixels[i]) - double(b.pixels[i]);
    sum += d * d * weights[i];
  }
  return sum / (2 * double(a.pixels.size()));
}

bool pilotKeepsLightPaths(double withLightPaths, double withoutLightPaths) {
  return !(withoutLightPaths < kPilotOffMargin * withLightPaths);
}

bool pilotTakesTwoLightSamples(double oneLightSample, double twoLightSamples) {
  return twoLightSamples < oneLightSample;
}

bool pilotLimitsLightPathDepth(double everyInteraction, double firstInteractions) {
  return firstInteractions < kPilotDepthMargin * everyInteraction;
}

PilotChoice choosePilot(Renderer& renderer, const SceneData& scene, const RenderOptions& options) {
  PilotChoice choice;
  const RenderSettings& settings = scene.settings;
  const SceneView view = scene.view();
  if (settings.lightPaths != LightPaths::Auto)
    choice.lightPaths = settings.lightPaths == LightPaths::On;
  choice.firstHitLightSamples = view.firstHitLightSamples;
  choice.lightPathDepth = view.lightPathDepth;
  const bool pilotsLightPaths = settings.lightPaths == LightPaths::Auto && view.lightPathLights > 0;
  // Connections at the first two interactions alone differ from connections at every one only
  // where a path has a fourth (its last interaction connects to none).
  bool pilotsDepth = settings.lightPathDepth == 0 && view.lightPathLights > 0 &&
                     settings.maxDepth > kPilotLightPathDepth + 1;
  bool pilotsLightSamples = settings.firstHitLightSamples == 0 && takesFirstHitLightSamples(view);
  if (!pilotsLightPaths && !pilotsDepth && !pilotsLightSamples) return choice;
  const uint32_t width = scene.camera.width, height = scene.camera.height;
  const uint32_t stride = pilotStride(width, height, kPilotPixels);
  const uint64_t pixels = uint64_t(width / stride) * (height / stride);
  if (pixels == 0) return choice;  // a sliver of an image, too thin to sample
  const uint32_t spp = uint32_t((kPilotPixels + pixels - 1) / pixels);
  const double renderSamples = double(width) * height * settings.spp;
  // Whether `renders` more renders of the pilot's usual size (pixels x spp) keep it in its share.
  double used = 0;  // in such renders
  const auto fits = [&](int renders) {
    return spp <= settings.spp &&
           (used + renders) * double(pixels) * spp <= kPilotShare * renderSamples;
  };
  if (!fits(4)) return choice;

  RenderOptions pilot;
  pilot.threads = options.threads;
  pilot.cancel = options.cancel;
  pilot.sceneLabel = options.sceneLabel;
  pilot.samples = {0, spp};
  pilot.adjust.pixelStride = stride;
  pilot.adjust.reseed = true;
  // Renders the pilot's view twice, with seeds of its own, with light subpaths or without,
  // connected at interactions up to `depth` (0: the scene's) and `lightSamples` at the first
  // interaction; false where cancelled.
  const auto renderTwice = [&](const RenderOptions& base, bool lightPaths, uint32_t depth,
                               uint32_t lightSamples, PilotImages* images) {
    RenderOptions o = base;
    images->spp = o.samples.count;
    for (int k = 0; k < 2; ++k) {
      o.adjust.seed = mix64(settings.seed + 0x9e3779b97f4a7c15ull * uint64_t(k + 1));
      o.adjust.lightPaths = lightPaths;
      o.adjust.lightPathDepth = depth;
      o.adjust.firstHitLightSamples = lightSamples;
      RenderResult r = renderer.render(o);
      choice.seconds += r.seconds;
      choice.rays += r.rays;
      if (r.cancelled) return false;  // the render itself stops at once
      (k == 0 ? images->a : images->b) = std::move(r);
    }
    return true;
  };

  PilotImages with, without;
  if (pilotsLightPaths) {
    if (!renderTwice(pilot, true, 0, 1, &with) || !renderTwice(pilot, false, 0, 1, &without))
      return choice;
    used += 4;
    const double raysWith = raysPerSample(with), raysWithout = raysPerSample(without);
    choice.piloted = true;
    std::tie(choice.withLightPaths, choice.withoutLightPaths) =
        varianceTimesCost(with, costWithConnections(raysWith, raysWithout), without, raysWithout);
    choice.lightPaths = pilotKeepsLightPaths(choice.withLightPaths, choice.withoutLightPaths);
  }

  if (pilotsLightSamples && fits(pilotsLightPaths ? 2 : 4)) {
    PilotImages one, two;
    if (pilotsLightPaths) {
      one = std::move(choice.lightPaths ? with : without);
    } else if (!renderTwice(pilot, choice.lightPaths, 0, 1, &one)) {
      return choice;
    }
    if (!renderTwice(pilot, choice.lightPaths, 0, 2, &two)) return choice;
    used += pilotsLightPaths ? 2 : 4;
    const double raysOne = raysPerSample(one), raysTwo = raysPerSample(two);
    choice.lightSamplesPiloted = true;
    std::tie(choice.oneLightSample, choice.twoLightSamples) =
        varianceTimesCost(one, raysOne, two, raysTwo);
    choice.firstHitLightSamples =
        pilotTakesTwoLightSamples(choice.oneLightSample, choice.twoLightSamples) ? 2 : 1;
  }

  // With the light samples so chosen.
  pilotsDepth = pilotsDepth && choice.lightPaths && fits(4);
  if (pilotsDepth) {
    // As many samples, over fewer pixels: the render's own per pixel, up to kPilotDepthSamples.
    const uint32_t deepSpp = std::min(settings.spp, kPilotDepthSamples);
    const uint32_t deepStride = pilotStride(width, height, kPilotPixels / deepSpp);
    RenderOptions deep = pilot;
    deep.adjust.pixelStride = deepStride;
    deep.samples = {0, deepSpp};
    PilotImages every, first;
    if (!renderTwice(deep, true, kEveryInteraction, choice.firstHitLightSamples, &every) ||
        !renderTwice(deep, true, kPilotLightPathDepth, choice.firstHitLightSamples, &first))
      return choice;
    used += 4;
    const double raysEvery = raysPerSample(every), raysFirst = raysPerSample(first);
    choice.depthPiloted = true;
    std::tie(choice.everyInteraction, choice.firstInteractions) =
        varianceTimesCost(every, costWithConnections(raysEvery, raysFirst), first, raysFirst);
    if (pilotLimitsLightPathDepth(choice.everyInteraction, choice.firstInteractions))
      choice.lightPathDepth = kPilotLightPathDepth;
  }

  return choice;
}

RenderResult renderWithPilot(Renderer& renderer, const SceneData& scene, RenderOptions options,
                             PilotChoice* choice) {
  const PilotChoice chosen = choosePilot(renderer, scene, options);
  options.adjust.lightPaths = options.adjust.lightPaths && chosen.lightPaths;
  if (options.adjust.lightPathDepth == 0) options.adjust.lightPathDepth = chosen.lightPathDepth;
  if (options.adjust.firstHitLightSamples == 0)
    options.adjust.firstHitLightSamples = chosen.firstHitLightSamples;
  RenderResult result = renderer.render(options);
  result.seconds += chosen.seconds;
  if (choice) *choice = chosen;
  return result;
}

}  // namespace candela
