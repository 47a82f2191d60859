// A camera that follows a glTF file's animation ("gltf_animation"): at frame k of the scene's
// animation its pose is its node's at k / fps seconds, the file's LINEAR (spherical for
// rotations), STEP and CUBICSPLINE samplers against the test's own arithmetic, held past the last
// key; the refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "gltf_test_util.h"
#include "render_test_util.h"
#include "scene/animation.h"
#include "scene/camera_resolve.h"
#include "scene/read/gltf_animation.h"
#include "scene/read/gltf_camera.h"
#include "scene/read/gltf_file.h"
#include "scene/read/scene_loader.h"
#include "temp_dir.h"

namespace candela {
namespace {

using test::GltfFile;
using test::TempDir;

constexpr double kPiD = 3.14159265358979323846;

// A camera node at (0, 0, 5) under a parent at (1, 2, 3), and three animations of it over one
// second: "fly" moves it to (2, 0, 5) and turns it 90 degrees about +y (LINEAR), "step" moves it
// there by STEP, "cubic" by CUBICSPLINE with out-tangent (4, 0, 0) at the start and in-tangent
// (-4, 0, 0) at the end.
GltfFile animatedCamera() {
  GltfFile f;
  const int p = f.addFloats({-1, -1, 0, 1, -1, 0, 0, 1, 0}, "VEC3", 3);
  f.doc["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", p}}}}}}}};
  f.doc["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.1}}}}};
  f.doc["nodes"] = {{{"mesh", 0}},
                    {{"translation", {1, 2, 3}}, {"children", {2}}},
                    {{"camera", 0}, {"translation", {0, 0, 5}}}};
  f.doc["scenes"] = {{{"nodes", {0, 1}}}};
  const int times = f.addFloats({0, 1}, "SCALAR", 1);
  const int moves = f.addFloats({0, 0, 5, 2, 0, 5}, "VEC3", 3);
  const double s = std::sin(kPiD / 4), c = std::cos(kPiD / 4);
  const int turns = f.addFloats({0, 0, 0, 1, 0, float(s), 0, float(c)}, "VEC4", 4);
  const int cubic = f.addFloats({0, 0, 0, 0, 0, 5, 4, 0, 0, -4, 0, 0, 2, 0, 5, 0, 0, 0}, "VEC3", 3);
  const auto channel = [](int sampler, const char* path) {
    return nlohmann::json{{"sampler", sampler}, {"target", {{"node", 2}, {"path", path}}}};
  };
  const auto sampler = [&](int output, const char* interpolation) {
    return nlohmann::json{{"input", times}, {"output", output}, {"interpolation", interpolation}};
  };
  f.doc["animations"] = {{{"name", "fly"},
                          {"channels", {channel(0, "translation"), channel(1, "rotation")}},
                          {"samplers", {sampler(moves, "LINEAR"), sampler(turns, "LINEAR")}}},
                         {{"name", "step"},
                          {"channels", {channel(0, "translation")}},
                          {"samplers", {sampler(moves, "STEP")}}},
                         {{"name", "cubic"},
                          {"channels", {channel(0, "translation")}},
                          {"samplers", {sampler(cubic, "CUBICSPLINE")}}}};
  return f;
}

std::string sceneWith(const std::string& animation, const std::string& more = "") {
  return R"({"camera": {"width": 40, "height": 30, "gltf": "cam.gltf", "gltf_animation": )" +
         animation + R"(}, "animation": {"frames": 30, "fps": 24}, "objects": [{"file":
         "cam.gltf"}])" +
         more + "}";
}

