// Crops (CameraDesc::crop, docs/scene-format.md *Crops*): a cropped render's pixels are the whole
// image's render's there, bit for bit, image and passes, whatever the camera; the windows of the
// emitters seen sampled again and the pilot's sparse pixels lie in the crop's image; and the
// crops that fit no image are refused.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "backends/cpu/cpu_renderer.h"
#include "backends/seen_emitters.h"
#include "render/aov_layers.h"
#include "render/camera_ray.h"
#include "render/view_adjustment.h"
#include "render_test_util.h"

namespace candela {
namespace {

constexpr uint32_t kWidth = 40, kHeight = 30;
const CameraCrop kCrop{11, 7, 17, 13};

// A scene of `camera` members on a kWidth x kHeight image (cropped to kCrop with `cropped`):
// spheres of several materials over a floor, a sphere light and a visible environment.
std::string sceneJson(const std::string& camera, bool cropped) {
  return R"({"camera": {"width": )" + std::to_string(kWidth) + R"(, "height": )" +
         std::to_string(kHeight) + R"(, "spp": 8, )" + camera +
         (cropped ? R"(, "crop": [11, 7, 17, 13])" : "") + R"(},
    "render": {"max_depth": 5, "light_paths": "on"},
    "environment": {"color": [0.2, 0.3, 0.4]},
    "spheres": [{"position": [0, -1001, 0], "radius": 1000, "color": 0.6},
                {"position": [-1.1, 0, 0], "radius": 1, "material": {"type": "glass", "ior": 1.5}},
                {"position": [1.1, 0, 0], "radius": 1,
                 "material": {"type": "plastic", "color": [0.8, 0.2, 0.1], "roughness": 0.3}}],
    "lights": [{"type": "sphere", "position": [0, 4, 2], "radius": 0.5, "intensity": 300}]})";
}

struct Rendered {
  SceneData scene;
  RenderResult result;
  std::vector<ImageLayer> passes;
};

Rendered render(const std::string& json) {
  Rendered r{test::loadTestScene(json), {}, {}};
  RenderOptions options;
  options.threads = 2;
  options.aovs = true;
  r.result = renderCpu(r.scene.view(), options);
  r.passes = makeAovLayers(r.scene, parseAovList("depth,normal,albedo,instance,direct,alpha"),
                           r.result.aovs);
  return r;
}

// Channel values of crop pixel (x, y) of `pixels` (of `width` pixels a row, `n` channels) and of
// the whole image's pixel under it must be bit-identical.
void expectCropOf(const std::vector<float>& whole, const std::vector<float>& crop, size_t n,
                  const char* what) {
  ASSERT_EQ(crop.size(), n * kCrop.width * kCrop.height) << what;
  size_t differing = 0;
  for (uint32_t y = 0; y < kCrop.height; ++y)
    for (uint32_t x = 0; x < kCrop.width; ++x)
      differing += std::memcmp(&crop[n * (size_t(y) * kCrop.width + x)],
                               &whole[n * (size_t(y + kCrop.y) * kWidth + x + kCrop.x)],
                               n * sizeof(float)) != 0;
  EXPECT_EQ(differing, 0u) << what;
}

TEST(CameraCrop, PixelsAreTheWholeImagesBitForBitOnEveryCamera) {
  for (const char* camera :
       {R"("fov": 50, "position": [0, 0.5, 6])",
        R"("fov": 50, "position": [0, 0.5, 6], "aperture_radius": 0.1, "focus_distance": 6)",
        R"("projection": "equirectangular", "position": [0, 0.5, 4])",
        R"("projection": "fisheye", "fov": 180, "position": [0, 0.5, 4])",
        R"("projection": "orthographic", "view_width": 5, "position": [0, 0.5, 6])"}) {
    const Rendered whole = render(sceneJson(camera, false));
    const Rendered crop = render(sceneJson(camera, true));
    ASSERT_EQ(crop.result.image.width, kCrop.width) << camera;
    ASSERT_EQ(crop.result.image.height, kCrop.height) << camera;
    expectCropOf(whole.result.image.pixels, crop.result.image.pixels, 3, camera);
    for (size_t i = 0; i < whole.passes.size(); ++i)
      expectCropOf(whole.passes[i].pixels, crop.passes[i].pixels, whole.passes[i].channels.size(),
                   (std::string(camera) + ": " + whole.passes[i].name).c_str());
    // The crop sees what the test is about: some of the scene, some of the sky.
    double albedo = 0;
    for (float v : crop.passes[2].pixels) albedo += v;
    EXPECT_GT(albedo, 0.0) << camera;
  }
}

