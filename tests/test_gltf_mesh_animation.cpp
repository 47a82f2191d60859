// Meshes that a glTF file's animation moves: morph targets at their weights, skins by their
// joints, nodes below the object's node, each at frame k's time k / fps and at the times of an
// open shutter, held against the test's own arithmetic; a frame renders as a still mesh of the
// vertices that arithmetic gives; what the loader refuses.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/constants.h"
#include "flow_test_util.h"
#include "gltf_test_util.h"
#include "render_test_util.h"
#include "scene/animation.h"
#include "scene/flatten.h"
#include "scene/read/scene_loader.h"
#include "scene/scene_error.h"
#include "temp_dir.h"

namespace candela {
namespace {

using test::GltfFile;
using test::TempDir;

constexpr float kHalfTurnSine = 0.70710678f;  // sin 45 degrees

// A LINEAR sampler from time 0 to 1 second over `keys` (two keys' values).
nlohmann::json linearSampler(GltfFile& f, const std::vector<float>& keys, const char* type,
                             size_t components) {
  const int input = f.addFloats({0, 1}, "SCALAR", 1);
  const int output = f.addFloats(keys, type, components);
  return {{"input", input}, {"output", output}};
}

nlohmann::json channel(int sampler, int node, const char* path) {
  return {{"sampler", sampler}, {"target", {{"node", node}, {"path", path}}}};
}

// An arm: vertex A (0, 0, 0) on joint "shoulder" (at the origin), B (2, 0, 0) on joint "elbow"
// (at (1, 0, 0)), C (2, 1, 0) on both, half each; normals +z. The skinned node "arm" stands at
// (5, 0, 0), which glTF ignores. Animation "bend" turns the elbow 90 degrees about +y over one
// second.
GltfFile skinnedArm() {
  GltfFile f;
  const int p = f.addFloats({0, 0, 0, 2, 0, 0, 2, 1, 0}, "VEC3", 3);
  const int n = f.addFloats({0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3", 3);
  const int joints =
      f.addAccessor(std::vector<uint8_t>{0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0}, 5121, "VEC4", 3);
  const int weights = f.addFloats({1, 0, 0, 0, 1, 0, 0, 0, 0.5f, 0.5f, 0, 0}, "VEC4", 4);
  const int inverseBinds = f.addFloats({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0,  0, 0, 1,
                                        1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -1, 0, 0, 1},
                                       "MAT4", 16);
  f.doc["meshes"] = {
      {{"primitives",
        {{{"attributes",
           {{"POSITION", p}, {"NORMAL", n}, {"JOINTS_0", joints}, {"WEIGHTS_0", weights}}}}}}}};
  f.doc["skins"] = {{{"joints", {1, 2}}, {"inverseBindMatrices", inverseBinds}}};
  f.doc["nodes"] = {{{"name", "arm"}, {"mesh", 0}, {"skin", 0}, {"translation", {5, 0, 0}}},
                    {{"name", "shoulder"}, {"children", {2}}},
                    {{"name", "elbow"}, {"translation", {1, 0, 0}}}};
  f.doc["scenes"] = {{{"nodes", {0, 1}}}};
  f.doc["animations"] = {
      {{"name", "bend"},
       {"channels", {channel(0, 2, "rotation")}},
       {"samplers",
        {linearSampler(f, {0, 0, 0, 1, 0, kHalfTurnSine, 0, kHalfTurnSine}, "VEC4", 4)}}}};
  return f;
}

// The arm's vertices with the elbow turned by `theta` (radians) about +y: B turns about the elbow;
// C, half on each joint, lies halfway between where each would put it.
std::vector<Vec3> bentArm(double theta) {
  const double c = std::cos(theta), s = std::sin(theta);
  return {Vec3(0, 0, 0), Vec3(float(1 + c), 0, float(-s)),
          Vec3(float((3 + c) / 2), 1, float(-s / 2))};
}

std::string sceneWith(const std::string& object, const std::string& animation) {
  return R"({"camera": {"width": 8, "height": 6, "position": [0, 0, 20]},
    "lights": [{"position": [0, 5, 20], "intensity": 100}],
    "objects": [)" +
         object + "]" + animation + "}";
}

const char* kThirtyFrames = R"(, "animation": {"frames": 30, "fps": 24})";

void expectNear(const Vec3& got, const Vec3& want, const std::string& what) {
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[i], want[i], 2e-6) << what << ", component " << i;
}

TEST(GltfMeshAnimation, ASkinAtRestPlacesItsVerticesAsBoundIgnoringItsNode) {
  TempDir dir;
  dir.write("arm.gltf", skinnedArm().gltf());
  const MeshDesc mesh = test::loadGltfMesh(dir.file("arm.gltf"), "arm.gltf");
  const std::vector<Vec3> bound = bentArm(0);
  ASSERT_EQ(mesh.positions.size(), 3u);
  for (size_t v = 0; v < 3; ++v)
    expectNear(mesh.positions[v], bound[v], "vertex " + std::to_string(v));
  for (const std::string& w : mesh.warnings)
    EXPECT_EQ(w.find("skin"), std::string::npos) << w;  // skins are applied now
}

TEST(GltfMeshAnimation, ASkinFollowsItsJointsAtEachFramesTime) {
  TempDir dir;
  dir.write("arm.gltf", skinnedArm().gltf());
  const SceneDesc scene =
      parseSceneText(sceneWith(R"({"file": "arm.gltf", "gltf_animation": "bend"})", kThirtyFrames),
                     "test.json", dir.path());
  ASSERT_TRUE(scene.objects[0].meshMotion);
  for (const uint32_t frame : {0u, 6u, 12u, 24u, 29u}) {
    const double theta = std::min(frame / 24.0, 1.0) * kPiDouble / 2;
    const SceneDesc at = sceneAtFrame(scene, frame);
    const MeshDesc& mesh = *at.objects[0].mesh;
    const std::vector<Vec3> want = bentArm(theta);
    for (size_t v = 0; v < 3; ++v)
      expectNear(mesh.positions[v], want[v],
                 "frame " + std::to_string(frame) + ", vertex " + std::to_string(v));
    // Normals: A's stays, B's turns with the elbow, C's (its matrix half of each joint's)
    // by half the angle.
    expectNear(mesh.normals[0], Vec3(0, 0, 1), "normal 0");
    expectNear(mesh.normals[1], Vec3(float(std::sin(theta)), 0, float(std::cos(theta))),
               "normal 1, frame " + std::to_string(frame));
    expectNear(mesh.normals[2], Vec3(float(std::sin(theta / 2)), 0, float(std::cos(theta / 2))),
               "normal 2, frame " + std::to_string(frame));
    EXPECT_TRUE(at.objects[0].shutterPoses.empty());  // a closed shutter
  }
  // Held after the last key, as glTF says.
  const MeshDesc& last = *sceneAtFrame(scene, 29).objects[0].mesh;
  for (size_t v = 0; v < 3; ++v) expectNear(last.positions[v], bentArm(kPiDouble / 2)[v], "held");
}

// An object of the skinned node alone sees the joints (outside the node) from the node's frame,
// and is placed where the node stands: the file's pose again.
TEST(GltfMeshAnimation, AnObjectOfTheSkinnedNodeSeesItsJointsFromTheNode) {
  TempDir dir;
  dir.write("arm.gltf", skinnedArm().gltf());
  const SceneDesc scene = parseSceneText(
      sceneWith(R"({"file": "arm.gltf", "gltf_node": "arm", "gltf_animation": "bend"})",
                kThirtyFrames),
      "test.json", dir.path());
  const SceneDesc at = sceneAtFrame(scene, 12);
  expectNear(at.objects[0].position, Vec3(5, 0, 0), "the node's place");
  const std::vector<Vec3> want = bentArm(kPiDouble / 4);
  for (size_t v = 0; v < 3; ++v)
    expectNear(at.objects[0].mesh->positions[v], want[v] - Vec3(5, 0, 0),
               "vertex " + std::to_string(v));
}

// A vertex without skin weights stays with its node, with a warning.
TEST(GltfMeshAnimation, AVertexWithoutWeightsStaysWithItsNode) {
  TempDir dir;
  GltfFile arm = skinnedArm();
  const int none = arm.addFloats({1, 0, 0, 0, 0, 0, 0, 0, 0.5f, 0.5f, 0, 0}, "VEC4", 4);
  arm.doc["meshes"][0]["primitives"][0]["attributes"]["WEIGHTS_0"] = none;
  dir.write("arm.gltf", arm.gltf());
  const MeshDesc mesh = test::loadGltfMesh(dir.file("arm.gltf"), "arm.gltf");
  expectNear(mesh.positions[1], Vec3(7, 0, 0), "B at the node's (5, 0, 0)");
  EXPECT_NE(std::find(mesh.warnings.begin(), mesh.warnings.end(),
                      "arm.gltf: vertices without skin weights stay with their node "
                      "(meshes[0].primitives[0])"),
            mesh.warnings.end());
}

// A triangle whose third vertex a morph target lifts by (0, 0, 1) and whose normals it tilts
// towards +x; the mesh's weight is 0.25, and node "lid" draws it, node "copy" too, 10 to the right
// with weight 0.5 of its own. Animation "open" takes lid's weight from 0 to 1 over one second.
GltfFile morphingLid() {
  GltfFile f;
  const int p = f.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3);
  const int n = f.addFloats({0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3", 3);
  const int dp = f.addFloats({0, 0, 0, 0, 0, 0, 0, 0, 1}, "VEC3", 3);
  const int dn = f.addFloats({1, 0, 0, 1, 0, 0, 1, 0, 0}, "VEC3", 3);
  nlohmann::json primitive = {{"attributes", {{"POSITION", p}, {"NORMAL", n}}}};
  primitive["targets"] = nlohmann::json::array({{{"POSITION", dp}, {"NORMAL", dn}}});
  nlohmann::json mesh = {{"weights", {0.25}}};
  mesh["primitives"] = nlohmann::json::array({primitive});
  f.doc["meshes"] = nlohmann::json::array({mesh});
  f.doc["nodes"] = {
      {{"name", "lid"}, {"mesh", 0}},
      {{"name", "copy"}, {"mesh", 0}, {"translation", {10, 0, 0}}, {"weights", {0.5}}}};
  f.doc["scenes"] = {{{"nodes", {0, 1}}}};
  f.doc["animations"] = {{{"name", "open"},
                          {"channels", {channel(0, 0, "weights")}},
                          {"samplers", {linearSampler(f, {0, 1}, "SCALAR", 1)}}}};
  return f;
}

TEST(GltfMeshAnimation, MorphTargetsMoveVerticesAndNormalsByTheirWeights) {
  TempDir dir;
  dir.write("lid.gltf", morphingLid().gltf());
  const MeshDesc rest = test::loadGltfMesh(dir.file("lid.gltf"), "lid.gltf");
  ASSERT_EQ(rest.positions.size(), 6u);
  expectNear(rest.positions[2], Vec3(0, 1, 0.25f), "the mesh's weight");
  expectNear(rest.positions[5], Vec3(10, 1, 0.5f), "the node's own weight");
  const float tilt = 1 / std::sqrt(1 + 0.25f * 0.25f);
  expectNear(rest.normals[0], Vec3(0.25f * tilt, 0, tilt), "the normal tilted by 0.25");

  const SceneDesc scene =
      parseSceneText(sceneWith(R"({"file": "lid.gltf", "gltf_animation": "open"})", kThirtyFrames),
                     "test.json", dir.path());
  for (const uint32_t frame : {0u, 12u, 24u}) {
    const float w = float(frame) / 24;
    const MeshDesc& mesh = *sceneAtFrame(scene, frame).objects[0].mesh;
    expectNear(mesh.positions[2], Vec3(0, 1, w), "lid, frame " + std::to_string(frame));
    expectNear(mesh.positions[5], Vec3(10, 1, 0.5f), "copy, frame " + std::to_string(frame));
    const float length = std::sqrt(1 + w * w);
    expectNear(mesh.normals[1], Vec3(w / length, 0, 1 / length),
               "lid's normal, frame " + std::to_string(frame));
  }
}

// The car of test_gltf_object_animation.cpp: a triangle node "car" at (0, 0, 5) under a parent
// "road" at (1, 2, 3); "drive" moves it to (2, 0, 5) and turns it 90 degrees about +y over one
// second.
GltfFile drivingCar() {
  GltfFile f;
  const int p = f.addFloats({-1, -1, 0, 1, -1, 0, 0, 1, 0}, "VEC3", 3);
  f.doc["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", p}}}}}}}};
  f.doc["nodes"] = {{{"name", "road"}, {"translation", {1, 2, 3}}, {"children", {1}}},
                    {{"name", "car"}, {"mesh", 0}, {"translation", {0, 0, 5}}}};
  f.doc["scenes"] = {{{"nodes", {0}}}};
  f.doc["animations"] = {
      {{"name", "drive"},
       {"channels", {channel(0, 1, "translation"), channel(1, 1, "rotation")}},
       {"samplers",
        {linearSampler(f, {0, 0, 5, 2, 0, 5}, "VEC3", 3),
         linearSampler(f, {0, 0, 0, 1, 0, kHalfTurnSine, 0, kHalfTurnSine}, "VEC4", 4)}}}};
  return f;
}