// The camera at `frame`: its centre and its forward (OpenCV +z) axis.
void expectPose(const SceneDesc& scene, uint32_t frame, double x, double y, double z, double fx,
                double fz) {
  const Camera cam = resolveCamera(cameraAtFrame(scene.camera, *scene.animation, frame), "t");
  EXPECT_NEAR(cam.position.x, x, 1e-5) << "frame " << frame;
  EXPECT_NEAR(cam.position.y, y, 1e-5) << "frame " << frame;
  EXPECT_NEAR(cam.position.z, z, 1e-5) << "frame " << frame;
  const Vec3 forward = cam.cameraToWorld.column(2);
  EXPECT_NEAR(forward.x, fx, 1e-5) << "frame " << frame;
  EXPECT_NEAR(forward.y, 0, 1e-5) << "frame " << frame;
  EXPECT_NEAR(forward.z, fz, 1e-5) << "frame " << frame;
  // Up stays +y: the turn is about it.
  EXPECT_NEAR(cam.cameraToWorld.column(1).y, -1, 1e-5) << "frame " << frame;
}

TEST(GltfCameraAnimation, LinearMovesAndTurnsItsNodeAtEachFramesTime) {
  TempDir dir;
  dir.write("cam.gltf", animatedCamera().gltf());
  const SceneDesc scene = parseSceneText(sceneWith("\"fly\""), "test.json", dir.path());
  // Frame k is k / 24 seconds; the parent adds (1, 2, 3).
  for (const uint32_t frame : {0u, 6u, 12u, 24u, 29u}) {
    const double t = std::min(frame / 24.0, 1.0), angle = t * kPiD / 2;
    expectPose(scene, frame, 1 + 2 * t, 2, 8, -std::sin(angle), -std::cos(angle));
  }
  // By number as by name.
  const SceneDesc byNumber = parseSceneText(sceneWith("0"), "test.json", dir.path());
  expectPose(byNumber, 12, 2, 2, 8, -std::sin(kPiD / 4), -std::cos(kPiD / 4));
}

TEST(GltfCameraAnimation, StepAndCubicSplineSamplersAsGltfDefinesThem) {
  TempDir dir;
  dir.write("cam.gltf", animatedCamera().gltf());
  const SceneDesc step = parseSceneText(sceneWith("\"step\""), "test.json", dir.path());
  expectPose(step, 23, 1, 2, 8, 0, -1);  // the first key held until the second
  expectPose(step, 24, 3, 2, 8, 0, -1);
  const SceneDesc cubic = parseSceneText(sceneWith("2"), "test.json", dir.path());
  for (const uint32_t frame : {6u, 12u, 18u}) {
    const double u = frame / 24.0, u2 = u * u, u3 = u2 * u;
    // Hermite: v0 = 0, out-tangent 4, v1 = 2, in-tangent -4, over one second.
    const double x = (u3 - 2 * u2 + u) * 4 + (-2 * u3 + 3 * u2) * 2 + (u3 - u2) * -4;
    expectPose(cubic, frame, 1 + x, 2, 8, 0, -1);
  }
}

// glTF stores rotation keys as floats or as normalized integers; a key of normalized shorts
// (made unit again: 23170 / 32767 is sin 45 degrees only to 5 digits) turns the camera as the
// floats do.
TEST(GltfCameraAnimation, RotationKeysOfNormalizedShortsTurnAsFloats) {
  TempDir dir;
  GltfFile f = animatedCamera();
  const int16_t h = int16_t(std::lround(std::sin(kPiD / 4) * 32767));
  const int turns =
      f.addAccessor(std::vector<int16_t>{0, 0, 0, 32767, 0, h, 0, h}, 5122, "VEC4", 2, 0, true);
  f.doc["animations"][0]["samplers"][1]["output"] = turns;
  dir.write("cam.gltf", f.gltf());
  const SceneDesc scene = parseSceneText(sceneWith("\"fly\""), "test.json", dir.path());
  for (const uint32_t frame : {0u, 6u, 12u, 24u}) {
    const double t = frame / 24.0, angle = t * kPiD / 2;
    expectPose(scene, frame, 1 + 2 * t, 2, 8, -std::sin(angle), -std::cos(angle));
  }
  // Translations are floats only.
  const int moves = f.addAccessor(std::vector<int16_t>{0, 0, 5, 2, 0, 5}, 5122, "VEC3", 2, 0, true);
  f.doc["animations"][0]["samplers"][0]["output"] = moves;
  dir.write("cam.gltf", f.gltf());
  try {
    parseSceneText(sceneWith("\"fly\""), "test.json", dir.path());
    ADD_FAILURE() << "no error";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("animations[0].samplers[0].output: accessor " +
                                         std::to_string(moves) +
                                         " holds normalized SHORT; expected FLOAT"),
              std::string::npos)
        << e.what();
  }
}

