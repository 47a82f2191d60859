// The CUDA backend against the CPU backend and the closed-form answers. These tests need a
// GPU: where none is present they skip and say why. Where the build has no CUDA backend at all,
// one test says so.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/constants.h"
#include "gltf_test_util.h"
#include "image/image_io.h"
#include "image_difference.h"
#include "render_test_util.h"
#include "require_gpu.h"
#include "temp_dir.h"
#include "texture_test_util.h"

#if defined(CANDELA_HAS_CUDA)
#include "backends/cpu/cpu_renderer.h"
#include "backends/cuda/cuda_renderer.h"
#include "backends/seen_emitters.h"
#include "render/aov.h"
#include "scene/animation.h"
#include "scene/flow_motion.h"
#include "scene/frame_scene.h"
#include "scene/mesh_layout.h"
#include "scene/read/scene_loader.h"
#endif

namespace candela {
namespace {

#if !defined(CANDELA_HAS_CUDA)

TEST(CudaBackend, NotBuilt) { GTEST_SKIP() << "this build has no CUDA backend (nvcc not found)"; }

#else

RenderResult renderCuda(const SceneData& data, bool aovs = false) {
  CudaRenderer renderer;
  renderer.setScene(data, SceneChange::Structure);
  RenderOptions options;
  options.sceneLabel = "test.json";
  options.aovs = aovs;
  return renderer.render(options);
}

std::string sceneWithEverything(int spp) {
  return R"({
    "camera": {"width": 48, "height": 36, "fov": 50, "position": [0, 1.5, 6], "look_at": [0, 0.5, 0],
               "spp": )" + std::to_string(spp) + R"(},
    "render": {"max_depth": 6, "seed": 3},
    "environment": {"color": [0.05, 0.07, 0.1]},
    "spheres": [
      {"position": [0, -1000, 0], "radius": 1000, "color": 0.7},
      {"position": [-1.2, 0.5, 0], "radius": 0.5, "color": [0.8, 0.3, 0.2]},
      {"position": [0, 0.5, -0.6], "radius": 0.5, "material": "mirror"},
      {"position": [1.2, 0.5, 0], "radius": 0.5, "material": "glass"}],
    "lights": [
      {"position": [2, 4, 3], "intensity": 800},
      {"type": "sphere", "position": [-3, 3, 1], "radius": 0.4, "intensity": 300}]})";
}

// Same scene and seed: the same random numbers drive the same paths, so pixels agree up to
// rounding (fused multiply-add and fast math differ between compilers); a rare path may
// diverge where rounding flips a discrete choice, so the gate is relMSE plus a per-pixel count.
TEST(CudaBackend, MatchesCpuWithinRounding) {
  REQUIRE_GPU();
  const SceneData data = test::loadTestScene(sceneWithEverything(16));
  const RenderResult cpu = renderCpu(data.view(), RenderOptions{});
  const RenderResult gpu = renderCuda(data);
  ASSERT_EQ(cpu.image.pixels.size(), gpu.image.pixels.size());
  size_t outliers = 0;
  for (size_t i = 0; i < cpu.image.pixels.size(); ++i) {
    const double a = cpu.image.pixels[i], b = gpu.image.pixels[i];
    if (std::fabs(a - b) > 1e-3 * (std::fabs(a) + 1e-2)) ++outliers;
  }
  EXPECT_LT(test::relMseAgainst(cpu.image.pixels, gpu.image.pixels), 1e-4);
  EXPECT_LT(outliers, cpu.image.pixels.size() / 50);
  EXPECT_EQ(cpu.rays.camera, gpu.rays.camera);
}