// The car's corner (x, y, 0) at time t, under a parent at `parent`.
Vec3 carCorner(double x, double y, double t, const Vec3& parent) {
  const double theta = t * kPiDouble / 2, c = std::cos(theta), s = std::sin(theta);
  return Vec3(float(parent.x + 2 * t + c * x), float(parent.y + y), float(parent.z + 5 - s * x));
}

TEST(GltfMeshAnimation, NodesBelowTheObjectsNodeMoveItsMesh) {
  TempDir dir;
  dir.write("car.gltf", drivingCar().gltf());
  // The whole file: the car moves within the object's one mesh.
  const SceneDesc file =
      parseSceneText(sceneWith(R"({"file": "car.gltf", "gltf_animation": "drive"})", kThirtyFrames),
                     "test.json", dir.path());
  // The road's node: the object holds it in the road's frame, and the car moves below it.
  const SceneDesc road = parseSceneText(
      sceneWith(R"({"file": "car.gltf", "gltf_node": "road", "gltf_animation": "drive"})",
                kThirtyFrames),
      "test.json", dir.path());
  for (const uint32_t frame : {0u, 12u, 24u}) {
    const double t = frame / 24.0;
    const MeshDesc& whole = *sceneAtFrame(file, frame).objects[0].mesh;
    const MeshDesc& below = *sceneAtFrame(road, frame).objects[0].mesh;
    const std::string at = "frame " + std::to_string(frame);
    expectNear(whole.positions[0], carCorner(-1, -1, t, Vec3(1, 2, 3)), at);
    expectNear(whole.positions[2], carCorner(0, 1, t, Vec3(1, 2, 3)), at);
    expectNear(below.positions[1], carCorner(1, -1, t, Vec3(0, 0, 0)), at);
  }
  // The car's own node: its motion is the object's placement (its tracks), the mesh stays.
  const SceneDesc car = parseSceneText(
      sceneWith(R"({"file": "car.gltf", "gltf_node": "car", "gltf_animation": "drive"})",
                kThirtyFrames),
      "test.json", dir.path());
  EXPECT_FALSE(car.objects[0].meshMotion);
  EXPECT_FALSE(car.animation->meshesMove);
}

