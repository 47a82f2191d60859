// An object that follows a glTF file's animation of its node ("gltf_animation"): at frame k it is
// placed as the node is at k / fps seconds (its parent's placement included), after the object's
// own placement; keys that turn the short way; the refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/constants.h"
#include "core/rotation.h"
#include "gltf_test_util.h"
#include "scene/animation.h"
#include "scene/read/scene_loader.h"
#include "scene/scene_error.h"
#include "temp_dir.h"

namespace candela {
namespace {

using test::GltfFile;
using test::TempDir;

// A triangle node "car" at (0, 0, 5) under a parent at (1, 2, 3); its animation "drive" moves it
// to (2, 0, 5) and turns it 90 degrees about +y over one second (LINEAR), and "spin" turns it a
// whole turn about +y in four quarter-turn keys.
GltfFile animatedCar() {
  GltfFile f;
  const int p = f.addFloats({-1, -1, 0, 1, -1, 0, 0, 1, 0}, "VEC3", 3);
  f.doc["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", p}}}}}}}};
  f.doc["nodes"] = {{{"translation", {1, 2, 3}}, {"children", {1}}},
                    {{"name", "car"}, {"mesh", 0}, {"translation", {0, 0, 5}}}};
  f.doc["scenes"] = {{{"nodes", {0}}}};
  const int times = f.addFloats({0, 1}, "SCALAR", 1);
  const int moves = f.addFloats({0, 0, 5, 2, 0, 5}, "VEC3", 3);
  const double s = std::sin(kPiDouble / 4), c = std::cos(kPiDouble / 4);
  const int turns = f.addFloats({0, 0, 0, 1, 0, float(s), 0, float(c)}, "VEC4", 4);
  const int quarters = f.addFloats({0, 1, 2, 3, 4}, "SCALAR", 1);
  const int spin = f.addFloats(
      {0, 0, 0, 1, 0, float(s), 0, float(c), 0, 1, 0, 0, 0, float(s), 0, float(-c), 0, 0, 0, -1},
      "VEC4", 4);
  const auto channel = [](int sampler, const char* path) {
    return nlohmann::json{{"sampler", sampler}, {"target", {{"node", 1}, {"path", path}}}};
  };
  f.doc["animations"] = {
      {{"name", "drive"},
       {"channels", {channel(0, "translation"), channel(1, "rotation")}},
       {"samplers",
        {{{"input", times}, {"output", moves}}, {{"input", times}, {"output", turns}}}}},
      {{"name", "spin"},
       {"channels", {channel(0, "rotation")}},
       {"samplers", {{{"input", quarters}, {"output", spin}}}}}};
  return f;
}

std::string sceneWith(
    const std::string& object,
    const std::string& animation = R"(, "animation": {"frames": 30, "fps": 24})") {
  return R"({"camera": {"width": 8, "height": 6, "position": [0, 0, 20]},
    "lights": [{"position": [0, 5, 20], "intensity": 100}],
    "objects": [)" +
         object + "]" + animation + "}";
}

// The object's placement at `frame` against position p, a turn of `degrees` about +y and scale s.
void expectPlacement(const SceneDesc& scene, uint32_t frame, const Vec3& p, double degrees,
                     float s) {
  const ObjectDesc o = sceneAtFrame(scene, frame).objects[0];
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(o.position[i], p[i], 1e-5) << "frame " << frame;
    EXPECT_NEAR(o.scale[i], s, 1e-6) << "frame " << frame;
  }
  const Mat3 r = eulerRotation(o.rotation), expected = rotationY(float(degrees));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(r.m[i][j], expected.m[i][j], 1e-5) << "frame " << frame;
}

TEST(GltfObjectAnimation, FollowsItsNodeAtEachFramesTimeAfterItsOwnPlacement) {
  TempDir dir;
  dir.write("car.gltf", animatedCar().gltf());
  const SceneDesc scene = parseSceneText(
      sceneWith(R"({"file": "car.gltf", "gltf_node": "car", "gltf_animation": "drive"})"),
      "test.json", dir.path());
  for (const uint32_t frame : {0u, 6u, 12u, 24u, 29u}) {
    const double t = std::min(frame / 24.0, 1.0);
    expectPlacement(scene, frame, Vec3(float(1 + 2 * t), 2, 8), 90 * t, 1);
  }
  // The object's own placement puts the file in the scene: shifted by (10, 0, 0) and doubled.
  const SceneDesc placed = parseSceneText(sceneWith(R"({"file": "car.gltf", "gltf_node": "car",
      "gltf_animation": 0, "position": [10, 0, 0], "scale": 2})"),
                                          "test.json", dir.path());
  expectPlacement(placed, 12, Vec3(10 + 2 * 2.0f, 4, 16), 45, 2);
}

// A whole turn in quarter-turn keys: frame by frame the rotation keys turn the short way, so the
// frames between keys of the scene's tracks (and a motion-blurred exposure) turn with the file.
TEST(GltfObjectAnimation, KeysTurnTheShortWayThroughAWholeTurn) {
  TempDir dir;
  dir.write("car.gltf", animatedCar().gltf());
  const SceneDesc scene = parseSceneText(
      sceneWith(R"({"file": "car.gltf", "gltf_node": "car", "gltf_animation": "spin"})",
                R"(, "animation": {"frames": 9, "fps": 2})"),
      "test.json", dir.path());
  Vec3 last;
  for (uint32_t frame = 0; frame < 9; ++frame) {
    expectPlacement(scene, frame, Vec3(1, 2, 8), 45.0 * frame, 1);
    const Vec3 e = sceneAtFrame(scene, frame).objects[0].rotation;
    if (frame > 0) {
      EXPECT_LT(std::fabs(e.x - last.x) + std::fabs(e.y - last.y) + std::fabs(e.z - last.z), 45.5f)
          << "frame " << frame;
    }
    last = e;
  }
}

std::string error(const std::string& object,
                  const std::string& animation = R"(, "animation": {"frames": 30, "fps": 24})") {
  TempDir dir;
  dir.write("car.gltf", animatedCar().gltf());
  try {
    parseSceneText(sceneWith(object, animation), "test.json", dir.path());
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no SceneError)";
}

TEST(GltfObjectAnimation, Refusals) {
  EXPECT_EQ(error(R"({"shape": "cube", "gltf_animation": "drive"})"),
            "test.json: objects[0].gltf_animation: a glTF file's animation, and the "
            "object is a cube");
  EXPECT_EQ(error(R"({"id": "c", "file": "car.gltf", "gltf_node": "car", "gltf_animation": 0})",
                  R"(, "animation": {"frames": 3, "tracks": [{"target": "c", "property":
                  "rotation", "keys": [[0, [0, 0, 0]]]}]})"),
            "test.json: animation.tracks[0]: the object follows its \"gltf_animation\", which "
            "places it at every frame");
  const std::string unknown =
      error(R"({"file": "car.gltf", "gltf_node": "car", "gltf_animation": "drvie"})");
  EXPECT_EQ(unknown.rfind("test.json: objects[0].gltf_animation: ", 0), 0u) << unknown;
  EXPECT_NE(unknown.find("drvie"), std::string::npos) << unknown;
  EXPECT_EQ(error(R"({"file": "car.gltf", "gltf_node": "car", "gltf_animation": ""})"),
            "test.json: objects[0].gltf_animation: expected an animation's name or number, from "
            "0, got a string \"\"");
}

}  // namespace
}  // namespace candela
