// Motion blur of moving objects and spheres: their poses across a frame's exposure, the motion BVH
// on each CPU engine, the surface at a ray's time, and images against the share of the exposure
// for which each pixel's ray is blocked or against the mean of the stills across it (moving
// emitters among them).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/constants.h"
#include "core/rotation.h"
#include "cpu_engines.h"
#include "geometry/bvh_traverse.h"
#include "geometry/surface.h"
#include "render/light_emission.h"
#include "render/light_path.h"
#include "render/light_sample.h"
#include "render/light_selection.h"
#include "scene/animation.h"
#include "scene/flatten.h"
#include "scene/read/scene_loader.h"

namespace candela {
namespace {

namespace fs = std::filesystem;

// Writes quad.obj, the unit square [0, 1] x [0, 1] in the plane z = 0 facing +z, and half.obj,
// the half x >= 0 of a square 200 across there; returns `dir`.
std::string writeQuads(const fs::path& dir) {
  fs::create_directories(dir);
  std::ofstream(dir / "quad.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
  std::ofstream(dir / "half.obj") << "v 0 -100 0\nv 100 -100 0\nv 100 100 0\nv 0 100 0\n"
                                     "f 1 2 3 4\n";
  return dir.string();
}

// An orthographic camera `size` pixels square spanning [-4, 4] x [-4, 4] of the plane z = 0 from
// +z, each sample through its pixel's centre, under a white sky, over `scene` (spheres and objects,
// black), in an animation of two frames whose tracks are `tracks`, the shutter open over frame 0.
std::string blockedSky(uint32_t size, const std::string& scene, const std::string& tracks,
                       const std::string& shutter = R"("shutter": [0, 1], )") {
  return R"({"camera": {"width": )" + std::to_string(size) + R"(, "height": )" +
         std::to_string(size) + R"(, "projection": "orthographic", "view_width": 8,
      "position": [0, 0, 10], "look_at": [0, 0, 0], "spp": 64},
    "render": {"antialiasing": false, "max_depth": 1},
    "environment": {"color": 1},
    "materials": {"black": {"type": "diffuse", "color": 0}},
    )" + scene +
         R"(,
    "animation": {"frames": 2, )" +
         shutter + R"("tracks": [)" + tracks + "]}}";
}

// Frame 0 of `json` (files from `dir`), flattened for `engine` and rendered by it.
ImageRGB renderFrame(const std::string& json, const std::string& dir, CpuEngine engine) {
  SceneDesc desc = sceneAtFrame(parseSceneText(json, "s.json", dir), 0);
  if (engine == CpuEngine::Embree) desc.ownBvh = OwnBvh::None;
  const SceneData data = flattenScene(desc);
  CpuRenderer renderer(engine);
  renderer.setScene(data, SceneChange::Structure);
  return renderer.render(RenderOptions{}).image;
}

// The centre of pixel (x, y) of blockedSky's camera, in the plane z = 0.
double centreX(uint32_t x, uint32_t size) { return (x + 0.5) * 8.0 / size - 4.0; }
double centreY(uint32_t y, uint32_t size) { return 4.0 - (y + 0.5) * 8.0 / size; }

class ObjectMotionBlur : public ::testing::TestWithParam<CpuEngine> {};

// A black quad, [0, 100] x [0, 100] from its position, slides along x from -3 to 3 while the
// shutter is open, over the upper half of the image; two still quads cover the lower rows left
// of x = 0 and right of x = 2 (before and after it among the objects, so that Embree holds them
// in runs around it). Each upper pixel's sky is blocked for the share (x + 3) / 6 of the exposure,
// within 1/64 as the 64 samples' times are stratified; the lower rows are sharp.
TEST_P(ObjectMotionBlur, SlidingQuadBlocksEachPixelForItsShareOfTheExposure) {
  const fs::path dir = fs::temp_directory_path() / "candela_object_motion_blur";
  const std::string json = blockedSky(32, R"("objects": [
      {"file": "quad.obj", "position": [-100, -100, 0], "scale": [100, 99, 1], "material": "black"},
      {"id": "slider", "file": "quad.obj", "position": [-3, 0, 0], "scale": [100, 100, 1],
       "material": "black"},
      {"file": "quad.obj", "position": [2, -100, 0], "scale": [100, 99, 1], "material": "black"}])",
                                      R"({"target": "slider", "property": "position",
          "keys": [[0, [-3, 0, 0]], [1, [3, 0, 0]]]})");
  const ImageRGB image = renderFrame(json, writeQuads(dir), GetParam());
  fs::remove_all(dir);
  int ramp = 0;
  for (uint32_t y = 0; y < 32; ++y)
    for (uint32_t x = 0; x < 32; ++x) {
      const double cx = centreX(x, 32), cy = centreY(y, 32);
      double seen;
      if (cy > 0) {
        seen = 1 - std::clamp((cx + 3) / 6, 0.0, 1.0);
        ramp += seen > 0 && seen < 1;
      } else {
        seen = cy < -1 && (cx < 0 || cx > 2) ? 0 : 1;
      }
      EXPECT_NEAR(image.pixels[3 * (y * 32 + x)], seen, 1.0 / 64 + 1e-5) << x << "," << y;
    }
  EXPECT_EQ(ramp, 16 * 24);  // the edge sweeps 24 of the 32 columns
}