TEST(GltfMeshAnimation, AnOpenShutterPosesTheMeshAtItsTimes) {
  TempDir dir;
  dir.write("arm.gltf", skinnedArm().gltf());
  const SceneDesc scene =
      parseSceneText(sceneWith(R"({"file": "arm.gltf", "gltf_animation": "bend"})",
                               R"(, "animation": {"frames": 30, "fps": 24, "shutter": [0, 1]})"),
                     "test.json", dir.path());
  const SceneDesc at = sceneAtFrame(scene, 6);
  const ObjectDesc& arm = at.objects[0];
  ASSERT_EQ(at.shutterTimes.size(), arm.shutterPoses.size());
  ASSERT_GT(arm.shutterPoses.size(), 2u);
  for (size_t k = 0; k < arm.shutterPoses.size(); ++k) {
    const double frames = 6 + at.shutterTimes[k];  // the exposure runs from frame 6 to 7
    ASSERT_TRUE(arm.shutterPoses[k].mesh);
    expectNear(arm.shutterPoses[k].mesh->positions[1], bentArm(frames / 24 * kPiDouble / 2)[1],
               "time " + std::to_string(at.shutterTimes[k]));
  }
  // Its flattened scene holds the vertices at each time for the motion pass.
  const SceneData data = flattenScene(at);
  EXPECT_EQ(data.motionPositions.size(), 3 * arm.shutterPoses.size());
  // Past the animation's last key the mesh holds still: no poses.
  EXPECT_TRUE(sceneAtFrame(scene, 26).objects[0].shutterPoses.empty());
}