// A scene with every kind of light the CPU samples: emissive faces and spheres (found by
// bisection and by the sphere's index), an importance-sampled environment map (`map`, written by
// writeSky) and the light tree of more than eight lights.
std::string sceneWithAreaLights(const std::string& dir, const std::string& map,
                                const std::string& cameraPosition,
                                const std::string& lampRadiance) {
  std::ofstream(dir + "cuda_lamp.obj")
      << "v -0.5 2 -1\nv 1 2 -1\nv 1 2 0.5\nv -0.5 2 0.5\nf 1 2 3 4\n";
  std::string lights;
  for (int i = 0; i < 9; ++i)
    lights += std::string(i ? ", " : "") + R"({"position": [)" + std::to_string(i - 4) +
              R"(, 3, 2], "intensity": )" + std::to_string(50 + 10 * i) + "}";
  return R"({
    "camera": {"width": 48, "height": 36, "fov": 50, "position": )" +
         cameraPosition +
         R"(, "look_at": [0, 0.5, 0], "spp": 16},
    "render": {"max_depth": 6, "seed": 3},
    "environment": {"map": ")" +
         dir + map + R"(", "strength": 0.5, "rotation": [0, 30, 0]},
    "spheres": [{"position": [0, -1000, 0], "radius": 1000, "color": 0.7},
                {"position": [1.2, 0.5, 0], "radius": 0.5,
                 "material": {"type": "emissive", "radiance": [3, 2, 1]}}],
    "objects": [{"file": ")" +
         dir + R"(cuda_lamp.obj",
                 "material": {"type": "emissive", "radiance": )" +
         lampRadiance + R"(}}],
    "lights": [)" +
         lights + "]}";
}

// A 32 x 16 sky with a sun of `sun` at texel (20, 5), as `file` in `dir`.
// A sky of w x h texels (32 x 16 by default) whose sun covers a sixteenth of its height and a
// thirty-second of its width (one texel of the default).
void writeSky(const std::string& dir, const std::string& file, float sun, uint32_t w = 32,
              uint32_t h = 16) {
  ImageRGB sky(w, h);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      const bool inSun = x * 32 / w == 20 && y * 16 / h == 5;
      sky.set(x, y, inSun ? Vec3(sun) : Vec3(0.2f + 0.64f * float(x) / float(w), 0.3f, 0.5f));
    }
  writeImage(dir + file, sky, OutputDesc{});
}

// Every kind of light the CPU samples, on the device against the CPU.
TEST(CudaBackend, MatchesCpuWithAreaLightsAndAnEnvironmentMap) {
  REQUIRE_GPU();
  const std::string dir = ::testing::TempDir();
  writeSky(dir, "cuda_sky.pfm", 200.0f);
  const SceneData data =
      test::loadTestScene(sceneWithAreaLights(dir, "cuda_sky.pfm", "[0, 1.5, 6]", "4"));
  ASSERT_FALSE(data.lightTree.empty());
  const RenderResult cpu = renderCpu(data.view(), RenderOptions{});
  const RenderResult gpu = renderCuda(data);
  EXPECT_LT(test::relMseAgainst(cpu.image.pixels, gpu.image.pixels), 1e-4);
  EXPECT_EQ(cpu.rays.camera, gpu.rays.camera);
}

// An orthographic camera over a mesh of vertex colours under a plastic and a mirror: its rays and
// the colours' interpolation on the device as on the CPU.
TEST(CudaBackend, MatchesCpuThroughAnOrthographicCameraOnVertexColours) {
  REQUIRE_GPU();
  const std::string dir = ::testing::TempDir();
  std::ofstream(dir + "cuda_coloured.obj")
      << "v -2 0 -2 1 0.2 0.1\nv 2 0 -2 0.1 0.9 0.3\nv 2 0 2 0.3 0.4 1\nv -2 0 2 0.8 0.8 0\n"
         "f 1 3 2\nf 1 4 3\n";
  const SceneData data = test::loadTestScene(R"({
    "camera": {"width": 48, "height": 36, "projection": "orthographic", "view_width": 4,
               "position": [3, 3, 3], "look_at": [0, 0.3, 0], "spp": 16},
    "render": {"max_depth": 6, "seed": 3},
    "environment": {"color": [0.3, 0.35, 0.4]},
    "objects": [{"file": ")" + dir + R"(cuda_coloured.obj"},
                {"file": ")" + dir + R"(cuda_coloured.obj", "position": [0, 0.01, 0],
                 "scale": 0.3, "material": {"type": "plastic", "color": 1, "roughness": 0.2}}],
    "spheres": [{"position": [-0.8, 0.5, 0.3], "radius": 0.5, "material": "mirror"}],
    "lights": [{"type": "directional", "direction": [-0.3, -1, -0.4], "intensity": 2}]})");
  ASSERT_FALSE(data.vertexColors.empty());
  const RenderResult cpu = renderCpu(data.view(), RenderOptions{});
  const RenderResult gpu = renderCuda(data);
  EXPECT_LT(test::relMseAgainst(cpu.image.pixels, gpu.image.pixels), 1e-4);
  EXPECT_EQ(cpu.rays.camera, gpu.rays.camera);
}

// Frame 0 of sceneWithEverything(16) with `more` (its spheres' ids, objects and an animation
// block) after its last member, rendered on both backends: the same image up to rounding.
void expectFrameZeroMatchesCpu(const std::function<void(std::string&)>& more,
                               const std::function<void(const SceneData&)>& check) {
  std::string json = sceneWithEverything(16);
  json.erase(json.rfind('}'));
  more(json);
  const SceneData data =
      flattenScene(sceneAtFrame(parseSceneText(json + "}", "test.json", "."), 0));
  check(data);
  if (::testing::Test::HasFatalFailure()) return;
  const RenderResult cpu = renderCpu(data.view(), RenderOptions{});
  const RenderResult gpu = renderCuda(data);
  EXPECT_LT(test::relMseAgainst(cpu.image.pixels, gpu.image.pixels), 1e-4);
  EXPECT_EQ(cpu.rays.camera, gpu.rays.camera);
}