// Under a rolling shutter whose rows are instants, a still camera sees the sliding quad sharp in
// each row, where it stood when that row was read: row y at (y + 0.5) / 16 of the exposure.
TEST_P(ObjectMotionBlur, RollingShutterReadsEachRowWhereTheQuadThenStood) {
  const fs::path dir = fs::temp_directory_path() / "candela_object_motion_blur_rolling";
  const std::string json = blockedSky(
      16, R"("objects": [{"id": "slider", "file": "half.obj", "material": "black"}])",
      R"({"target": "slider", "property": "position", "keys": [[0, [-3, 0, 0]], [1, [3, 0, 0]]]})",
      R"("shutter": [0, 1], "rolling_shutter": {}, )");
  const ImageRGB image = renderFrame(json, writeQuads(dir), GetParam());
  fs::remove_all(dir);
  for (uint32_t y = 0; y < 16; ++y) {
    const double edge = -3 + 6 * (y + 0.5) / 16;
    for (uint32_t x = 0; x < 16; ++x)
      EXPECT_EQ(image.pixels[3 * (y * 16 + x)], centreX(x, 16) >= edge ? 0.0f : 1.0f)
          << x << "," << y;
  }
}

// A black half-plane x >= 0 turns a quarter about the view's axis while the shutter is open: the
// pixel at angle phi is blocked while the half-plane's axis, at alpha, lies within 90 degrees of
// it. The exposure's poses keep the share within 1/64; the first and last poses alone, their
// vertices interpolated, would turn the edge unevenly, up to 4 degrees off (4% of the share).
TEST_P(ObjectMotionBlur, TurningHalfPlaneBlocksByTheAngleItSweeps) {
  const fs::path dir = fs::temp_directory_path() / "candela_object_motion_blur_turn";
  const std::string json =
      blockedSky(24, R"("objects": [{"id": "half", "file": "half.obj", "material": "black"}])",
                 R"({"target": "half", "property": "rotation",
                     "keys": [[0, [0, 0, 0]], [1, [0, 0, 90]]]})");
  const ImageRGB image = renderFrame(json, writeQuads(dir), GetParam());
  fs::remove_all(dir);
  for (uint32_t y = 0; y < 24; ++y)
    for (uint32_t x = 0; x < 24; ++x) {
      const double phi = std::atan2(centreY(y, 24), centreX(x, 24));
      int blocked = 0;
      constexpr int kSteps = 9000;
      for (int i = 0; i < kSteps; ++i) {
        const double alpha = (i + 0.5) / kSteps * kPi / 2;
        blocked += std::cos(phi - alpha) >= 0;
      }
      EXPECT_NEAR(image.pixels[3 * (y * 24 + x)], 1 - double(blocked) / kSteps, 1.0 / 64 + 1e-3)
          << x << "," << y;
    }
}

