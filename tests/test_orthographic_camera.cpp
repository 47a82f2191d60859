// Orthographic cameras ("projection": "orthographic"): every pixel's ray leaves its own point of
// the camera's plane along the camera's axis. Checked against the test's own mapping in double:
// each camera ray; a glowing ball that covers the same pixels near and far; the depth pass, from
// the camera's plane; the flow of a sliding camera, the same shift
// everywhere; the camera file, which gives the same camera back. Then the refusals.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "flow_test_util.h"
#include "render/aov_layers.h"
#include "render/camera_ray.h"
#include "render_test_util.h"
#include "scene/camera_resolve.h"

namespace candela {
namespace {

using test::num;

// A 64 x 32 image 4 units wide (16 pixels a unit) at (1, 2, 3), looking down -z with +y up: pixel
// (px, py) looks from (1 + (px - 32) / 16, 2 - (py - 16) / 16, 3) along -z.
TEST(OrthographicCamera, RaysAreParallelFromTheirPointsOfThePlane) {
  const SceneData data = test::loadTestScene(
      R"({"camera": {"width": 64, "height": 32, "projection": "orthographic", "view_width": 4,
                     "position": [1, 2, 3], "look_at": [1, 2, -10]}})");
  const Camera& camera = data.view().camera;
  double worst = 0;
  for (float py = 0.0f; py <= 32.0f; py += 0.75f)
    for (float px = 0.0f; px <= 64.0f; px += 1.25f) {
      const Ray ray = generateCameraRay(camera, px, py, 0.3f, 0.7f);
      const double ox = 1 + (px - 32.0) / 16, oy = 2 - (py - 16.0) / 16;
      for (const double miss :
           {std::fabs(ray.origin.x - ox), std::fabs(ray.origin.y - oy),
            std::fabs(ray.origin.z - 3.0), double(std::fabs(ray.direction.x)),
            double(std::fabs(ray.direction.y)), std::fabs(ray.direction.z + 1.0)})
        worst = std::max(worst, miss);
    }
  EXPECT_LT(worst, 2e-6);
}

// A glowing ball of radius 1 (centre a little off the axis, so that no pixel centre lies on its
// rim) 3 and 30 units in front of the camera, pixel centres only: the pixels that see it are
// those whose centres lie within 1 of its centre across the plane, the same near and far.
TEST(OrthographicCamera, ABallCoversTheSamePixelsNearAndFar) {
  const double cx = 0.013, cy = -0.021;
  const auto render = [&](double distance) {
    return test::renderTestScene(R"({
      "camera": {"width": 48, "height": 40, "projection": "orthographic", "view_width": 4,
                 "spp": 1},
      "render": {"antialiasing": false, "max_depth": 1},
      "spheres": [{"position": [)" +
                                 num(cx) + ", " + num(cy) + ", " + num(-distance) +
                                 R"(], "radius": 1, "material": {"type": "emissive",
                 "radiance": 1}}]})");
  };
  const RenderResult near = render(3), far = render(30);
  int seen = 0;
  for (uint32_t y = 0; y < 40; ++y)
    for (uint32_t x = 0; x < 48; ++x) {
      const double wx = (x + 0.5 - 24) / 12, wy = -(y + 0.5 - 20) / 12;
      const bool inside = (wx - cx) * (wx - cx) + (wy - cy) * (wy - cy) < 1;
      seen += inside;
      ASSERT_EQ(near.image.at(x, y)[0], inside ? 1.0f : 0.0f) << x << "," << y;
      ASSERT_EQ(far.image.at(x, y)[0], inside ? 1.0f : 0.0f) << x << "," << y;
    }
  EXPECT_GT(seen, 400);  // pi 12^2, about 452
}

// Looking straight down from 5 above a floor tilted by 30 degrees about x: the depth pass is the
// distance from the camera's plane (5 at the image's centre, changing by tan 30 per unit down the
// image), the distance pass the distance from the camera's centre, `position`, as for any camera.
TEST(OrthographicCamera, DepthAndDistanceRunFromTheCamerasPlane) {
  const SceneData data = test::loadTestScene(R"({
    "camera": {"width": 32, "height": 24, "projection": "orthographic", "view_width": 4,
               "position": [0, 5, 0], "rotation": [-90, 0, 0], "spp": 2},
    "render": {"antialiasing": false},
    "objects": [{"file": ")" + test::writePlaneObj("ortho_floor.obj", 50) +
                                             R"(", "rotation": [30, 0, 0]}],
    "lights": [{"position": [0, 4, 0], "intensity": 10}]})");
  RenderOptions options;
  options.aovs = true;
  const RenderResult r = renderCpu(data.view(), options);
  const std::vector<ImageLayer> layers =
      makeAovLayers(data, parseAovList("depth,distance"), r.aovs);
  // Rotation -90 about x: the camera looks down -y with its image's up along -z, so pixel row y
  // sees world z = (y + 0.5 - 12) / 8 (8 pixels a unit), where the floor (the plane y = 0 turned
  // 30 degrees about +x) is at height -z tan 30.
  const double t = std::tan(30.0 * 3.14159265358979323846 / 180);
  ASSERT_EQ(layers.size(), 2u);
  for (uint32_t y = 0; y < 24; ++y)
    for (uint32_t x = 0; x < 32; ++x) {
      const double wx = (x + 0.5 - 16) / 8, z = (y + 0.5 - 12) / 8;
      const double drop = 5 + z * t;
      ASSERT_NEAR(layers[0].pixels[y * 32 + x], drop, 2e-5) << x << "," << y;
      ASSERT_NEAR(layers[1].pixels[y * 32 + x], std::sqrt(wx * wx + drop * drop + z * z), 2e-5)
          << x << "," << y;
    }
}