// A motion-blurred frame (render/camera_motion.h): a look-at camera sliding past the spheres under
// an open shutter draws each sample's time and pose on the device as on the CPU.
TEST(CudaBackend, MatchesCpuUnderMotionBlur) {
  REQUIRE_GPU();
  expectFrameZeroMatchesCpu(
      [](std::string& json) {
        json += R"(, "animation": {"frames": 2, "shutter": [0, 1], "tracks": [
      {"target": "camera", "property": "position", "keys": [[0, [-1, 1.5, 6]], [1, [1, 1.2, 5.5]]]}]})";
      },
      [](const SceneData& data) { ASSERT_EQ(data.cameraPoses.size(), kShutterSegments + 1); });
}

// Spheres, objects and a point light that move while the shutter is open (geometry/motion.h,
// render/light_motion.h), one of the objects emitting: the device traces the motion BVHs, poses
// the surfaces at each ray's time and samples the moving emitter and light where they then stand,
// as the CPU does.
TEST(CudaBackend, MatchesCpuWithMovingShapes) {
  REQUIRE_GPU();
  expectFrameZeroMatchesCpu(
      [](std::string& json) {
        json.replace(json.find(R"({"position": [-1.2, 0.5, 0])"), 1, R"({"id": "ball", )");
        json.replace(json.find(R"({"position": [2, 4, 3])"), 1, R"({"id": "lamp", )");
        json +=
            R"(, "objects": [{"id": "box", "shape": "cube", "position": [0, 1.6, 0], "scale": 0.4},
                {"id": "glow", "shape": "cube", "position": [1.2, 1.4, 0.6], "scale": 0.2,
                 "material": {"type": "emissive", "radiance": [4, 3, 2]}}],
    "animation": {"frames": 2, "shutter": [0, 1], "tracks": [
      {"target": "ball", "property": "position", "keys": [[0, [-1.2, 0.5, 0]], [1, [-0.4, 0.9, 0]]]},
      {"target": "box", "property": "rotation", "keys": [[0, [0, 0, 0]], [1, [30, 90, 0]]]},
      {"target": "glow", "property": "position", "keys": [[0, [1.2, 1.4, 0.6]], [1, [0.4, 1.1, 0.9]]]},
      {"target": "lamp", "property": "position", "keys": [[0, [2, 4, 3]], [1, [-1, 4, 2]]]}]})";
      },
      [](const SceneData& data) {
        ASSERT_FALSE(data.motionNodes.empty());
        ASSERT_FALSE(data.lightPoses.empty());
        ASSERT_TRUE(data.cameraPoses.empty());
      });
}

// Clear coats (render/bsdf_coat.h), smooth and rough, over diffuse, a rough metal, a mirror and
// a plastic, and sheen (render/bsdf_sheen.h) under a coat and alone, lit by a lamp, a sphere
// light and the sky: on the device as on the CPU.
TEST(CudaBackend, MatchesCpuOnCoatedAndSheenedMaterials) {
  REQUIRE_GPU();
  const SceneData data = test::loadTestScene(R"({
    "camera": {"width": 48, "height": 36, "fov": 50, "position": [0, 1.5, 6], "look_at": [0, 0.5, 0],
               "spp": 16},
    "render": {"max_depth": 6, "seed": 3},
    "environment": {"color": [0.2, 0.25, 0.3]},
    "spheres": [
      {"position": [0, -1000, 0], "radius": 1000,
       "material": {"type": "diffuse", "color": 0.6, "coat": 0.5, "coat_roughness": 0.3}},
      {"position": [-1.2, 0.5, 0], "radius": 0.5,
       "material": {"type": "conductor", "metal": "Cu", "roughness": 0.4, "coat": 1}},
      {"position": [0, 0.5, -0.6], "radius": 0.5,
       "material": {"type": "mirror", "coat": 0.8, "coat_roughness": 0.2, "coat_ior": 1.6}},
      {"position": [1.2, 0.5, 0], "radius": 0.5,
       "material": {"type": "plastic", "color": [0.2, 0.3, 0.8], "roughness": 0.3, "coat": 1,
                    "sheen": [0.9, 0.7, 0.5], "sheen_roughness": 0.3}},
      {"position": [0.6, 0.3, 1.2], "radius": 0.3,
       "material": {"type": "diffuse", "color": 0.05, "sheen": 0.8, "sheen_roughness": 0.1}}],
    "lights": [
      {"position": [2, 4, 3], "intensity": 800},
      {"type": "sphere", "position": [-3, 3, 1], "radius": 0.4, "intensity": 300}]})");
  const RenderResult cpu = renderCpu(data.view(), RenderOptions{});
  const RenderResult gpu = renderCuda(data);
  EXPECT_LT(test::relMseAgainst(cpu.image.pixels, gpu.image.pixels), 1e-4);
  EXPECT_EQ(cpu.rays.camera, gpu.rays.camera);
}