// A black sphere of radius 1 moves along x from -2 to 2 while the shutter is open: the pixel at
// (x, y) is blocked while the centre lies within sqrt(1 - y^2) of x.
TEST_P(ObjectMotionBlur, MovingSphereBlocksWhileItsDiscCoversThePixel) {
  const std::string json = blockedSky(
      24, R"("spheres": [{"id": "ball", "position": [0, 0, 0], "radius": 1, "material": "black"}])",
      R"({"target": "ball", "property": "position",
                     "keys": [[0, [-2, 0, 0]], [1, [2, 0, 0]]]})");
  const ImageRGB image = renderFrame(json, ".", GetParam());
  for (uint32_t y = 0; y < 24; ++y)
    for (uint32_t x = 0; x < 24; ++x) {
      const double cx = centreX(x, 24), cy = centreY(y, 24);
      double covered = 0;
      if (std::fabs(cy) < 1) {
        const double w = std::sqrt(1 - cy * cy);
        covered = std::max(0.0, std::min(cx + w, 2.0) - std::max(cx - w, -2.0)) / 4;
      }
      EXPECT_NEAR(image.pixels[3 * (y * 24 + x)], 1 - covered, 1.0 / 64 + 1e-5) << x << "," << y;
    }
}

// Where a track names a shape but holds it still through the exposure, nothing moves and no time
// is drawn: the image of a closed shutter, to the bit.
TEST_P(ObjectMotionBlur, ShapesHeldStillKeepTheImageOfAClosedShutter) {
  const std::string scene =
      R"("spheres": [{"id": "ball", "position": [0, 0, 0], "radius": 1, "material": "black"}])";
  const std::string held = R"({"target": "ball", "property": "position",
                               "keys": [[0, [0.5, 0, 0]], [1, [0.5, 0, 0]]]})";
  EXPECT_EQ(renderFrame(blockedSky(8, scene, held), ".", GetParam()).pixels,
            renderFrame(blockedSky(8, scene, held, ""), ".", GetParam()).pixels);
}

INSTANTIATE_TEST_SUITE_P(Engines, ObjectMotionBlur, ::testing::ValuesIn(test::builtCpuEngines()),
                         test::cpuEngineName);

// A lit scene (a point light and, with `sky`, a sky; a white ball moving over a floor and a
// turning cube, shadows, and with `sky` bounces and light subpaths), 24 x 24: `animation` its
// animation block. Without the sky, one interaction and each sample through its pixel's centre:
// a still renders every sample of a pixel alike. `glowing`: the ball and the cube emit (and are
// lights that next-event estimation samples and light subpaths start from), and a spot, a
// rectangle and a sphere light and a sun with a disc take the point light's place.
std::string litScene(uint32_t spp, bool sky, const std::string& animation, bool glowing = false) {
  const std::string ball = glowing ? R"({"type": "emissive", "radiance": [3, 2.5, 2]})" : "0.9";
  const std::string box =
      glowing ? R"({"type": "emissive", "radiance": [2, 1, 0.5]})" : "[0.8, 0.4, 0.2]";
  const auto material = [glowing](const std::string& m) {
    return std::string(glowing ? R"("material": )" : R"("color": )") + m;
  };
  return R"({"camera": {"width": 24, "height": 24, "fov": 50, "position": [0, 2, 6],
               "look_at": [0, 0.5, 0], "spp": )" +
         std::to_string(spp) + R"(},
    "render": )" +
         (sky ? R"({"max_depth": 4}, "environment": {"color": [0.2, 0.25, 0.3]},)"
              : R"({"max_depth": 1, "antialiasing": false},)") +
         R"(
    "spheres": [{"position": [0, -1000, 0], "radius": 1000, "color": 0.6},
                {"id": "ball", "position": [-1.5, 0.6, 0], "radius": 0.6, )" +
         material(ball) + R"(}],
    "objects": [{"id": "box", "shape": "cube", "position": [1, 0.5, -0.5], "scale": 0.5, )" +
         material(box) + R"(}],
    "lights": )" +
         (glowing ? R"([{"id": "lamp", "type": "spot", "position": [1, 4, 3], "look_at": [0, 0, 0],
                 "intensity": 200, "cutoff_angle": 35},
                {"id": "panel", "type": "rectangle", "position": [-1, 3, 1], "look_at": [0, 0, 0],
                 "size": [1, 0.5], "intensity": 40, "visible": false},
                {"id": "bulb", "type": "sphere", "position": [0, 1.8, 1.5], "radius": 0.2,
                 "intensity": 40, "visible": false},
                {"id": "sun", "type": "directional", "direction": [-0.3, -1, -0.4],
                 "intensity": 1.5, "angle": 4}])"
                  : R"([{"position": [1, 4, 3], "intensity": 60}])") +
         R"(,
    "animation": )" +
         animation + "}";
}