// The camera slides by (0.3, 0.2, 0) between frames before a large quad: every pixel's first hit
// moves by the same -0.3 * 8 pixels across and +0.2 * 8 down (8 pixels a unit).
TEST(OrthographicCamera, FlowOfASlidingCameraIsTheSameEverywhere) {
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "ortho_flow";
  test::writeQuad(dir);
  const test::FlowRender r = test::renderFlow(
      R"({"camera": {"width": 32, "height": 24, "projection": "orthographic", "view_width": 4,
                     "spp": 1},)" +
          std::string(test::kCameraSlidingPastTheQuad) + "}",
      0, dir.string());
  for (uint32_t y = 0; y < 24; ++y)
    for (uint32_t x = 0; x < 32; ++x) {
      ASSERT_NEAR(r.at("flow", x, y, 0), -2.4f, 1e-4f) << x << "," << y;
      ASSERT_NEAR(r.at("flow", x, y, 1), 1.6f, 1e-4f) << x << "," << y;
    }
}

// The camera file names the projection and K (pixels per unit); given back as "intrinsics", it is
// the same camera.
TEST(OrthographicCamera, TheCameraFileGivesTheSameCameraBack) {
  const SceneDesc desc = parseSceneText(
      R"({"camera": {"width": 40, "height": 30, "projection": "orthographic", "view_width": 5,
                     "position": [1, 2, 3], "look_at": [0, 0, 0]}})",
      "test.json", ".");
  const CameraMatrices m = cameraMatrices(desc.camera, desc.file);
  EXPECT_EQ(m.projection, CameraProjection::Orthographic);
  EXPECT_EQ(std::string(projectionName(m.projection)), "orthographic");
  EXPECT_FLOAT_EQ(m.intrinsics.m[0][0], 8.0f);
  EXPECT_FLOAT_EQ(m.intrinsics.m[1][2], 15.0f);
  std::string k, e;
  for (int i = 0; i < 3; ++i)
    k += std::string(i ? ", " : "") + "[" + num(m.intrinsics.m[i][0]) + ", " +
         num(m.intrinsics.m[i][1]) + ", " + num(m.intrinsics.m[i][2]) + "]";
  const AffineRows rows = affineRows(m.rotation, m.translation);
  for (int i = 0; i < 4; ++i)
    e += std::string(i ? ", " : "") + "[" + num(rows[i][0]) + ", " + num(rows[i][1]) + ", " +
         num(rows[i][2]) + ", " + num(rows[i][3]) + "]";
  const SceneData given = test::loadTestScene(
      R"({"camera": {"width": 40, "height": 30, "projection": "orthographic", "intrinsics": [)" +
      k + R"(], "extrinsics": [)" + e + "]}}");
  const SceneData first = test::loadTestScene(
      R"({"camera": {"width": 40, "height": 30, "projection": "orthographic", "view_width": 5,
                     "position": [1, 2, 3], "look_at": [0, 0, 0]}})");
  for (float p : {0.0f, 7.5f, 40.0f}) {
    const Ray a = generateCameraRay(first.view().camera, p, p * 0.75f, 0.5f, 0.5f);
    const Ray b = generateCameraRay(given.view().camera, p, p * 0.75f, 0.5f, 0.5f);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(a.origin[c], b.origin[c], 1e-5);
      EXPECT_NEAR(a.direction[c], b.direction[c], 1e-6);
    }
  }
}

std::string cameraError(const std::string& camera, const std::string& more = "") {
  return test::loadError(R"({"camera": {"width": 64, "height": 32, )" + camera + "}" + more + "}",
                         ".");
}

TEST(OrthographicCamera, RefusesWhatItDoesNotUse) {
  const std::string ortho = R"("projection": "orthographic", )";
  const std::string why =
      "not used by an orthographic camera (its rays are parallel: \"view_width\" or "
      "\"intrinsics\" gives its scale)";
  EXPECT_EQ(cameraError(ortho + R"("view_width": 2, "fov": 40)"), "test.json: camera.fov: " + why);
  EXPECT_EQ(cameraError(ortho + R"("view_width": 2, "aperture_radius": 0.1)"),
            "test.json: camera.aperture_radius: " + why);
  EXPECT_EQ(cameraError(ortho + R"("view_width": 2, "distortion": [0.1, 0, 0, 0])"),
            "test.json: camera.distortion: " + why);
  EXPECT_EQ(cameraError(R"("projection": "orthographic")"),
            "test.json: camera: missing required key \"view_width\" (an orthographic camera's "
            "width in world units) or \"intrinsics\"");
  EXPECT_EQ(cameraError(ortho + R"("view_width": 0)"),
            "test.json: camera.view_width: expected a positive number, got 0");
  EXPECT_NE(cameraError(ortho + R"("view_width": 2, "intrinsics": {"fx": 10, "fy": 10, "cx": 32,
                                   "cy": 16})")
                .find("\"view_width\""),
            std::string::npos);
  EXPECT_EQ(cameraError(R"("view_width": 2)"),
            "test.json: camera.view_width: not used by a perspective camera (only orthographic "
            "cameras have a view width)");
  EXPECT_EQ(cameraError(R"("projection": "equirectangular", "view_width": 2)"),
            "test.json: camera.view_width: not used by an equirectangular camera (only "
            "orthographic cameras have a view width)");
  EXPECT_EQ(cameraError(ortho + R"("view_width": 2)",
                        test::oneTrack("camera", "fov", "[[0, 40], [2, 50]]")),
            "test.json: animation.tracks[0].property: \"fov\" is not used by an orthographic "
            "camera");
}

}  // namespace
}  // namespace candela