// Translucent diffuse surfaces (render/bsdf_diffuse.h): a lantern around a point light, a ball of
// textured transmittance lit from behind by a sun and a sphere light: on the device as on the
// CPU.
TEST(CudaBackend, MatchesCpuOnTranslucentSurfaces) {
  REQUIRE_GPU();
  const std::string dir = ::testing::TempDir();
  ASSERT_TRUE(
      test::writeTestPng(dir + "cuda_translucent.png", 2, 1, 3, {60, 230, 40, 200, 120, 30}));
  const SceneData data = test::loadTestScene(R"({
    "camera": {"width": 48, "height": 36, "fov": 50, "position": [0, 1.5, 6], "look_at": [0, 0.8, 0],
               "spp": 16},
    "render": {"max_depth": 6, "seed": 5},
    "environment": {"color": [0.05, 0.06, 0.08]},
    "spheres": [
      {"position": [0, -1000, 0], "radius": 1000, "material": {"type": "diffuse", "color": 0.5}},
      {"position": [-1, 1, 0], "radius": 0.6,
       "material": {"type": "diffuse", "color": [0.5, 0.4, 0.3], "transmittance": [0.4, 0.35, 0.2]}},
      {"position": [1.2, 0.8, -0.5], "radius": 0.5,
       "material": {"type": "diffuse", "color": 0.1, "transmittance": {"texture": ")" +
                                             dir + R"(cuda_translucent.png"}}}],
    "lights": [
      {"position": [-1, 1, 0], "intensity": 40},
      {"type": "directional", "direction": [0.2, -0.4, 1], "intensity": 2},
      {"type": "sphere", "position": [2, 2, -3], "radius": 0.4, "intensity": 300}]})");
  const RenderResult cpu = renderCpu(data.view(), RenderOptions{});
  const RenderResult gpu = renderCuda(data);
  EXPECT_LT(test::relMseAgainst(cpu.image.pixels, gpu.image.pixels), 1e-4);
  EXPECT_EQ(cpu.rays.camera, gpu.rays.camera);
}

// Textures clamped, mirrored and read from the nearest texel (core/texture.h's wrap and filter),
// a mirrored normal map and a clamped emission among them, clear coats smooth over a normal map
// and on a normal map of their own, and a coat and a sheen of textured roughness (their tables by
// level): on the device as on the CPU.
TEST(CudaBackend, MatchesCpuOnWrappedAndNearestTextures) {
  REQUIRE_GPU();
  const std::string dir = ::testing::TempDir();
  ASSERT_TRUE(test::writeTestPng(dir + "cuda_wrap.png", 2, 2, 3,
                                 {230, 40, 20, 20, 200, 40, 30, 60, 220, 240, 240, 240}));
  ASSERT_TRUE(
      test::writeTestPng(dir + "cuda_wrap_normals.png", 2, 1, 3, {200, 90, 230, 110, 160, 220}));
  const std::string t = R"("texture": ")" + dir;
  const SceneData data = test::loadTestScene(R"({
    "camera": {"width": 48, "height": 36, "fov": 50, "position": [0, 1.5, 6], "look_at": [0, 0.5, 0],
               "spp": 16},
    "render": {"max_depth": 6, "seed": 3},
    "environment": {"color": [0.2, 0.25, 0.3]},
    "spheres": [
      {"position": [0, -1000, 0], "radius": 1000,
       "material": {"type": "diffuse", "color": {)" +
                                             t + R"(cuda_wrap.png", "scale": [3000, 1500],
         "wrap": "mirror", "filter": "nearest"}, "normal_map": {)" +
                                             t + R"(cuda_wrap_normals.png",
         "scale": [900, 900], "wrap": "mirror"}, "coat": 0.6}},
      {"position": [-1.2, 0.5, 0], "radius": 0.5,
       "material": {"type": "plastic", "roughness": 0.3, "color": {)" +
                                             t + R"(cuda_wrap.png",
         "scale": [3, 2], "offset": [-1, -0.5], "wrap": ["clamp", "mirror"]}, "coat": 1,
         "coat_roughness": {)" + t + R"(cuda_wrap.png", "scale": [4, 4], "channel": "g"},
         "sheen": [0.5, 0.4, 0.3], "sheen_roughness": {)" +
                                             t + R"(cuda_wrap.png", "channel": "r"},
         "coat_normal_map": {)" + t + R"(cuda_wrap_normals.png", "scale": [6, 3]}}},
      {"position": [1.2, 0.5, 0], "radius": 0.5,
       "material": {"type": "emissive", "radiance": {)" +
                                             t + R"(cuda_wrap.png", "scale": [2, 2],
         "offset": [-0.5, -0.5], "wrap": "clamp", "filter": "nearest"}}}],
    "lights": [{"position": [2, 4, 3], "intensity": 800}]})");
  const RenderResult cpu = renderCpu(data.view(), RenderOptions{});
  const RenderResult gpu = renderCuda(data);
  EXPECT_LT(test::relMseAgainst(cpu.image.pixels, gpu.image.pixels), 1e-4);
  EXPECT_EQ(cpu.rays.camera, gpu.rays.camera);
}

