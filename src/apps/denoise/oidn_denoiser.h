// Denoising with Intel Open Image Denoise's "RT" filter: the image's direct and indirect light
// apart, guided by the albedo and normal passes (docs/aovs.md, Denoising). The one implementation
// behind `candela render --denoise` and Python's scene.render(denoise=True).
//
// Debian has no OIDN package; PyPI's `pyoidn` (which scripts/install-python installs) carries the
// library. It is loaded at run time, so the build needs none of it: from a path the caller gives
// (Python gives pyoidn's), else from $CANDELA_OIDN_LIBRARY when set, else
// libOpenImageDenoise.so.2 on the library path, else the one inside the pyoidn package of the
// `python3` on PATH. The filters run on OIDN's CPU device.
#pragma once

#include <cstddef>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "backends/seen_emitters.h"
#include "image/image.h"
#include "render/render_result.h"
#include "render/scene_data.h"

namespace candela {

class OidnDenoiser {
 public:
  // The denoiser from the library file `library`, or where that is empty from the places the
  // file comment lists; null with *whyNot saying what was looked for and how to install it.
  static std::unique_ptr<OidnDenoiser> load(std::string* whyNot, const std::string& library = "");
  ~OidnDenoiser();
  OidnDenoiser(const OidnDenoiser&) = delete;
  OidnDenoiser& operator=(const OidnDenoiser&) = delete;

  // Denoises `image` (width x height HDR radiance, 3 floats a pixel) in place. With `direct`
  // (its direct light pass) the direct light, less the emitters it shows (`emission`, or none
  // where null), and the rest are filtered apart, and the two and the emission added (or, where
  // given, `seenEmission`: the same emitters sampled again, backends/seen_emitters.h); without,
  // one filter runs over the image. `albedo` and `normal` guide every filter, each denoised
  // first. `threads` > 0 caps OIDN's threads (0: all cores). Calls take turns.
  // Throws std::runtime_error with OIDN's message when it fails.
  void denoise(float* image, size_t width, size_t height, const float* albedo, const float* normal,
               const float* direct, const float* emission, const float* seenEmission = nullptr,
               int threads = 0) const;

  // Denoises the image of `result`, a render of `scene` with passes (RenderOptions::aovs), by its
  // direct light and emission passes, guided by its albedo and normal passes, adding back the
  // emitters seen as `renderer` (which holds `scene` and made `result` with `options`, whose
  // threads and cancellation hold here too) samples them again (backends/seen_emitters.h). A
  // cancel while they are sampled marks `result` cancelled and leaves it as it was.
  void denoise(RenderResult& result, const SceneData& scene, Renderer& renderer,
               const RenderOptions& options) const;

  struct Api;

 private:
  OidnDenoiser() = default;
  // The committed device of at most `threads` threads, made on first use: a device takes its
  // thread count once.
  void* device(int threads) const;

  void* handle_ = nullptr;
  std::unique_ptr<Api> api_;
  mutable std::mutex mutex_;
  mutable std::map<int, void*> devices_;
};

}  // namespace candela
