// A camera from a glTF file ("gltf" in the scene's camera): the pose of the camera node that the
// file's scene places, under its parents' transforms, and its vertical field of view, against
// the same camera given by position, look_at, up and the horizontal field of view that the
// test's own arithmetic finds; the refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "gltf_test_util.h"
#include "render/camera_ray.h"
#include "render_test_util.h"
#include "scene/read/scene_loader.h"
#include "scene/scene_error.h"
#include "temp_dir.h"

namespace candela {
namespace {

using test::GltfFile;
using test::TempDir;

constexpr double kPiD = 3.14159265358979323846;

// A triangle to see, and a camera node (yfov 0.6 rad) under a parent: the parent moved by
// (1, 2, 3) and turned 30 degrees about y, the camera moved by (0, 0.5, 4) and turned -10 degrees
// about x.
GltfFile cameraFile(const std::string& type = "perspective") {
  GltfFile f;
  const int p = f.addFloats({-1, -1, 0, 1, -1, 0, 0, 1, 0}, "VEC3", 3);
  f.doc["meshes"] = nlohmann::json::array(
      {nlohmann::json{{"primitives", {nlohmann::json{{"attributes", {{"POSITION", p}}}}}}}});
  f.doc["cameras"] = nlohmann::json::array(
      {type == "perspective"
           ? nlohmann::json{{"type", type}, {"perspective", {{"yfov", 0.6}, {"znear", 0.01}}}}
           : nlohmann::json{
                 {"type", type},
                 {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"znear", 0.01}, {"zfar", 10}}}}});
  const double b = 15.0 * kPiD / 180.0, a = -5.0 * kPiD / 180.0;
  f.doc["nodes"] =
      nlohmann::json::array({nlohmann::json{{"mesh", 0}},
                             nlohmann::json{{"translation", {1, 2, 3}},
                                            {"rotation", {0, std::sin(b), 0, std::cos(b)}},
                                            {"children", {2}}},
                             nlohmann::json{{"camera", 0},
                                            {"translation", {0, 0.5, 4}},
                                            {"rotation", {std::sin(a), 0, 0, std::cos(a)}}}});
  f.doc["scenes"] = nlohmann::json::array({nlohmann::json{{"nodes", {0, 1}}}});
  return f;
}

std::string vec(double x, double y, double z) {
  return "[" + test::num(x) + ", " + test::num(y) + ", " + test::num(z) + "]";
}

TEST(GltfCamera, TheCameraNodeSeesAsTheSameCameraByLookAt) {
  TempDir dir;
  dir.write("cam.gltf", cameraFile().gltf());
  const SceneData fromFile = test::loadTestScene(
      R"({"camera": {"width": 40, "height": 30, "gltf": "cam.gltf"}})", dir.path());
  // The camera's place: the parent's turn (30 degrees about y) of (0, 0.5, 4), moved by (1, 2,
  // 3); it looks along the turns of -z, -10 degrees about x then 30 about y, with their +y up.
  const double cb = std::cos(kPiD / 6), sb = std::sin(kPiD / 6);
  const double ca = std::cos(-kPiD / 18), sa = std::sin(-kPiD / 18);
  const auto turnY = [&](double x, double y, double z) {
    return std::array<double, 3>{cb * x + sb * z, y, -sb * x + cb * z};
  };
  const auto position = turnY(0, 0.5, 4);
  const double px = position[0] + 1, py = position[1] + 2, pz = position[2] + 3;
  const auto forward = turnY(0, sa, -ca), up = turnY(0, ca, sa);
  const double fov = 2 * std::atan(std::tan(0.3) * 40 / 30) * 180 / kPiD;
  const SceneData byLookAt = test::loadTestScene(
      R"({"camera": {"width": 40, "height": 30, "position": )" + vec(px, py, pz) +
      R"(, "look_at": )" + vec(px + forward[0], py + forward[1], pz + forward[2]) + R"(, "up": )" +
      vec(up[0], up[1], up[2]) + R"(, "fov": )" + test::num(fov) + "}}");
  const Camera& a = fromFile.view().camera;
  const Camera& b = byLookAt.view().camera;
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(a.position[i], b.position[i], 1e-5);
    for (int j = 0; j < 3; ++j) {
      EXPECT_NEAR(a.cameraToWorld.m[i][j], b.cameraToWorld.m[i][j], 1e-5);
      EXPECT_NEAR(a.inverseK.m[i][j], b.inverseK.m[i][j], 1e-6);
    }
  }
  // Not the identity: the test tells poses apart.
  EXPECT_GT(std::fabs(a.cameraToWorld.m[0][2]), 0.3f);
}