// A map of over a million texels is sampled on a grid shifted by half a texel
// (render/environment.h): the device samples it as the CPU does.
TEST(CudaBackend, MatchesCpuUnderAMapOfUnsplitTexels) {
  REQUIRE_GPU();
  const std::string dir = ::testing::TempDir();
  writeSky(dir, "cuda_sky_large.pfm", 200.0f, 1600, 800);
  const SceneData data =
      test::loadTestScene(sceneWithAreaLights(dir, "cuda_sky_large.pfm", "[0, 1.5, 6]", "4"));
  ASSERT_TRUE(data.environment.grid.shifted);
  const RenderResult cpu = renderCpu(data.view(), RenderOptions{});
  const RenderResult gpu = renderCuda(data);
  EXPECT_LT(test::relMseAgainst(cpu.image.pixels, gpu.image.pixels), 1e-4);
}

TEST(CudaBackend, FurnaceInsideDiffuseSphereIsOne) {
  REQUIRE_GPU();
  const double power = 4 * kPi * kPi * 100;
  const SceneData data = test::loadTestScene(R"({
    "camera": {"width": 32, "height": 32, "fov": 90, "position": [0, 0, 3], "spp": 64},
    "render": {"max_depth": 200},
    "spheres": [{"position": [0, 0, 0], "radius": 10, "color": 0.5}],
    "lights": [{"position": [0, 0, 0], "intensity": )" + std::to_string(power) + "}]}");
  const RenderResult r = renderCuda(data);
  for (int c = 0; c < 3; ++c) {
    const auto s = test::regionStats(r.image, 0, 0, 32, 32, c);
    EXPECT_NEAR(s.mean, 1.0, 5 * s.standardError() + 1e-4);
  }
}

TEST(CudaBackend, UniformEnvironmentGlassConservesEnergy) {
  REQUIRE_GPU();
  const SceneData data = test::loadTestScene(R"({
    "camera": {"width": 32, "height": 32, "fov": 60, "position": [0, 0, 3], "spp": 16},
    "render": {"max_depth": 64},
    "environment": {"color": 1},
    "spheres": [{"position": [0, 0, 0], "radius": 1, "material": "glass", "ior": 1.5}]})");
  const RenderResult r = renderCuda(data);
  const auto s = test::regionStats(r.image, 12, 12, 20, 20, 0);
  EXPECT_NEAR(s.mean, 1.0, 5 * s.standardError() + 1e-4);
}

TEST(CudaBackend, SphereLightSeenDirectlyHasItsRadiance) {
  REQUIRE_GPU();
  const SceneData data = test::loadTestScene(R"({
    "camera": {"width": 16, "height": 16, "fov": 40, "position": [0, 0, 5], "spp": 2},
    "lights": [{"type": "sphere", "position": [0, 0, 0], "radius": 0.5, "intensity": 300}]})");
  const RenderResult r = renderCuda(data);
  const double radiance = 300 / (4 * kPi * kPi * 0.25);
  EXPECT_NEAR(r.image.at(8, 8).x, radiance, 1e-4 * radiance);
}

// A scene kept on the GPU across `frames` follows each kind of change FrameScene reports (and
// the keyed groups' own changes), moving only what may differ, and renders exactly what a fresh
// upload of the same frame renders.
void expectResidentSceneFollows(const std::vector<std::pair<std::string, SceneChange> >& frames) {
  FrameScene frameScene;
  CudaRenderer resident;
  for (size_t f = 0; f < frames.size(); ++f) {
    const SceneData& data = frameScene.prepare(parseSceneText(frames[f].first, "test.json", "."));
    EXPECT_EQ(frameScene.change(), frames[f].second) << "frame " << f;
    resident.setScene(data, frameScene.change());
    const RenderResult kept = resident.render(RenderOptions{});
    const RenderResult fresh = renderCuda(data);
    for (uint32_t y = 0; y < fresh.image.height; ++y)
      for (uint32_t x = 0; x < fresh.image.width; ++x)
        for (int c = 0; c < 3; ++c)
          ASSERT_EQ(kept.image.at(x, y)[c], fresh.image.at(x, y)[c]) << "frame " << f;
  }
}

