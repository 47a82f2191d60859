// Objects placed by a "transform" matrix: read back as the position, rotation and scale whose
// product is the matrix (mirroring and at gimbal lock too), Euler angles recovered from any
// rotation, a glowing cube posed by a matrix covering the outline the matrix gives it, and the
// refusals (a shear, a singular block, a projective row, a matrix beside a position). Cameras
// posed by their camera-to-world matrix (Blender's axes) cast the rays of the same pose given by
// position and rotation.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "core/rotation.h"
#include "render/camera_ray.h"
#include "render_test_util.h"

namespace candela {
namespace {

using test::num;

double largestDifference(const Mat3& a, const Mat3& b) {
  double worst = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) worst = std::max(worst, double(std::fabs(a.m[i][j] - b.m[i][j])));
  return worst;
}

// Rotations from random angles, and at and near y = +-90 degrees where x and z turn about one
// axis: the angles found give the rotation back to rounding.
TEST(ObjectTransform, EulerAnglesGiveTheirRotationBack) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> angle(-180.0f, 180.0f);
  std::vector<Vec3> cases = {Vec3(0, 90, 0),         Vec3(30, 90, -50), Vec3(-120, -90, 10),
                             Vec3(10, 89.99f, 5),    Vec3(0, 0, 0),     Vec3(180, 0, 180),
                             Vec3(45, -89.999f, 170)};
  for (int i = 0; i < 200; ++i) cases.push_back(Vec3(angle(rng), angle(rng) / 2, angle(rng)));
  for (const Vec3& degrees : cases) {
    const Mat3 r = eulerRotation(degrees);
    EXPECT_LT(largestDifference(eulerRotation(eulerDegrees(r)), r), 1e-6)
        << degrees.x << " " << degrees.y << " " << degrees.z;
  }
}

// The rows of [linear | t] as the scene writes them.
std::string rows(const Mat3& linear, Vec3 t, bool fourth) {
  std::string text = "[";
  for (int i = 0; i < 3; ++i)
    text += std::string(i ? ", " : "") + "[" + num(linear.m[i][0]) + ", " + num(linear.m[i][1]) +
            ", " + num(linear.m[i][2]) + ", " + num(t[i]) + "]";
  return text + (fourth ? ", [0, 0, 0, 1]]" : "]");
}

ObjectDesc loadedObject(const std::string& object) {
  const SceneDesc scene = parseSceneText(
      R"({"camera": {"width": 4, "height": 4}, "objects": [)" + object + "]}", "s.json", ".");
  return scene.objects.at(0);
}

TEST(ObjectTransform, ReadsAsThePlacementWhoseProductIsTheMatrix) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> angle(-180.0f, 180.0f), size(0.1f, 5.0f);
  std::vector<Mat3> linears = {eulerRotation(Vec3(20, 90, 35)) * Mat3::diagonal(Vec3(1, 2, 3)),
                               Mat3::diagonal(Vec3(-1, 1, 1)),  // a mirror
                               eulerRotation(Vec3(0, 0, 90)) * Mat3::diagonal(Vec3(2, -0.5f, 4))};
  for (int i = 0; i < 50; ++i)
    linears.push_back(eulerRotation(Vec3(angle(rng), angle(rng) / 2, angle(rng))) *
                      Mat3::diagonal(Vec3(size(rng), size(rng), i % 2 ? -size(rng) : size(rng))));
  for (size_t i = 0; i < linears.size(); ++i) {
    const Vec3 t(0.5f * i, -3.0f, 1e3f);
    const ObjectDesc o =
        loadedObject(R"({"shape": "cube", "transform": )" + rows(linears[i], t, i % 2) + "}");
    const Mat3 placed = eulerRotation(o.rotation) * Mat3::diagonal(o.scale);
    double scale = 0;
    for (int j = 0; j < 3; ++j) scale = std::max(scale, double(std::fabs(o.scale[j])));
    EXPECT_LT(largestDifference(placed, linears[i]), 1e-6 * scale) << i;
    EXPECT_EQ(o.position.x, t.x);
    EXPECT_EQ(o.position.y, t.y);
    EXPECT_EQ(o.position.z, t.z);
  }
}

// Object x to world y, object y doubled to world -x, moved 1 along x: a glowing unit cube seen
// from the front covers 2 x 1 about (1, 0). 32 x 32 pixels over 4 x 4 units, pixel centres only.
TEST(ObjectTransform, AGlowingCubeCoversTheOutlineItsMatrixGives) {
  const RenderResult r = test::renderTestScene(R"({
      "camera": {"width": 32, "height": 32, "projection": "orthographic", "view_width": 4,
                 "position": [0, 0, 5], "spp": 1},
      "render": {"antialiasing": false, "max_depth": 1},
      "objects": [{"shape": "cube", "material": {"type": "emissive", "radiance": 1},
                   "transform": [[0, -2, 0, 1], [1, 0, 0, 0], [0, 0, 1, 0]]}]})");
  int seen = 0;
  for (uint32_t y = 0; y < 32; ++y)
    for (uint32_t x = 0; x < 32; ++x) {
      const double a = (x + 0.5 - 16) / 8, b = -(y + 0.5 - 16) / 8;
      const bool inside = std::fabs(a - 1) < 1 && std::fabs(b) < 0.5;
      seen += inside;
      ASSERT_EQ(r.image.at(x, y)[0], inside ? 1.0f : 0.0f) << x << "," << y;
    }
  EXPECT_EQ(seen, 16 * 8);
}

