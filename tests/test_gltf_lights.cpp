// The lights of a glTF file ({"gltf": file} in "lights", KHR_lights_punctual): placed by their
// nodes' transforms and their parents', shining along their nodes' -z, their photometric units
// read at 683 lm/W; a diffuse plane under a point, a spot and a directional light of one file
// against the closed forms, pixel for pixel; the warnings and refusals.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/constants.h"
#include "gltf_test_util.h"
#include "render_test_util.h"
#include "scene/read/scene_loader.h"
#include "temp_dir.h"

namespace candela {
namespace {

using test::num;
using test::TempDir;

constexpr double kPiD = 3.14159265358979323846;

// Turns of glTF's quaternions [x, y, z, w].
nlohmann::json aboutX(double degrees) {
  const double h = degrees * kPiD / 360.0;
  return {std::sin(h), 0, 0, std::cos(h)};
}
nlohmann::json aboutY(double degrees) {
  const double h = degrees * kPiD / 360.0;
  return {0, std::sin(h), 0, std::cos(h)};
}

// A point light of 4000 cd under a parent moved by (1, 4, -1), turned 30 degrees about y and
// scaled by 2 (which moves the light, not its intensity); a spot of 3000 cd pointing straight
// down from (-1.5, 3, 0.5), its cone 0.3 and 0.6 radians; a sun of 683 lux (irradiance 1)
// shining along (0, -sin 60, -cos 60). Node 4 places nothing.
nlohmann::json lightsFile() {
  nlohmann::json doc = {{"asset", {{"version", "2.0"}}}};
  doc["extensionsUsed"] = {"KHR_lights_punctual"};
  doc["extensions"]["KHR_lights_punctual"]["lights"] = {
      {{"type", "point"}, {"intensity", 4000}, {"color", {1, 0.5, 0.25}}},
      {{"type", "spot"},
       {"intensity", 3000},
       {"spot", {{"innerConeAngle", 0.3}, {"outerConeAngle", 0.6}}}},
      {{"type", "directional"}, {"intensity", 683}}};
  const auto light = [](int index) {
    return nlohmann::json{{"KHR_lights_punctual", {{"light", index}}}};
  };
  doc["nodes"] = {
      {{"translation", {1, 4, -1}},
       {"rotation", aboutY(30)},
       {"scale", {2, 2, 2}},
       {"children", {1}}},
      {{"translation", {0.5, 0, 0}}, {"extensions", light(0)}},
      {{"translation", {-1.5, 3, 0.5}}, {"rotation", aboutX(-90)}, {"extensions", light(1)}},
      {{"rotation", aboutX(-60)}, {"extensions", light(2)}},
      {{"translation", {0, 1, 0}}}};
  doc["scenes"] = {{{"nodes", {0, 2, 3, 4}}}};
  return doc;
}

// Where the test's arithmetic puts them.
constexpr double kPointX = 1 + 2 * 0.5 * 0.86602540378443865, kPointY = 4,
                 kPointZ = -1 - 2 * 0.5 * 0.5;
constexpr double kSunX = 0, kSunY = -0.86602540378443865, kSunZ = -0.5;

TEST(GltfLights, TakeTheirNodesPlacesAndTheirUnitsAt683LumensPerWatt) {
  TempDir dir;
  dir.write("lights.gltf", lightsFile().dump());
  const SceneDesc scene =
      parseSceneText(R"({"camera": {"width": 4, "height": 4}, "lights": [{"position": [0, 9, 0],
                         "intensity": 1}, {"gltf": "lights.gltf"}]})",
                     "test.json", dir.path());
  ASSERT_EQ(scene.lights.size(), 4u);
  const LightDesc& point = scene.lights[1];
  const LightDesc& spot = scene.lights[2];
  const LightDesc& sun = scene.lights[3];
  EXPECT_EQ(point.where, "lights[1].gltf: lights.gltf: nodes[1]");
  EXPECT_EQ(spot.where, "lights[1].gltf: lights.gltf: nodes[2]");
  EXPECT_EQ(point.gltfFile, dir.path() + "/lights.gltf");
  EXPECT_TRUE(scene.lights[0].gltfFile.empty());

  EXPECT_EQ(point.type, LightType::Point);
  EXPECT_FALSE(point.spot);
  EXPECT_NEAR(point.position.x, kPointX, 1e-5);
  EXPECT_NEAR(point.position.y, kPointY, 1e-5);
  EXPECT_NEAR(point.position.z, kPointZ, 1e-5);
  EXPECT_NEAR(point.intensity, 4 * kPiD * 4000 / 683, 1e-3);  // the power, unscaled
  EXPECT_FLOAT_EQ(point.color.y, 0.5f);
  EXPECT_FLOAT_EQ(point.color.z, 0.25f);

  EXPECT_EQ(spot.type, LightType::Point);
  ASSERT_TRUE(spot.spot);
  EXPECT_NEAR(spot.spot->cutoffDegrees, 0.6 * 180 / kPiD, 1e-4);
  EXPECT_NEAR(spot.spot->beamDegrees, 0.3 * 180 / kPiD, 1e-4);
  EXPECT_NEAR(spot.direction.y, -1.0, 1e-6);
  EXPECT_NEAR(spot.position.y, 3.0, 1e-6);
  EXPECT_NEAR(spot.intensity, 4 * kPiD * 3000 / 683, 1e-3);

  EXPECT_EQ(sun.type, LightType::Directional);
  EXPECT_NEAR(sun.direction.x, kSunX, 1e-6);
  EXPECT_NEAR(sun.direction.y, kSunY, 1e-6);
  EXPECT_NEAR(sun.direction.z, kSunZ, 1e-6);
  EXPECT_NEAR(sun.intensity, 1.0, 1e-6);  // 683 lux
}