TEST(CudaBackend, ResidentSceneFollowsEveryKindOfFrameChange) {
  REQUIRE_GPU();
  const std::string base = sceneWithEverything(4);
  std::string cameraMoved = base, sphereMoved = base, sphereAdded = base;
  cameraMoved.replace(cameraMoved.find("[0, 1.5, 6]"), 11, "[0.3, 1.4, 6]");
  sphereMoved.replace(sphereMoved.find("[-1.2, 0.5, 0]"), 14, "[-1.0, 0.7, 0.2]");
  sphereAdded.replace(sphereAdded.find(R"("spheres": [)"), 12,
                      R"("spheres": [{"position": [0, 2, 0], "radius": 0.3, "color": 0.5},)");
  expectResidentSceneFollows({{base, SceneChange::Structure},
                              {cameraMoved, SceneChange::Values},
                              {sphereMoved, SceneChange::Motion},
                              {sphereAdded, SceneChange::Structure},
                              {base, SceneChange::Structure}});
}

// The environment map's arrays and the light tree, kept on the device while their keys are equal
// and replaced when not: every frame renders as a fresh upload of it does.
TEST(CudaBackend, ResidentSceneKeepsTheMapAndTheLightTreeOnlyWhileTheyAreTheSame) {
  REQUIRE_GPU();
  const std::string dir = ::testing::TempDir();
  writeSky(dir, "cuda_sky_a.pfm", 200.0f);
  writeSky(dir, "cuda_sky_b.pfm", 200.0f);  // the same texels in another file
  writeSky(dir, "cuda_sky_c.pfm", 50.0f);
  const auto frame = [&](const char* map, const char* camera, const char* lamp) {
    return sceneWithAreaLights(dir, map, camera, lamp);
  };
  expectResidentSceneFollows({
      {frame("cuda_sky_a.pfm", "[0, 1.5, 6]", "4"), SceneChange::Structure},
      {frame("cuda_sky_b.pfm", "[0.3, 1.4, 6]", "4"), SceneChange::Values},  // equal keys
      {frame("cuda_sky_c.pfm", "[0.3, 1.4, 6]", "4"), SceneChange::Values},  // a new map
      {frame("cuda_sky_c.pfm", "[0.3, 1.4, 6]", "9"), SceneChange::Values},  // a new tree
      {frame("cuda_sky_a.pfm", "[0, 1.5, 6]", "4"), SceneChange::Values},
  });
}

// The texture pool, kept on the device while the textures are the same, across rebuilds too, and
// replaced when they differ.
TEST(CudaBackend, ResidentSceneKeepsTheTexturePoolWhileTheTexturesAreTheSame) {
  REQUIRE_GPU();
  const std::string dir = ::testing::TempDir();
  ASSERT_TRUE(test::writeTestPng(dir + "cuda_checks.png", 2, 2, 3,
                                 {230, 40, 20, 20, 200, 40, 30, 60, 220, 240, 240, 240}));
  ASSERT_TRUE(test::writeTestPng(dir + "cuda_checks_b.png", 2, 2, 3,
                                 {20, 40, 230, 200, 200, 40, 230, 60, 30, 40, 40, 40}));
  const auto frame = [&](const char* texture, const char* extraSphere) {
    return R"({
    "camera": {"width": 48, "height": 36, "fov": 50, "position": [0, 1.5, 6],
               "look_at": [0, 0.5, 0], "spp": 4},
    "render": {"max_depth": 4, "seed": 5},
    "environment": {"color": [0.4, 0.45, 0.5]},
    "spheres": [)" +
           std::string(extraSphere) +
           R"({"position": [0, -1000, 0], "radius": 1000, "color": 0.7},
      {"position": [0, 0.8, 0], "radius": 0.8,
       "color": {"texture": ")" +
           dir + texture + R"(", "scale": [4, 2]}}],
    "lights": [{"position": [2, 4, 3], "intensity": 400}]})";
  };
  const char* added = R"({"position": [1.6, 0.4, 0.5], "radius": 0.4, "color": 0.5}, )";
  expectResidentSceneFollows({
      {frame("cuda_checks.png", ""), SceneChange::Structure},
      {frame("cuda_checks.png", added), SceneChange::Structure},    // the pool stays
      {frame("cuda_checks_b.png", added), SceneChange::Structure},  // a new pool
      {frame("cuda_checks.png", ""), SceneChange::Structure},
  });
}

