// Emitters seen straight from the camera, sampled again for the denoiser.
//
// Where an emitter covers a sliver of a pixel, few samples cannot say how much: at 16 spp, one
// sample landing on a lamp's rim makes the pixel read a sixteenth of the lamp's radiance, often
// far above everything around, and no filter can tell from those samples where in the pixel the
// rim lies (docs/performance.md, Denoising). The denoiser leaves the emitters seen (the
// `emission` pass) out of its filters and adds them back (apps/denoise/oidn_denoiser.h); this
// gives it a sharper emission pass to add: sampled again,
// kSeenEmitterSampleFactor times the render's samples per pixel, in the windows of the image
// around the edges of the emitters seen, with camera rays alone (max_depth 0), each a small part of
// a sample's cost.
//
// Which windows is found by a pilot of its own (every pixel, kSeenEmitterPilotSamples samples
// per pixel, camera rays alone, its own seed), not from the render's emission pass: the pass is
// kept where no window covers it, so a choice made from its own samples would bias it (a sub-pixel
// emitter that the render's samples missed would stay black, one they found would be sampled
// again). With an independent pilot, each pixel's emission is either the render's or the windows',
// both unbiased.
#pragma once

#include <cstdint>
#include <vector>

#include "backends/render_options.h"
#include "backends/renderer.h"
#include "image/image_layer.h"
#include "render/scene_data.h"
#include "render/view_adjustment.h"

namespace candela {

// The emission pass is sampled again with this many times the render's samples per pixel...
constexpr uint32_t kSeenEmitterSampleFactor = 16;
// ...but at most this many (a render of as many samples has sharp emitters of its own).
constexpr uint32_t kMaxSeenEmitterSamples = 4096;
// The pilot's samples per pixel (the render's where it has fewer): an emitter that covers a
// pixel or more is found in a tile whatever the samples; a smaller one, which fewer find, keeps
// the render's own samples more often, still unbiased.
constexpr uint32_t kSeenEmitterPilotSamples = 4;
// The windows are made of tiles of this many pixels square.
constexpr uint32_t kSeenEmitterTile = 8;

// The samples per pixel with which the emitters seen in a render of `scene` are sampled again;
// 0 where that gains nothing: the scene has no emitting surface, every sample of a pixel goes
// through its centre (no antialiasing, a pinhole, a still camera), or the render has as many
// samples already.
uint32_t seenEmitterSamples(const SceneData& scene);

// The windows around the edges of the emitters that `emission` (an emission pass, 3 channels)
// shows: the tiles (kSeenEmitterTile square) that hold a pixel whose emission differs from one
// of its eight neighbours' where either is not black (the inside of an emitter of one radiance
// needs nothing), each run of them along a row of tiles one window.
std::vector<PixelWindow> seenEmitterWindows(const ImageLayer& emission);

// The emission pass sampled again in the windows where the pilot saw emitters.
struct SeenEmitters {
  ImageLayer emission;           // where `covered`, the pass's value from these samples
  std::vector<uint8_t> covered;  // per pixel, rows from the top; empty where none is
  bool cancelled = false;        // a cancel stopped the renders: nothing is covered
  // `pass` (a render's emission pass of this image) with the values sampled here in place of its
  // own where they cover it.
  void replaceIn(float* pass) const;
};

// Samples the emitters seen in the image of `scene`, the scene last given to `renderer`, again
// (seenEmitterSamples), where the pilot described above finds them; nothing where
// seenEmitterSamples is 0. The renders take `options`' threads and cancellation. It needs
// nothing of the image's own render, so it can run before or after it, or elsewhere.
SeenEmitters sampleSeenEmitters(Renderer& renderer, const SceneData& scene,
                                const RenderOptions& options);

}  // namespace candela
