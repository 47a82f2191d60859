// Motion blur of a moving camera: the shutter's reading, the poses across a frame's exposure, and
// images against the fraction of the exposure for which each pixel sees an emitter.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "backends/cpu/cpu_renderer.h"
#include "core/rotation.h"
#include "render/aov_layers.h"
#include "scene/animation.h"
#include "scene/camera_resolve.h"
#include "scene/flatten.h"
#include "scene/read/scene_loader.h"
#include "scene/scene_error.h"

namespace candela {
namespace {

namespace fs = std::filesystem;

SceneDesc parse(const std::string& json, const std::string& dir = ".") {
  return parseSceneText(json, "s.json", dir);
}

std::string error(const std::string& json) {
  try {
    parse(json);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no SceneError)";
}

// A scene whose camera slides along x from `from` at frame 0 to `to` at frame 1, with an
// animation block of `shutter` (the text after "frames": 2), before a sphere.
std::string slidingCamera(const std::string& shutter, float from = -1, float to = 1) {
  return R"({"camera": {"width": 8, "height": 4, "spp": 4},
    "spheres": [{"id": "ball", "position": [0, 0, -5], "radius": 1, "color": 0.5}],
    "lights": [{"position": [0, 5, 0], "intensity": 10}],
    "animation": {"frames": 2)" +
         shutter + R"(, "tracks": [{"target": "camera", "property": "position",
      "keys": [[0, [)" +
         std::to_string(from) + R"(, 0, 0]], [1, [)" + std::to_string(to) + R"(, 0, 0]]]}]}})";
}

TEST(Quaternion, RoundTripsRotationsAndTurnsAtConstantSpeed) {
  for (const Vec3 degrees : {Vec3(0.0f), Vec3(10, 20, 30), Vec3(170, -80, 45), Vec3(0, 180, 0),
                             Vec3(180, 0, 0), Vec3(-90, 90, 90)}) {
    const Mat3 r = eulerRotation(degrees);
    const Mat3 back = rotationMatrix(quaternionOf(r));
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) EXPECT_NEAR(back.m[i][j], r.m[i][j], 1e-6f) << degrees.x;
  }
  // A third of the way from no turn to 120 degrees about y is 40 degrees about y, along the
  // shorter arc whichever sign the end's quaternion has.
  const Quaternion none = quaternionOf(Mat3()), end = quaternionOf(rotationY(120));
  const Quaternion flipped{-end.x, -end.y, -end.z, -end.w};
  for (const Quaternion& b : {end, flipped}) {
    const Mat3 r = rotationMatrix(slerp(none, b, 1.0f / 3.0f)), expected = rotationY(40);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) EXPECT_NEAR(r.m[i][j], expected.m[i][j], 1e-6f);
  }
}

// Keys made of poses frame by frame (a glTF camera's) must turn the short way between frames,
// where a blurred frame's exposure evaluates them: the Euler angles of each pose are taken
// nearest the last.
TEST(Quaternion, EulerAnglesNearThePreviousKeyTurnTheShortWay) {
  const Vec3 near = eulerDegrees(eulerRotation(Vec3(0, 0, 179)));
  EXPECT_NEAR(eulerDegreesNear(eulerRotation(Vec3(0, 0, -179)), near).z, 181.0f, 1e-3f);
  // Through y = 90 degrees the other triple of a rotation is the near one.
  const Vec3 before(30, 89, 10), after(30, 91, 10);
  const Vec3 e = eulerDegreesNear(eulerRotation(after), before);
  const Mat3 r = eulerRotation(e), expected = eulerRotation(after);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(r.m[i][j], expected.m[i][j], 1e-5f);
  EXPECT_LT(std::fabs(e.x - before.x) + std::fabs(e.y - before.y) + std::fabs(e.z - before.z), 3.0f)
      << e.x << " " << e.y << " " << e.z;
}

TEST(MotionBlur, ShutterReadsAsAShareOfTheFrameOrAsOpenAndClose) {
  const SceneDesc centred = parse(slidingCamera(R"(, "shutter": 0.5)"));
  EXPECT_EQ(centred.animation->shutterOpen, -0.25f);
  EXPECT_EQ(centred.animation->shutterClose, 0.25f);
  const SceneDesc given = parse(slidingCamera(R"(, "shutter": [0, 1])"));
  EXPECT_EQ(given.animation->shutterOpen, 0.0f);
  EXPECT_EQ(given.animation->shutterClose, 1.0f);
  EXPECT_TRUE(parse(slidingCamera("")).warnings.empty());
}

TEST(MotionBlur, ShutterErrors) {
  const std::string share =
      "expected a number in [0, 1] (the share of the frame interval, centred on the frame)";
  EXPECT_EQ(error(slidingCamera(R"(, "shutter": 1.5)")),
            "s.json: animation.shutter: " + share + ", got 1.5");
  EXPECT_EQ(error(slidingCamera(R"(, "shutter": "half")")),
            "s.json: animation.shutter: " + share + " or [open, close], got a string \"half\"");
  const std::string pair =
      "s.json: animation.shutter: expected [open, close] with -1 <= open <= close <= 1 and "
      "close - open <= 1 (frames), got an array ";
  EXPECT_EQ(error(slidingCamera(R"(, "shutter": [0.5, 0.25])")), pair + "[0.5,0.25]");
  EXPECT_EQ(error(slidingCamera(R"(, "shutter": [-0.75, 0.5])")), pair + "[-0.75,0.5]");
  EXPECT_EQ(error(slidingCamera(R"(, "shutter": [0, 1, 2])")), pair + "[0,1,2]");
  EXPECT_EQ(error(slidingCamera(R"(, "shutter": [0, "1"])")),
            "s.json: animation.shutter[1]: expected a number, got a string \"1\"");
}

// A look-at camera must make a camera at every time of every exposure, not only at frames: here
// it passes through the point it looks at half-way between frames 0 and 1.
TEST(MotionBlur, CameraUnusableWithinAnExposureIsAnError) {
  const std::string scene = R"({"camera": {"position": [-1, 0, 0], "look_at": [0, 0, 0], "spp": 1},
    "spheres": [{"position": [0, 0, -5], "radius": 1}],
    "animation": {"frames": 2)";
  const std::string track = R"(, "tracks": [{"target": "camera", "property": "position",
      "keys": [[0, [-1, 0, 0]], [1, [1, 0, 0]]]}]}})";
  EXPECT_EQ(error(scene + track),
            "(no SceneError)");  // no frame puts the camera on its target, so a still is fine
  EXPECT_EQ(error(scene + R"(, "shutter": [0, 1])" + track),
            "s.json: animation: at time 0.5 (frame 0's exposure) the camera looks at its own "
            "position");
}