// An object of a file with cameras gets a warning that they are not used (once per file),
// unless the scene's camera takes one from that file, however its path is written.
TEST(GltfCamera, AFilesCamerasAreNamedUnlessTheSceneTakesOne) {
  TempDir dir;
  dir.write("cam.gltf", cameraFile().gltf());
  const std::string objects =
      R"(, "objects": [{"file": "cam.gltf"}, {"file": "cam.gltf", "position": [1, 0, 0]}]})";
  const SceneDesc unused =
      parseSceneText(R"({"camera": {"width": 4, "height": 4})" + objects, "test.json", dir.path());
  EXPECT_EQ(unused.warnings,
            std::vector<std::string>{
                "test.json: objects[0].file: cam.gltf: the file's cameras are not used (the "
                "scene's camera takes one with \"gltf\")"});
  const SceneDesc taken =
      parseSceneText(R"({"camera": {"width": 4, "height": 4, "gltf": "./cam.gltf"})" + objects,
                     "test.json", dir.path());
  EXPECT_TRUE(taken.warnings.empty());
}

// An orthographic camera (ymag 1) at the same node: an orthographic camera of the same pose whose
// image is 2 ymag high, its width following from the image's: every ray leaves the camera's
// plane where that camera's does, along its axis.
TEST(GltfCamera, AnOrthographicCameraKeepsItsHeight) {
  TempDir dir;
  dir.write("ortho.gltf", cameraFile("orthographic").gltf());
  dir.write("cam.gltf", cameraFile().gltf());
  const SceneData fromFile = test::loadTestScene(
      R"({"camera": {"width": 40, "height": 30, "gltf": "ortho.gltf"}})", dir.path());
  const SceneData perspective = test::loadTestScene(
      R"({"camera": {"width": 40, "height": 30, "gltf": "cam.gltf"}})", dir.path());
  const Camera& a = fromFile.view().camera;
  const Camera& pose = perspective.view().camera;
  EXPECT_EQ(a.projection, CameraProjection::Orthographic);
  for (const auto& [px, py] : {std::pair<float, float>{20, 15}, {0, 0}, {40, 30}, {10, 25}}) {
    const Ray ray = generateCameraRay(a, px, py, 0.5f, 0.5f);
    // 30 pixels span 2 units: (px - 20, py - 15) / 15 along the pose's right and down.
    const Vec3 expected = pose.position + pose.cameraToWorld.column(0) * ((px - 20.0f) / 15.0f) +
                          pose.cameraToWorld.column(1) * ((py - 15.0f) / 15.0f);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(ray.origin[c], expected[c], 1e-5);
      EXPECT_NEAR(ray.direction[c], pose.cameraToWorld.column(2)[c], 1e-6);
    }
  }
}

TEST(GltfCamera, RefusesWhatItCannotTake) {
  TempDir dir;
  dir.write("cam.gltf", cameraFile().gltf());
  dir.write("ortho.gltf", cameraFile("orthographic").gltf());
  const auto error = [&](const std::string& camera, const std::string& more = "") {
    return test::loadError(R"({"camera": )" + camera + more + "}", dir.path());
  };
  EXPECT_EQ(error(R"({"gltf": "cam.gltf", "gltf_camera": 1})"),
            "test.json: camera.gltf: cam.gltf: camera 1 is asked for, but the file's scene "
            "places 1 camera");
  GltfFile flat = cameraFile("orthographic");
  flat.doc["cameras"][0]["orthographic"]["ymag"] = -1;
  dir.write("flat.gltf", flat.gltf());
  EXPECT_EQ(error(R"({"gltf": "flat.gltf"})"),
            "test.json: camera.gltf: flat.gltf: cameras[0].orthographic.ymag: expected a positive "
            "number, got -1");
  EXPECT_EQ(error(R"({"gltf_camera": 0})"),
            "test.json: camera.gltf_camera: not used without \"gltf\"");
  EXPECT_NE(error(R"({"gltf": "cam.gltf", "position": [0, 0, 0]})").find("\"gltf\""),
            std::string::npos);
  EXPECT_EQ(error(R"({"gltf": "cam.gltf"})",
                  R"(, "animation": {"frames": 2, "tracks": [{"target": "camera", "property":
                     "position", "keys": [[0, [0, 0, 0]], [1, [0, 0, 1]]]}]})"),
            "test.json: animation.tracks[0].property: \"position\" is not used by a camera taken "
            "from a glTF file (\"gltf\")");
  GltfFile far = cameraFile();
  far.doc["nodes"][2]["translation"] = {0, 0, 1e200};
  dir.write("far.gltf", far.gltf());
  EXPECT_EQ(error(R"({"gltf": "far.gltf"})"),
            "test.json: camera.gltf: far.gltf: nodes[2].camera: the camera's place is beyond "
            "reach");
  EXPECT_EQ(error(R"({"gltf": "gone.gltf"})"),
            "test.json: camera.gltf: cannot open \"gone.gltf\" (No such file or directory)");
}

}  // namespace
}  // namespace candela
