// Vertex colours: read from OBJ (`v x y z r g b`, sRGB), PLY (test_ply_loader.cpp) and glTF
// (COLOR_0, linear), interpolated across each face and multiplying the colour of whatever
// material shades the mesh. Against the closed form: a quad of four coloured corners under a sun,
// pixel for pixel, beside a quad without colours; an object that leaves its colours; the
// refusals.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <fstream>
#include <string>

#include "gltf_test_util.h"
#include "render_test_util.h"
#include "scene/read/gltf_loader.h"
#include "scene/read/scene_loader.h"
#include "temp_dir.h"

namespace candela {
namespace {

using test::num;
using test::TempDir;

constexpr double kPiD = 3.14159265358979323846;

double srgbToLinear(double s) {
  return s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4);
}

// The corners of the quad [-1, 1] x [-1, 1] in the plane y = 0, as sRGB colours.
constexpr double kCorner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
constexpr double kColour[4][3] = {{1, 0.2, 0.1}, {0.1, 0.9, 0.3}, {0.3, 0.4, 1}, {0.8, 0.8, 0}};

// The quad as an OBJ with its corners' colours, faces 1 3 2 and 1 4 3 (facing +y).
std::string colouredQuadObj() {
  std::string text;
  for (int v = 0; v < 4; ++v)
    text += "v " + num(kCorner[v][0]) + " 0 " + num(kCorner[v][1]) + " " + num(kColour[v][0]) +
            " " + num(kColour[v][1]) + " " + num(kColour[v][2]) + "\n";
  return text + "f 1 3 2\nf 1 4 3\n";
}

// The linear colour at (x, z) of the quad: its triangle's corners' colours made linear and
// weighted by the point's barycentrics.
std::array<double, 3> colourAt(double x, double z) {
  // Triangle (0, 2, 1) below the diagonal z = x, (0, 3, 2) above it.
  const int tri[2][3] = {{0, 2, 1}, {0, 3, 2}};
  const int* t = z <= x ? tri[0] : tri[1];
  const auto& a = kCorner[t[0]];
  const auto& b = kCorner[t[1]];
  const auto& c = kCorner[t[2]];
  const double det = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
  const double wb = ((x - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (z - a[1])) / det;
  const double wc = ((b[0] - a[0]) * (z - a[1]) - (x - a[0]) * (b[1] - a[1])) / det;
  const double w[3] = {1 - wb - wc, wb, wc};
  std::array<double, 3> out{0, 0, 0};
  for (int k = 0; k < 3; ++k)
    for (int ch = 0; ch < 3; ++ch) out[size_t(ch)] += w[k] * srgbToLinear(kColour[t[k]][ch]);
  return out;
}

// A sun straight down of irradiance 1 over the coloured quad (its default material diffuse 1,
// so its colours are its albedo) and a plain quad beside it (diffuse 0.8), seen from above
// through pixel centres at one bounce: every pixel is albedo / pi.
TEST(VertexColors, AQuadsCornerColoursAreInterpolatedAcrossItsFaces) {
  TempDir dir;
  dir.write("coloured.obj", colouredQuadObj());
  dir.write("plain.obj", "v 1.2 0 -1\nv 3 0 -1\nv 3 0 1\nv 1.2 0 1\nf 1 3 2\nf 1 4 3\n");
  const auto render = [&](const std::string& coloured) {
    return test::renderTestScene(R"({
      "camera": {"width": 60, "height": 30, "fov": 90, "position": [1, 2, 0],
                 "look_at": [1, 0, 0.001], "up": [0, 0, -1], "spp": 1},
      "render": {"antialiasing": false, "max_depth": 1},
      "objects": [{"file": "plain.obj"}, )" +
                                     coloured + R"(],
      "lights": [{"type": "directional", "direction": [0, -1, 0], "intensity": 1}]})",
                                 0, dir.path());
  };
  const SceneData data = test::loadTestScene(R"({
      "camera": {"width": 60, "height": 30, "fov": 90, "position": [1, 2, 0],
                 "look_at": [1, 0, 0.001], "up": [0, 0, -1]},
      "objects": [{"file": "plain.obj"}, {"file": "coloured.obj"}]})",
                                             dir.path());
  const RenderResult colours = render(R"({"file": "coloured.obj"})");
  const RenderResult tinted = render(R"({"file": "coloured.obj", "color": 0.5})");
  const RenderResult left = render(R"({"file": "coloured.obj", "vertex_colors": false})");
  const Camera& cam = data.camera;
  int coloured = 0, plain = 0;
  double worst = 0;
  for (uint32_t y = 0; y < 30; ++y)
    for (uint32_t x = 0; x < 60; ++x) {
      const Vec3 d = cam.cameraToWorld * (cam.inverseK * Vec3(x + 0.5f, y + 0.5f, 1.0f));
      const double t = -double(cam.position.y) / d.y;
      const double px = cam.position.x + t * d.x, pz = cam.position.z + t * d.z;
      const bool onColoured = std::fabs(px) < 0.98 && std::fabs(pz) < 0.98;
      const bool onPlain = px > 1.22 && px < 2.98 && std::fabs(pz) < 0.98;
      if (!onColoured && !onPlain) continue;
      (onColoured ? coloured : plain) += 1;
      const std::array<double, 3> albedo =
          onColoured ? colourAt(px, pz) : std::array<double, 3>{0.8, 0.8, 0.8};
      for (int c = 0; c < 3; ++c) {
        const double expected = albedo[size_t(c)] / kPiD;
        const auto rel = [&](double got, double want) { return std::fabs(got - want) / want; };
        worst = std::max(worst, rel(colours.image.at(x, y)[c], expected));
        // The scene's colour 0.5 tints the vertex colours; "vertex_colors": false leaves them
        // (its default material diffuse 1).
        worst =
            std::max(worst, rel(tinted.image.at(x, y)[c], onColoured ? 0.5 * expected : expected));
        worst = std::max(worst, rel(left.image.at(x, y)[c], onColoured ? 1 / kPiD : expected));
      }
    }
  EXPECT_GT(coloured, 400);
  EXPECT_GT(plain, 300);
  EXPECT_LT(worst, 2e-4);
}

