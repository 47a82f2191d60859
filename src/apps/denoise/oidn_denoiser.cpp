#include "apps/denoise/oidn_denoiser.h"

#include <dlfcn.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <utility>

#include "render/aov_layers.h"

namespace candela {

// The few entry points of OIDN's C API (OpenImageDenoise/oidn.h, version 2) that denoising
// needs, as X(member, symbol, return type, parameters): declared here because only the library,
// not its header, comes with pyoidn.
#define CANDELA_OIDN_ENTRY_POINTS(X)                                                        \
  X(newDevice, oidnNewDevice, void*, (int type))                                            \
  X(setDeviceInt, oidnSetDeviceInt, void, (void* device, const char* name, int value))      \
  X(commitDevice, oidnCommitDevice, void, (void* device))                                   \
  X(getDeviceError, oidnGetDeviceError, int, (void* device, const char** message))          \
  X(releaseDevice, oidnReleaseDevice, void, (void* device))                                 \
  X(newBuffer, oidnNewBuffer, void*, (void* device, size_t byteSize))                       \
  X(writeBuffer, oidnWriteBuffer, void,                                                     \
    (void* buffer, size_t byteOffset, size_t byteSize, const void* source))                 \
  X(readBuffer, oidnReadBuffer, void,                                                       \
    (void* buffer, size_t byteOffset, size_t byteSize, void* destination))                  \
  X(releaseBuffer, oidnReleaseBuffer, void, (void* buffer))                                 \
  X(newFilter, oidnNewFilter, void*, (void* device, const char* type))                      \
  X(setFilterImage, oidnSetFilterImage, void,                                               \
    (void* filter, const char* name, void* buffer, int format, size_t width, size_t height, \
     size_t byteOffset, size_t pixelStride, size_t rowStride))                              \
  X(setFilterBool, oidnSetFilterBool, void, (void* filter, const char* name, bool value))   \
  X(setFilterInt, oidnSetFilterInt, void, (void* filter, const char* name, int value))      \
  X(commitFilter, oidnCommitFilter, void, (void* filter))                                   \
  X(executeFilter, oidnExecuteFilter, void, (void* filter))                                 \
  X(releaseFilter, oidnReleaseFilter, void, (void* filter))

struct OidnDenoiser::Api {
  static constexpr int kFormatFloat3 = 3;     // OIDN_FORMAT_FLOAT3
  static constexpr int kDeviceTypeCpu = 1;    // OIDN_DEVICE_TYPE_CPU
  static constexpr int kQualityBalanced = 5;  // OIDN_QUALITY_BALANCED
#define CANDELA_OIDN_MEMBER(member, symbol, Result, Parameters) \
  Result(*member) Parameters = nullptr;
  CANDELA_OIDN_ENTRY_POINTS(CANDELA_OIDN_MEMBER)
#undef CANDELA_OIDN_MEMBER
};

namespace {

template <typename F>
bool bind(void* handle, const char* name, F* f) {
  *f = reinterpret_cast<F>(dlsym(handle, name));
  return *f != nullptr;
}

// The folder of the pyoidn package of python3 on PATH, or "" (no python3, no pyoidn). The
// package is found, not imported: importing it loads numpy too, a quarter of a second.
std::string pyoidnLibraryFolder() {
  FILE* pipe = popen(
      "python3 -c 'import importlib.util, os, sys; s = importlib.util.find_spec(\"pyoidn\"); "
      "sys.exit(1) if s is None or not s.submodule_search_locations else "
      "print(os.path.join(list(s.submodule_search_locations)[0], \"oidn\", \"lib\"))' "
      "2>/dev/null < /dev/null",
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

std::unique_ptr<OidnDenoiser> OidnDenoiser::load(std::string* whyNot, const std::string& library) {
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
    d->api_ = std::make_unique<Api>();
    Api& a = *d->api_;
    bool complete = true;
#define CANDELA_OIDN_BIND(member, symbol, Result, Parameters) \
  complete = complete && bind(handle, #symbol, &a.member);
    CANDELA_OIDN_ENTRY_POINTS(CANDELA_OIDN_BIND)
#undef CANDELA_OIDN_BIND
    if (!complete) {
      d.reset();
      *whyNot = path + " is not Open Image Denoise 2 (an entry point is missing)";
    }
    return true;
  };
  // pyoidn's copy is looked for (by running python3) only when the library path has none.
  if (!library.empty()) {
    if (open(library)) return d;
  } else if (const char* env = std::getenv("CANDELA_OIDN_LIBRARY"); env && *env) {
    if (open(env)) return d;
  } else if (open("libOpenImageDenoise.so.2")) {
    return d;
  } else if (const std::string folder = pyoidnLibraryFolder();
             !folder.empty() && open(folder + "/libOpenImageDenoise.so.2")) {
    return d;
  }
  *whyNot = "denoising needs Intel Open Image Denoise 2, which was not found (tried " + tried +
            "): install it with `pip install pyoidn` (scripts/install-python does), or set "
            "CANDELA_OIDN_LIBRARY to its libOpenImageDenoise.so";
  return nullptr;
}

OidnDenoiser::~OidnDenoiser() {
  if (api_)
    for (const auto& [threads, device] : devices_) api_->releaseDevice(device);
  if (handle_) dlclose(handle_);
}

void* OidnDenoiser::device(int threads) const {
  if (const auto found = devices_.find(threads); found != devices_.end()) return found->second;
  const Api& a = *api_;
  // The CPU device: OIDN's GPU devices (pyoidn's library has CUDA) have not run with candela yet.
  // The images go through OIDN's buffers, which any device reads, so one may take its place.
  void* device = a.newDevice(Api::kDeviceTypeCpu);
  if (!device) throw std::runtime_error("Open Image Denoise could not create a device");
  if (threads > 0) a.setDeviceInt(device, "numThreads", threads);
  a.commitDevice(device);
  const char* message = nullptr;
  if (a.getDeviceError(device, &message) != 0) {
    const std::string why = message ? message : "unknown error";
    a.releaseDevice(device);
    throw std::runtime_error("Open Image Denoise could not start: " + why);
  }
  devices_[threads] = device;
  return device;
}

namespace {

// An OIDN buffer of `bytes`, filled from `source` where given, released when it goes.
class Buffer {
 public:
  Buffer(const OidnDenoiser::Api& api, void* device, size_t bytes, const float* source = nullptr)
      : api_(api), buffer_(api.newBuffer(device, bytes)) {
    if (!buffer_)
      throw std::runtime_error("Open Image Denoise could not allocate " + std::to_string(bytes) +
                               " bytes for an image");
    if (source) api.writeBuffer(buffer_, 0, bytes, source);
  }
  ~Buffer() {
    if (buffer_) api_.releaseBuffer(buffer_);
  }
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;
  void* get() const { return buffer_; }

 private:
  const OidnDenoiser::Api& api_;
  void* buffer_;
};

}  // namespace

void OidnDenoiser::denoise(float* image, size_t width, size_t height, const float* albedo,
                           const float* normal, const float* direct, const float* emission,
                           const float* seenEmission, int threads) const {
  std::lock_guard<std::mutex> lock(mutex_);
  const Api& a = *api_;
  void* dev = device(threads);
  const size_t n = 3 * width * height, bytes = n * sizeof(float), pixel = 3 * sizeof(float);
  // One "RT" filter over `inputs` (name, buffer) into `output`, at OIDN's default quality (high)
  // unless `balanced`.
  const auto run = [&](std::initializer_list<std::pair<const char*, const Buffer*>> inputs,
                       const Buffer& output, bool hdr, bool cleanAux, bool balanced = false) {
    void* filter = a.newFilter(dev, "RT");
    for (const auto& [name, buffer] : inputs)
      a.setFilterImage(filter, name, buffer->get(), Api::kFormatFloat3, width, height, 0, pixel,
                       pixel * width);
    a.setFilterImage(filter, "output", output.get(), Api::kFormatFloat3, width, height, 0, pixel,
                     pixel * width);
    if (hdr) a.setFilterBool(filter, "hdr", true);
    if (cleanAux) a.setFilterBool(filter, "cleanAux", true);
    if (balanced) a.setFilterInt(filter, "quality", Api::kQualityBalanced);
    a.commitFilter(filter);
    a.executeFilter(filter);
    a.releaseFilter(filter);
  };
  // OIDN expects albedo in [0, 1] and normals in [-1, 1]; the passes hold those already, up to
  // rounding, which the clamps take away.
  std::vector<float> host(n);
  std::transform(albedo, albedo + n, host.begin(),
                 [](float v) { return std::min(1.0f, std::max(0.0f, v)); });
  const Buffer albedoIn(a, dev, bytes, host.data());
  std::transform(normal, normal + n, host.begin(),
                 [](float v) { return std::min(1.0f, std::max(-1.0f, v)); });
  const Buffer normalIn(a, dev, bytes, host.data());
  // The guides come from the same samples as the image and carry a little noise of their own
  // (antialiased edges, depth of field, what glass and mirrors show): each is denoised first and
  // the image then filtered with clean guides, as OIDN's documentation recommends
  // (docs/performance.md, Denoising, has what it gains). At OIDN's balanced quality: its high
  // quality's larger networks took twice the time and left the denoised images no closer to the
  // converged ones (docs/performance.md, Denoising).
  const Buffer albedoClean(a, dev, bytes), normalClean(a, dev, bytes);
  run({{"albedo", &albedoIn}}, albedoClean, false, false, true);
  run({{"normal", &normalIn}}, normalClean, false, false, true);
  // Direct and indirect light are filtered apart and added: the direct part is far less noisy
  // and keeps its detail. Emitters seen directly carry no noise but their edges' and are left
  // out of both: their radiance, far above the rest, would spread into it (docs/performance.md,
  // Denoising).
  std::vector<std::vector<float>> parts;
  if (!direct) {
    parts.emplace_back(image, image + n);
  } else {
    parts.assign(2, std::vector<float>(n));
    for (size_t i = 0; i < n; ++i) {
      parts[0][i] = direct[i] - (emission ? emission[i] : 0.0f);
      parts[1][i] = image[i] - direct[i];
    }
  }
  std::vector<float> sum(n, 0.0f), filtered(n);
  for (const std::vector<float>& part : parts) {
    const Buffer colour(a, dev, bytes, part.data()), output(a, dev, bytes);
    run({{"color", &colour}, {"albedo", &albedoClean}, {"normal", &normalClean}}, output, true,
        true);
    a.readBuffer(output.get(), 0, bytes, filtered.data());
    for (size_t i = 0; i < n; ++i) sum[i] += filtered[i];
  }
  const char* message = nullptr;
  if (a.getDeviceError(dev, &message) != 0)
    throw std::runtime_error(std::string("Open Image Denoise failed: ") +
                             (message ? message : "unknown error"));
  const float* added = direct ? (seenEmission ? seenEmission : emission) : nullptr;
  for (size_t i = 0; i < n; ++i) image[i] = sum[i] + (added ? added[i] : 0.0f);
}

void OidnDenoiser::denoise(RenderResult& result, const SceneData& scene, Renderer& renderer,
                           const RenderOptions& options) const {
  const SeenEmitters seen = sampleSeenEmitters(renderer, scene, options);
  if (seen.cancelled) {
    result.cancelled = true;
    return;
  }
  const std::vector<ImageLayer> passes =
      makeAovLayers(scene, {Aov::Albedo, Aov::Normal, Aov::Direct, Aov::Emission}, result.aovs);
  std::vector<float> seenEmission = passes[3].pixels;
  seen.replaceIn(seenEmission.data());
  denoise(result.image.pixels.data(), result.image.width, result.image.height,
          passes[0].pixels.data(), passes[1].pixels.data(), passes[2].pixels.data(),
          passes[3].pixels.data(), seenEmission.data(), options.threads);
}

}  // namespace candela
