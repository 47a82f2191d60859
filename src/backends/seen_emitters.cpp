// Emitters seen, sampled again; see seen_emitters.h.
#include "backends/seen_emitters.h"

#include <algorithm>
#include <cstddef>

#include "core/rng.h"
#include "render/aov_layers.h"
#include "render/bsdf.h"

namespace candela {

namespace {

// A render of only what the camera sees, with the passes, over `window` (the whole image where
// its width is 0) at `spp` samples per pixel.
RenderOptions seenOnlyRender(const RenderOptions& options, PixelWindow window, uint32_t spp) {
  RenderOptions seen;
  seen.threads = options.threads;
  seen.cancel = options.cancel;
  seen.sceneLabel = options.sceneLabel;
  seen.aovs = true;
  seen.adjust.seenOnly = true;
  seen.adjust.spp = spp;
  seen.adjust.window = window;
  return seen;
}

}  // namespace

uint32_t seenEmitterSamples(const SceneData& scene) {
  const bool emitters = std::any_of(scene.materials.begin(), scene.materials.end(),
                                    [](const Material& m) { return hasEmission(m); });
  const bool spread = scene.settings.antialiasing || scene.camera.apertureRadius > 0.0f ||
                      !scene.cameraPoses.empty() || !scene.motionTimes.empty();
  const uint64_t spp = scene.settings.spp;
  const uint32_t samples =
      uint32_t(std::min<uint64_t>(kSeenEmitterSampleFactor * spp, kMaxSeenEmitterSamples));
  return emitters && spread && samples > spp ? samples : 0;
}

std::vector<PixelWindow> seenEmitterWindows(const ImageLayer& emission) {
  const uint32_t w = emission.width, h = emission.height, t = kSeenEmitterTile;
  const uint32_t tilesX = (w + t - 1) / t, tilesY = (h + t - 1) / t;
  std::vector<char> tileSees(size_t(tilesX) * tilesY, 0);
  const auto at = [&](uint32_t x, uint32_t y) { return &emission.pixels[3 * (size_t(y) * w + x)]; };
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      const float* v = at(x, y);
      if (v[0] <= 0.0f && v[1] <= 0.0f && v[2] <= 0.0f) continue;
      // An emitter's edge (or a change of its radiance) between the pixel and a neighbour: both
      // may hold a part of a pixel that samples cannot place. Inside an emitter of one radiance
      // every sample sees the same, and nothing is sampled again.
      for (uint32_t j = y > 0 ? y - 1 : 0; j <= std::min(y + 1, h - 1); ++j)
        for (uint32_t i = x > 0 ? x - 1 : 0; i <= std::min(x + 1, w - 1); ++i) {
          const float* n = at(i, j);
          if (n[0] != v[0] || n[1] != v[1] || n[2] != v[2]) {
            tileSees[size_t(y / t) * tilesX + x / t] = 1;
            tileSees[size_t(j / t) * tilesX + i / t] = 1;
          }
        }
    }
  std::vector<PixelWindow> windows;
  for (uint32_t ty = 0; ty < tilesY; ++ty)
    for (uint32_t tx = 0; tx < tilesX;) {
      if (!tileSees[size_t(ty) * tilesX + tx]) {
        ++tx;
        continue;
      }
      const uint32_t first = tx;
      while (tx < tilesX && tileSees[size_t(ty) * tilesX + tx]) ++tx;
      PixelWindow window;
      window.x = first * t;
      window.y = ty * t;
      window.width = std::min(tx * t, w) - window.x;
      window.height = std::min(window.y + t, h) - window.y;
      windows.push_back(window);
    }
  return windows;
}

void SeenEmitters::replaceIn(float* pass) const {
  for (size_t i = 0; i < covered.size(); ++i)
    if (covered[i])
      for (size_t c = 0; c < 3; ++c) pass[3 * i + c] = emission.pixels[3 * i + c];
}

SeenEmitters sampleSeenEmitters(Renderer& renderer, const SceneData& scene,
                                const RenderOptions& options) {
  SeenEmitters seen;
  const uint32_t samples = seenEmitterSamples(scene);
  if (samples == 0) return seen;
  const uint32_t width = scene.camera.width, height = scene.camera.height;
  RenderOptions pilot = seenOnlyRender(options, PixelWindow(),
                                       std::min(scene.settings.spp, kSeenEmitterPilotSamples));
  pilot.adjust.reseed = true;
  pilot.adjust.seed = mix64(scene.settings.seed ^ 0x5ee7e3177e25ull);
  const RenderResult found = renderer.render(pilot);
  if (found.cancelled) {
    seen.cancelled = true;
    return seen;
  }
  const std::vector<PixelWindow> windows =
      seenEmitterWindows(makeAovLayers(scene, {Aov::Emission}, found.aovs)[0]);
  if (windows.empty()) return seen;
  seen.emission = ImageLayer("emission", {"R", "G", "B"}, false, width, height);
  seen.covered.assign(size_t(width) * height, 0);
  for (const PixelWindow& window : windows) {
    const RenderResult r = renderer.render(seenOnlyRender(options, window, samples));
    if (r.cancelled) {
      seen.cancelled = true;
      seen.covered.clear();
      return seen;
    }
    for (uint32_t y = 0; y < window.height; ++y)
      for (uint32_t x = 0; x < window.width; ++x) {
        const size_t i = size_t(window.y + y) * width + window.x + x;
        const AovPixel& p = r.aovs[size_t(y) * window.width + x];
        const Vec3 mean = meanOverSamples(p, p.emissionSum);
        seen.covered[i] = 1;
        for (int c = 0; c < 3; ++c) seen.emission.pixels[3 * i + c] = mean[c];
      }
  }
  return seen;
}

}  // namespace candela
