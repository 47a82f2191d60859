// Camera conventions: a world point projected by the contract's own definitions (K and E, or
// fov and Euler rotations) must land where the renderer's camera rays go.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/constants.h"
#include "render/camera_ray.h"
#include "render_test_util.h"
#include "scene/camera_resolve.h"
#include "scene/read/scene_loader.h"

namespace candela {
namespace {

struct Projection {
  double u, v;
};

// Distance from point x to the camera ray through pixel position (u, v).
double rayMiss(const Camera& cam, Projection px, const Vec3& x) {
  const Ray r = generateCameraRay(cam, float(px.u), float(px.v), 0.5f, 0.5f);
  const Vec3 toX = x - r.origin;
  const Vec3 perpendicular = toX - r.direction * dot(toX, r.direction);
  EXPECT_GT(dot(toX, r.direction), 0.0f) << "point behind the camera";
  return length(perpendicular);
}

Camera cameraOf(const std::string& cameraJson) {
  const SceneDesc d = parseSceneText(R"({"camera": )" + cameraJson + "}", "cam.json", ".");
  return resolveCamera(d.camera, "cam.json");
}

TEST(CameraConventions, FovCameraAtZ55LooksAtOrigin) {
  const Camera cam = cameraOf(R"({"width": 64, "height": 48, "fov": 60, "position": [0, 0, 55]})");
  const double f = 64 / (2 * std::tan(kPi / 6));
  for (const Vec3 x : {Vec3(0, 0, 0), Vec3(10, 5, -3), Vec3(-7, -9, 20)}) {
    // +x right and +y up in the image: v grows downwards.
    const Projection p{32 + f * x.x / (55 - x.z), 24 - f * x.y / (55 - x.z)};
    EXPECT_LT(rayMiss(cam, p, x), 1e-4 * 55) << x.x << " " << x.y << " " << x.z;
  }
}

TEST(CameraConventions, EulerRotationTurnsTheView) {
  // ry = 90: counter-clockwise seen from +y, so the view direction -z turns to -x and
  // "right" (+x) turns to -z.
  const Camera cam = cameraOf(R"({"width": 50, "height": 50, "fov": 90, "rotation": [0, 90, 0]})");
  const Vec3 x(-10, 2, -3);  // 10 ahead, 3 to the right, 2 up
  const double f = 25;       // fov 90 on 50 pixels
  EXPECT_LT(rayMiss(cam, {25 + f * 3 / 10, 25 - f * 2 / 10}, x), 1e-4 * 10);
}

TEST(CameraConventions, LookAtWithUp) {
  const Camera cam = cameraOf(
      R"({"width": 40, "height": 30, "fov": 45, "position": [5, 0, 0], "look_at": [0, 0, 0]})");
  // Looking along -x with +y up: right is -z.
  const double f = 40 / (2 * std::tan(kPi / 8));
  const Vec3 x(0, 1, -1.5);
  EXPECT_LT(rayMiss(cam, {20 + f * 1.5 / 5, 15 - f * 1 / 5}, x), 1e-4 * 5);
}

TEST(CameraConventions, IntrinsicsAndOpenCvExtrinsicsNonSquare) {
  // A general rotation (about y by 30 degrees, then x by -10) and translation; K with fx != fy.
  const double a = 30 * kPi / 180, b = -10 * kPi / 180;
  const double ry[3][3] = {{std::cos(a), 0, std::sin(a)}, {0, 1, 0}, {-std::sin(a), 0, std::cos(a)}};
  const double rx[3][3] = {{1, 0, 0}, {0, std::cos(b), -std::sin(b)}, {0, std::sin(b), std::cos(b)}};
  double R[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      R[i][j] = 0;
      for (int k = 0; k < 3; ++k) R[i][j] += rx[i][k] * ry[k][j];
    }
  const double t[3] = {0.5, -1.0, 12.0};
  char json[1024];
  std::snprintf(json, sizeof json,
                R"({"width": 80, "height": 50, "intrinsics": {"fx": 60, "fy": 75, "cx": 41.5, "cy": 23},
                    "extrinsics": [[%.12g, %.12g, %.12g, %.12g], [%.12g, %.12g, %.12g, %.12g],
                                   [%.12g, %.12g, %.12g, %.12g], [0, 0, 0, 1]]})",
                R[0][0], R[0][1], R[0][2], t[0], R[1][0], R[1][1], R[1][2], t[1], R[2][0], R[2][1],
                R[2][2], t[2]);
  const Camera cam = cameraOf(json);
  for (const Vec3 x : {Vec3(0, 0, 0), Vec3(1, 2, -3), Vec3(-2, -1, 1)}) {
    double xc[3];
    for (int i = 0; i < 3; ++i) xc[i] = R[i][0] * x.x + R[i][1] * x.y + R[i][2] * x.z + t[i];
    const Projection p{60 * xc[0] / xc[2] + 41.5, 75 * xc[1] / xc[2] + 23};
    EXPECT_LT(rayMiss(cam, p, x), 1e-4 * 12) << x.x << " " << x.y << " " << x.z;
  }
}

TEST(CameraConventions, IntrinsicsAsMatrixEqualsObjectForm) {
  const Camera a = cameraOf(R"({"width": 64, "height": 32, "intrinsics": {"fx": 50, "fy": 40, "cx": 30, "cy": 17}})");
  const Camera b = cameraOf(R"({"width": 64, "height": 32, "intrinsics": [[50, 0, 30], [0, 40, 17], [0, 0, 1]]})");
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_FLOAT_EQ(a.inverseK.m[i][j], b.inverseK.m[i][j]);
}