// A frame of the bending arm renders as a still glTF file of the vertices the test computes.
TEST(GltfMeshAnimation, AFrameRendersAsTheStillMeshOfItsPose) {
  TempDir dir;
  dir.write("arm.gltf", skinnedArm().gltf());
  const double theta = 12.0 / 24 * kPiDouble / 2;
  const std::vector<Vec3> bent = bentArm(theta);
  GltfFile still;
  std::vector<float> positions;
  for (const Vec3& v : bent) positions.insert(positions.end(), {v.x, v.y, v.z});
  const int p = still.addFloats(positions, "VEC3", 3);
  const float h = float(std::sin(theta / 2)), c = float(std::cos(theta / 2));
  const int n = still.addFloats(
      {0, 0, 1, float(std::sin(theta)), 0, float(std::cos(theta)), h, 0, c}, "VEC3", 3);
  still.doc["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", p}, {"NORMAL", n}}}}}}}};
  still.doc["nodes"] = {{{"mesh", 0}}};
  dir.write("still.gltf", still.gltf());
  const std::string camera = R"({"camera": {"width": 24, "height": 16, "position": [1.2, 0.4, 6],
      "fov": 40, "spp": 16}, "render": {"max_depth": 3},
      "lights": [{"position": [3, 4, 6], "intensity": 60}],
      "environment": {"color": [0.2, 0.2, 0.25]}, "objects": [)";
  const SceneDesc animated =
      parseSceneText(camera + R"({"file": "arm.gltf", "gltf_animation": "bend", "smooth": true}])" +
                         kThirtyFrames + "}",
                     "test.json", dir.path());
  const SceneDesc reference = parseSceneText(camera + R"({"file": "still.gltf", "smooth": true}]})",
                                             "test.json", dir.path());
  SceneDesc frame = sceneAtFrame(animated, 12);
  frame.render.seed = reference.render.seed;
  const std::vector<float> a = renderCpu(flattenScene(frame).view(), RenderOptions()).image.pixels;
  const std::vector<float> b =
      renderCpu(flattenScene(reference).view(), RenderOptions()).image.pixels;
  ASSERT_EQ(a.size(), b.size());
  double sum = 0, differs = 0, arm = 0;
  const float environment[3] = {0.2f, 0.2f, 0.25f};
  for (size_t i = 0; i < a.size(); ++i) {
    sum += a[i];
    differs += std::fabs(a[i] - b[i]);
    arm += std::fabs(a[i] - environment[i % 3]) > 1e-3f;
  }
  // The arm covers a twentieth of the image or more (channels that are not the environment's).
  EXPECT_GT(arm, 0.05 * double(a.size()));
  // The same triangle up to the rounding of its vertices: the same samples see it alike.
  EXPECT_LT(differs / sum, 1e-4);
}

