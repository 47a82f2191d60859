// Equirectangular cameras (render/panorama.h): every pixel of the panorama looks along its own
// longitude and latitude. Checked against the test's own mapping in double: each camera ray; the
// flow of a camera that turns about the vertical (a shift along the rows, the short way across the
// seam); the depth pass, which for a panorama is the distance (inside a ball about the camera, its
// radius everywhere); the camera file, which renders the same panorama given back. Then the
// refusals.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "core/constants.h"
#include "flow_test_util.h"
#include "render/aov_layers.h"
#include "render/camera_ray.h"
#include "render_test_util.h"
#include "scene/camera_resolve.h"

namespace candela {
namespace {

// The world direction of point (px, py) of a w x h panorama whose camera is turned by `yaw`
// degrees about +y from looking down -z: longitude 0 ahead, 90 to the camera's right, latitude 90
// straight up.
std::array<double, 3> panoramaWorld(double px, double py, double w, double h, double yaw) {
  const double longitude = (px / w - 0.5) * 2 * kPi, latitude = (0.5 - py / h) * kPi;
  // Camera frame (right, up, back) of the contract's camera: right +x, up +y, looking -z.
  const double x = std::cos(latitude) * std::sin(longitude), y = std::sin(latitude),
               z = -std::cos(latitude) * std::cos(longitude);
  const double c = std::cos(yaw * kPi / 180), s = std::sin(yaw * kPi / 180);
  return {c * x + s * z, y, -s * x + c * z};  // R_y(yaw)
}

TEST(Panorama, RaysLookAlongTheirLongitudeAndLatitude) {
  const SceneData data = test::loadTestScene(
      R"({"camera": {"width": 64, "height": 32, "projection": "equirectangular",
                     "position": [1, 2, 3], "rotation": [0, 30, 0]}})");
  const Camera& camera = data.view().camera;
  double worst = 0;
  for (float py = 0.0f; py <= 32.0f; py += 0.75f)
    for (float px = 0.0f; px <= 64.0f; px += 1.25f) {
      const Ray ray = generateCameraRay(camera, px, py, 0.5f, 0.5f);
      EXPECT_EQ(ray.origin.x, 1.0f);
      const std::array<double, 3> d = panoramaWorld(px, py, 64, 32, 30);
      worst =
          std::max(worst, std::fabs(ray.direction.x - d[0]) + std::fabs(ray.direction.y - d[1]) +
                              std::fabs(ray.direction.z - d[2]));
    }
  EXPECT_LT(worst, 2e-6);
}

// The sky alone, a camera that turns 10 degrees about +y between frames: every direction moves
// along the rows by the same w * 10 / 360 pixels, to the right as the camera turns left (towards
// +yaw), across the seam the short way; nothing moves up or down.
TEST(Panorama, FlowOfATurningCameraShiftsTheRows) {
  const std::string json = R"({
    "camera": {"width": 72, "height": 36, "projection": "equirectangular", "spp": 1},
    "environment": {"color": 0.5},
    "animation": {"frames": 2, "tracks": [
      {"target": "camera", "property": "rotation", "keys": [[0, [0, 0, 0]], [1, [0, 10, 0]]]}]}})";
  const test::FlowRender r = test::renderFlow(json);
  const float shift = 72.0f * 10.0f / 360.0f;
  for (uint32_t y = 2; y < 34; ++y)  // away from the poles, where longitude is undefined
    for (uint32_t x = 0; x < 72; ++x) {
      ASSERT_NEAR(r.at("flow", x, y, 0), shift, 1e-3f) << x << "," << y;
      ASSERT_NEAR(r.at("flow", x, y, 1), 0.0f, 1e-3f) << x << "," << y;
    }
}

// Inside a ball of radius 5 about the camera, the panorama's depth and distance are 5 in every
// pixel, behind the camera too (a perspective camera's z-depth would be negative there).
TEST(Panorama, DepthIsTheDistance) {
  const SceneData data = test::loadTestScene(R"({
    "camera": {"width": 32, "height": 16, "projection": "equirectangular", "position": [1, 1, 1],
               "spp": 2},
    "spheres": [{"position": [1, 1, 1], "radius": 5, "color": 0.5}],
    "lights": [{"position": [1, 1, 1], "intensity": 10}]})");
  RenderOptions options;
  options.aovs = true;
  const RenderResult r = renderCpu(data.view(), options);
  const std::vector<ImageLayer> layers =
      makeAovLayers(data, parseAovList("depth,distance"), r.aovs);
  for (const ImageLayer& layer : layers)
    for (const float v : layer.pixels) ASSERT_NEAR(v, 5.0f, 1e-4f) << layer.name;
}

// The camera's matrices name the projection in place of K; given back, the camera is the same.
TEST(Panorama, CameraMatricesNameTheProjection) {
  const SceneDesc desc = parseSceneText(
      R"({"camera": {"width": 32, "height": 16, "projection": "equirectangular",
                     "position": [1, 2, 3], "look_at": [0, 0, 0]}})",
      "test.json", ".");
  const CameraMatrices m = cameraMatrices(desc.camera, desc.file);
  EXPECT_EQ(m.projection, CameraProjection::Equirectangular);
  EXPECT_TRUE(m.distortion.empty());
}

std::string cameraError(const std::string& camera, const std::string& more = "") {
  return test::loadError(R"({"camera": {"width": 64, "height": 32, )" + camera + "}" + more + "}",
                         ".");
}

TEST(Panorama, RefusesWhatAPanoramaDoesNotUse) {
  EXPECT_EQ(cameraError(R"("projection": "equirectangular", "fov": 90)"),
            "test.json: camera.fov: not used by an equirectangular camera (its image spans every "
            "direction)");
  EXPECT_EQ(cameraError(R"("projection": "equirectangular", "aperture_radius": 0.1)"),
            "test.json: camera.aperture_radius: not used by an equirectangular camera (its image "
            "spans every direction)");
  EXPECT_EQ(cameraError(R"("projection": "equirectangula")"),
            "test.json: camera.projection: expected one of \"perspective\", \"equirectangular\", "
            "\"fisheye\", \"orthographic\", got a string \"equirectangula\", did you mean "
            "\"equirectangular\"?");
  EXPECT_EQ(cameraError(R"("projection": "equirectangular")",
                        test::oneTrack("camera", "fov", "[[0, 40], [2, 50]]")),
            "test.json: animation.tracks[0].property: \"fov\" is not used by an equirectangular "
            "camera");
}

}  // namespace
}  // namespace candela
