// CUDA entry points: upload, the progressive render kernel and the host loop. All rendering
// logic is the shared integrator; this file only maps pixels to threads.
#include "backends/cuda/cuda_renderer.h"

#include <unistd.h>

#include <chrono>

#include "backends/cuda/cuda_check.h"
#include "backends/cuda/device_buffer.h"
#include "geometry/bvh_tracer.h"
#include "render/render_pixel.h"

namespace candela {

std::string formatBytes(size_t bytes) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.1f MiB", double(bytes) / (1024.0 * 1024.0));
  return buf;
}

void throwCudaError(cudaError_t err, const char* call, const char* file, int line) {
  throw CudaError(std::string("CUDA error: ") + cudaGetErrorString(err) + " in " + call + " (" +
                  file + ":" + std::to_string(line) + ")");
}

bool cudaBackendAvailable(std::string* reason) {
  int count = 0;
  const cudaError_t err = cudaGetDeviceCount(&count);
  if (err != cudaSuccess) {
    cudaGetLastError();
    if (reason) {
      *reason = cudaGetErrorString(err);
      // What the runtime says where no driver is loaded at all is about versions; say what is
      // missing first.
      if (err == cudaErrorInsufficientDriver && access("/proc/driver/nvidia/version", F_OK) != 0)
        *reason = "no NVIDIA driver is loaded (CUDA: " + *reason + ")";
    }
    return false;
  }
  if (count == 0) {
    if (reason) *reason = "no CUDA device found";
    return false;
  }
  return true;
}

std::string cudaDeviceSummary() {
  int device = 0, count = 0, driver = 0, runtime = 0;
  cudaDeviceProp p{};
  if (cudaGetDevice(&device) != cudaSuccess || cudaGetDeviceCount(&count) != cudaSuccess ||
      cudaGetDeviceProperties(&p, device) != cudaSuccess) {
    cudaGetLastError();
    return "a CUDA device that does not describe itself";
  }
  cudaDriverGetVersion(&driver);
  cudaRuntimeGetVersion(&runtime);
  char text[512];
  std::snprintf(text, sizeof text,
                "%s (device %d of %d), %.1f GiB, compute capability %d.%d, %d multiprocessors; "
                "driver %d.%d, runtime %d.%d",
                p.name, device, count, double(p.totalGlobalMem) / (1024.0 * 1024.0 * 1024.0),
                p.major, p.minor, p.multiProcessorCount, driver / 1000, driver % 1000 / 10,
                runtime / 1000, runtime % 1000 / 10);
  return text;
}

namespace {

constexpr int kBlockWidth = 16, kBlockHeight = 8;

// Ray counts are summed per warp before one atomic add, so counting costs next to nothing.
__device__ void addCounters(unsigned long long* global, const RayCounters& c) {
  unsigned long long v[3] = {c.camera, c.bounce, c.shadow};
  for (int i = 0; i < 3; ++i) {
    for (int offset = 16; offset > 0; offset /= 2) v[i] += __shfl_down_sync(0xffffffffu, v[i], offset);
    if ((threadIdx.x + threadIdx.y * blockDim.x) % 32 == 0) atomicAdd(&global[i], v[i]);
  }
}

// With kAovs each pixel's pass sums (render/aov.h) continue from the last pass's.
// The scene is __grid_constant__: the integrator takes its address, and a plain parameter whose
// address is taken is copied into every thread's local memory (its kilobyte read back from there
// by every access) where this one is read in place from the constant bank.
template <bool kAovs>
__global__ void renderPassKernel(const __grid_constant__ SceneView scene, uint32_t sampleBegin,
                                 uint32_t sampleCount, float3* accumulation, AovPixel* aovs,
                                 unsigned long long* rayCounts) {
  const uint32_t x = blockIdx.x * blockDim.x + threadIdx.x;
  const uint32_t y = blockIdx.y * blockDim.y + threadIdx.y;
  RayCounters counters;
  if (x < scene.camera.width && y < scene.camera.height) {
    const size_t pixel = size_t(y) * scene.camera.width + x;
    AovPixel aov;
    if (kAovs) aov = aovs[pixel];
    const Vec3 sum = renderPixelSamples<kAovs>(scene, BvhTracer{&scene}, x, y, sampleBegin,
                                               sampleCount, counters, Vec3(0.0f), &aov);
    if (kAovs) aovs[pixel] = aov;
    float3& acc = accumulation[pixel];
    acc.x += sum.x;
    acc.y += sum.y;
    acc.z += sum.z;
  }
  addCounters(rayCounts, counters);  // every lane takes part in the shuffle
}

}  // namespace

// Samples per pixel of one kernel launch: few enough that a pass stays short, so progress and
// Ctrl-C are answered promptly.
constexpr uint32_t kSamplesPerPass = 4;

#define CANDELA_DEVICE_ARRAY(Type, name, count, rewrittenBy) DeviceBuffer<Type> name;

