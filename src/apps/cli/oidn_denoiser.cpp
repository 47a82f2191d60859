#include "apps/cli/oidn_denoiser.h"

#include <dlfcn.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <initializer_list>
#include <stdexcept>
#include <utility>

#include "render/aov_layers.h"

namespace candela::cli {

// The few entry points of OIDN's C API (OpenImageDenoise/oidn.h, version 2) that denoising
// needs, declared here because only the library, not its header, comes with pyoidn.
struct OidnDenoiser::Api {
  using Device = void*;
  using Filter = void*;
  static constexpr int kDeviceTypeDefault = 0;  // OIDN_DEVICE_TYPE_DEFAULT
  static constexpr int kFormatFloat3 = 3;       // OIDN_FORMAT_FLOAT3
  static constexpr int kDeviceTypeCpu = 1;      // OIDN_DEVICE_TYPE_CPU
  Device (*newDevice)(int type);
  int (*getDeviceInt)(Device, const char* name);
  void (*setDeviceInt)(Device, const char* name, int value);
  void (*commitDevice)(Device);
  int (*getDeviceError)(Device, const char** message);
  void (*releaseDevice)(Device);
  Filter (*newFilter)(Device, const char* type);
  void (*setSharedFilterImage)(Filter, const char* name, void* pointer, int format, size_t width,
                               size_t height, size_t byteOffset, size_t pixelStride,
                               size_t rowStride);
  void (*setFilterBool)(Filter, const char* name, bool value);
  void (*commitFilter)(Filter);
  void (*executeFilter)(Filter);
  void (*releaseFilter)(Filter);
};

namespace {

template <typename F>
bool bind(void* handle, const char* name, F* f) {
  *f = reinterpret_cast<F>(dlsym(handle, name));
  return *f != nullptr;
}

// The folder of the pyoidn package of python3 on PATH, or "" (no python3, no pyoidn).
std::string pyoidnLibraryFolder() {
  FILE* pipe = popen(
      "python3 -c 'import os, pyoidn; print(os.path.join(os.path.dirname(pyoidn.__file__), "
      "\"oidn\", \"lib\"))' 2>/dev/null < /dev/null",
      "r");
  if (!pipe) return "";
  std::array<char, 4096> line{};
  std::string folder;
  if (std::fgets(line.data(), int(line.size()), pipe)) folder = line.data();
  const int status = pclose(pipe);
  while (!folder.empty() && (folder.back() == '\n' || folder.back() == '\r')) folder.pop_back();
  return status == 0 ? folder : "";
}

}  // namespace

std::unique_ptr<OidnDenoiser> OidnDenoiser::load(std::string* whyNot) {
  std::string tried;
  std::unique_ptr<OidnDenoiser> d;
  // Opens `path`; true when it opened, with d set, or whyNot where it is not OIDN 2.
  const auto open = [&](const std::string& path) {
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      tried += (tried.empty() ? "" : ", ") + path;
      return false;
    }
    d.reset(new OidnDenoiser);
    d->handle_ = handle;
    d->path_ = path;
    d->api_ = std::make_unique<Api>();
    Api& a = *d->api_;
    const bool complete =
        bind(handle, "oidnNewDevice", &a.newDevice) &&
        bind(handle, "oidnGetDeviceInt", &a.getDeviceInt) &&
        bind(handle, "oidnSetDeviceInt", &a.setDeviceInt) &&
        bind(handle, "oidnCommitDevice", &a.commitDevice) &&
        bind(handle, "oidnGetDeviceError", &a.getDeviceError) &&
        bind(handle, "oidnReleaseDevice", &a.releaseDevice) &&
        bind(handle, "oidnNewFilter", &a.newFilter) &&
        bind(handle, "oidnSetSharedFilterImage", &a.setSharedFilterImage) &&
        bind(handle, "oidnSetFilterBool", &a.setFilterBool) &&
        bind(handle, "oidnCommitFilter", &a.commitFilter) &&
        bind(handle, "oidnExecuteFilter", &a.executeFilter) &&
        bind(handle, "oidnReleaseFilter", &a.releaseFilter);
    if (!complete) {
      d.reset();
      *whyNot = path + " is not Open Image Denoise 2 (an entry point is missing)";
    }
    return true;
  };
  // pyoidn's copy is looked for (by running python3) only when the library path has none.
  if (const char* env = std::getenv("CANDELA_OIDN_LIBRARY"); env && *env) {
    if (open(env)) return d;
  } else if (open("libOpenImageDenoise.so.2")) {
    return d;
  } else if (const std::string folder = pyoidnLibraryFolder();
             !folder.empty() && open(folder + "/libOpenImageDenoise.so.2")) {
    return d;
  }
  *whyNot = "--denoise needs Intel Open Image Denoise 2, which was not found (tried " + tried +
            "): install it with `pip install pyoidn` (scripts/install-python does), or set "
            "CANDELA_OIDN_LIBRARY to its libOpenImageDenoise.so";
  return nullptr;
}