// A sphere that moves beside the camera is blurred too (tests/test_object_motion_blur.cpp), with
// no warning.
TEST(MotionBlur, WhatMovesBesideTheCameraIsBlurredToo) {
  std::string json = slidingCamera(R"(, "shutter": 0.5)");
  json.replace(json.find(R"("tracks": [)") + 11, 0,
               R"({"target": "ball", "property": "position", "keys": [[0, [0, 0, -5]],
                  [1, [1, 0, -5]]]}, )");
  const SceneDesc desc = parse(json);
  EXPECT_TRUE(desc.warnings.empty());
  const SceneDesc frame = sceneAtFrame(desc, 1);
  EXPECT_EQ(frame.shutterCameras.size(), kShutterSegments + 1);
  ASSERT_EQ(frame.spheres[0].shutterPoses.size(), kShutterSegments + 1);
  EXPECT_EQ(frame.spheres[0].shutterPoses.front().position.x, 0.75f);  // frame 0.75
  EXPECT_EQ(frame.spheres[0].shutterPoses.back().position.x, 1.0f);    // held after frame 1
}

// The exposure's poses: the shutter's ends, steps between and the key inside; a centred shutter
// of frame 0 holds the first key's pose before it.
TEST(MotionBlur, PosesSpanTheExposureAndBendAtKeys) {
  const SceneDesc desc = parse(slidingCamera(R"(, "shutter": [-0.5, 0.5])"));
  const std::vector<double> times = shutterTimes(*desc.animation, 1);
  ASSERT_EQ(times.size(), kShutterSegments + 1);  // frame 1 lies on a step
  EXPECT_EQ(times.front(), 0.5);
  EXPECT_EQ(times.back(), 1.5);
  const std::vector<double> shifted =
      shutterTimes(AnimationDesc{2, 24, desc.animation->tracks, -0.3f, 0.6f}, 1);
  EXPECT_EQ(shifted.size(), kShutterSegments + 2);  // and here between steps
  EXPECT_TRUE(std::is_sorted(shifted.begin(), shifted.end()));

  const SceneDesc still = sceneAtFrame(desc, 1);
  ASSERT_EQ(still.shutterCameras.size(), kShutterSegments + 1);
  EXPECT_EQ(still.shutterCameras.front().time, 0.0f);
  EXPECT_EQ(still.shutterCameras.back().time, 1.0f);
  EXPECT_NEAR(still.shutterCameras.front().camera.position.x, 0.0f, 1e-6f);  // half-way
  EXPECT_EQ(still.shutterCameras.back().camera.position.x, 1.0f);  // held after the last key
  EXPECT_EQ(still.camera.position.x, 1.0f);                        // the frame's own camera

  // No shutter, or a camera that no track moves: no poses, so no blur and no time drawn.
  EXPECT_TRUE(sceneAtFrame(parse(slidingCamera("")), 1).shutterCameras.empty());
  const SceneDesc held = sceneAtFrame(parse(slidingCamera(R"(, "shutter": 1)", 2, 2)), 1);
  EXPECT_FALSE(held.shutterCameras.empty());
  EXPECT_TRUE(shutterPoses(held).empty());
}