// The light-path pilot's sparse pixels (every stride-th) of a panorama: the rays through them are
// those through the same pixels of the whole image, its angles spanning the whole image.
TEST(CameraCrop, APanoramasSparsePixelsLookWhereTheWholeImagesDo) {
  const SceneData scene =
      test::loadTestScene(sceneJson(R"("projection": "equirectangular")", false));
  ViewAdjustment adjust;
  adjust.pixelStride = 4;
  const Camera sparse = adjustedView(scene.view(), adjust).camera;
  ASSERT_EQ(sparse.width, kWidth / 4);
  for (uint32_t x = 0; x < sparse.width; ++x) {
    const float px = float(x * 4 + 2) + 0.5f, py = 10.5f;
    const Ray a = generateCameraRay(sparse, px, py, 0.5f, 0.5f);
    const Ray b = generateCameraRay(scene.camera, px, py, 0.5f, 0.5f);
    EXPECT_EQ(std::memcmp(&a.direction, &b.direction, sizeof(Vec3)), 0) << x;
  }
}

// The emitters seen are sampled again in windows of the crop's pixels: where the crop's windows
// and the whole image's both cover a pixel, they hold the same samples' mean.
TEST(CameraCrop, EmittersSeenAreSampledAgainWhereTheWholeImageSamplesThem) {
  const auto scene = [](bool cropped) {
    return sceneJson(R"("fov": 60, "position": [0, 3.2, 4], "look_at": [0, 4, 2])", cropped);
  };
  const SceneData wholeScene = test::loadTestScene(scene(false));
  const SceneData cropScene = test::loadTestScene(scene(true));
  ASSERT_GT(seenEmitterSamples(wholeScene), 0u);
  CpuRenderer renderer(CpuEngine::Bvh);
  renderer.setScene(wholeScene, SceneChange::Structure);
  const SeenEmitters whole = sampleSeenEmitters(renderer, wholeScene, RenderOptions());
  renderer.setScene(cropScene, SceneChange::Structure);
  const SeenEmitters crop = sampleSeenEmitters(renderer, cropScene, RenderOptions());
  ASSERT_EQ(crop.covered.size(), size_t(kCrop.width) * kCrop.height);
  size_t both = 0, differing = 0;
  for (uint32_t y = 0; y < kCrop.height; ++y)
    for (uint32_t x = 0; x < kCrop.width; ++x) {
      const size_t c = size_t(y) * kCrop.width + x;
      const size_t w = size_t(y + kCrop.y) * kWidth + x + kCrop.x;
      if (!crop.covered[c] || !whole.covered[w]) continue;
      ++both;
      differing += std::memcmp(&crop.emission.pixels[3 * c], &whole.emission.pixels[3 * w],
                               3 * sizeof(float)) != 0;
    }
  EXPECT_GT(both, 10u);  // the light's edge crosses the crop
  EXPECT_EQ(differing, 0u);
}

TEST(CameraCrop, CropsThatFitNoImageAreRefused) {
  const auto error = [](const char* crop) {
    return test::loadError(
        R"({"camera": {"width": 64, "height": 48, "crop": )" + std::string(crop) + "}}", ".");
  };
  EXPECT_EQ(error("[10, 10, 60, 10]"),
            "test.json: camera.crop: the crop [10, 10, 60, 10] reaches past the 64 x 48 image; "
            "expected x + width <= 64 and y + height <= 48");
  EXPECT_EQ(error("[0, 40, 64, 9]"),
            "test.json: camera.crop: the crop [0, 40, 64, 9] reaches past the 64 x 48 image; "
            "expected x + width <= 64 and y + height <= 48");
  EXPECT_EQ(error("[0, 0, 0, 10]"),
            "test.json: camera.crop[2]: expected a positive integer, got 0");
  EXPECT_EQ(error("[-1, 0, 5, 10]"),
            "test.json: camera.crop[0]: expected a non-negative integer, got -1");
  EXPECT_EQ(error("[0, 0, 5]"),
            "test.json: camera.crop: expected an array [x, y, width, height] of pixels, got "
            "an array [0,0,5]");
  EXPECT_EQ(error("[0, 0, 64, 48]"), "(no error)");
}

}  // namespace
}  // namespace candela