struct CudaRenderer::Impl {
  CANDELA_SCENE_ARRAYS(CANDELA_DEVICE_ARRAY)
  SceneView view;
  bool complete = false;  // whether every array holds the scene given last
  // The keys of the keyed groups on the device (render/scene_change.h, RewrittenBy).
  uint64_t environmentMapHash = 0;
  uint64_t lightTreeHash = 0;
  uint64_t texturePoolHash = 0;
};

#undef CANDELA_DEVICE_ARRAY

CudaRenderer::CudaRenderer() : impl_(new Impl) {
  std::string reason;
  if (!cudaBackendAvailable(&reason)) throw CudaError(reason);
}

CudaRenderer::~CudaRenderer() = default;

void CudaRenderer::setScene(const SceneData& scene, SceneChange change) {
  Impl& d = *impl_;
  SceneUpdate update;  // everything, unless the device holds the last scene whole
  if (d.complete) {
    update.change = change;
    update.environmentMap = scene.environmentMapHash != d.environmentMapHash;
    update.lightTree = scene.lightTreeHash != d.lightTreeHash;
    update.texturePool = scene.texturePoolHash != d.texturePoolHash;
  }
  d.complete = false;
  d.view = scene.view();  // counts, camera and settings; pointers replaced below
#define CANDELA_UPLOAD(Type, name, count, rewrittenBy)                              \
  if (mayRewrite(update, RewrittenBy::rewrittenBy)) d.name.upload(scene.name); \
  d.view.name = d.name.get();
  CANDELA_SCENE_ARRAYS(CANDELA_UPLOAD)
#undef CANDELA_UPLOAD
  d.environmentMapHash = scene.environmentMapHash;
  d.lightTreeHash = scene.lightTreeHash;
  d.texturePoolHash = scene.texturePoolHash;
  d.complete = true;
}

RenderResult CudaRenderer::render(const RenderOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const SceneView view = adjustedView(impl_->view, options.adjust);
  const uint32_t width = view.camera.width, height = view.camera.height;
  const SampleRange samples = resolveSampleRange(options.samples, view.settings.spp);
  const uint32_t first = samples.begin, end = samples.begin + samples.count;
  const uint32_t perPass = kSamplesPerPass;

  DeviceBuffer<float3> accumulation(size_t(width) * height);
  accumulation.zero();
  DeviceBuffer<AovPixel> aovs;
  if (options.aovs) aovs.upload(std::vector<AovPixel>(size_t(width) * height));
  DeviceBuffer<unsigned long long> rayCounts(3);
  rayCounts.zero();

  cudaEvent_t passDone;
  CANDELA_CUDA_CHECK(cudaEventCreateWithFlags(&passDone, cudaEventBlockingSync | cudaEventDisableTiming));
  const dim3 block(kBlockWidth, kBlockHeight);
  const dim3 grid((width + kBlockWidth - 1) / kBlockWidth, (height + kBlockHeight - 1) / kBlockHeight);

  RenderResult result;
  uint32_t pass = 0;
  for (uint32_t begin = first; begin < end; begin += perPass, ++pass) {
    if (options.cancel && options.cancel->load()) {
      result.cancelled = true;
      break;
    }
    const uint32_t count = end - begin < perPass ? end - begin : perPass;
    if (options.aovs)
      renderPassKernel<true><<<grid, block>>>(view, begin, count, accumulation.get(), aovs.get(),
                                              rayCounts.get());
    else
      renderPassKernel<false><<<grid, block>>>(view, begin, count, accumulation.get(), nullptr,
                                               rayCounts.get());
    cudaError_t err = cudaGetLastError();
    if (err == cudaSuccess) err = cudaEventRecord(passDone);
    if (err == cudaSuccess) err = cudaEventSynchronize(passDone);  // sleeps, does not spin
    if (err != cudaSuccess) {
      cudaEventDestroy(passDone);
      throw CudaError("CUDA kernel failed while rendering " + options.sceneLabel + " (pass " +
                      std::to_string(pass) + ", samples " + std::to_string(begin) + "-" +
                      std::to_string(begin + count - 1) + "): " + cudaGetErrorString(err));
    }
    if (options.progress) options.progress(double(begin + count - first) / samples.count);
  }
  cudaEventDestroy(passDone);

  std::vector<float3> sums;
  accumulation.download(&sums);
  std::vector<unsigned long long> counts;
  rayCounts.download(&counts);
  result.image = ImageRGB(width, height);
  const float inv = 1.0f / float(samples.count);
  for (size_t i = 0; i < sums.size(); ++i) {
    result.image.pixels[3 * i] = sums[i].x * inv;
    result.image.pixels[3 * i + 1] = sums[i].y * inv;
    result.image.pixels[3 * i + 2] = sums[i].z * inv;
  }
  if (options.aovs) aovs.download(&result.aovs);
  result.rays.camera = counts[0];
  result.rays.bounce = counts[1];
  result.rays.shadow = counts[2];
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace candela