// The arm bending through its whole turn while the shutter is open (frame 0 of 1 a second, the
// shutter from it to the next) renders as the mean of its stills at the midpoints of 64 even parts
// of the exposure: each pixel within half a 64th of its range over the exposure at each of its
// jumps, as ObjectMotion.BlurredFrameIsTheMeanOfTheStillsAcrossItsExposure holds moving shapes.
TEST(GltfMeshAnimation, BlurredFrameIsTheMeanOfTheStillsAcrossItsExposure) {
  TempDir dir;
  dir.write("arm.gltf", skinnedArm().gltf());
  const auto scene = [&](uint32_t spp, const std::string& animation) {
    return parseSceneText(
        R"({"camera": {"width": 24, "height": 24, "fov": 50, "position": [1, 0.5, 5], "spp": )" +
            std::to_string(spp) + R"(}, "render": {"max_depth": 1, "antialiasing": false},
            "lights": [{"position": [2, 3, 5], "intensity": 30}],
            "objects": [{"file": "arm.gltf", "gltf_animation": "bend"}],
            "animation": )" +
            animation + "}",
        "test.json", dir.path());
  };
  const std::vector<float> blurred =
      renderCpu(flattenScene(
                    sceneAtFrame(scene(1024, R"({"frames": 2, "fps": 1, "shutter": [0, 1]})"), 0))
                    .view(),
                RenderOptions())
          .image.pixels;
  const SceneDesc stills = scene(1, R"({"frames": 129, "fps": 128})");
  std::vector<double> mean(blurred.size(), 0.0), lo(blurred.size(), 1e30),
      hi(blurred.size(), -1e30);
  for (uint32_t frame = 1; frame < 128; frame += 2) {
    const std::vector<float> image =
        renderCpu(flattenScene(sceneAtFrame(stills, frame)).view(), RenderOptions()).image.pixels;
    ASSERT_EQ(image.size(), blurred.size());
    for (size_t i = 0; i < image.size(); ++i) {
      mean[i] += image[i] / 64.0;
      lo[i] = std::min(lo[i], double(image[i]));
      hi[i] = std::max(hi[i], double(image[i]));
    }
  }
  size_t moving = 0;
  for (size_t i = 0; i < mean.size(); ++i) {
    const double range = hi[i] - lo[i];
    EXPECT_NEAR(blurred[i], mean[i], std::max(range, mean[i]) * 2.0 / 64 + 1e-6) << i;
    moving += range > 0;
  }
  EXPECT_GT(moving, mean.size() / 20);  // the arm sweeps a good part of the image
}

