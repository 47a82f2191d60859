// `candela render --denoise`: Intel Open Image Denoise's "RT" filter on the rendered image's direct
// and indirect light, guided by the albedo and normal passes (docs/aovs.md, Denoising), as
// scene.render(denoise=True) does in Python.
//
// Debian has no OIDN package; PyPI's `pyoidn` (which scripts/install-python installs) carries the
// library. It is loaded at run time, so the build needs none of it: from $CANDELA_OIDN_LIBRARY
// when set, else libOpenImageDenoise.so.2 on the library path, else the one inside the pyoidn
// package of the `python3` on PATH.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "image/image.h"
#include "render/render_result.h"
#include "render/scene_data.h"

namespace candela::cli {

class OidnDenoiser {
 public:
  // The denoiser, or null with *whyNot saying what was looked for and how to install it.
  static std::unique_ptr<OidnDenoiser> load(std::string* whyNot);
  ~OidnDenoiser();

  // Replaces `image` (HDR radiance) by its denoised version: its direct light `direct` less the
  // emitters it shows (`emission`) and its indirect light, each filtered, and the emission, added.
  // `albedo`, `normal`, `direct` and `emission` hold 3 floats per pixel of the same size. On
  // OIDN's CPU device, `threads` > 0 caps its threads (0: all cores). Throws std::runtime_error
  // with OIDN's message when it fails.
  void denoise(ImageRGB& image, const std::vector<float>& albedo, const std::vector<float>& normal,
               const std::vector<float>& direct, const std::vector<float>& emission,
               int threads = 0) const;

  // Denoises the image of `result`, a render of `scene` with passes (RenderOptions::aovs), by its
  // direct light and emission passes, guided by its albedo and normal passes.
  void denoise(RenderResult& result, const SceneData& scene, int threads = 0) const;

  // The library file that was loaded.
  const std::string& path() const { return path_; }

  struct Api;

 private:
  OidnDenoiser() = default;
  void* handle_ = nullptr;
  std::unique_ptr<Api> api_;
  std::string path_;
};

}  // namespace candela::cli
