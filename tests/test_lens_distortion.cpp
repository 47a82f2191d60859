// Lens distortion (render/lens_distortion.h): a camera with OpenCV's distortion coefficients
// renders what that calibrated camera sees. Checked against the test's own OpenCV projection
// (cv::projectPoints' formulas, in double): each camera ray, and each pixel's first hit in the
// position pass, projects back onto the pixel; the flow pass of a camera sliding past a plane
// moves each point by the difference of its two projections. Then the refusals: a malformed list,
// and a lens that folds the image over itself.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "flow_test_util.h"
#include "render/camera_ray.h"
#include "render_test_util.h"

namespace fs = std::filesystem;

namespace candela {
namespace {

using test::num;

// A 160 x 120 camera with a skewed K, at `position` looking down -z (OpenCV's +z), whose lens has
// the rational model's coefficients below.
constexpr double kFx = 150, kFy = 140, kSkew = 0.5, kCx = 83, kCy = 57;
constexpr std::array<double, 8> kCoefficients = {-0.28, 0.09, 0.0015, -0.002,
                                                 -0.01, 0.02, 0.003,  0.001};

std::string distortedCamera(const std::string& more = "") {
  std::string list;
  for (double k : kCoefficients) list += (list.empty() ? "" : ", ") + num(k);
  return R"("camera": {"width": 160, "height": 120, "rotation": [0, 0, 0],
                       "intrinsics": [[)" +
         num(kFx) + ", " + num(kSkew) + ", " + num(kCx) + "], [0, " + num(kFy) + ", " + num(kCy) +
         R"(], [0, 0, 1]], "distortion": [)" + list + "]" + more + "}";
}

// OpenCV's projection of camera-space point c (x right, y down, z forward) to a pixel.
std::array<double, 2> projectOpenCv(const std::array<double, 3>& c) {
  const double x = c[0] / c[2], y = c[1] / c[2], r2 = x * x + y * y;
  const auto& k = kCoefficients;  // k1 k2 p1 p2 k3 k4 k5 k6
  const double radial = (1 + k[0] * r2 + k[1] * r2 * r2 + k[4] * r2 * r2 * r2) /
                        (1 + k[5] * r2 + k[6] * r2 * r2 + k[7] * r2 * r2 * r2);
  const double xd = x * radial + 2 * k[2] * x * y + k[3] * (r2 + 2 * x * x);
  const double yd = y * radial + k[2] * (r2 + 2 * y * y) + 2 * k[3] * x * y;
  return {kFx * xd + kSkew * yd + kCx, kFy * yd + kCy};
}

// Every camera ray, over a grid of points of the image and just beyond it, leaves towards what
// OpenCV projects back onto its pixel (to a thousandth of a pixel; float rounding alone).
TEST(LensDistortion, RaysProjectBackOntoTheirPixels) {
  const SceneData data = test::loadTestScene("{" + distortedCamera() + "}");
  const Camera& camera = data.view().camera;
  ASSERT_TRUE(camera.distortion.enabled);
  double worst = 0;
  for (float py = -1.0f; py <= 121.0f; py += 2.75f)
    for (float px = -1.0f; px <= 161.0f; px += 3.25f) {
      const Ray ray = generateCameraRay(camera, px, py, 0.5f, 0.5f);
      const std::array<double, 2> back =
          projectOpenCv(test::unturnedCameraSpace(ray.origin + ray.direction));
      worst = std::max(worst, std::hypot(back[0] - px, back[1] - py));
    }
  EXPECT_LT(worst, 1e-3);
  // The lens is really undone: K^-1 alone would send the corner's ray where OpenCV sees pixels
  // away from it.
  const Vec3 plain = camera.inverseK * Vec3(0.0f, 0.0f, 1.0f);
  const std::array<double, 2> unbent = projectOpenCv({plain.x, plain.y, plain.z});
  EXPECT_GT(std::hypot(unbent[0], unbent[1]), 3.0);
}

// The renderer uses the lens: with antialiasing off each pixel's samples pass through its
// centre, so the position pass holds the plane's point there, and OpenCV projects it back onto the
// centre. The camera then slides by (0.3, 0.2, 0) before the plane: the flow pass moves each
// point by its projection from the second camera less that from the first.
TEST(LensDistortion, PositionsAndFlowFollowTheLens) {
  const fs::path dir = fs::temp_directory_path() / "candela_lens_distortion";
  const test::FlowRender r = test::renderFlow(
      "{" + distortedCamera(R"(, "spp": 1)") + "," + test::kCameraSlidingPastTheQuad + "}", 0,
      test::writeQuad(dir));
  const test::SlidingCameraErrors e = test::slidingCameraErrors(r, 160, 120, projectOpenCv);
  EXPECT_EQ(e.seen, 160 * 120);
  EXPECT_LT(e.position, 2e-3);
  EXPECT_LT(e.flow, 2e-3);
  fs::remove_all(dir);
}

std::string cameraError(const std::string& camera) {
  return test::loadError(R"({"camera": {"width": 640, "height": 480, "fov": 90, )" + camera + "}}",
                         ".");
}

TEST(LensDistortion, RefusesALensItCannotUndo) {
  EXPECT_EQ(cameraError(R"("distortion": [0.1, 0.2, 0])"),
            "test.json: camera.distortion: expected OpenCV's distortion coefficients, an array "
            "[k1, k2, p1, p2], [k1, k2, p1, p2, k3] or [k1, k2, p1, p2, k3, k4, k5, k6], got an "
            "array [0.1,0.2,0]");
  EXPECT_EQ(cameraError(R"("distortion": [0.1, "a", 0, 0])"),
            "test.json: camera.distortion[1]: expected a number, got a string \"a\"");
  // Barrel distortion this strong turns back at r = 1 / sqrt(3 * 0.3), inside a 90-degree view
  // (its corners at r = 1.25).
  EXPECT_EQ(cameraError(R"("distortion": [-0.3, 0, 0, 0])"),
            "test.json: camera.distortion: folds the image over itself near pixel (0, 0), where "
            "no direction or more than one would reach a pixel; expected coefficients whose "
            "distortion grows steadily out to the image's corners");
  // The same lens on a narrow view is fine; so are all-zero coefficients (no lens at all).
  EXPECT_EQ(test::loadError(R"({"camera": {"width": 640, "height": 480, "fov": 40,
                                           "distortion": [-0.3, 0, 0, 0]}})",
                            "."),
            "(no error)");
  EXPECT_FALSE(test::loadTestScene(R"({"camera": {"distortion": [0, 0, 0, 0, 0]}})")
                   .view()
                   .camera.distortion.enabled);
}

}  // namespace
}  // namespace candela
