// How a render's samples are drawn where the scene leaves it to candela, decided by a pilot
// render: whether they start light subpaths, and how many lights they sample at their first
// interaction.
//
// Light-vertex connections (render/light_path.h) cut the noise of indirect light where a light
// brightens small patches (a lamp beside a wall) and cost a sample about half again as many
// rays. Where the lights hang far from every surface, BSDF samples find what they light and the
// connections cost more than they save. A second light sample at a path's first interaction
// (SceneView::firstHitLightSamples) halves the noise of picking one light among many there,
// which is most of the image's where a lamp of thousands of triangles lights a room, and costs
// a light-tree walk and a shadow ray, wasted where one light sample already does well. Which
// holds is the scene's, so for `light_paths: "auto"` and `first_hit_light_samples: "auto"` (the
// defaults) a pilot renders a sparse sample of the image's pixels (every stride-th in x and
// y, about 16k) with and without light subpaths, twice each with seeds of its own, and keeps the
// estimator of lower variance times cost: variance from the two seeds' difference, each pixel's
// relative to its value as the bench's relMSE weighs it, and cost the rays traced (those a light
// subpath adds weigh kLightPathRayCost, for the shading each connection also does), with a
// margin (kPilotOffMargin) for the connections. With the connections on and
// `light_path_depth: "auto"` (not the default: docs/performance.md), a third part renders twice
// with them at every interaction and twice at the first two alone, and keeps the cheaper
// (kPilotDepthMargin): connections deeper in a path pay where a light brightens patches of the
// walls that paths reach after bounces (a point light beside a wall) and cost a tenth of the rays
// where they do not (lights hung in the open). What the deeper connections gain depends on what the
// stratification of a pixel's many samples leaves them (one sample a pixel shows them a third
// to a half less useful than a 16-spp render finds them), so this part renders fewer pixels
// with the render's samples per pixel, up to kPilotDepthSamples. Then, with the
// light paths so chosen, twice with two light samples at the first interaction, kept where
// their variance times cost is the lower (the shadow ray each adds, with its light-tree walk and
// light sample, cost about one ray's time: 0.5-1.2 on four scenes, docs/performance.md). The
// pilot is a
// function of the scene and its seed, so the image is the same on every run and thread count,
// on either backend (up to rounding where the two estimators tie) and in every sample range of a
// distributed render. Where the pilot's samples would exceed a sixteenth of the render's it is
// skipped: light subpaths stay on, and one light sample is taken. docs/performance.md has the
// measurements.
#pragma once

#include <initializer_list>
#include <vector>

#include "backends/render_options.h"
#include "backends/renderer.h"
#include "image/image.h"
#include "render/scene_data.h"