// A camera moving along a chord past the point it looks at turns ever faster as it nears it:
// between the exposure's poses, which turn at constant speed, its pose is within what sixteen
// steps leave of the exact one: here, through a quarter turn in one exposure, about 0.06 degrees.
TEST(MotionBlur, PosesBetweenStepsFollowALookAtCamera) {
  const SceneDesc desc =
      parse(R"({"camera": {"position": [10, 0, 0], "look_at": [0, 0, 0], "spp": 1},
    "spheres": [{"position": [0, 0, 0], "radius": 1}],
    "animation": {"frames": 2, "shutter": [0, 1], "tracks": [
      {"target": "camera", "property": "position", "keys": [[0, [10, 0, 0]], [1, [0, 0, 10]]]}]}})");
  const SceneDesc still = sceneAtFrame(desc, 0);
  const std::vector<CameraPose> poses = shutterPoses(still);
  ASSERT_EQ(poses.size(), kShutterSegments + 1);
  const Camera frame = resolveCamera(still.camera, "s.json");
  for (float u : {0.0f, 0.06f, 0.3f, 0.5f, 0.77f, 1.0f}) {
    const Camera posed = cameraAtShutterTime(frame, poses.data(), uint32_t(poses.size()), u);
    const Camera exact = resolveCamera(cameraAtTime(desc.camera, *desc.animation, u), "s.json");
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(posed.position[i], exact.position[i], 1e-5f) << u;
      for (int j = 0; j < 3; ++j)
        EXPECT_NEAR(posed.cameraToWorld.m[i][j], exact.cameraToWorld.m[i][j], 1.5e-3f) << u;
    }
  }
}

// Writes half.obj, the half x >= 0 of a square 200 across in the plane z = 0; returns `dir`.
std::string writeHalfPlane(const fs::path& dir) {
  fs::create_directories(dir);
  std::ofstream(dir / "half.obj") << "v 0 -100 0\nv 100 -100 0\nv 100 100 0\nv 0 100 0\n"
                                     "f 1 2 3 4\n";
  return dir.string();
}

// The camera slides along x from -3 to 3 while the shutter is open, 7.5 before an emitter that
// covers x >= 0, with antialiasing off so that every sample passes through its pixel's centre,
// 64 samples a pixel. `extra` adds to the animation block; `height` rows.
struct HalfPlaneRender {
  RenderResult result;
  std::vector<ImageLayer> layers;  // the distance pass
};
HalfPlaneRender renderPastHalfPlane(const std::string& extra, uint32_t height) {
  const fs::path dir = fs::temp_directory_path() / "candela_motion_blur";
  const std::string json = R"({"camera": {"width": 40, "height": )" + std::to_string(height) +
                           R"(, "fov": 90, "spp": 64},
    "render": {"antialiasing": false, "max_depth": 1},
    "objects": [{"file": "half.obj", "position": [0, 0, -7.5],
                 "material": {"type": "emissive", "radiance": 1}}],
    "animation": {"frames": 2, "shutter": [0, 1])" +
                           extra + R"(, "tracks": [
      {"target": "camera", "property": "position", "keys": [[0, [-3, 0, 0]], [1, [3, 0, 0]]]}]}})";
  const SceneDesc still = sceneAtFrame(parse(json, writeHalfPlane(dir)), 0);
  fs::remove_all(dir);
  SceneData scene = flattenScene(still);
  RenderOptions options;
  options.aovs = true;
  HalfPlaneRender r{renderCpu(scene.view(), options), {}};
  r.layers = makeAovLayers(scene, parseAovList("distance"), r.result.aovs);
  return r;
}

// The share of the exposure times [from, to] (as fractions of the shutter, from <= to) for which
// the pixel centre (x + 0.5, y + 0.5) of the half-plane render sees the emitter: while the camera
// is at x >= -7.5 (px - 20) / 20.
double shareSeen(uint32_t x, double from, double to) {
  const double dx = (x + 0.5 - 20) / 20;
  const double a = -3 + 6 * from, b = -3 + 6 * to, edge = -7.5 * dx;
  if (b == a) return a >= edge ? 1 : 0;
  return std::min(1.0, std::max(0.0, (b - edge) / (b - a)));
}