// The flow pass follows each point of a mesh that moves apart: a square whose morph target
// stretches it along x, its weight from 0 to 1 over a second (8 frames of it), moves each point
// (x, y) of frame 3 to (x 1.5 / 1.375, y) at frame 4.
TEST(GltfMeshAnimation, TheFlowPassFollowsTheVerticesOfAMovingMesh) {
  TempDir dir;
  dir.write("stretch.gltf", test::stretchingSquare().gltf());
  const test::FlowRender r = test::renderFlow(test::kStretchingSquareScene, 3, dir.path());
  EXPECT_GT(
      test::expectFlowFollows(r, "flow", 4.0f,
                              [](const Vec3& p) { return Vec3(p.x * 1.5f / 1.375f, p.y, 0.0f); }),
      20);
}

// The animation's clock: a start, a speed (backwards too) and a loop, for the mesh's motion and
// for the object's placement by its node alike.
TEST(GltfMeshAnimation, AnObjectSetsTheAnimationsClock) {
  TempDir dir;
  dir.write("arm.gltf", skinnedArm().gltf());
  dir.write("car.gltf", drivingCar().gltf());
  const auto elbowAt = [&](const std::string& clock, uint32_t frame) {
    const SceneDesc scene = parseSceneText(
        sceneWith(R"({"file": "arm.gltf", "gltf_animation": )" + clock + "}", kThirtyFrames),
        "test.json", dir.path());
    return sceneAtFrame(scene, frame).objects[0].mesh->positions[1];
  };
  const auto bentAt = [](double seconds) { return bentArm(seconds * kPiDouble / 2)[1]; };
  // Looped, 1.25 seconds in is 0.25 seconds into the one-second animation.
  expectNear(elbowAt(R"({"name": "bend", "loop": true})", 30), bentAt(0.25), "looped");
  expectNear(elbowAt(R"({"name": "bend"})", 30), bentAt(1), "held");
  expectNear(elbowAt(R"({"index": 0, "start": 0.5, "speed": 2})", 6), bentAt(1), "sped up");
  expectNear(elbowAt(R"({"name": "bend", "start": 1, "speed": -1})", 12), bentAt(0.5), "backwards");
  // Without an animation block the scene is a still of the clock's start.
  const SceneDesc still = parseSceneText(
      sceneWith(R"({"file": "arm.gltf", "gltf_animation": {"name": "bend", "start": 0.5}})", ""),
      "test.json", dir.path());
  EXPECT_FALSE(still.objects[0].meshMotion);
  expectNear(still.objects[0].mesh->positions[1], bentAt(0.5), "a still of the start");
  const SceneDesc parked = parseSceneText(sceneWith(R"({"file": "car.gltf", "gltf_node": "car",
                    "gltf_animation": {"name": "drive", "start": 0.5}})",
                                                    ""),
                                          "test.json", dir.path());
  expectNear(parked.objects[0].position, Vec3(2, 2, 8), "the car's node, still");
  // A node the object follows keeps the same clock.
  const SceneDesc car = parseSceneText(sceneWith(R"({"file": "car.gltf", "gltf_node": "car",
                    "gltf_animation": {"name": "drive", "loop": true, "start": 0.5}})",
                                                 kThirtyFrames),
                                       "test.json", dir.path());
  const ObjectDesc driven = sceneAtFrame(car, 18).objects[0];  // 0.75 s on: 1.25, looped 0.25
  expectNear(driven.position, Vec3(1 + 2 * 0.25f, 2, 8), "the car's node");
}

