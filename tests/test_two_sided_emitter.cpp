// Two-sided emitters: an emissive material with "two_sided" emits its radiance from both sides of
// each face (pbrt-v4's two-sided diffuse area light), so a lamp panel modelled as one sheet lights
// the room on either side. Such a panel is the same light as two one-sided sheets back to back
// (each the other's mirror, a hair apart): the room renders the same both ways, by next-event
// estimation, by the rays that hit the panel, and by light subpaths that leave either side. The
// light tree weighs the panel's back, which a one-sided panel's points behind it never pick.
// Spheres refuse it, and so does every material that does not emit. A material that reflects
// and emits ("emission_two_sided") is the same light.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "render/light_selection.h"
#include "render_test_util.h"

namespace candela {
namespace {

using test::num;

// The panel: 2 wide and 1.5 high, centred at (0, 3, -1), facing (1, 0, 0.3) normalised. Where it
// stands in the room of test::kSmallRoomWalls, both sides light walls of their own colours.
const Vec3 kCentre(0.0f, 3.0f, -1.0f);
const Vec3 kFacing = normalize(Vec3(1.0f, 0.0f, 0.3f));

// An OBJ file `name` of the panel moved `offset` along kFacing, its two triangles wound to face
// along `side` times kFacing; returns its path (in the test's temporary folder, written whole
// before it is renamed into place, as test::writePlaneObj does).
std::string writePanelObj(const std::string& name, float offset, int side) {
  const Vec3 across = normalize(cross(Vec3(0.0f, 1.0f, 0.0f), kFacing));
  const Vec3 up(0.0f, 0.75f, 0.0f), c = kCentre + kFacing * offset;
  const Vec3 corners[4] = {c - across - up, c + across - up, c + across + up, c - across + up};
  // corners run counter-clockwise seen from along `across` x `up` = kFacing.
  const std::string faces = side > 0 ? "f 1 2 3\nf 1 3 4\n" : "f 1 3 2\nf 1 4 3\n";
  const std::string path = ::testing::TempDir() + name;
  const std::string own = path + "." + std::to_string(getpid()) + ".tmp";
  {
    std::ofstream f(own);
    for (const Vec3& p : corners) f << "v " << p.x << " " << p.y << " " << p.z << "\n";
    f << faces;
  }
  std::rename(own.c_str(), path.c_str());
  return path;
}

const char* const kLamp = R"({"type": "emissive", "radiance": [6, 5.5, 4.5]})";
const char* const kTwoSidedLamp =
    R"({"type": "emissive", "radiance": [6, 5.5, 4.5], "two_sided": true})";

// The room of kSmallRoomWalls with a ball on its floor, lit only by `panels` (JSON objects), seen
// through a camera that sees the panel slanted, at `seed`.
std::string roomWith(const std::string& panels, const std::string& lightPaths, int seed) {
  return R"({
    "camera": {"width": 32, "height": 24, "fov": 70, "position": [2.5, 2.5, 9],
               "look_at": [0, 2.5, 0], "spp": 48},
    "render": {"max_depth": 4, "light_paths": ")" +
         lightPaths + R"(", "seed": )" + std::to_string(seed) + R"(},
    "spheres": [)" +
         test::kSmallRoomWalls + R"(,
                {"position": [1.5, 1, 1], "radius": 1, "color": 0.5}],
    "objects": [)" +
         panels + "]}";
}

std::string panel(const std::string& obj, const char* material) {
  return R"({"file": ")" + obj + R"(", "material": )" + material + "}";
}

TEST(TwoSidedEmitter, APanelLightsTheRoomAsTwoOneSidedPanelsBackToBack) {
  const std::string sheet = writePanelObj("two_sided_sheet.obj", 0.0f, 1);
  const std::string front = writePanelObj("two_sided_front.obj", 1e-4f, 1);
  const std::string back = writePanelObj("two_sided_back.obj", -1e-4f, -1);
  const std::string twoSided = panel(sheet, kTwoSidedLamp);
  const std::string backToBack = panel(front, kLamp) + ", " + panel(back, kLamp);
  for (const std::string lightPaths : {"off", "on"}) {
    SCOPED_TRACE("light_paths " + lightPaths);
    const auto render = [&](const std::string& panels) {
      return test::SeedPair{test::renderTestScene(roomWith(panels, lightPaths, 1)),
                            test::renderTestScene(roomWith(panels, lightPaths, 2))};
    };
    const test::SeedPair one = render(twoSided), two = render(backToBack);
    test::expectSameImage(one, two);
  }
}

// From a point behind the panel, the light tree picks a two-sided panel's triangles, which of a
// one-sided panel it never picks there (they show that point nothing); in front, both are picked.
// A small lamp far away makes the tree weigh the triangles by where they face (two clusters of
// one box and one cone alone are picked by power).
TEST(TwoSidedEmitter, TheLightTreePicksItsTrianglesFromBehind) {
  const std::string sheet = writePanelObj("two_sided_tree.obj", 0.0f, 1);
  const Vec3 behind = kCentre - kFacing * 2.0f, inFront = kCentre + kFacing * 2.0f;
  for (const bool twoSided : {false, true}) {
    std::string json = roomWith(panel(sheet, twoSided ? kTwoSidedLamp : kLamp), "off", 1);
    json.insert(json.size() - 1,
                R"(, "lights": [{"type": "sphere", "position": [-4, 5.5, 8], "radius": 0.2,
                                  "intensity": 5}])");
    const SceneData data = test::loadTestScene(json);
    const SceneView scene = data.view();
    ASSERT_EQ(scene.lightCount, 3u);  // the lamp, then the panel's two triangles
    for (uint32_t i = 1; i < 3; ++i) {
      // Points on the floor, whose hemisphere is up.
      const Vec3 up(0.0f, 1.0f, 0.0f);
      const Vec3 floorBehind(behind.x, 0.0f, behind.z), floorInFront(inFront.x, 0.0f, inFront.z);
      EXPECT_GT(lightSelectPmf(scene, i, floorInFront, up), 0.2f) << i;
      if (twoSided)
        EXPECT_GT(lightSelectPmf(scene, i, floorBehind, up), 0.2f) << i;
      else
        EXPECT_EQ(lightSelectPmf(scene, i, floorBehind, up), 0.0f) << i;
    }
  }
}

