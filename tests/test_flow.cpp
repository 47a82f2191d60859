// The optical flow pass (render/flow.h, scene/flow_motion.h) against closed forms: a camera
// sliding past a plane, a sphere moving before a still camera, a turning camera seeing only the
// background, a spinning object against the projection of its own position pass, and a still
// scene, whose flow is exactly 0.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/rotation.h"
#include "flow_test_util.h"
#include "moving_sphere_scene.h"
#include "render/aov_layers.h"
#include "render_test_util.h"
#include "scene/animation.h"
#include "scene/flow_motion.h"
#include "scene/scene_error.h"

namespace fs = std::filesystem;

namespace candela {
namespace {

using test::renderFlow;
using test::writeQuad;

// The camera moves by (0.3, 0.2, 0) between frames before a plane 7.5 away: every point of the
// plane moves by -f (0.3, -0.2) / 7.5 pixels (OpenCV's y points down, world y up).
TEST(Flow, CameraSlidingPastAPlane) {
  const fs::path dir = fs::temp_directory_path() / "candela_flow_plane";
  const test::FlowRender r =
      renderFlow(std::string(R"({"camera": {"width": 20, "height": 10, "fov": 90, "spp": 2},)") +
                     test::kCameraSlidingPastTheQuad + "}",
                 0, writeQuad(dir));
  const float f = 10.0f;  // fov 90: width / 2
  for (uint32_t y = 0; y < 10; ++y)
    for (uint32_t x = 0; x < 20; ++x) {
      EXPECT_NEAR(r.at("flow", x, y, 0), -f * 0.3f / 7.5f, 1e-4f) << x << "," << y;
      EXPECT_NEAR(r.at("flow", x, y, 1), f * 0.2f / 7.5f, 1e-4f) << x << "," << y;
    }
  fs::remove_all(dir);
}

// A sphere moves right by 0.25 before a still camera 5 away: its nearest point, 4 away, moves
// f 0.25 / 4 pixels right; the background does not move.
TEST(Flow, SphereMovingBeforeAStillCamera) {
  const test::FlowRender r = renderFlow(test::kMovingSphereScene, 0);
  const float f = 7.5f / std::tan(15.0f * kPi / 180.0f);
  EXPECT_NEAR(r.at("flow", 7, 7, 0), f * 0.25f / 4.0f, 1e-4f);
  EXPECT_NEAR(r.at("flow", 7, 7, 1), 0.0f, 1e-5f);
  EXPECT_EQ(r.at("instance", 0, 0), 0.0f);
  EXPECT_EQ(r.at("flow", 0, 0, 0), 0.0f);
  EXPECT_EQ(r.at("flow", 0, 0, 1), 0.0f);
}

// A camera turning by 5 degrees about +y (to its left) sees the distant background move right by
// f tan(5 degrees) at the image centre.
TEST(Flow, TurningCameraMovesTheBackground) {
  const test::FlowRender r = renderFlow(R"({
    "camera": {"width": 21, "height": 21, "fov": 60, "spp": 1},
    "render": {"antialiasing": false},
    "environment": {"color": 0.5},
    "animation": {"frames": 2, "tracks": [
      {"target": "camera", "property": "rotation", "keys": [[0, [0, 0, 0]], [1, [0, 5, 0]]]}]}
  })",
                                        0);
  const float f = 10.5f / std::tan(30.0f * kPi / 180.0f);
  EXPECT_NEAR(r.at("flow", 10, 10, 0), f * std::tan(5.0f * kPi / 180.0f), 1e-3f);
  EXPECT_NEAR(r.at("flow", 10, 10, 1), 0.0f, 1e-4f);
}

// A quad spinning about its own vertical axis: each pixel's flow is the projection of its
// position-pass point turned by the frame's rotation, minus the pixel centre.
TEST(Flow, SpinningObjectFollowsItsRotation) {
  const fs::path dir = fs::temp_directory_path() / "candela_flow_spin";
  const test::FlowRender r = renderFlow(test::kSpinningCardScene, 3, writeQuad(dir));
  const Mat3 turn = eulerRotation(Vec3(0, 40, 0)) * eulerRotation(Vec3(0, 30, 0)).transposed();
  EXPECT_GT(test::expectFlowFollows(
                r, "flow", 40.0f,
                [&](const Vec3& p) { return turn * (p - Vec3(2, 0, 0)) + Vec3(2, 0, 0); }),
            10);
  fs::remove_all(dir);
}

// Nothing moves in a still scene (or after an animation's last key): the flow is exactly 0.
TEST(Flow, StillSceneHasExactlyZeroFlow) {
  const test::FlowRender r = renderFlow(R"({
    "camera": {"width": 12, "height": 8, "fov": 50, "spp": 4, "position": [0, 0, 10],
               "rotation": [10, 20, 0]},
    "environment": {"color": 0.2},
    "spheres": [{"position": [0, 0, 0], "radius": 2, "color": 0.5}],
    "lights": [{"position": [0, 3, 3], "intensity": 100}]
  })");
  for (uint32_t y = 0; y < 8; ++y)
    for (uint32_t x = 0; x < 12; ++x) {
      EXPECT_EQ(r.at("flow", x, y, 0), 0.0f);
      EXPECT_EQ(r.at("flow", x, y, 1), 0.0f);
    }
}

TEST(Flow, EntitiesMustCorrespond) {
  const SceneDesc a = parseSceneText(
      R"({"camera": {}, "spheres": [{"position": [0, 0, 0], "radius": 1}]})", "a.json", ".");
  const SceneDesc b = parseSceneText(R"({"camera": {}, "spheres": []})", "b.json", ".");
  EXPECT_THROW(flowMotion(a, b), SceneError);
}

}  // namespace
}  // namespace candela