std::string error(const GltfFile& file, const std::string& object,
                  const std::string& animation = kThirtyFrames) {
  TempDir dir;
  dir.write("m.gltf", file.gltf());
  try {
    parseSceneText(sceneWith(object, animation), "test.json", dir.path());
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no SceneError)";
}

TEST(GltfMeshAnimation, Refusals) {
  GltfFile farJoint = skinnedArm();
  farJoint.doc["skins"][0]["joints"] = {1};
  farJoint.doc["skins"][0].erase("inverseBindMatrices");
  EXPECT_EQ(error(farJoint, R"({"file": "m.gltf"})"),
            "test.json: objects[0].file: m.gltf: meshes[0].primitives[0].attributes.JOINTS_0: "
            "element 1 names joint 1, past the skin's 1 joints");
  GltfFile noWeights = skinnedArm();
  noWeights.doc["meshes"][0]["primitives"][0]["attributes"].erase("WEIGHTS_0");
  EXPECT_EQ(error(noWeights, R"({"file": "m.gltf"})"),
            "test.json: objects[0].file: m.gltf: meshes[0].primitives[0].attributes.JOINTS_0: "
            "expected WEIGHTS_0 beside it");
  GltfFile fewBinds = skinnedArm();
  fewBinds.doc["skins"][0]["joints"] = {1, 2, 0};
  EXPECT_EQ(error(fewBinds, R"({"file": "m.gltf"})"),
            "test.json: objects[0].file: m.gltf: skins[0].inverseBindMatrices: expected 3 "
            "matrices, one per joint, got 2");
  // A broken skin that no node uses is left alone.
  GltfFile unusedSkin = skinnedArm();
  unusedSkin.doc["skins"].push_back({{"joints", nlohmann::json::array()}});
  EXPECT_EQ(error(unusedSkin, R"({"file": "m.gltf"})"), "(no SceneError)");
  unusedSkin.doc["nodes"][0]["skin"] = 1;
  EXPECT_EQ(error(unusedSkin, R"({"file": "m.gltf"})"),
            "test.json: objects[0].file: m.gltf: skins[1].joints: expected at least one joint");
  GltfFile weighsNothing = skinnedArm();
  weighsNothing.doc["animations"][0]["channels"][0]["target"]["path"] = "weights";
  const std::string nothing = error(weighsNothing, R"({"file": "m.gltf", "gltf_animation": 0})");
  EXPECT_EQ(nothing,
            "test.json: objects[0].gltf_animation: m.gltf: animations[0].channels[0].target: node "
            "2 has no mesh with morph targets, whose weights the channel could set");
  EXPECT_EQ(error(skinnedArm(), R"({"file": "m.gltf", "gltf_animation": {"loop": true}})"),
            "test.json: objects[0].gltf_animation: expected its \"name\" or its \"index\"");
  EXPECT_EQ(error(skinnedArm(), R"({"file": "m.gltf", "gltf_animation": {"name": "bend",
                                    "speed": 0}})"),
            "test.json: objects[0].gltf_animation.speed: expected a speed other than 0 (negative "
            "plays it backwards), got 0");
}

}  // namespace
}  // namespace candela
