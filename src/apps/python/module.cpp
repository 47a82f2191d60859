// candela._candela: the nanobind extension behind the `candela` Python package.
//
// Exposes the loader, the animation (sceneAtFrame) and the backends' one seam
// (backends/renderer.h) with the smallest surface the Python layer (python/candela/__init__.py)
// needs; argument defaults, docs and conveniences live there. Images cross the boundary as
// float32 arrays (H, W, 3) of linear radiance, rows from the top. Errors: SceneError ->
// candela.SceneError (a ValueError), ImageWriteError -> candela.ImageWriteError (an OSError),
// std::invalid_argument -> ValueError, BackendError -> RuntimeError.
#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/array.h>
#include <nanobind/stl/optional.h>
#include <nanobind/stl/shared_ptr.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/tuple.h>
#include <nanobind/stl/vector.h>

#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include "apps/denoise/oidn_denoiser.h"
#include "apps/python/interruptible.h"
#include "backends/backend_report.h"
#include "backends/render_pilot.h"
#include "backends/renderer.h"
#include "backends/seen_emitters.h"
#include "backends/thread_limit.h"
#include "image/image_io.h"
#include "render/aov_layers.h"
#include "scene/animation.h"
#include "scene/camera_crop.h"
#include "scene/camera_resolve.h"
#include "scene/flatten.h"
#include "scene/frame_scene.h"
#include "scene/instance_poses.h"
#include "scene/mesh_layout.h"
#include "scene/read/scene_loader.h"
#include "scene/scene_error.h"

namespace nb = nanobind;
using namespace nb::literals;

namespace candela::python {
namespace {

using ImageArray = nb::ndarray<nb::numpy, float, nb::shape<-1, -1, 3>, nb::c_contig>;
using ImageInput = nb::ndarray<const float, nb::shape<-1, -1, 3>, nb::c_contig, nb::device::cpu>;
using PassInput = nb::ndarray<const float, nb::shape<-1, -1>, nb::c_contig, nb::device::cpu>;

// What the renders of one loaded scene share, whichever of its frames they render: the last
// frame's flattened scene (FrameScene reuses or refits it for the next, as the CLI does) and the
// renderer that holds it (the GPU keeps it resident). Renders of one scene take turns.
struct RenderCache {
  std::mutex mutex;
  FrameScene frames;
  std::unique_ptr<Renderer> renderer;
  Backend backend = Backend::Auto;  // of `renderer`
};

// A loaded scene and, for an animation, which frame of it (nullopt: frame 0 with the animation
// still attached, so `frames` and `frame(i)` work).
struct Scene {
  std::shared_ptr<const SceneDesc> desc;
  std::optional<uint32_t> frame;
  std::shared_ptr<RenderCache> cache = std::make_shared<RenderCache>();