// Frames 1, 3, ..., 127 of an animation that makes over 128 frames the motion litScene's blurred
// frame makes over its exposure: the stills at the midpoints of 64 even parts of it, and the
// mean of their images (each with its seed shifted by `seedShift`).
// With `glowing`, litScene's lights move too (the spot turning to keep its aim, the sun turning).
std::string motionTracks(int end, bool glowing = false) {
  const std::string e = std::to_string(end);
  const auto track = [&e](const char* target, const char* property, const char* from,
                          const char* to) {
    return std::string(R"({"target": ")") + target + R"(", "property": ")" + property +
           R"(", "keys": [[0, )" + from + "], [" + e + ", " + to + "]]}";
  };
  std::string tracks = track("ball", "position", "[-1.5, 0.6, 0]", "[1.5, 0.6, 0.5]") + ", " +
                       track("box", "rotation", "[0, 0, 0]", "[0, 90, 30]");
  if (glowing)
    tracks += ", " + track("lamp", "position", "[1, 4, 3]", "[-1, 4, 2]") + ", " +
              track("panel", "position", "[-1, 3, 1]", "[1, 3, 0]") + ", " +
              track("bulb", "position", "[0, 1.8, 1.5]", "[1.2, 1.6, 1]") + ", " +
              track("sun", "direction", "[-0.3, -1, -0.4]", "[0.5, -1, -0.2]");
  return R"("tracks": [)" + tracks + "]";
}
std::vector<float> renderDesc(const SceneDesc& desc) {
  return renderCpu(flattenScene(desc).view(), RenderOptions()).image.pixels;
}
std::vector<double> meanOfStills(uint32_t spp, bool sky, uint32_t seedShift,
                                 std::vector<double>* range = nullptr, bool glowing = false) {
  const SceneDesc stills = parseSceneText(
      litScene(spp, sky, R"({"frames": 129, )" + motionTracks(128, glowing) + "}", glowing),
      "s.json", ".");
  std::vector<double> mean, lo, hi;
  for (uint32_t frame = 1; frame < 128; frame += 2) {
    SceneDesc still = sceneAtFrame(stills, frame);
    still.render.seed += seedShift;
    const std::vector<float> image = renderDesc(still);
    mean.resize(image.size(), 0.0);
    lo.resize(image.size(), 1e30);
    hi.resize(image.size(), -1e30);
    for (size_t i = 0; i < image.size(); ++i) {
      mean[i] += image[i] / 64.0;
      lo[i] = std::min(lo[i], double(image[i]));
      hi[i] = std::max(hi[i], double(image[i]));
    }
  }
  if (range)
    for (size_t i = 0; i < mean.size(); ++i) range->push_back(hi[i] - lo[i]);
  return mean;
}
SceneDesc blurredLitScene(uint32_t spp, bool sky, bool glowing = false) {
  return sceneAtFrame(parseSceneText(litScene(spp, sky,
                                              R"({"frames": 2, "shutter": [0, 1], )" +
                                                  motionTracks(1, glowing) + "}",
                                              glowing),
                                     "s.json", "."),
                      0);
}

// The blurred frame is the mean over its exposure of the still scene. Where a still renders each
// pixel's samples alike (one interaction under a point light, every sample through the pixel's
// centre), each pixel of the blurred frame (1024 samples, their times stratified) is within what
// the stills at 64 midpoints leave of the exact mean: half a 64th of the pixel's range over the
// exposure at each of its few jumps (the ball's and its shadow's edges, the cube's), or, where
// an edge passes the pixel between two midpoints, a 64th of its value.
TEST(ObjectMotion, BlurredFrameIsTheMeanOfTheStillsAcrossItsExposure) {
  std::vector<double> range;
  const std::vector<double> mean = meanOfStills(1, false, 0, &range);
  const std::vector<float> blurred = renderDesc(blurredLitScene(1024, false));
  const std::vector<float> sharp = renderDesc(sceneAtFrame(
      parseSceneText(litScene(1, false, R"({"frames": 129, )" + motionTracks(128) + "}"), "s.json",
                     "."),
      64));
  ASSERT_EQ(blurred.size(), mean.size());
  size_t moving = 0, apart = 0;
  for (size_t i = 0; i < mean.size(); ++i) {
    EXPECT_NEAR(blurred[i], mean[i], std::max(range[i], mean[i]) * 2.0 / 64 + 1e-6) << i;
    moving += range[i] > 0;
    apart += std::fabs(sharp[i] - mean[i]) > range[i] * 4.0 / 64 + 1e-3;
  }
  EXPECT_GT(moving, mean.size() / 10);  // the motion covers a good part of the image
  EXPECT_GT(apart, mean.size() / 20);   // and the frame's own still is far from the mean
}