OidnDenoiser::~OidnDenoiser() {
  if (handle_) dlclose(handle_);
}

void OidnDenoiser::denoise(ImageRGB& image, const std::vector<float>& albedo,
                           const std::vector<float>& normal, const std::vector<float>& direct,
                           const std::vector<float>& emission, int threads) const {
  const Api& a = *api_;
  const size_t w = image.width, h = image.height, n = 3 * w * h;
  if (albedo.size() != n || normal.size() != n || direct.size() != n || emission.size() != n)
    throw std::invalid_argument("denoise: the passes do not match the image's size");
  // OIDN expects albedo in [0, 1] and normals in [-1, 1]; the passes hold those already, up to
  // rounding, which the clamps take away.
  std::vector<float> a01(n), n11(n), out(n);
  std::transform(albedo.begin(), albedo.end(), a01.begin(),
                 [](float v) { return std::min(1.0f, std::max(0.0f, v)); });
  std::transform(normal.begin(), normal.end(), n11.begin(),
                 [](float v) { return std::min(1.0f, std::max(-1.0f, v)); });
  void* device = a.newDevice(Api::kDeviceTypeDefault);
  if (!device) throw std::runtime_error("Open Image Denoise could not create a device");
  if (threads > 0 && a.getDeviceInt(device, "type") == Api::kDeviceTypeCpu)
    a.setDeviceInt(device, "numThreads", threads);
  a.commitDevice(device);
  const size_t pixel = 3 * sizeof(float);
  // One "RT" filter over `inputs` (name, pixels) into `output`.
  const auto run = [&](std::initializer_list<std::pair<const char*, float*>> inputs, float* output,
                       bool hdr, bool cleanAux) {
    void* filter = a.newFilter(device, "RT");
    for (const auto& [name, pixels] : inputs)
      a.setSharedFilterImage(filter, name, pixels, Api::kFormatFloat3, w, h, 0, pixel, pixel * w);
    a.setSharedFilterImage(filter, "output", output, Api::kFormatFloat3, w, h, 0, pixel, pixel * w);
    if (hdr) a.setFilterBool(filter, "hdr", true);
    if (cleanAux) a.setFilterBool(filter, "cleanAux", true);
    a.commitFilter(filter);
    a.executeFilter(filter);
    a.releaseFilter(filter);
  };
  // The guides come from the same samples as the image and carry a little noise of their own
  // (antialiased edges, depth of field, what glass and mirrors show): each is denoised first and
  // the image then filtered with clean guides, as OIDN's documentation recommends
  // (docs/performance.md, Denoising, has what it gains).
  std::vector<float> albedoClean(n), normalClean(n);
  run({{"albedo", a01.data()}}, albedoClean.data(), false, false);
  run({{"normal", n11.data()}}, normalClean.data(), false, false);
  // Direct and indirect light are filtered apart and added: the direct part is far less noisy
  // and keeps its detail. Emitters seen directly carry no noise but their edges' and are left
  // out of both: their radiance, far above the rest, would spread into it (docs/performance.md,
  // Denoising).
  std::vector<float> directPart(n), indirectPart(n), indirectOut(n);
  for (size_t i = 0; i < n; ++i) {
    directPart[i] = direct[i] - emission[i];
    indirectPart[i] = image.pixels[i] - direct[i];
  }
  for (auto [colour, output] : {std::pair{&directPart, &out}, {&indirectPart, &indirectOut}})
    run({{"color", colour->data()}, {"albedo", albedoClean.data()}, {"normal", normalClean.data()}},
        output->data(), true, true);
  for (size_t i = 0; i < n; ++i) out[i] += indirectOut[i] + emission[i];
  const char* message = nullptr;
  const int error = a.getDeviceError(device, &message);
  a.releaseDevice(device);
  if (error != 0)
    throw std::runtime_error(std::string("Open Image Denoise failed: ") +
                             (message ? message : "unknown error"));
  image.pixels = std::move(out);
}

void OidnDenoiser::denoise(RenderResult& result, const SceneData& scene, int threads) const {
  const std::vector<ImageLayer> passes =
      makeAovLayers(scene, {Aov::Albedo, Aov::Normal, Aov::Direct, Aov::Emission}, result.aovs);
  denoise(result.image, passes[0].pixels, passes[1].pixels, passes[2].pixels, passes[3].pixels,
          threads);
}

}  // namespace candela::cli