// End to end: a small emitter at a world point shows up at the pixel the projection predicts,
// in a non-square image.
TEST(CameraConventions, RenderedEmitterLandsOnProjectedPixel) {
  const Vec3 x(3, -2, -4);
  const std::string scene = R"({
    "camera": {"width": 80, "height": 40, "fov": 60, "position": [0, 0, 20], "spp": 1},
    "render": {"antialiasing": false},
    "spheres": [{"position": [3, -2, -4], "radius": 0.15,
                 "material": {"type": "emissive", "radiance": 5}}]})";
  const RenderResult r = test::renderTestScene(scene);
  uint32_t bx = 0, by = 0;
  float best = -1;
  for (uint32_t y = 0; y < 40; ++y)
    for (uint32_t xx = 0; xx < 80; ++xx)
      if (r.image.at(xx, y).x > best) best = r.image.at(xx, y).x, bx = xx, by = y;
  const double f = 80 / (2 * std::tan(kPi / 6));
  const double u = 40 + f * x.x / (20 - x.z), v = 20 - f * x.y / (20 - x.z);
  EXPECT_EQ(best, 5.0f);
  EXPECT_LE(std::fabs(bx + 0.5 - u), 1.0);
  EXPECT_LE(std::fabs(by + 0.5 - v), 1.0);
}

CameraMatrices matricesOf(const std::string& cameraJson) {
  const SceneDesc d = parseSceneText(R"({"camera": )" + cameraJson + "}", "cam.json", ".");
  return cameraMatrices(d.camera, "cam.json");
}

// The matrices a camera file holds (docs/aovs.md) project a world point to where the renderer's
// ray through that pixel passes: u ~ K (R x + t), for every way of writing a camera.
TEST(CameraMatrices, ProjectWorldPointsWhereTheRaysGo) {
  for (const char* json :
       {R"({"width": 64, "height": 48, "fov": 60, "position": [0, 0, 55]})",
        R"({"width": 50, "height": 40, "fov": 90, "position": [6, 1, 0.5], "rotation": [10, 90, -20]})",
        R"({"width": 40, "height": 30, "fov": 45, "position": [5, 1, 2], "look_at": [0, 0, 0],
            "up": [0, 0, 1]})",
        R"({"width": 80, "height": 50, "intrinsics": {"fx": 60, "fy": 75, "cx": 41.5, "cy": 23},
            "position": [0, 0, 9], "look_at": [1, 0, 0]})",
        R"({"width": 32, "height": 32, "fov": 40, "position": [0, 0, 9], "aperture_radius": 0.5,
            "focus_distance": 9})"}) {
    const Camera cam = cameraOf(json);
    const CameraMatrices m = matricesOf(json);
    EXPECT_EQ(m.width, cam.width);
    EXPECT_EQ(m.height, cam.height);
    for (int i = 0; i < 3; ++i) {  // the files print -0 as 0
      EXPECT_FALSE(m.translation[i] == 0.0f && std::signbit(m.translation[i])) << json;
      for (int j = 0; j < 3; ++j)
        EXPECT_FALSE(m.rotation.m[i][j] == 0.0f && std::signbit(m.rotation.m[i][j])) << json;
    }
    for (const Vec3 x : {Vec3(0, 0, 0), Vec3(0.5f, 1, -0.3f), Vec3(-1, -0.5f, 0.8f)}) {
      const Vec3 xc = m.rotation * x + m.translation;
      const Vec3 p = m.intrinsics * xc;
      ASSERT_GT(xc.z, 0.0f) << json;
      EXPECT_LT(rayMiss(cam, {p.x / p.z, p.y / p.z}, x), 1e-4 * (1 + length(x - cam.position)))
          << json << " at " << x.x << " " << x.y << " " << x.z;
    }
  }
}

TEST(CameraMatrices, GiveBackTheExtrinsicsAndLensAsWritten) {
  const CameraMatrices m = matricesOf(
      R"({"width": 20, "height": 10, "intrinsics": [[30, 0, 10], [0, 31, 5], [0, 0, 1]],
          "extrinsics": [[0, 0, 1, 0.5], [1, 0, 0, -2], [0, 1, 0, 7], [0, 0, 0, 1]],
          "aperture_radius": 0.25, "focus_distance": 6})");
  const float r[3][3] = {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}}, t[3] = {0.5f, -2, 7};
  const float k[3][3] = {{30, 0, 10}, {0, 31, 5}, {0, 0, 1}};
  for (int i = 0; i < 3; ++i) {
    EXPECT_FLOAT_EQ(m.translation[i], t[i]);
    for (int j = 0; j < 3; ++j) {
      EXPECT_EQ(m.rotation.m[i][j], r[i][j]);
      EXPECT_EQ(m.intrinsics.m[i][j], k[i][j]);
    }
  }
  EXPECT_EQ(m.apertureRadius, 0.25f);
  EXPECT_EQ(m.focusDistance, 6.0f);
  // A pinhole has no lens to report.
  const CameraMatrices pinhole = matricesOf(R"({"fov": 40, "position": [0, 0, 3]})");
  EXPECT_EQ(pinhole.apertureRadius, 0.0f);
  EXPECT_EQ(pinhole.focusDistance, 0.0f);
}

}  // namespace
}  // namespace candela