// A diffuse plane y = 0 of albedo rho under the three lights, seen from above through pixel
// centres at one bounce: every pixel is the sum of the closed forms, rho / pi times the point
// light's I cos / d^2 (I in W/sr: candela over 683), the spot's likewise inside its beam and
// fading linearly in angle to 0 at its cutoff, and the sun's irradiance times its cosine.
TEST(GltfLights, LightADiffusePlaneAsTheirClosedFormsSay) {
  TempDir dir;
  dir.write("lights.gltf", lightsFile().dump());
  const std::string obj = test::writePlaneObj("gltf_lights_plane.obj", 100);
  const double rho = 0.5;
  const SceneData data = test::loadTestScene(R"({
    "camera": {"width": 48, "height": 40, "fov": 90, "position": [0, 8, 0],
               "look_at": [0, 0, 0.001], "up": [0, 0, -1], "spp": 2},
    "render": {"antialiasing": false, "max_depth": 1},
    "objects": [{"file": ")" + obj + R"(", "color": )" +
                                                 num(rho) + R"(}],
    "lights": [{"gltf": "lights.gltf"}]})",
                                             dir.path());
  const RenderResult r = renderCpu(data.view(), RenderOptions{});
  const Camera& cam = data.camera;
  double worst = 0;
  int inBeam = 0, inFade = 0;
  for (uint32_t y = 0; y < 40; ++y)
    for (uint32_t x = 0; x < 48; ++x) {
      const Vec3 d = cam.cameraToWorld * (cam.inverseK * Vec3(x + 0.5f, y + 0.5f, 1.0f));
      const double t = -double(cam.position.y) / d.y;
      const double px = cam.position.x + t * d.x, pz = cam.position.z + t * d.z;
      // The point light: I cos / d^2, cos = height / d.
      const double qx = kPointX - px, qz = kPointZ - pz;
      const double q2 = qx * qx + kPointY * kPointY + qz * qz;
      const double point = 4000.0 / 683 * kPointY / std::sqrt(q2) / q2;
      // The spot straight down from (-1.5, 3, 0.5): the angle off its axis is the one off the
      // plane's normal.
      const double sx = -1.5 - px, sz = 0.5 - pz;
      const double s2 = sx * sx + 9 + sz * sz, cosine = 3 / std::sqrt(s2);
      const double angle = std::acos(cosine);
      const double cone = angle <= 0.3 ? 1 : angle >= 0.6 ? 0 : (0.6 - angle) / 0.3;
      inBeam += angle <= 0.3;
      inFade += angle > 0.32 && angle < 0.58;
      const double spot = 3000.0 / 683 * cosine / s2 * cone;
      const double sun = -kSunY;
      const double expected[3] = {rho / kPiD * (point + spot + sun),
                                  rho / kPiD * (0.5 * point + spot + sun),
                                  rho / kPiD * (0.25 * point + spot + sun)};
      for (int c = 0; c < 3; ++c) {
        const double got = r.image.at(x, y)[c];
        worst = std::max(worst, std::fabs(got - expected[c]) / expected[c]);
      }
    }
  EXPECT_LT(worst, 2e-4);
  // The frame holds the spot's beam and its fade.
  EXPECT_GT(inBeam, 20);
  EXPECT_GT(inFade, 20);
}

