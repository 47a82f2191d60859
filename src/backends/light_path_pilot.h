// Whether a render's samples start light subpaths, decided by a pilot render.
//
// Light-vertex connections (render/light_path.h) cut the noise of indirect light where a light
// brightens small patches (a lamp beside a wall) and cost a sample about half again as many
// rays. Where the lights hang far from every surface, BSDF samples find what they light and the
// connections cost more than they save. Which holds is the scene's, so for `light_paths: "auto"`
// (the default) a pilot renders a sparse sample of the image's pixels (every stride-th in x and
// y, about 16k) with and without light subpaths, twice each with seeds of its own, and keeps the
// estimator of lower variance (from the two seeds' difference, relative to the image's mean, the
// noisiest half percent of the pixels capped) times cost (rays traced; those a light subpath
// adds weigh kLightPathRayCost, for the shading each connection also does). The pilot is a
// function of the scene and its seed, so the image is the same on every run and thread count,
// on either backend (up to rounding where the two estimators tie) and in every sample range of a
// distributed render. Where the pilot's samples would exceed a sixteenth of the render's it is
// skipped and light subpaths stay on. docs/performance.md has the measurements.
#pragma once

#include "backends/render_options.h"
#include "backends/renderer.h"
#include "render/scene_data.h"

namespace candela {

// The pilot's image has at most this many pixels, and this many samples each time it renders.
constexpr uint32_t kPilotPixels = 16384;
// The pilot renders four times; it runs only where those samples are at most this share of the
// render's.
constexpr double kPilotShare = 1.0 / 16.0;
// The cost of a ray a light subpath adds, relative to the others: its connection's two BSDF
// evaluations and weight come with it.
constexpr double kLightPathRayCost = 1.25;
// The pilot's variance caps each pixel's share at what all but this share of the pixels stay
// under: a few pixels whose noise is the same either way (the rim of a lamp seen directly, of
// radiance far above the rest) would otherwise outweigh the light the connections are for.
constexpr double kPilotTrimmedShare = 0.005;

struct LightPathChoice {
  bool lightPaths = true;  // what the render should do (RenderOptions::adjust.lightPaths)
  bool piloted = false;    // whether a pilot decided it
  double seconds = 0;      // the pilot's render time
  RayCounters rays;        // and the rays it traced
  // With a pilot: each estimator's relative variance per pixel times its rays per pixel.
  double withLightPaths = 0, withoutLightPaths = 0;
};

// Decides for the scene last given to `renderer` (it must be `scene`), whose render will take
// `options` (threads and cancellation are the pilot's too). No pilot unless the scene's
// light_paths is "auto" and it has point lights that start subpaths.
LightPathChoice chooseLightPaths(Renderer& renderer, const SceneData& scene,
                                 const RenderOptions& options);

// Renders the scene last given to `renderer` (it must be `scene`) as chooseLightPaths decides,
// which it returns in *choice where given. The pilot's seconds count in the result's (its rays,
// in the choice, do not: the result's are those of the image).
RenderResult renderChoosingLightPaths(Renderer& renderer, const SceneData& scene,
                                      RenderOptions options, LightPathChoice* choice = nullptr);

}  // namespace candela