// A time just below the last key, which rounds onto it in single precision, is still between the
// last two keys: compared in float it was taken for the last, whose next key (past the end of the
// sampler's values) was read, which AddressSanitizer reports where this runs under it.
TEST(GltfCameraAnimation, ATimeJustBeforeTheLastKeyStaysBetweenKeys) {
  TempDir dir;
  const std::unique_ptr<candela::GltfFile> file =
      readGltfFile(dir.write("cam.gltf", animatedCamera().gltf()), "cam.gltf");
  const GltfAnimation fly(file->model, 0, "cam.gltf");
  GltfMatrix local;
  ASSERT_TRUE(fly.localAt(2, file->model.nodes[2], 1.0 - 1e-9, &local));
  EXPECT_NEAR(local[12], 2.0, 1e-6);
  EXPECT_NEAR(local[14], 5.0, 1e-6);
  EXPECT_FALSE(fly.localAt(1, file->model.nodes[1], 0.5, &local));  // a node it does not move
}

TEST(GltfCameraAnimation, RefusesWhatItCannotPlay) {
  TempDir dir;
  dir.write("cam.gltf", animatedCamera().gltf());
  const auto error = [&](const std::string& json) { return test::loadError(json, dir.path()); };
  EXPECT_EQ(error(R"({"camera": {"gltf": "cam.gltf", "gltf_animation": 0}})"),
            "test.json: camera.gltf_animation: needs an \"animation\" block, whose frames and fps "
            "give the times at which the file's animation is played");
  EXPECT_EQ(error(sceneWith("\"walk\"")),
            "test.json: camera.gltf_animation: cam.gltf: no animation is named \"walk\"; its "
            "animations: \"fly\", \"step\", \"cubic\"");
  EXPECT_EQ(error(sceneWith("\"flz\"")),
            "test.json: camera.gltf_animation: cam.gltf: no animation is named \"flz\" (did you "
            "mean \"fly\"?); its animations: \"fly\", \"step\", \"cubic\"");
  EXPECT_EQ(error(sceneWith("3")),
            "test.json: camera.gltf_animation: cam.gltf: animation 3 is asked for, but the file "
            "has 3 animations");
  EXPECT_EQ(error(R"({"camera": {"gltf_animation": 0}})"),
            "test.json: camera.gltf_animation: not used without \"gltf\"");
  GltfFile backwards = animatedCamera();
  const int times = backwards.addFloats({1, 0}, "SCALAR", 1);
  backwards.doc["animations"][0]["samplers"][0]["input"] = times;
  dir.write("cam.gltf", backwards.gltf());
  EXPECT_EQ(error(sceneWith("0")),
            "test.json: camera.gltf_animation: cam.gltf: animations[0].samplers[0].input: key "
            "times must increase, got 0 after 1");
  // A moved node's own transform is checked as any other's: the parts the animation leaves were
  // copied into fixed arrays unchecked (found by gltf_fuzzer, which plays the poses directly: a
  // stack overflow).
  GltfFile longScale = animatedCamera();
  longScale.doc["nodes"][2]["scale"] = {1, 1, 1, 1, 1, 1};
  const std::string path = dir.write("cam.gltf", longScale.gltf());
  try {
    readGltfCameraPoses(path, "cam.gltf", 0, "fly", -1, {0.0, 0.5});
    ADD_FAILURE() << "a scale of six numbers played";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()), "cam.gltf: nodes[2].scale: expected 3 numbers");
  }
  EXPECT_EQ(error(sceneWith("0")),
            "test.json: camera.gltf: cam.gltf: nodes[2].scale: expected 3 numbers");
}

}  // namespace
}  // namespace candela