// The blurred frame (1024 samples) differs from the stills' mean (64 x 16 samples) by about what
// the two renders' noises make together, each measured by a second render of other seeds. (The
// blurred frame's stratified times make its noise lighter-tailed than the stills', so the bound
// is loose.)
void expectBlurredFrameIsTheMeanOfTheStillsWithinTheNoise(bool glowing, CpuEngine engine) {
  const auto render = [engine](SceneDesc desc) {
    if (engine == CpuEngine::Embree) desc.ownBvh = OwnBvh::None;
    const SceneData data = flattenScene(desc);
    CpuRenderer renderer(engine);
    renderer.setScene(data, SceneChange::Structure);
    return renderer.render(RenderOptions{}).image.pixels;
  };
  const std::vector<float> a = render(blurredLitScene(1024, true, glowing));
  SceneDesc reseeded = blurredLitScene(1024, true, glowing);
  reseeded.render.seed += 1000;
  const std::vector<float> b = render(reseeded);
  const std::vector<double> m = meanOfStills(16, true, 0, nullptr, glowing),
                            m2 = meanOfStills(16, true, 5000, nullptr, glowing);
  double blurNoise = 0, stillsNoise = 0, offMean = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    blurNoise += std::fabs(a[i] - b[i]);
    stillsNoise += std::fabs(m[i] - m2[i]);
    offMean += std::fabs(a[i] - m[i]);
  }
  // Independent noises add in quadrature: what the difference of the two means is from noise.
  const double noise = std::sqrt((blurNoise * blurNoise + stillsNoise * stillsNoise) / 2);
  EXPECT_LT(offMean, 1.3 * noise) << offMean / noise;
}

// With a sky, bounces and light subpaths, the blurred frame is the mean of the stills within the
// noise.
TEST_P(ObjectMotionBlur, BlurredLitFrameIsTheMeanOfTheStillsWithinTheNoise) {
  expectBlurredFrameIsTheMeanOfTheStillsWithinTheNoise(false, GetParam());
}

// So it is where the moving shapes emit and the lights move (the spot turning to keep its aim, the
// sun turning, its disc seen by the rays that leave the scene where it then stands):
// next-event estimation samples each where it stands at the shading point's time, light subpaths
// leave it from there, and the densities that weigh the strategies against one another are taken
// there too.
TEST_P(ObjectMotionBlur, MovingEmittersAndLightsLightTheSceneAsTheStillsDo) {
  expectBlurredFrameIsTheMeanOfTheStillsWithinTheNoise(true, GetParam());
}