std::string transformError(const std::string& object) {
  return test::loadError(R"({"camera": {"width": 4, "height": 4}, "objects": [)" + object + "]}",
                         ".");
}

TEST(ObjectTransform, RefusesWhatNoPlacementGives) {
  EXPECT_EQ(transformError(R"({"shape": "cube", "transform": [[1, 0.5, 0, 0], [0, 1, 0, 0],
                                                              [0, 0, 1, 0]]})"),
            "test.json: objects[0].transform: expected a rotation times a scale along the object's "
            "axes in the upper-left 3x3 block; its columns 1 and 2 are not at right angles (a "
            "shear, which an object cannot take), got an array [[1,0.5,0,0],[0,1,0,0],[0,0,1,0]]");
  EXPECT_EQ(
      transformError(R"({"shape": "cube", "transform": [[1, 0, 0, 0], [0, 0, 0, 0],
                                                              [0, 0, 1, 0]]})"),
      "test.json: objects[0].transform: expected a transform that keeps the object solid (the "
      "upper-left 3x3 block is singular, flattening it), got an array "
      "[[1,0,0,0],[0,0,0,0],[0,0,1,0]]");
  EXPECT_EQ(transformError(R"({"shape": "cube", "transform": [[1, 0, 0, 0], [0, 1, 0, 0],
                                                              [0, 0, 1, 0], [0, 0, 1, 1]]})"),
            "test.json: objects[0].transform[3]: expected [0, 0, 0, 1] (an affine transform), got "
            "an array [0,0,1,1]");
  EXPECT_EQ(transformError(R"({"shape": "cube", "transform": [[1, 0, 0], [0, 1, 0]]})"),
            "test.json: objects[0].transform: expected an object-to-world matrix: 3 rows of 4 "
            "numbers, [R S | t], and optionally [0, 0, 0, 1], got an array [[1,0,0],[0,1,0]]");
  EXPECT_EQ(
      transformError(R"({"shape": "cube", "transform": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]})"),
      "test.json: objects[0].transform[0]: expected a row of 4 numbers, got an array [1,0,0]");
  EXPECT_EQ(transformError(R"({"shape": "cube", "position": [0, 1, 0],
                               "transform": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]})"),
            "test.json: objects[0]: expected either \"transform\" or \"position\", got both");
}

// A camera given by its camera-to-world matrix casts, through every pixel, the ray of the camera
// at that position with that rotation; one at (0, 0, 5) turned 90 degrees about y looks down -x.
TEST(ObjectTransform, ACameraMatrixPosesTheCameraAsItsRotationAndPositionDo) {
  const Vec3 degrees(-25, 140, 10), position(1, 2, 3);
  const Mat3 r = eulerRotation(degrees);
  const std::string camera =
      R"({"width": 32, "height": 24, "fov": 50, "transform": )" + rows(r, position, true) + "}";
  const SceneData byMatrix = test::loadTestScene(R"({"camera": )" + camera + "}");
  const SceneData byAngles = test::loadTestScene(
      R"({"camera": {"width": 32, "height": 24, "fov": 50, "position": [1, 2, 3],
                     "rotation": [-25, 140, 10]}})");
  double worst = 0;
  for (float py = 0.5f; py < 24; py += 5.0f)
    for (float px = 0.5f; px < 32; px += 7.0f) {
      const Ray a = generateCameraRay(byMatrix.view().camera, px, py, 0.5f, 0.5f);
      const Ray b = generateCameraRay(byAngles.view().camera, px, py, 0.5f, 0.5f);
      for (int k = 0; k < 3; ++k)
        worst = std::max({worst, double(std::fabs(a.origin[k] - b.origin[k])),
                          double(std::fabs(a.direction[k] - b.direction[k]))});
    }
  EXPECT_LT(worst, 2e-6);
  const SceneData turned = test::loadTestScene(R"({"camera": {"width": 8, "height": 8,
      "transform": [[0, 0, 1, 0], [0, 1, 0, 0], [-1, 0, 0, 5]]}})");
  const Ray centre = generateCameraRay(turned.view().camera, 4.0f, 4.0f, 0.0f, 0.0f);
  EXPECT_NEAR(centre.direction.x, -1.0f, 1e-6f);
  EXPECT_NEAR(centre.origin.z, 5.0f, 1e-6f);
  EXPECT_EQ(test::loadError(R"({"camera": {"transform": [[2, 0, 0, 0], [0, 2, 0, 0],
                                                           [0, 0, 2, 0]]}})",
                            "."),
            "test.json: camera.transform: expected a rotation (orthonormal, determinant +1) in the "
            "upper-left 3x3 block: a camera takes no scale or mirror, got an array "
            "[[2,0,0,0],[0,2,0,0],[0,0,2,0]]");
  EXPECT_EQ(test::loadError(R"({"camera": {"look_at": [0, 0, 0], "transform": [[1, 0, 0, 0],
                                           [0, 1, 0, 0], [0, 0, 1, 5]]}})",
                            "."),
            "test.json: camera: expected either \"transform\" or \"look_at\", got both");
}

}  // namespace
}  // namespace candela
