// The backward optical flow pass (docs/aovs.md): where each sample's first hit stood on the image
// in the previous frame, against closed forms: a camera sliding past a plane, a sphere moving
// before a still camera, a spinning card against the projection of its own position pass; frame
// 0's is exactly 0; and the forward pass beside it is the forward pass alone.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>

#include "core/rotation.h"
#include "flow_test_util.h"
#include "gltf_test_util.h"
#include "moving_sphere_scene.h"
#include "temp_dir.h"

namespace fs = std::filesystem;

namespace candela {
namespace {

using test::writeQuad;

// Frame `frame` of `json` with its flow to the next frame and from the previous (frame 0: from
// itself), and its positions and instances.
test::FlowRender renderFlows(const std::string& json, uint32_t frame, const std::string& dir = ".",
                             const char* passes = "flow,backward_flow,position,instance") {
  const SceneDesc desc = parseSceneText(json, "test.json", dir);
  const SceneDesc now = sceneAtFrame(desc, frame);
  SceneData scene = flattenScene(now);
  applyFlowMotion(scene, flowMotion(now, sceneAtFrame(desc, frame + 1)));
  applyFlowMotion(scene, flowMotion(now, sceneAtFrame(desc, frame > 0 ? frame - 1 : 0)),
                  FlowDirection::Backward);
  RenderOptions options;
  options.aovs = true;
  const RenderResult result = renderCpu(scene.view(), options);
  return {makeAovLayers(scene, parseAovList(passes), result.aovs)};
}

// Frame 1 of the camera sliding by (0.3, 0.2, 0) a frame before a plane 7.5 away: every point of
// the plane was f (0.3, -0.2) / 7.5 pixels away from where it is, the other way from its forward
// flow; at frame 0, which has no frame before it, it is 0.
TEST(BackwardFlow, CameraSlidingPastAPlane) {
  const fs::path dir = fs::temp_directory_path() / "candela_backward_flow_plane";
  const std::string json =
      std::string(R"({"camera": {"width": 20, "height": 10, "fov": 90, "spp": 2},)") +
      test::kCameraSlidingPastTheQuad + "}";
  const test::FlowRender second = renderFlows(json, 1, writeQuad(dir));
  const test::FlowRender first = renderFlows(json, 0, dir.string());
  const float f = 10.0f;  // fov 90: width / 2
  for (uint32_t y = 0; y < 10; ++y)
    for (uint32_t x = 0; x < 20; ++x) {
      EXPECT_NEAR(second.at("backward_flow", x, y, 0), f * 0.3f / 7.5f, 1e-4f) << x << "," << y;
      EXPECT_NEAR(second.at("backward_flow", x, y, 1), -f * 0.2f / 7.5f, 1e-4f) << x << "," << y;
      EXPECT_EQ(first.at("backward_flow", x, y, 0), 0.0f) << x << "," << y;
      EXPECT_EQ(first.at("backward_flow", x, y, 1), 0.0f) << x << "," << y;
      EXPECT_NEAR(first.at("flow", x, y, 0), -f * 0.3f / 7.5f, 1e-4f) << x << "," << y;
    }
  fs::remove_all(dir);
}

// Frame 1 of a sphere moving right by 0.25 a frame before a still camera 5 away: the point the
// centre pixel sees, at depth 5 - sqrt(1 - 0.25^2), was 0.25 to its left.
TEST(BackwardFlow, SphereMovingBeforeAStillCamera) {
  const test::FlowRender r = renderFlows(test::kMovingSphereScene, 1);
  const float f = 7.5f / std::tan(15.0f * kPi / 180.0f);
  const float depth = 5.0f - std::sqrt(1.0f - 0.25f * 0.25f);
  EXPECT_NEAR(r.at("backward_flow", 7, 7, 0), -f * 0.25f / depth, 1e-4f);
  EXPECT_NEAR(r.at("backward_flow", 7, 7, 1), 0.0f, 1e-5f);
  EXPECT_NEAR(r.at("flow", 7, 7, 0), f * 0.25f / depth, 1e-4f);
  EXPECT_EQ(r.at("backward_flow", 0, 0, 0), 0.0f);  // the background stands still
}

// A card spinning 10 degrees a frame about its own vertical axis, at frame 3 (30 degrees): each
// pixel's backward flow is the projection of its position-pass point turned back to 20 degrees,
// minus the pixel centre.
TEST(BackwardFlow, SpinningObjectFollowsItsRotationBack) {
  const fs::path dir = fs::temp_directory_path() / "candela_backward_flow_spin";
  const test::FlowRender r = renderFlows(test::kSpinningCardScene, 3, writeQuad(dir));
  const Mat3 turn = eulerRotation(Vec3(0, 20, 0)) * eulerRotation(Vec3(0, 30, 0)).transposed();
  EXPECT_GT(test::expectFlowFollows(
                r, "backward_flow", 40.0f,
                [&](const Vec3& p) { return turn * (p - Vec3(2, 0, 0)) + Vec3(2, 0, 0); }),
            10);
  fs::remove_all(dir);
}

// A mesh that moves apart: a square whose morph target stretches it along x, to 1.375 times its
// width at frame 3 and 1.25 at frame 2, was at (x 1.25 / 1.375, y) a frame before.
TEST(BackwardFlow, FollowsTheVerticesOfAMovingMeshBack) {
  test::TempDir dir;
  dir.write("stretch.gltf", test::stretchingSquare().gltf());
  const test::FlowRender r = renderFlows(test::kStretchingSquareScene, 3, dir.path());
  EXPECT_GT(
      test::expectFlowFollows(r, "backward_flow", 4.0f,
                              [](const Vec3& p) { return Vec3(p.x * 1.25f / 1.375f, p.y, 0.0f); }),
      20);
}

// Each direction has its own motions: the forward flow beside the backward one is bit for bit the
// forward flow rendered alone.
TEST(BackwardFlow, LeavesTheForwardFlowAlone) {
  const test::FlowRender both = renderFlows(test::kMovingSphereScene, 1);
  const test::FlowRender alone = test::renderFlow(test::kMovingSphereScene, 1);
  for (uint32_t y = 0; y < 15; ++y)
    for (uint32_t x = 0; x < 15; ++x)
      for (uint32_t c = 0; c < 2; ++c) {
        const float a = both.at("flow", x, y, c), b = alone.at("flow", x, y, c);
        EXPECT_EQ(std::memcmp(&a, &b, sizeof a), 0) << x << "," << y;
      }
}

}  // namespace
}  // namespace candela