TEST(TwoSidedEmitter, TheSceneFormatRefusesItWhereNothingEmitsFromTwoSides) {
  const auto error = [](const std::string& scene) { return test::loadError(scene, "."); };
  const std::string camera = R"("camera": {"width": 8, "height": 8, "fov": 40})";
  EXPECT_EQ(error("{" + camera + R"(, "spheres": [{"position": [0, 0, -5], "radius": 1,
                    "material": {"type": "diffuse", "two_sided": true}}]})"),
            "test.json: spheres[0].material.two_sided: not used by a \"diffuse\" material");
  EXPECT_EQ(
      error("{" + camera + R"(, "spheres": [{"position": [0, 0, -5], "radius": 1,
                    "material": {"type": "emissive", "radiance": 1, "two_sided": "yes"}}]})"),
      "test.json: spheres[0].material.two_sided: expected true or false, got a string \"yes\"");
  EXPECT_EQ(error("{" + camera + R"(, "materials": {"lamp": )" + kTwoSidedLamp + R"(},
                    "spheres": [{"position": [0, 0, -5], "radius": 1, "material": "lamp"}]})"),
            "test.json: spheres[0].material: a two-sided emitter on a sphere, which emits outwards "
            "only; expected a material without \"two_sided\" or \"emission_two_sided\" "
            "(two-sided emitters are mesh faces and rectangle lights)");
  EXPECT_EQ(error("{" + camera + R"(, "spheres": [{"position": [0, 0, -5], "radius": 1,
                    "material": {"type": "diffuse", "emission_two_sided": true}}]})"),
            "test.json: spheres[0].material.emission_two_sided: not used without an \"emission\" "
            "beside it");
  EXPECT_EQ(error("{" + camera + R"(, "spheres": [{"position": [0, 0, -5], "radius": 1,
                    "material": {"type": "glass", "emission": 1, "emission_two_sided": true}}]})"),
            "test.json: spheres[0].material.emission_two_sided: not used by a \"glass\" material");
  EXPECT_EQ(error("{" + camera + R"(, "spheres": [{"position": [0, 0, -5], "radius": 1,
                    "material": {"type": "plastic", "emission": 1, "emission_two_sided": true}}]})")
                .find("a two-sided emitter on a sphere"),
            std::string("test.json: spheres[0].material: ").size());
}

// A sheet that reflects and glows ("emission" with "emission_two_sided" on a diffuse material,
// as glTF's doubleSided emissive materials and Blender's emission are) lights the room as two
// one-sided glowing sheets back to back: each reflects what reaches its side and emits from it.
TEST(TwoSidedEmitter, AGlowingSheetLightsTheRoomAsTwoOneSidedSheetsBackToBack) {
  const std::string sheet = writePanelObj("glowing_sheet.obj", 0.0f, 1);
  const std::string front = writePanelObj("glowing_front.obj", 1e-4f, 1);
  const std::string back = writePanelObj("glowing_back.obj", -1e-4f, -1);
  const char* const glow = R"({"type": "diffuse", "color": 0.5, "emission": [6, 5.5, 4.5]})";
  const char* const twoSidedGlow = R"({"type": "diffuse", "color": 0.5, "emission": [6, 5.5,
      4.5], "emission_two_sided": true})";
  for (const std::string lightPaths : {"off", "on"}) {
    SCOPED_TRACE("light_paths " + lightPaths);
    const auto render = [&](const std::string& panels) {
      return test::SeedPair{test::renderTestScene(roomWith(panels, lightPaths, 1)),
                            test::renderTestScene(roomWith(panels, lightPaths, 2))};
    };
    test::expectSameImage(render(panel(sheet, twoSidedGlow)),
                          render(panel(front, glow) + ", " + panel(back, glow)));
  }
  // And not as one one-sided sheet, whose back is dark: what the test tells apart.
  const RenderResult oneSided = test::renderTestScene(roomWith(panel(sheet, glow), "off", 1));
  const RenderResult twoSided =
      test::renderTestScene(roomWith(panel(sheet, twoSidedGlow), "off", 1));
  double sumOne = 0, sumTwo = 0;
  for (size_t i = 0; i < oneSided.image.pixels.size(); ++i) {
    sumOne += oneSided.image.pixels[i];
    sumTwo += twoSided.image.pixels[i];
  }
  EXPECT_GT(sumTwo, 1.2 * sumOne);
}

}  // namespace
}  // namespace candela