// A global shutter: each pixel sees the emitter for its share of the whole exposure, within 1/64
// as the 64 samples' times are stratified, one in each 64th of it. The distance pass, from each
// sample's own eye, does not depend on where the camera was.
TEST(MotionBlur, SlidingCameraSeesAnEdgeForItsShareOfTheExposure) {
  const HalfPlaneRender r = renderPastHalfPlane("", 4);
  int ramp = 0;
  for (uint32_t y = 0; y < 4; ++y)
    for (uint32_t x = 0; x < 40; ++x) {
      const double dx = (x + 0.5 - 20) / 20, dy = (y + 0.5 - 2) / 20;
      const double share = shareSeen(x, 0, 1);
      const float* rgb = &r.result.image.pixels[3 * (size_t(y) * 40 + x)];
      EXPECT_NEAR(rgb[0], share, 1.0 / 64 + 1e-5) << x << "," << y;
      EXPECT_EQ(rgb[0], rgb[2]);
      ramp += share > 0 && share < 1;
      if (share > 0) {
        EXPECT_NEAR(r.layers[0].pixels[size_t(y) * 40 + x], 7.5 * std::sqrt(1 + dx * dx + dy * dy),
                    1e-4)
            << x << "," << y;
      }
    }
  EXPECT_EQ(ramp, 4 * 16);  // the edge spreads over 16 columns
}

// A rolling shutter reads its rows from the top: row y (its centre at y + 0.5 of 8) is open from
// (y + 0.5) / 8 (1 - e) for a share e of the exposure. Each row instant (e = 0) sees the edge
// sharp where the camera was then, a column further left every half row; e = 0.5 spreads each
// row's edge over half the global shutter's ramp, the rows still apart.
TEST(MotionBlur, RollingShutterReadsItsRowsFromTheTop) {
  for (const double e : {0.0, 0.5}) {
    const HalfPlaneRender r = renderPastHalfPlane(
        R"(, "rolling_shutter": {"row_exposure": )" + std::to_string(e) + "}", 8);
    for (uint32_t y = 0; y < 8; ++y) {
      const double from = (y + 0.5) / 8 * (1 - e);
      for (uint32_t x = 0; x < 40; ++x)
        EXPECT_NEAR(r.result.image.pixels[3 * (size_t(y) * 40 + x)], shareSeen(x, from, from + e),
                    e == 0 ? 1e-6 : 1.0 / 64 + 1e-5)
            << "e " << e << " at " << x << "," << y;
    }
  }
  // By default each row is an instant, a step: row 0 turns on at column 27, row 7 at 13.
  const HalfPlaneRender sharp = renderPastHalfPlane(R"(, "rolling_shutter": {})", 8);
  EXPECT_EQ(sharp.result.image.pixels[3 * 27], 1.0f);
  EXPECT_EQ(sharp.result.image.pixels[3 * 26], 0.0f);
  EXPECT_EQ(sharp.result.image.pixels[3 * (7 * 40 + 13)], 1.0f);
  EXPECT_EQ(sharp.result.image.pixels[3 * (7 * 40 + 12)], 0.0f);
}

TEST(MotionBlur, RollingShutterErrors) {
  EXPECT_EQ(error(slidingCamera(R"(, "rolling_shutter": {"row_exposure": 0.1})")),
            "s.json: animation.rolling_shutter: a rolling shutter needs an open \"shutter\" to "
            "read its rows over");
  EXPECT_EQ(error(slidingCamera(R"(, "shutter": 1, "rolling_shutter": {"row_exposure": 1})")),
            "s.json: animation.rolling_shutter.row_exposure: expected a number in [0, 1) (each "
            "row's share of the exposure), got 1");
  EXPECT_EQ(error(slidingCamera(R"(, "shutter": 1, "rolling_shutter": {"rows": 1})")),
            "s.json: animation.rolling_shutter.rows: unknown key, expected one of "
            "\"row_exposure\"");
}

// A camera that no track moves renders under an open shutter the image of a closed one, to the
// bit: it draws no time, so every sample keeps its numbers.
TEST(MotionBlur, StillCameraUnderAnOpenShutterKeepsTheImage) {
  const auto render = [](const std::string& shutter) {
    SceneData scene = flattenScene(sceneAtFrame(parse(slidingCamera(shutter, 2, 2)), 1));
    EXPECT_TRUE(scene.cameraPoses.empty());
    return renderCpu(scene.view(), RenderOptions()).image.pixels;
  };
  EXPECT_EQ(render(R"(, "shutter": 1)"), render(""));
  // And a moving one does blur.
  const auto blurred =
      renderCpu(flattenScene(sceneAtFrame(parse(slidingCamera(R"(, "shutter": 1)")), 1)).view(),
                RenderOptions())
          .image.pixels;
  const auto sharp =
      renderCpu(flattenScene(sceneAtFrame(parse(slidingCamera("")), 1)).view(), RenderOptions())
          .image.pixels;
  EXPECT_NE(blurred, sharp);
}

}  // namespace
}  // namespace candela