// The surface a ray meets is where the shape stands at the ray's time: a quad with vertex normals
// turning a quarter about y, met at mid-exposure where it has turned 45 degrees.
TEST(ObjectMotion, SurfaceIsWhereTheShapeStandsAtTheRaysTime) {
  const fs::path dir = fs::temp_directory_path() / "candela_object_motion_surface";
  fs::create_directories(dir);
  std::ofstream(dir / "smooth.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\n"
                                       "f 1//1 2//1 3//1 4//1\n";
  const std::string json = blockedSky(4, R"("objects": [{"id": "quad", "file": "smooth.obj"}])",
                                      R"({"target": "quad", "property": "rotation",
                                          "keys": [[0, [0, 0, 0]], [1, [0, 90, 0]]]})");
  const SceneData data =
      flattenScene(sceneAtFrame(parseSceneText(json, "s.json", dir.string()), 0));
  fs::remove_all(dir);
  ASSERT_EQ(data.motionTimes.size(), kShutterSegments + 1);
  ASSERT_FALSE(data.motionNodes.empty());
  EXPECT_EQ(data.motionRoots.size(), kShutterSegments);  // a BVH for each step between poses
  EXPECT_TRUE(data.nodes.empty());                       // nothing stands still
  const GeometryView view = data.view();
  const float c = std::sqrt(0.5f);
  for (const float time : {0.0f, 0.5f}) {
    Ray ray;
    ray.origin = Vec3(0.2f, 0.5f, 10.0f);
    ray.direction = Vec3(0.0f, 0.0f, -1.0f);
    ray.time = time;
    Hit hit;
    ASSERT_TRUE(intersectClosest(view, ray, &hit)) << time;
    const SurfacePoint sp = surfaceAt(view, ray, hit);
    const Vec3 n = time == 0.0f ? Vec3(0, 0, 1) : Vec3(c, 0, c);
    const Vec3 p = time == 0.0f ? Vec3(0.2f, 0.5f, 0.0f) : Vec3(0.2f, 0.5f, -0.2f);
    EXPECT_EQ(sp.time, time);
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(sp.p[i], p[i], 1e-5f) << time;
      EXPECT_NEAR(sp.ng[i], n[i], 1e-5f) << time;
      EXPECT_NEAR(sp.ns[i], n[i], 1e-3f) << time;  // through octahedral encoding
    }
    // The brute-force reference agrees; a still ray at the shutter's close misses (turned away).
    Hit brute;
    ASSERT_TRUE(intersectClosestBruteForce(view, ray, &brute));
    EXPECT_NEAR(brute.t, hit.t, 1e-5f);
  }
  Ray late;
  late.origin = Vec3(0.2f, 0.5f, 10.0f);
  late.direction = Vec3(0.0f, 0.0f, -1.0f);
  late.time = 1.0f;  // edge-on: the quad spans only x = 0
  Hit missed;
  EXPECT_FALSE(intersectClosest(view, late, &missed));
  EXPECT_FALSE(intersectAny(view, late, 0xffffffffu));
}

// Shapes and lights that move are blurred without a warning, those that emit too, and a
// directional light that turns.
TEST(ObjectMotion, ShapesAndLightsThatMoveBlurWithoutAWarning) {
  const auto scene = [](const std::string& shapes, const std::string& target,
                        const std::string& property = "position") {
    return parseSceneText(blockedSky(4, shapes,
                                     R"({"target": ")" + target + R"(", "property": ")" + property +
                                         R"(", "keys": [[0, [0, -1, 1]], [1, [1, -1, 1]]]})"),
                          "s.json", ".");
  };
  const std::string ball =
      R"("spheres": [{"id": "ball", "position": [0, 0, 0], "radius": 1, "material": "black"}])";
  EXPECT_TRUE(scene(ball, "ball").warnings.empty());
  for (const std::string light : {R"({"id": "lamp", "position": [0, 5, 0], "intensity": 1})",
                                  R"({"id": "lamp", "type": "directional", "direction": [0, -1, 0],
                                      "intensity": 1})"}) {
    const bool sun = light.find("directional") != std::string::npos;
    const SceneDesc lamp =
        scene(ball + R"(, "lights": [)" + light + "]", "lamp", sun ? "direction" : "position");
    EXPECT_TRUE(lamp.warnings.empty()) << lamp.warnings.front();
    const SceneData lit = flattenScene(sceneAtFrame(lamp, 0));
    ASSERT_EQ(lit.lights.size(), 2u);  // the lamp and the sky
    EXPECT_TRUE(lit.lights[0].moves);
    EXPECT_EQ(lit.lightPoses.size(), kShutterSegments + 1);
    EXPECT_EQ(lit.motionTimes.size(), kShutterSegments + 1);
    EXPECT_TRUE(lit.motionNodes.empty());  // no primitive moves
  }
  const std::string glowing = R"("spheres": [{"id": "ball", "position": [0, 0, 0], "radius": 1,
                                              "material": {"type": "emissive", "radiance": 1}}])";
  const SceneDesc glow = scene(glowing, "ball");
  EXPECT_TRUE(glow.warnings.empty());
  const SceneDesc frame = sceneAtFrame(glow, 0);
  EXPECT_EQ(frame.spheres[0].shutterPoses.size(), kShutterSegments + 1);
  const SceneData data = flattenScene(frame);
  EXPECT_EQ(data.motionTimes.size(), kShutterSegments + 1);
  ASSERT_EQ(data.lights.size(), 2u);  // the ball and the sky
  EXPECT_EQ(data.lights[0].type, LightType::Sphere);
}