// The passes' sums (render/aov.h) on the device against the CPU's, on the scene with everything
// and an animation that gives the flow pass camera and object motion: the same samples find the
// same first hits, so the sums agree up to rounding, and the id passes' nearest samples agree
// exactly but where rounding flips a rare hit.
TEST(CudaBackend, PassesMatchCpuWithinRounding) {
  REQUIRE_GPU();
  std::string json = sceneWithEverything(4);
  json.replace(json.find(R"({"position": [-1.2)"), 1, R"({"id": "ball", )");
  json.insert(json.rfind('}'), R"(, "animation": {"frames": 2, "tracks": [
      {"target": "camera", "property": "position", "keys": [[0, [0, 1.5, 6]], [1, [0.2, 1.4, 6]]]},
      {"target": "ball", "property": "position", "keys": [[0, [-1.2, 0.5, 0]], [1, [-1, 0.7, 0.1]]]}]})");
  const SceneDesc desc = parseSceneText(json, "test.json", ".");
  SceneDesc now = sceneAtFrame(desc, 0);
  layOutForPasses(now, {Aov::Uv, Aov::ObjectCoordinates});
  SceneData data = flattenScene(now);
  applyFlowMotion(data, flowMotion(now, sceneAtFrame(desc, 1)));
  // The backward pass's arithmetic, with frame 1 standing in for a frame before.
  applyFlowMotion(data, flowMotion(now, sceneAtFrame(desc, 1)), FlowDirection::Backward);
  RenderOptions options;
  options.aovs = true;
  const RenderResult cpu = renderCpu(data.view(), options);
  const RenderResult gpu = renderCuda(data, true);
  ASSERT_EQ(cpu.aovs.size(), size_t(48 * 36));
  ASSERT_EQ(gpu.aovs.size(), cpu.aovs.size());
  const auto close = [](float a, float b) {
    return std::fabs(a - b) <= 1e-3f * (std::fabs(a) + 1);
  };
  const auto close3 = [&](const Vec3& a, const Vec3& b) {
    return close(a.x, b.x) && close(a.y, b.y) && close(a.z, b.z);
  };
  // Which fields differ, by name, for the failure message.
  std::map<std::string, size_t> fieldsDiffering;
  size_t differing = 0, flowing = 0;
  for (size_t i = 0; i < cpu.aovs.size(); ++i) {
    const AovPixel &c = cpu.aovs[i], &g = gpu.aovs[i];
    ASSERT_EQ(c.samples, 4u);
    ASSERT_EQ(g.samples, 4u);
    flowing += c.flowSamples > 0 && (c.flowSum.x != 0 || c.flowSum.y != 0);
    // The squared distance of the nearest sample to the pixel centre is rounded differently
    // where the device fuses its multiply-add; the sample it picks is the same.
    const std::pair<const char*, bool> fields[] = {
        {"hits", c.hits == g.hits},
        {"covered", c.covered == g.covered},
        {"flowSamples", c.flowSamples == g.flowSamples},
        {"nearestMaterial", c.nearestMaterial == g.nearestMaterial},
        {"nearestDistance2", close(c.nearestDistance2, g.nearestDistance2)},
        {"positionSum", close3(c.positionSum, g.positionSum)},
        {"normalSum", close3(c.normalSum, g.normalSum)},
        {"albedoSum", close3(c.albedoSum, g.albedoSum)},
        {"directSum", close3(c.directSum, g.directSum)},
        {"emissionSum", close3(c.emissionSum, g.emissionSum)},
        {"distanceSum", close(c.distanceSum, g.distanceSum)},
        {"uvSum", close(c.uvSum.x, g.uvSum.x) && close(c.uvSum.y, g.uvSum.y)},
        {"objectCoordinatesSum", close3(c.objectCoordinatesSum, g.objectCoordinatesSum)},
        {"flowSum", close(c.flowSum.x, g.flowSum.x) && close(c.flowSum.y, g.flowSum.y)},
        {"backwardFlowSamples", c.backwardFlowSamples == g.backwardFlowSamples},
        {"backwardFlowSum", close(c.backwardFlowSum.x, g.backwardFlowSum.x) &&
                                close(c.backwardFlowSum.y, g.backwardFlowSum.y)}};
    bool same = true;
    for (const auto& [name, equal] : fields) {
      if (!equal) ++fieldsDiffering[name];
      same = same && equal;
    }
    differing += !same;
  }
  std::string differingText;
  for (const auto& [name, count] : fieldsDiffering)
    differingText += " " + name + ": " + std::to_string(count);
  EXPECT_GT(flowing, cpu.aovs.size() / 2);  // the flow pass has motion to agree on
  EXPECT_LT(differing, cpu.aovs.size() / 100) << "pixels differing in" << differingText;
}