// glTF's COLOR_0, linear: RGBA bytes normalized (the alpha dropped) on one primitive, floats on
// another, and none on a third, whose vertices take 1.
TEST(VertexColors, GltfColoursAreReadPerPrimitive) {
  TempDir dir;
  test::GltfFile f;
  const int p = f.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3);
  const int bytes = f.addAccessor(std::vector<uint8_t>{255, 0, 51, 7, 0, 255, 0, 7, 0, 0, 255, 7},
                                  5121, "VEC4", 3, 0, true);
  const int floats = f.addFloats({0.25f, 0.5f, 0.75f, 1, 1, 1, 0, 0, 0}, "VEC3", 3);
  const auto primitive = [&](int colours) {
    nlohmann::json a = {{"POSITION", p}};
    if (colours >= 0) a["COLOR_0"] = colours;
    return nlohmann::json{{"attributes", a}};
  };
  f.doc["meshes"] = {{{"primitives", {primitive(-1), primitive(bytes), primitive(floats)}}}};
  f.doc["nodes"] = {{{"mesh", 0}}};
  std::vector<std::shared_ptr<const TextureDesc>> textures;
  TextureLoader loader(textures, dir.path());
  const MeshDesc mesh = loadGltfFile(dir.write("c.gltf", f.gltf()), "c.gltf", loader);
  ASSERT_EQ(mesh.positions.size(), 9u);
  ASSERT_EQ(mesh.colors.size(), 9u);
  for (int v = 0; v < 3; ++v) EXPECT_EQ(mesh.colors[size_t(v)].x, 1.0f);
  EXPECT_FLOAT_EQ(mesh.colors[3].x, 1.0f);
  EXPECT_FLOAT_EQ(mesh.colors[3].z, 0.2f);
  EXPECT_FLOAT_EQ(mesh.colors[4].y, 1.0f);
  EXPECT_FLOAT_EQ(mesh.colors[4].z, 0.0f);
  EXPECT_FLOAT_EQ(mesh.colors[5].z, 1.0f);
  EXPECT_FLOAT_EQ(mesh.colors[6].y, 0.5f);
  EXPECT_FLOAT_EQ(mesh.colors[8].x, 0.0f);

  f.doc["accessors"][size_t(floats)]["count"] = 2;
  EXPECT_THROW(loadGltfFile(dir.write("short.gltf", f.gltf()), "short.gltf", loader), SceneError);
  test::GltfFile g;
  const int gp = g.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3);
  const int bright = g.addFloats({0, 0, 0, 1.5f, 0, 0, 0, 0, 0}, "VEC3", 3);
  g.doc["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", gp}, {"COLOR_0", bright}}}}}}}};
  g.doc["nodes"] = {{{"mesh", 0}}};
  try {
    loadGltfFile(dir.write("bright.gltf", g.gltf()), "bright.gltf", loader);
    ADD_FAILURE() << "a colour of 1.5 was taken";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()),
              "bright.gltf: meshes[0].primitives[0].attributes.COLOR_0: accessor 1, element 1: "
              "expected colours from 0 to 1, got 1.5");
  }
}

TEST(VertexColors, AnObjColourOutsideZeroToOneIsRefusedAtItsLine) {
  TempDir dir;
  dir.write("bad.obj", "v 0 0 0 1 1 1\nv 1 0 0 1.5 0 0\nv 0 1 0 0 0 0\nf 1 2 3\n");
  EXPECT_EQ(test::loadError(R"({"camera": {}, "objects": [{"file": "bad.obj"}]})", dir.path()),
            "test.json: objects[0].file: bad.obj:2: expected a vertex colour \"v x y z r g b\" of "
            "numbers from 0 to 1, got \"1.5\"");
  dir.write("some.obj", "v 0 0 0 1 1 1\nv 1 0 0\nv 0 1 0 0 0 0\nf 1 2 3\n");
  const SceneDesc some = parseSceneText(R"({"camera": {}, "objects": [{"file": "some.obj"}]})",
                                        "test.json", dir.path());
  EXPECT_TRUE(some.objects[0].mesh->colors.empty());
  EXPECT_EQ(some.warnings, std::vector<std::string>{
                               "test.json: objects[0].file: some.obj:2: a vertex without a colour, "
                               "where 2 of the file's 3 have one: no vertex colours are used"});
  EXPECT_EQ(test::loadError(R"({"camera": {}, "objects": [{"file": "bad.obj",
                               "vertex_colors": 1}]})",
                            dir.path()),
            "test.json: objects[0].vertex_colors: expected true or false, got 1");
}

}  // namespace
}  // namespace candela