// A light whose shape moves is sampled where the shape stands at the shading point's time, with
// the density that a BSDF-sampled ray meeting it then is weighed by: a sphere light sliding 4
// along x as its radius grows from 1 to 2, and a one-sided quad turning half a turn about y,
// which a point behind it at the opening sees the front of at the close. The light tree bounds
// each over all it sweeps: it picks the quad's triangles at that point, whose front it faces
// only late in the exposure.
TEST(ObjectMotion, LightSamplesFindMovingEmittersWhereTheyStandAtTheirTime) {
  const std::string dir = writeQuads(fs::temp_directory_path() / "candela_moving_emitters");
  const std::string scene = R"("spheres": [{"id": "lamp", "position": [0, 0, 0], "radius": 1,
                                            "material": {"type": "emissive", "radiance": 1}}],
    "objects": [{"id": "panel", "file": "quad.obj", "position": [0, 0, -20],
                 "material": {"type": "emissive", "radiance": 2}}])";
  const std::string tracks = R"({"target": "lamp", "property": "position",
                                  "keys": [[0, [0, 0, 0]], [1, [4, 0, 0]]]},
                                 {"target": "lamp", "property": "radius", "keys": [[0, 1], [1, 2]]},
                                 {"target": "panel", "property": "rotation",
                                  "keys": [[0, [0, 0, 0]], [1, [0, 180, 0]]]})";
  SceneDesc desc = sceneAtFrame(parseSceneText(blockedSky(4, scene, tracks), "s.json", dir), 0);
  fs::remove_all(dir);
  const SceneData data = flattenScene(desc);
  const SceneView view = data.view();
  ASSERT_EQ(view.lightCount, 4u);  // the lamp, the sky and the panel's two triangles
  const Light& lamp = view.lights[0];
  ASSERT_EQ(lamp.type, LightType::Sphere);
  const Vec3 above(0.0f, 5.0f, 0.0f);
  for (const float time : {0.0f, 0.3f, 0.5f, 1.0f}) {
    const Vec3 centre(4.0f * time, 0.0f, 0.0f);
    const float radius = 1.0f + time;
    EXPECT_NEAR(emissionAreaPdf(view, lamp, time), 1.0f / (4.0f * kPi * radius * radius), 1e-6f);
    for (int k = 0; k < 16; ++k) {
      LightSample ls;
      ASSERT_TRUE(sampleLight(view, lamp, above, time, (k + 0.5f) / 16, 0.37f, &ls));
      const Vec3 q = above + ls.wi * ls.distance;
      EXPECT_NEAR(length(q - centre), radius, 1e-4f) << time;
      EXPECT_NEAR(emitterPdf(view, lamp, above, time, ls.wi, ls.distance, normalize(q - centre)),
                  ls.pdf, 1e-5f * ls.pdf);
      const EmissionPoint e = sampleEmissionPoint(view, lamp, time, (k + 0.5f) / 16, 0.37f);
      EXPECT_NEAR(length(e.p - centre), radius, 1e-4f) << time;
    }
  }
  const Vec3 behind(-0.5f, 0.5f, -23.0f), facing(0.0f, 0.0f, 1.0f);
  for (uint32_t i = 2; i < 4; ++i) {
    const Light& half = view.lights[i];
    ASSERT_EQ(half.type, LightType::Triangle);
    EXPECT_GT(lightSelectPmf(view, i, behind, facing), 0.0f);
    LightSample ls;
    EXPECT_FALSE(sampleLight(view, half, behind, 0.0f, 0.4f, 0.3f, &ls));  // its back
    ASSERT_TRUE(sampleLight(view, half, behind, 1.0f, 0.4f, 0.3f, &ls));   // turned round
    const Vec3 q = behind + ls.wi * ls.distance;
    EXPECT_NEAR(q.z, -20.0f, 1e-4f);
    EXPECT_TRUE(q.x <= 1e-4f && q.x >= -1.0f - 1e-4f) << q.x;
    EXPECT_NEAR(emitterPdf(view, half, behind, 1.0f, ls.wi, ls.distance, Vec3(0, 0, -1)), ls.pdf,
                1e-4f * ls.pdf);
    EXPECT_NEAR(emissionAreaPdf(view, half, 0.5f), 2.0f, 1e-4f);  // it turns, not grows
  }
}