// The flow pass on a mesh that its glTF animation stretches (each point between its triangle's
// next vertices, SceneView::flowVertices) and the stretching mesh blurred by an open shutter: the
// device's passes and image against the CPU's.
TEST(CudaBackend, MeshesThatMoveApartMatchCpu) {
  REQUIRE_GPU();
  test::TempDir dir;
  dir.write("stretch.gltf", test::stretchingSquare().gltf());
  const auto scene = [&](const char* shutter) {
    return parseSceneText(R"({"camera": {"width": 32, "height": 24, "fov": 60, "spp": 4,
      "position": [0, 0, 4]}, "lights": [{"position": [0, 1, 4], "intensity": 10}],
      "environment": {"color": [0.2, 0.2, 0.2]},
      "objects": [{"file": "stretch.gltf", "gltf_animation": 0}],
      "animation": {"frames": 8, "fps": 8)" +
                              std::string(shutter) + "}}",
                          "test.json", dir.path());
  };
  const SceneDesc still = scene("");
  const SceneDesc now = sceneAtFrame(still, 3);
  SceneData data = flattenScene(now);
  applyFlowMotion(data, flowMotion(now, sceneAtFrame(still, 4)));
  RenderOptions options;
  options.aovs = true;
  const RenderResult cpu = renderCpu(data.view(), options);
  const RenderResult gpu = renderCuda(data, true);
  ASSERT_EQ(gpu.aovs.size(), cpu.aovs.size());
  size_t flowing = 0, differing = 0;
  for (size_t i = 0; i < cpu.aovs.size(); ++i) {
    const AovPixel &c = cpu.aovs[i], &g = gpu.aovs[i];
    flowing += c.flowSum.x != 0;
    differing += c.flowSamples != g.flowSamples ||
                 std::fabs(c.flowSum.x - g.flowSum.x) > 1e-3f * (std::fabs(c.flowSum.x) + 1) ||
                 std::fabs(c.flowSum.y - g.flowSum.y) > 1e-3f * (std::fabs(c.flowSum.y) + 1);
  }
  EXPECT_GT(flowing, cpu.aovs.size() / 4);  // the square stretches under much of the image
  EXPECT_LT(differing, cpu.aovs.size() / 100);
  const SceneData blurred = flattenScene(sceneAtFrame(scene(R"(, "shutter": [0, 1])"), 3));
  ASSERT_FALSE(blurred.motionPositions.empty());
  const RenderResult cpuBlur = renderCpu(blurred.view(), RenderOptions());
  const RenderResult gpuBlur = renderCuda(blurred);
  EXPECT_LT(test::relMseAgainst(cpuBlur.image.pixels, gpuBlur.image.pixels), 1e-4);
}

// A window of the image on the device (the emitters seen, sampled again: backends/
// seen_emitters.h) renders the pixels of the device's whole image, to the bit; and what the
// device samples again of the emitters seen agrees with what the CPU does.
TEST(CudaBackend, WindowsAndSeenEmittersMatch) {
  REQUIRE_GPU();
  std::string json = sceneWithEverything(4);  // and an emissive ball in view
  json.insert(json.find(R"("spheres": [)") + 12,
              R"({"position": [-0.4, 1.6, 0], "radius": 0.3,
                  "material": {"type": "emissive", "radiance": 20}}, )");
  const SceneData data = test::loadTestScene(json);
  CudaRenderer renderer;
  renderer.setScene(data, SceneChange::Structure);
  RenderOptions whole, window;
  window.sceneLabel = whole.sceneLabel = "test.json";
  window.adjust.window = {9, 5, 17, 11};
  const RenderResult a = renderer.render(whole), b = renderer.render(window);
  ASSERT_EQ(b.image.width, 17u);
  ASSERT_EQ(b.image.height, 11u);
  for (uint32_t y = 0; y < 11; ++y)
    for (uint32_t x = 0; x < 17; ++x)
      for (int c = 0; c < 3; ++c)
        ASSERT_EQ(b.image.at(x, y)[c], a.image.at(9 + x, 5 + y)[c]) << x << ", " << y;

  const SeenEmitters gpu = sampleSeenEmitters(renderer, data, whole);
  CpuRenderer cpuRenderer(CpuEngine::Bvh);
  cpuRenderer.setScene(data, SceneChange::Structure);
  const SeenEmitters cpu = sampleSeenEmitters(cpuRenderer, data, whole);
  ASSERT_FALSE(cpu.covered.empty());
  size_t differing = 0, covered = 0;
  for (size_t i = 0; i < cpu.covered.size(); ++i) {
    covered += cpu.covered[i];
    differing += gpu.covered[i] != cpu.covered[i] ||
                 std::fabs(gpu.emission.pixels[3 * i] - cpu.emission.pixels[3 * i]) >
                     1e-3f * (std::fabs(cpu.emission.pixels[3 * i]) + 1);
  }
  EXPECT_GT(covered, 0u);
  EXPECT_LT(differing, cpu.covered.size() / 100);
}

#endif

}  // namespace
}  // namespace candela