// An object of a file with lights is warned that they are not used (once per file), unless the
// scene's lights take them.
TEST(GltfLights, AFilesLightsAreNamedUnlessTheSceneTakesThem) {
  TempDir dir;
  test::GltfFile lit;
  lit.doc = lightsFile();
  const int p = lit.addFloats({-1, -1, 0, 1, -1, 0, 0, 1, 0}, "VEC3", 3);
  lit.doc["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", p}}}}}}}};
  lit.doc["nodes"][4]["mesh"] = 0;
  dir.write("lit.gltf", lit.gltf());
  const std::string objects =
      R"("objects": [{"file": "lit.gltf"}, {"file": "lit.gltf", "position": [1, 0, 0]}])";
  const SceneDesc unused = parseSceneText(
      R"({"camera": {"width": 4, "height": 4}, )" + objects + "}", "test.json", dir.path());
  EXPECT_EQ(unused.warnings,
            std::vector<std::string>{
                "test.json: objects[0].file: lit.gltf: the file's lights (KHR_lights_punctual) "
                "are not used (the scene's lights take them with {\"gltf\": file})"});
  const SceneDesc taken = parseSceneText(
      R"({"camera": {"width": 4, "height": 4}, "lights": [{"gltf": "./lit.gltf"}], )" + objects +
          "}",
      "test.json", dir.path());
  EXPECT_TRUE(taken.warnings.empty());
  EXPECT_EQ(taken.lights.size(), 3u);
}

TEST(GltfLights, RefusesWhatItCannotTake) {
  TempDir dir;
  const auto error = [&](const nlohmann::json& doc, const std::string& entry = "") {
    dir.write("l.gltf", doc.dump());
    return test::loadError(
        R"({"camera": {}, "lights": [)" + (entry.empty() ? R"({"gltf": "l.gltf"})" : entry) + "]}",
        dir.path());
  };
  const std::string at = "test.json: lights[0].gltf: l.gltf: ";
  const std::string light0 = at + "extensions.KHR_lights_punctual.lights[0]";
  const std::string light1 = at + "extensions.KHR_lights_punctual.lights[1]";
  nlohmann::json doc = lightsFile();
  doc["extensions"]["KHR_lights_punctual"]["lights"][0]["type"] = "area";
  EXPECT_EQ(error(doc),
            light0 + ".type: expected \"point\", \"spot\" or \"directional\", got \"area\"");
  doc = lightsFile();
  doc["extensions"]["KHR_lights_punctual"]["lights"][0]["intensity"] = -1;
  EXPECT_EQ(error(doc), light0 + ".intensity: expected a non-negative number, got -1");
  doc = lightsFile();
  doc["extensions"]["KHR_lights_punctual"]["lights"][0]["intensity"] = 1e300;
  EXPECT_EQ(error(doc).rfind(light0 + ".intensity: expected a number within single precision", 0),
            0u);
  doc = lightsFile();
  doc["extensions"]["KHR_lights_punctual"]["lights"][0]["color"] = {1, 1};
  EXPECT_EQ(error(doc), light0 + ".color: expected 3 numbers, got 2");
  doc = lightsFile();
  doc["extensions"]["KHR_lights_punctual"]["lights"][1]["spot"]["innerConeAngle"] = 0.6;
  EXPECT_EQ(error(doc), light1 +
                            ".spot.innerConeAngle: expected an angle from 0 to below the "
                            "outerConeAngle, 0.6, got 0.6");
  doc = lightsFile();
  doc["extensions"]["KHR_lights_punctual"]["lights"][1]["spot"]["outerConeAngle"] = 2;
  EXPECT_EQ(error(doc), light1 +
                            ".spot.outerConeAngle: expected an angle above 0, up to pi/2, "
                            "got 2");
  doc = lightsFile();
  doc["nodes"][3]["extensions"]["KHR_lights_punctual"]["light"] = 5;
  EXPECT_EQ(error(doc), at + "nodes[3].extensions.KHR_lights_punctual.light: light 5 does "
                             "not exist (3 lights)");
  doc = lightsFile();
  doc["nodes"][2]["translation"] = {0, 1e200, 0};
  EXPECT_EQ(error(doc), at + "nodes[2]: the light's place is beyond reach");
  doc = lightsFile();
  doc["nodes"][2]["scale"] = {1, 1, 0};
  EXPECT_EQ(error(doc), at + "nodes[2]: the node's transform flattens the light");
  doc = lightsFile();
  doc["scenes"][0]["nodes"] = {4};
  EXPECT_EQ(error(doc), at + "the file's scene places no lights (KHR_lights_punctual)");
  EXPECT_EQ(error(lightsFile(), R"({"gltf": "l.gltf", "intensity": 2})"),
            "test.json: lights[0].intensity: not used beside \"gltf\" (the file gives each of its "
            "lights' values)");
  EXPECT_EQ(error(lightsFile(), R"({"gltf": ""})"),
            "test.json: lights[0].gltf: expected the path of a glTF file, got a string \"\"");
  EXPECT_EQ(error(lightsFile(), R"({"gltf": "gone.gltf"})"),
            "test.json: lights[0].gltf: cannot open \"gone.gltf\" (No such file or "
            "directory)");
}

}  // namespace
}  // namespace candela