// A spot light that moves is sampled where it stands at the shading point's time, its cone
// aimed as it then is: one sliding from above the origin to 4 along x, aimed at the origin
// throughout, with a cone of 10 degrees.
TEST(ObjectMotion, MovingSpotLightShinesFromWhereItStandsAtEachTime) {
  const std::string scene =
      R"("spheres": [{"position": [0, -100, 0], "radius": 1, "material": "black"}],
    "lights": [{"id": "lamp", "type": "spot", "position": [0, 5, 0], "look_at": [0, 0, 0],
                "intensity": 100, "cutoff_angle": 10}])";
  const SceneData data = flattenScene(
      sceneAtFrame(parseSceneText(blockedSky(4, scene, R"({"target": "lamp", "property": "position",
                                              "keys": [[0, [0, 5, 0]], [1, [4, 5, 0]]]})"),
                                  "s.json", "."),
                   0));
  const SceneView view = data.view();
  const Light& lamp = view.lights[0];
  ASSERT_TRUE(lamp.moves);
  const Vec3 origin(0.0f), aside(4.0f, 0.0f, 0.0f), up(0.0f, 1.0f, 0.0f);
  LightSample ls;
  // Halfway, at (2, 5, 0): the origin lies on its axis.
  ASSERT_TRUE(sampleLight(view, lamp, origin, 0.5f, 0.0f, 0.0f, &ls));
  EXPECT_NEAR(ls.distance, std::sqrt(29.0f), 1e-4f);
  EXPECT_NEAR(ls.wi.x, 2.0f / std::sqrt(29.0f), 1e-5f);
  EXPECT_NEAR(ls.wi.y, 5.0f / std::sqrt(29.0f), 1e-5f);
  EXPECT_GT(lightVertexPdf(view, 0, 0.5f, origin, up), 0.0f);
  // At the close, above (4, 0, 0) but aimed at the origin: that point is 39 degrees off its axis,
  // as it is at the opening from straight above the origin.
  EXPECT_FALSE(sampleLight(view, lamp, aside, 1.0f, 0.0f, 0.0f, &ls));
  EXPECT_FALSE(sampleLight(view, lamp, aside, 0.0f, 0.0f, 0.0f, &ls));
  EXPECT_EQ(lightVertexPdf(view, 0, 1.0f, aside, up), 0.0f);
  ASSERT_TRUE(sampleLight(view, lamp, origin, 0.0f, 0.0f, 0.0f, &ls));
  EXPECT_NEAR(ls.distance, 5.0f, 1e-4f);
}

// A directional light that turns shines from its direction at the shading point's time: a sun
// of a 2-degree disc turning from straight down to 45 degrees towards +x.
TEST(ObjectMotion, TurningSunShinesFromItsDirectionAtEachTime) {
  const std::string scene =
      R"("spheres": [{"position": [0, -100, 0], "radius": 1, "material": "black"}],
    "lights": [{"id": "sun", "type": "directional", "direction": [0, -1, 0], "intensity": 1,
                "angle": 2}])";
  const SceneData data = flattenScene(
      sceneAtFrame(parseSceneText(blockedSky(4, scene, R"({"target": "sun", "property": "direction",
                                              "keys": [[0, [0, -1, 0]], [1, [1, -1, 0]]]})"),
                                  "s.json", "."),
                   0));
  const SceneView view = data.view();
  const Light& sun = view.lights[0];
  ASSERT_TRUE(sun.moves);
  for (const float time : {0.0f, 0.5f, 1.0f}) {
    // The keys' unit directions, blended, reversed.
    const Vec3 toSun =
        -normalize(Vec3(0, -1, 0) + (normalize(Vec3(1, -1, 0)) - Vec3(0, -1, 0)) * time);
    for (int k = 0; k < 8; ++k) {
      LightSample ls;
      ASSERT_TRUE(sampleLight(view, sun, Vec3(0.0f), time, (k + 0.5f) / 8, 0.3f, &ls));
      EXPECT_GT(dot(ls.wi, toSun), std::cos(1.001f * kPi / 180)) << time;  // within the disc
    }
  }
}

}  // namespace
}  // namespace candela