  uint32_t frameCount() const { return desc->animation ? desc->animation->frames : 1; }
  SceneDesc still() const { return sceneAtFrame(*desc, frame.value_or(0)); }
};

// "auto" | "cpu" | "cuda"; ValueError for any other name, RuntimeError (BackendError) for a
// backend that cannot run here.
Backend backendNamed(const std::string& name) {
  Backend backend;
  if (!backendFromName(name, &backend))
    throw std::invalid_argument("backend must be 'auto', 'cpu' or 'cuda', got '" + name + "'");
  return chooseBackend(backend);
}

// `values` moved to the heap, with the capsule that frees them once no array views them.
template <typename Scalar>
std::pair<Scalar*, nb::capsule> heapOwned(std::vector<Scalar>&& values) {
  auto* owned = new std::vector<Scalar>(std::move(values));
  return {owned->data(), nb::capsule(owned, [](void* p) noexcept {
            delete static_cast<std::vector<Scalar>*>(p);
          })};
}

// An array owning `values`: (h, w) for one channel, (h, w, channels) for more.
template <typename Scalar>
nb::object ownedArray(std::vector<Scalar>&& values, size_t h, size_t w, size_t channels) {
  auto [data, owner] = heapOwned(std::move(values));
  if (channels == 1) return nb::cast(nb::ndarray<nb::numpy, Scalar>(data, {h, w}, owner));
  return nb::cast(nb::ndarray<nb::numpy, Scalar>(data, {h, w, channels}, owner));
}

ImageArray toArray(ImageRGB&& image) {
  const size_t h = image.height, w = image.width;
  auto [data, owner] = heapOwned(std::move(image.pixels));
  return ImageArray(data, {h, w, size_t(3)}, owner);
}

// A pass as an array: (H, W) for one channel, (H, W, 3) for three; ids as uint32.
nb::object layerToArray(ImageLayer&& layer) {
  const size_t h = layer.height, w = layer.width, n = layer.channels.size();
  if (layer.integer)
    return ownedArray(std::vector<uint32_t>(layer.pixels.begin(), layer.pixels.end()), h, w, 1);
  return ownedArray(std::move(layer.pixels), h, w, n);
}

// Each layer into *out, under its pass's name.
void addLayers(std::vector<ImageLayer>&& layers, nb::dict* out) {
  for (ImageLayer& layer : layers) {
    const std::string name = layer.name;
    (*out)[name.c_str()] = layerToArray(std::move(layer));
  }
}

// One field of the per-pixel pass sums (render/aov.h) as an (h, w) or (h, w, kChannels) array.
template <typename Scalar, int kChannels, typename Member>
nb::object sumsArray(const std::vector<AovPixel>& pixels, size_t h, size_t w,
                     Member AovPixel::*member) {
  static_assert(sizeof(Member) == sizeof(Scalar) * kChannels, "one scalar per channel");
  std::vector<Scalar> values(pixels.size() * kChannels);
  for (size_t i = 0; i < pixels.size(); ++i)
    std::memcpy(values.data() + kChannels * i, &(pixels[i].*member), sizeof(Member));
  return ownedArray(std::move(values), h, w, size_t(kChannels));
}

// The per-pixel pass sums as arrays, one per field, named by CANDELA_AOV_PIXEL_FIELDS, as
// python/candela/distributed.py, which merges those of several sample ranges, knows them.
nb::dict sumsToDict(const std::vector<AovPixel>& pixels, size_t h, size_t w) {
  nb::dict d;
#define CANDELA_SUMS_TO_DICT(member, name, Scalar, channels, merge) \
  d[name] = sumsArray<Scalar, channels>(pixels, h, w, &AovPixel::member);
  CANDELA_AOV_PIXEL_FIELDS(CANDELA_SUMS_TO_DICT)
#undef CANDELA_SUMS_TO_DICT
  return d;
}

// The inverse of sumsToDict, checked against the image size.
std::vector<AovPixel> sumsFromDict(const nb::dict& d, size_t h, size_t w) {
  const auto field = [&](const char* name, auto type, size_t channels) {
    using T = decltype(type);
    if (!d.contains(name)) throw std::invalid_argument(std::string("pass sums lack ") + name);
    // Without conversion: a converted copy would die with `a`, before its data is read.
    nb::ndarray<const T, nb::c_contig, nb::device::cpu> a;
    if (!nb::try_cast(d[name], a, false))
      throw std::invalid_argument(std::string("pass sums: ") + name +
                                  " must be a C-contiguous array of the dtype render gave it");
    if (a.size() != h * w * channels)
      throw std::invalid_argument(std::string("pass sums: ") + name + " has " +
                                  std::to_string(a.size()) + " values, expected " +
                                  std::to_string(h * w * channels));
    return a.data();
  };
  std::vector<AovPixel> pixels(h * w);
#define CANDELA_SUMS_FROM_DICT(member, name, Scalar, channels, merge)                  \
  {                                                                                    \
    const Scalar* values = field(name, Scalar(), channels);                            \
    for (size_t i = 0; i < pixels.size(); ++i)                                         \
      std::memcpy(&pixels[i].member, values + (channels)*i, sizeof(pixels[i].member)); \
  }
  CANDELA_AOV_PIXEL_FIELDS(CANDELA_SUMS_FROM_DICT)
#undef CANDELA_SUMS_FROM_DICT
  return pixels;
}

// How each field of the pass sums merges over sample ranges: {"position_sum": "added", ...,
// "nearest_material": "nearest"}.
nb::dict passSumMerges() {
  nb::dict d;
#define CANDELA_SUM_MERGE(member, name, Scalar, channels, merge) \
  d[name] = std::string(#merge) == "Added" ? "added" : "nearest";
  CANDELA_AOV_PIXEL_FIELDS(CANDELA_SUM_MERGE)
#undef CANDELA_SUM_MERGE
  return d;
}

// The still `desc` of a scene flattened into `cache` and given to its renderer on `chosen`, made
// anew where it has none or one on another backend. The caller holds cache.mutex.
const SceneData& prepareRenderer(RenderCache& cache, SceneDesc& desc, Backend chosen,
                                 const FlowMotion* flow, const FlowMotion* backwardFlow = nullptr) {
  const CpuEngine engine =
      resolveCpuEngine(CpuEngine::Auto, false, triangleCount(desc), sphereCount(desc));
  if (!needsOwnBvh(chosen, engine)) desc.ownBvh = OwnBvh::None;
  const SceneData& data = cache.frames.prepare(desc, flow, backwardFlow);
  SceneChange change = cache.frames.change();
  if (!cache.renderer || cache.backend != chosen) {
    cache.renderer.reset();  // a GPU's copy is freed before the next is made
    cache.renderer = makeRenderer(chosen, engine);
    cache.backend = chosen;
    change = SceneChange::Structure;
  }
  cache.renderer->setScene(data, change);
  return data;
}

// A render's crop, (x, y, width, height) of the camera's image.
using CropArgument = std::optional<std::tuple<uint32_t, uint32_t, uint32_t, uint32_t>>;

// The still of `scene`, with spp, seed, max_depth and the camera's crop overridden where given.
SceneDesc stillWith(const Scene& scene, std::optional<uint32_t> spp, std::optional<uint64_t> seed,
                    std::optional<uint32_t> maxDepth = std::nullopt, CropArgument crop = {}) {
  SceneDesc desc = scene.still();
  if (crop) {
    const CameraCrop c{std::get<0>(*crop), std::get<1>(*crop), std::get<2>(*crop),
                       std::get<3>(*crop)};
    if (const std::optional<std::string> problem =
            cropProblem(c, desc.camera.width, desc.camera.height))
      throw std::invalid_argument("crop: " + *problem);
    desc.camera.crop = c;
  }
  if (spp) {
    if (*spp == 0) throw std::invalid_argument("spp must be positive");
    desc.render.spp = *spp;
  }
  if (seed) desc.render.seed = *seed;
  if (maxDepth) {
    if (*maxDepth == 0) throw std::invalid_argument("max_depth must be positive");
    desc.render.maxDepth = *maxDepth;
  }
  return desc;
}

// passSums: the passes as their per-pixel sums ({"image", "sums"}), for a caller that adds those
// of several sample ranges and then calls passesFromSums; else as layers.
nb::object render(const Scene& scene, std::optional<uint32_t> spp, std::optional<uint64_t> seed,
                  const std::string& backend, std::optional<std::tuple<uint32_t, uint32_t>> range,
                  int threads, std::optional<std::vector<std::string>> aovNames, bool passSums,
                  std::optional<uint32_t> maxDepth, CropArgument crop) {
  const ThreadLimit threadLimit(threads);  // the build and pilot too, not only the tiles
  if (passSums && !aovNames) aovNames.emplace();
  const std::vector<Aov> aovs = aovNames ? aovsFromNames(*aovNames) : std::vector<Aov>();
  SceneDesc desc = stillWith(scene, spp, seed, maxDepth, crop);
  layOutForPasses(desc, aovs);
  SampleRange samples;
  if (range) {
    samples = {std::get<0>(*range), std::get<1>(*range)};
    if (samples.count == 0) throw std::invalid_argument("sample_range count must be positive");
  }
  const Backend chosen = backendNamed(backend);
  RenderOptions options;
  options.threads = threads;
  options.samples = samples;
  options.sceneLabel = desc.file;
  options.aovs = aovNames.has_value();
  RenderResult result;
  std::vector<ImageLayer> layers;
  RenderCache& cache = *scene.cache;
  runInterruptible([&](const std::atomic<bool>& cancel) {
    std::lock_guard<std::mutex> lock(cache.mutex);
    std::optional<FlowMotion> flow, backwardFlow;
    const uint32_t frame = scene.frame.value_or(0);
    if (hasAov(aovs, Aov::Flow)) flow = flowMotion(desc, sceneAtFrame(*scene.desc, frame + 1));
    // Frame 0 has none before it: its backward flow is that of a still, 0.
    if (hasAov(aovs, Aov::BackwardFlow))
      backwardFlow = flowMotion(desc, sceneAtFrame(*scene.desc, frame > 0 ? frame - 1 : 0));
    const SceneData& data = prepareRenderer(cache, desc, chosen, flow ? &*flow : nullptr,
                                            backwardFlow ? &*backwardFlow : nullptr);
    options.cancel = &cancel;
    result = renderWithPilot(*cache.renderer, data, options);
    if (!result.cancelled && aovNames && !passSums)
      layers = makeAovLayers(data, aovs, result.aovs);
  });
  if (!aovNames) return nb::cast(toArray(std::move(result.image)));
  nb::dict out;
  const size_t h = result.image.height, w = result.image.width;
  out["image"] = toArray(std::move(result.image));
  if (passSums) {
    if (result.aovs.size() != h * w) throw std::runtime_error("the render returned no pass sums");
    out["sums"] = sumsToDict(result.aovs, h, w);
    return out;
  }
  addLayers(std::move(layers), &out);
  return out;
}

// `emission` (the emission pass of a render of `scene`, spp and seed as render's) with the
// emitters it sees sampled again for the denoiser in place of its own values there
// (backends/seen_emitters.h); None where nothing is sampled again.
nb::object seenEmitters(const Scene& scene, const ImageInput& emission, std::optional<uint32_t> spp,
                        std::optional<uint64_t> seed, const std::string& backend, int threads,
                        CropArgument crop) {
  const ThreadLimit threadLimit(threads);
  SceneDesc desc = stillWith(scene, spp, seed, std::nullopt, crop);
  const uint32_t width = renderedWidth(desc.camera), height = renderedHeight(desc.camera);
  if (emission.shape(0) != height || emission.shape(1) != width)
    throw std::invalid_argument("the emission pass must be the render's, (" +
                                std::to_string(height) + ", " + std::to_string(width) + ", 3)");
  const Backend chosen = backendNamed(backend);
  RenderOptions options;
  options.threads = threads;
  options.sceneLabel = desc.file;
  SeenEmitters seen;
  RenderCache& cache = *scene.cache;
  runInterruptible([&](const std::atomic<bool>& cancel) {
    std::lock_guard<std::mutex> lock(cache.mutex);
    const SceneData& data = prepareRenderer(cache, desc, chosen, nullptr);
    options.cancel = &cancel;
    seen = sampleSeenEmitters(*cache.renderer, data, options);
  });
  if (seen.covered.empty()) return nb::none();
  const size_t h = emission.shape(0), w = emission.shape(1);
  std::vector<float> pass(emission.data(), emission.data() + h * w * 3);
  seen.replaceIn(pass.data());
  return ownedArray(std::move(pass), h, w, 3);
}

// The layers of passes `aovNames` from per-pixel sums (sumsToDict's, possibly added over sample
// ranges) of a render of this scene.
nb::dict passesFromSums(const Scene& scene, const nb::dict& sums,
                        const std::vector<std::string>& aovNames, CropArgument crop) {
  const std::vector<Aov> aovs = aovsFromNames(aovNames);
  // A still scene's description as loaded; only an animation's frame, or a crop, is made (and
  // copied).
  std::optional<SceneDesc> frame;
  if (scene.desc->animation || crop)
    frame = stillWith(scene, std::nullopt, std::nullopt, std::nullopt, crop);
  const SceneData data = flattenPassContext(frame ? *frame : *scene.desc);
  nb::dict out;
  addLayers(makeAovLayers(data, aovs, sumsFromDict(sums, data.camera.height, data.camera.width)),
            &out);
  return out;
}

void writeImageArray(const std::string& path, const ImageInput& img, bool srgb, float gamma,
                     float exposure, int toneMap, const std::optional<PassInput>& alphaPass) {
  if (!isSupportedImagePath(path))
    throw std::invalid_argument(path + ": unsupported image format, expected .png, .exr or .pfm");
  ImageRGB image(uint32_t(img.shape(1)), uint32_t(img.shape(0)));
  std::memcpy(image.pixels.data(), img.data(), image.pixels.size() * sizeof(float));
  std::optional<ImageLayer> alpha;
  if (alphaPass) {
    if (alphaPass->shape(0) != img.shape(0) || alphaPass->shape(1) != img.shape(1))
      throw std::invalid_argument(
          "alpha must be of the image's shape (" + std::to_string(img.shape(0)) + ", " +
          std::to_string(img.shape(1)) + "), got (" + std::to_string(alphaPass->shape(0)) + ", " +
          std::to_string(alphaPass->shape(1)) + ")");
    alpha.emplace("alpha", std::vector<std::string>{"A"}, false, image.width, image.height);
    std::memcpy(alpha->pixels.data(), alphaPass->data(), alpha->pixels.size() * sizeof(float));
  }
  OutputDesc output;
  output.curve = srgb ? GammaCurve::Srgb : GammaCurve::Power;
  output.gamma = gamma;
  output.exposure = exposure;
  output.toneMap = ToneMap(toneMap);
  nb::gil_scoped_release release;
  writeImage(path, image, output, alpha ? &*alpha : nullptr);
}

// Open Image Denoise from the library file `library`, loaded once and kept for the process:
// its devices stay up between calls, as its first start is what costs. RuntimeError where it
// cannot be loaded.
const OidnDenoiser& oidn(const std::string& library) {
  static std::mutex mutex;
  static std::map<std::string, OidnDenoiser*> loaded;  // never unloaded (see above)
  std::lock_guard<std::mutex> lock(mutex);
  OidnDenoiser*& denoiser = loaded[library];
  if (!denoiser) {
    std::string whyNot;
    denoiser = OidnDenoiser::load(&whyNot, library).release();
    if (!denoiser) throw std::runtime_error(whyNot);
  }
  return *denoiser;
}

// OidnDenoiser::denoise on arrays of one shape: the denoised image, a new array.
ImageArray denoiseArrays(const std::string& library, const ImageInput& image,
                         const ImageInput& albedo, const ImageInput& normal,
                         const std::optional<ImageInput>& direct,
                         const std::optional<ImageInput>& emission,
                         const std::optional<ImageInput>& seenEmission, int threads) {
  const size_t h = image.shape(0), w = image.shape(1);
  for (const ImageInput* pass :
       {&albedo, &normal, direct ? &*direct : nullptr, emission ? &*emission : nullptr,
        seenEmission ? &*seenEmission : nullptr})
    if (pass && (pass->shape(0) != h || pass->shape(1) != w))
      throw std::invalid_argument("denoise: every pass must have the image's shape (" +
                                  std::to_string(h) + ", " + std::to_string(w) + ", 3)");
  const OidnDenoiser& denoiser = oidn(library);
  std::vector<float> pixels(image.data(), image.data() + 3 * w * h);
  {
    nb::gil_scoped_release release;
    denoiser.denoise(pixels.data(), w, h, albedo.data(), normal.data(),
                     direct ? direct->data() : nullptr, emission ? emission->data() : nullptr,
                     seenEmission ? seenEmission->data() : nullptr, threads);
  }
  auto [data, owner] = heapOwned(std::move(pixels));
  return ImageArray(data, {h, w, size_t(3)}, owner);
}

}  // namespace
}  // namespace candela::python

NB_MODULE(_candela, m) {
  using namespace candela;
  using namespace candela::python;
  m.doc() = "candela's C++ core; use the `candela` package rather than this module";
  nb::exception<SceneError>(m, "SceneError", PyExc_ValueError);
  nb::exception<ImageWriteError>(m, "ImageWriteError", PyExc_OSError);
  nb::exception<BackendError>(m, "BackendError", PyExc_RuntimeError);

  // The bindings as written, one a line or a lambda each.
  // clang-format off
  nb::class_<Scene>(m, "_Scene")
      .def_static("load", [](const std::string& path) {
        return Scene{std::make_shared<const SceneDesc>(loadSceneFile(path)), std::nullopt};
      }, "path"_a)
      .def_static("from_text", [](const std::string& text, const std::string& label,
                                  const std::string& baseDir) {
        return Scene{std::make_shared<const SceneDesc>(parseSceneText(text, label, baseDir)),
                     std::nullopt};
      }, "text"_a, "label"_a, "base_dir"_a)
      .def_prop_ro("frames", &Scene::frameCount)
      .def_prop_ro("warnings", [](const Scene& s) { return s.desc->warnings; })
      .def_prop_ro("frame_index", [](const Scene& s) { return s.frame; })
      .def_prop_ro("fps", [](const Scene& s) {
        return s.desc->animation ? s.desc->animation->fps : 24.0f;
      })
      .def_prop_ro("width", [](const Scene& s) { return s.desc->camera.width; })
      .def_prop_ro("height", [](const Scene& s) { return s.desc->camera.height; })
      .def_prop_ro("spp", [](const Scene& s) { return s.desc->render.spp; })
      .def_prop_ro("seed", [](const Scene& s) { return s.still().render.seed; })
      .def_prop_ro("output", [](const Scene& s) {
        const OutputDesc& o = s.desc->output;
        return std::make_tuple(o.curve == GammaCurve::Srgb, o.gamma, o.exposure, int(o.toneMap));
      })
      .def_prop_ro("instances", [](const Scene& s) {
        nb::dict names;
        // The same in every frame.
        for (const auto& [number, name] : instanceNames(*s.desc)) names[nb::int_(number)] = name;
        return names;
      })
      .def_prop_ro("_camera", [](const Scene& s) {
        // Rows of K and of [R t; 0 1] (docs/aovs.md, *The camera file*), as the CLI writes them.
        const SceneDesc frame = s.still();
        const CameraMatrices c = cameraMatrices(frame.camera, frame.file);
        nb::list intrinsics;
        for (const auto& row : c.intrinsics.m)
          intrinsics.append(nb::make_tuple(row[0], row[1], row[2]));
        nb::dict camera;
        camera["width"] = c.width;
        camera["height"] = c.height;
        if (const std::optional<CameraCrop>& crop = frame.camera.crop)
          camera["crop"] = nb::make_tuple(crop->x, crop->y, crop->width, crop->height);
        if (c.projection != CameraProjection::Perspective)
          camera["projection"] = projectionName(c.projection);
        if (c.projection != CameraProjection::Equirectangular) camera["intrinsics"] = intrinsics;
        camera["extrinsics"] = affineRows(c.rotation, c.translation);
        if (c.apertureRadius > 0.0f) {
          camera["aperture_radius"] = c.apertureRadius;
          camera["focus_distance"] = c.focusDistance;
        }
        if (!c.distortion.empty()) camera["distortion"] = c.distortion;
        return camera;
      })
      .def_prop_ro("_poses", [](const Scene& s) {
        // (number, name, rows of [linear position] to the world and to the camera, the model's
        // box as (lo, hi) or None), as the CLI's poses file (docs/aovs.md, *Instance poses*).
        const SceneDesc frame = s.still();
        const CameraMatrices camera = cameraMatrices(frame.camera, frame.file);
        nb::list poses;
        for (const InstancePose& pose : instancePoses(frame)) {
          const InstancePose seen = poseInCamera(pose, camera);
          nb::object box = nb::none();
          if (const std::optional<Bounds3>& b = pose.modelBox)
            box = nb::make_tuple(nb::make_tuple(b->lo.x, b->lo.y, b->lo.z),
                                 nb::make_tuple(b->hi.x, b->hi.y, b->hi.z));
          poses.append(nb::make_tuple(pose.number, pose.name,
                                      affineRows(pose.linear, pose.position),
                                      affineRows(seen.linear, seen.position), box));
        }
        return poses;
      })
      .def_prop_ro("_last_change", [](const Scene& s) -> std::optional<std::string> {
        // What the last render of this scene (or of any of its frames) did with the flattened
        // scene: "values" (reused), "motion" (refitted) or "structure" (built); None before any.
        std::lock_guard<std::mutex> lock(s.cache->mutex);
        if (!s.cache->renderer) return std::nullopt;
        return std::string(sceneChangeName(s.cache->frames.change()));
      })
      .def("frame", [](const Scene& s, uint32_t i) {
        if (i >= s.frameCount())
          throw nb::index_error(("frame " + std::to_string(i) + " out of range (" +
                                 std::to_string(s.frameCount()) + " frames)").c_str());
        return Scene{s.desc, i, s.cache};
      }, "index"_a)
      .def("render", &render, "spp"_a = nb::none(), "seed"_a = nb::none(), "backend"_a = "auto",
           "sample_range"_a = nb::none(), "threads"_a = 0, "aovs"_a = nb::none(),
           "pass_sums"_a = false, "max_depth"_a = nb::none(), "crop"_a = nb::none())
      .def("passes_from_sums", &passesFromSums, "sums"_a, "aovs"_a, "crop"_a = nb::none())
      .def("seen_emitters", &seenEmitters, "emission"_a, "spp"_a = nb::none(),
           "seed"_a = nb::none(), "backend"_a = "auto", "threads"_a = 0, "crop"_a = nb::none());
  // clang-format on

  m.attr("PASS_SUM_MERGES") = passSumMerges();
  m.def("check_aovs", [](const std::vector<std::string>& names) { aovsFromNames(names); },
        "names"_a);
  m.def("write_image", &writeImageArray, "path"_a, "img"_a, "srgb"_a, "gamma"_a, "exposure"_a,
        "tone_map"_a, "alpha"_a = nb::none());
  m.def("denoise", &denoiseArrays, "library"_a, "image"_a, "albedo"_a, "normal"_a,
        "direct"_a = nb::none(), "emission"_a = nb::none(), "seen_emission"_a = nb::none(),
        "threads"_a = 0);
  m.def("devices", [](int threads) {
    nb::list reports;
    for (const BackendReport& r : reportBackends(threads)) {
      nb::dict d;
      d["backend"] = r.backend;
      d["usable"] = r.usable;
      d["summary"] = r.summary;
      d["auto"] = r.autoPicks;
      reports.append(d);
    }
    return reports;
  }, "threads"_a = 0);
  m.def("cuda_available", [] {
    std::string reason;
    return cudaUsable(&reason);
  });
}