namespace candela {

// The pilot's image has at most this many pixels, and this many samples each time it renders.
constexpr uint32_t kPilotPixels = 16384;
// The pilot renders four times for the light paths, four times for their depth (as many samples
// each) and twice more for the light samples (four where the light paths are not its to choose);
// each part runs only where the pilot's samples so far are at most this share of the render's.
constexpr double kPilotShare = 1.0 / 16.0;
// The depth part's images have the render's samples per pixel, up to this many, over as many
// fewer pixels (kPilotPixels samples in all).
constexpr uint32_t kPilotDepthSamples = 16;
// The deepest interaction connected where the depth part limits them.
constexpr uint32_t kPilotLightPathDepth = 2;
// They are limited only where the pilot finds that cheaper than this share of every
// interaction's variance x cost: what the deeper connections gain grows with a pixel's samples
// (the Cornell box: 1.005, 1.031 and 1.072 of the variance without them at 4, 16 and 64 spp), so
// a render of more than the pilot's 16 finds the limit a few percent dearer than the pilot does,
// whose figure also varies by a few percent with its seed (docs/performance.md, *Connections at
// the first two interactions*).
constexpr double kPilotDepthMargin = 0.92;

// The cost of a ray a light subpath adds, relative to the others: its connection's two BSDF
// evaluations and weight come with it.
constexpr double kLightPathRayCost = 1.25;
// Connections go off only where the pilot finds the render without them cheaper than this
// share of the render with them: at one sample a pixel it understates their gain (0.58-0.93 of
// the variance ratio that full renders of 16 spp show on five of six bench scenes; docs/
// performance.md), since the stratification that helps a pixel's many samples is not there.
constexpr double kPilotOffMargin = 0.9;

struct PilotChoice {
  bool lightPaths = true;  // what the render should do (RenderOptions::adjust.lightPaths)
  bool piloted = false;    // whether a pilot decided it
  // The light samples of a path's first interaction the render takes
  // (RenderOptions::adjust.firstHitLightSamples; SceneView::firstHitLightSamples).
  uint32_t firstHitLightSamples = 1;
  bool lightSamplesPiloted = false;  // whether a pilot decided them
  double seconds = 0;                // the pilot's render time
  RayCounters rays;                  // and the rays it traced
  // With a pilot: each estimator's relative variance per sample times its cost per sample.
  double withLightPaths = 0, withoutLightPaths = 0;
  double oneLightSample = 0, twoLightSamples = 0;
  // The deepest interaction connected to the light vertex (RenderOptions::adjust.lightPathDepth;
  // SceneView::lightPathDepth), whether a pilot decided it, and its two estimators' figures.
  uint32_t lightPathDepth = kEveryInteraction;
  bool depthPiloted = false;
  double everyInteraction = 0, firstInteractions = 0;
};

// Each pixel channel's weight in the relative MSE that the bench judges images by (images over
// their mean, mean((a - b)^2 / (b^2 + 0.01))): 1 / (v^2 + 0.01 m^2), with m the mean of `images`
// (renders of one view, alike in size) and v the channel's value in their mean over the 3x3 pixels
// around it. The pilot gives all four of its images, so both estimators share weights that no
// one render's noise picks: from a pixel's own samples, one whose samples came out dark would
// weigh most, and the spikier estimator look better than it is.
std::vector<double> relativeErrorWeights(std::initializer_list<const ImageRGB*> images);

// One sample's variance, weighted per pixel channel, from two renders of a view with different
// seeds (the variance of their difference is twice each one's).
double relativeVariance(const ImageRGB& a, const ImageRGB& b, const std::vector<double>& weights);

// The pilot's verdict from its two estimators' variance x cost: the connections stay unless
// going without them costs less than kPilotOffMargin of going with them (a NaN, an image
// without light, keeps them).
bool pilotKeepsLightPaths(double withLightPaths, double withoutLightPaths);

// Decides for the scene last given to `renderer` (it must be `scene`), whose render will take
// `options` (threads and cancellation are the pilot's too). No pilot unless the scene's
// light_paths is "auto" and it has lights that start subpaths, or its light_path_depth is "auto"
// with the connections on and max_depth above 3, or its first_hit_light_samples is "auto" and a
// light is picked at the first interaction (takesFirstHitLightSamples).
PilotChoice choosePilot(Renderer& renderer, const SceneData& scene, const RenderOptions& options);

// Whether two light samples at the first interaction win: their variance times cost under
// one's (a NaN, an image without light, keeps one).
bool pilotTakesTwoLightSamples(double oneLightSample, double twoLightSamples);

// Whether connections at the first kPilotLightPathDepth interactions alone win: their variance
// times cost under kPilotDepthMargin of every interaction's (a NaN keeps every interaction).
bool pilotLimitsLightPathDepth(double everyInteraction, double firstInteractions);

// Renders the scene last given to `renderer` (it must be `scene`) as choosePilot decides,
// which it returns in *choice where given. The pilot's seconds count in the result's (its rays,
// in the choice, do not: the result's are those of the image).
RenderResult renderWithPilot(Renderer& renderer, const SceneData& scene, RenderOptions options,
                             PilotChoice* choice = nullptr);

}  // namespace candela
