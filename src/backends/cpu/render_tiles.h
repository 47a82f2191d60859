// The CPU backend's render loop: a SceneView's tiles rendered with oneTBB by one tracer (the own
// BVH's or Embree's), the integrator inlined into it. Compiled once per instruction set the
// backend can pick at run time (backends/cpu/tile_renderer.h), so only the files
// render_tiles_<isa>.cpp include it.
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>

#include "backends/cpu/flush_denormals.h"
#include "backends/cpu/sample_table_fill.h"
#include "backends/cpu/tile_renderer.h"
#include "backends/render_options.h"
#include "backends/thread_limit.h"
#include "render/render_pixel.h"
#include "render/render_result.h"
#include "render/scene_view.h"

#if defined(CANDELA_HAS_EMBREE)
#include "backends/cpu/embree_tracer.h"
#endif

namespace candela {

constexpr uint32_t kTileSize = 16;
// Samples of one pixel between two looks at the cancel flag, so that Ctrl-C stops a render of
// very many samples per pixel within moments, not at the end of its tile.
constexpr uint32_t kSamplesPerCancelCheck = 64;

template <bool kAovs, class Tracer>
RenderResult renderTilesWith(const SceneView& given, const Tracer& tracer,
                             const RenderOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const SceneView scene = adjustedView(given, options.adjust);
  const uint32_t width = scene.camera.width, height = scene.camera.height;
  const SampleRange samples = resolveSampleRange(options.samples, scene.settings.spp);
  const uint32_t tilesX = (width + kTileSize - 1) / kTileSize;
  const uint32_t tilesY = (height + kTileSize - 1) / kTileSize;

  RenderResult result;
  result.image = ImageRGB(width, height);
  if (kAovs) result.aovs.resize(size_t(width) * height);

  const ThreadLimit threadLimit(options.threads);

  tbb::enumerable_thread_specific<RayCounters> counters;
  std::mutex progressMutex;
  uint64_t pixelsDone = 0;
  const double pixelsTotal = double(width) * height;
  std::atomic<bool> cancelled{false};
  auto stopAsked = [&] {
    return options.cancel && options.cancel->load(std::memory_order_relaxed);
  };

  // Renders one tile; false when a cancel stopped it.
  auto renderTile = [&](uint32_t tile, RayCounters& local) {
    SampleTable table;
    table.fill = sampleTableFill();
    SampleTable* const sampleTable = table.fill ? &table : nullptr;
    const uint32_t x0 = (tile % tilesX) * kTileSize, y0 = (tile / tilesX) * kTileSize;
    const uint32_t x1 = std::min(x0 + kTileSize, width), y1 = std::min(y0 + kTileSize, height);
    for (uint32_t y = y0; y < y1; ++y) {
      for (uint32_t x = x0; x < x1; ++x) {
        Vec3 sum(0.0f);
        AovPixel* aov = kAovs ? &result.aovs[size_t(y) * width + x] : nullptr;
        for (uint32_t done = 0; done < samples.count; done += kSamplesPerCancelCheck) {
          if (stopAsked()) return false;
          const uint32_t count = std::min(kSamplesPerCancelCheck, samples.count - done);
          sum = renderPixelSamples<kAovs>(scene, tracer, x, y, samples.begin + done, count, local,
                                          sum, aov, sampleTable);
        }
        result.image.set(x, y, sum / float(samples.count));
      }
    }
    if (options.progress) {
      std::lock_guard<std::mutex> lock(progressMutex);
      pixelsDone += uint64_t(x1 - x0) * (y1 - y0);
      options.progress(double(pixelsDone) / pixelsTotal);
    }
    return true;
  };

  // One tile per task: tiles are independent, so the result never depends on the schedule.
  tbb::parallel_for(tbb::blocked_range<uint32_t>(0, tilesX * tilesY, 1),
                    [&](const tbb::blocked_range<uint32_t>& range) {
                      const FlushDenormals flush;
                      RayCounters& local = counters.local();
                      for (uint32_t tile = range.begin(); tile != range.end(); ++tile) {
                        if (!renderTile(tile, local)) {
                          cancelled = true;
                          return;
                        }
                      }
                    });

  for (const RayCounters& c : counters) result.rays += c;
  result.cancelled = cancelled.load();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

// The instance with or without the passes: only a render that asks for them runs their code.
template <class Tracer>
RenderResult renderTiles(const SceneView& scene, const Tracer& tracer,
                         const RenderOptions& options) {
  return options.aovs ? renderTilesWith<true>(scene, tracer, options)
                      : renderTilesWith<false>(scene, tracer, options);
}

namespace {

// The loops of the file that includes this header, which is compiled for `isa`.
inline TileRenderer tileRendererOfThisFile(const char* isa) {
  TileRenderer renderer{isa, renderTiles<BvhTracer>, nullptr};
#if defined(CANDELA_HAS_EMBREE)
  renderer.withEmbree = renderTiles<EmbreeTracer>;
#endif
  return renderer;
}

}  // namespace

}  // namespace candela
