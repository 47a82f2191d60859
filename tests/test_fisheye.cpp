// Fisheye cameras (render/fisheye.h): OpenCV's fisheye model, with the angle from the axis running
// past 90 degrees. Checked against the test's own cv::fisheye projection in double: each camera
// ray of a 200-degree lens, each pixel's first hit in the position pass, and the flow of a camera
// sliding past a plane; a field of view of 180 degrees puts the edges' middles square to the axis.
// Then the camera's matrices, and the refusals.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <string>

#include "core/constants.h"
#include "flow_test_util.h"
#include "render/camera_ray.h"
#include "render_test_util.h"
#include "scene/camera_resolve.h"

namespace fs = std::filesystem;

namespace candela {
namespace {

using test::num;

constexpr double kFx = 55, kFy = 53, kCx = 81, kCy = 59;
constexpr std::array<double, 4> kD = {0.03, -0.01, 0.002, -0.0004};

std::string fisheyeCamera(const std::string& more = "") {
  std::string list;
  for (double k : kD) list += (list.empty() ? "" : ", ") + num(k);
  return R"("camera": {"width": 160, "height": 120, "projection": "fisheye",
                       "intrinsics": {"fx": )" +
         num(kFx) + R"(, "fy": )" + num(kFy) + R"(, "cx": )" + num(kCx) + R"(, "cy": )" + num(kCy) +
         R"(}, "distortion": [)" + list + "]" + more + "}";
}

// cv::fisheye's projection of camera-space point c (x right, y down, z forward), with theta the
// angle from the axis (atan of r in front of the camera, and on past 90 degrees behind it).
std::array<double, 2> projectFisheye(const std::array<double, 3>& c) {
  const double rho = std::hypot(c[0], c[1]), theta = std::atan2(rho, c[2]), t2 = theta * theta;
  const double radius =
      theta * (1 + kD[0] * t2 + kD[1] * t2 * t2 + kD[2] * t2 * t2 * t2 + kD[3] * t2 * t2 * t2 * t2);
  return {kFx * radius * c[0] / rho + kCx, kFy * radius * c[1] / rho + kCy};
}

// The corners of this 160 x 120 image lie some 105 degrees from the axis, behind the camera's
// plane: every ray there, as everywhere, projects back onto its pixel.
TEST(Fisheye, RaysProjectBackOntoTheirPixels) {
  const SceneData data = test::loadTestScene("{" + fisheyeCamera() + "}");
  const Camera& camera = data.view().camera;
  ASSERT_EQ(camera.projection, CameraProjection::Fisheye);
  double worst = 0, widest = 0;
  for (float py = 0.0f; py <= 120.0f; py += 2.5f)
    for (float px = 0.0f; px <= 160.0f; px += 3.25f) {
      const Ray ray = generateCameraRay(camera, px, py, 0.5f, 0.5f);
      const std::array<double, 3> c = test::unturnedCameraSpace(ray.origin + ray.direction);
      const std::array<double, 2> back = projectFisheye(c);
      worst = std::max(worst, std::hypot(back[0] - px, back[1] - py));
      widest = std::max(widest, std::atan2(std::hypot(c[0], c[1]), c[2]) * 180 / kPi);
    }
  EXPECT_LT(worst, 2e-3);
  EXPECT_GT(widest, 100.0);
}

// An equidistant fisheye (no coefficients) whose fov is 180 degrees sees square to its axis at
// the middles of its left and right edges, and straight ahead at the centre.
TEST(Fisheye, AFieldOfViewOf180SeesSquareToTheAxisAtTheEdges) {
  const Camera camera =
      test::loadTestScene(
          R"({"camera": {"width": 100, "height": 60, "projection": "fisheye", "fov": 180}})")
          .view()
          .camera;
  const Vec3 forward(0.0f, 0.0f, -1.0f);  // rotation 0
  EXPECT_NEAR(dot(generateCameraRay(camera, 0.0f, 30.0f, 0.5f, 0.5f).direction, forward), 0.0f,
              1e-6f);
  EXPECT_NEAR(generateCameraRay(camera, 100.0f, 30.0f, 0.5f, 0.5f).direction.x, 1.0f, 1e-6f);
  EXPECT_NEAR(dot(generateCameraRay(camera, 50.0f, 30.0f, 0.5f, 0.5f).direction, forward), 1.0f,
              1e-6f);
}

// The renderer uses the lens: the position pass's point of each pixel projects back onto its
// centre, and the flow of the sliding camera is the difference of the two projections.
TEST(Fisheye, PositionsAndFlowFollowTheLens) {
  const fs::path dir = fs::temp_directory_path() / "candela_fisheye";
  const test::FlowRender r = test::renderFlow(
      "{" + fisheyeCamera(R"(, "spp": 1)") + "," + test::kCameraSlidingPastTheQuad + "}", 0,
      test::writeQuad(dir));
  const test::SlidingCameraErrors e = test::slidingCameraErrors(r, 160, 120, projectFisheye);
  EXPECT_GT(e.seen, 160 * 120 / 2);  // the rest lies beyond 90 degrees, behind the plane
  EXPECT_LT(e.position, 2e-3);
  EXPECT_LT(e.flow, 2e-3);
  fs::remove_all(dir);
}

TEST(Fisheye, CameraMatricesNameTheProjectionAndItsFourCoefficients) {
  const SceneDesc desc = parseSceneText("{" + fisheyeCamera() + "}", "test.json", ".");
  const CameraMatrices m = cameraMatrices(desc.camera, desc.file);
  EXPECT_EQ(m.projection, CameraProjection::Fisheye);
  ASSERT_EQ(m.distortion.size(), 4u);
  EXPECT_FLOAT_EQ(m.distortion[3], float(kD[3]));
  EXPECT_FLOAT_EQ(m.intrinsics.m[0][0], float(kFx));
}

std::string cameraError(const std::string& camera) {
  return test::loadError(
      R"({"camera": {"width": 64, "height": 64, "projection": "fisheye", )" + camera + "}}", ".");
}

TEST(Fisheye, RefusesALensItCannotUndo) {
  EXPECT_EQ(cameraError(R"("distortion": [0.1, 0, 0, 0, 0])"),
            "test.json: camera.distortion: expected OpenCV's fisheye coefficients, an array [k1, "
            "k2, k3, k4], got an array [0.1,0,0,0,0]");
  EXPECT_EQ(cameraError(R"("fov": 400)"),
            "test.json: camera.fov: expected a number above 0 and at most 360, got 400");
  EXPECT_EQ(cameraError(R"("aperture_radius": 0.1)"),
            "test.json: camera.aperture_radius: not used by a fisheye camera (a pinhole's)");
  // 360 degrees across the width reach past straight behind in the corners.
  EXPECT_EQ(cameraError(R"("fov": 360)"),
            "test.json: camera.fov: sees past straight behind the camera at pixel (0, 0) (180 "
            "degrees from its axis, where directions would repeat); expected a narrower view");
  // Coefficients whose image radius turns back (at 60 degrees) before the corners.
  EXPECT_EQ(cameraError(R"("fov": 170, "distortion": [-0.3, 0, 0, 0])"),
            "test.json: camera.distortion: folds the image over itself near pixel (0, 0), where "
            "no direction or more than one would reach a pixel; expected coefficients whose "
            "distortion grows steadily out to the image's corners");
  EXPECT_EQ(cameraError(R"("fov": 180)"), "(no error)");
  // A fisheye's fov track may go past 180 degrees too, and is checked at every frame.
  EXPECT_EQ(test::loadError(R"({"camera": {"width": 64, "height": 64, "projection": "fisheye"},
      "animation": {"frames": 3, "tracks": [
        {"target": "camera", "property": "fov", "keys": [[0, 170], [2, 361]]}]}})",
                            "."),
            "test.json: animation.tracks[0].keys[1][1]: expected a number above 0 and at most "
            "360, got 361");
  EXPECT_EQ(test::loadError(R"({"camera": {"width": 64, "height": 64, "projection": "fisheye"},
      "animation": {"frames": 3, "tracks": [
        {"target": "camera", "property": "fov", "keys": [[0, 170], [2, 200]]}]}})",
                            "."),
            "(no error)");
}

}  // namespace
}  // namespace candela
