// Bump maps: a texture of heights tilts the shading normal by its slopes (render/normal_map.h).
// Against closed forms: a plane under a directional light, bumped by heights that rise steadily
// in u and in v, shades as the normal of the raised surface says in every pixel, and its normal
// pass shows that normal; a sphere's normals follow the slopes along its own derivatives; level
// heights change nothing; MTL `bump` with -bm, and the refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/constants.h"
#include "render_test_util.h"
#include "scene/dvec3.h"
#include "scene/read/obj_loader.h"
#include "shading_normal_test_util.h"
#include "texture_test_util.h"

namespace candela {
namespace {

namespace fs = std::filesystem;
using test::num;

// A 4 x 4 grey PFM map whose value rises by `perTexelU` a texel to the right and `perTexelV` a
// texel up: within the map (away from where it repeats) its slopes are 4 perTexelU per unit u
// and 4 perTexelV per unit v.
void writeRampMap(const fs::path& path, float perTexelU, float perTexelV) {
  std::ofstream pfm(path, std::ios::binary);
  pfm << "PF\n4 4\n-1\n";
  for (int row = 0; row < 4; ++row)  // PFM rows run from the bottom: v grows with them
    for (int i = 0; i < 4; ++i) {
      const float value = 0.25f + perTexelU * float(i) + perTexelV * float(row);
      const float texel[3] = {value, value, value};
      pfm.write(reinterpret_cast<const char*>(texel), sizeof texel);
    }
}

const DVec3 kSun{0.3, -1, 0.5};

// Heights h = height f(su u, sv v) raise the surface p(u, v) + h n: its derivatives are
// dp/du + dh/du n and dp/dv + dh/dv n, and its normal their cross product, here
// (-200 dh/du, 40000, 200 dh/dv) up to scale. Every pixel is rho E max(0, n . l) / pi.
// The plane bumped by the ramp of slopes 0.1 and -0.05 a texel, scale 3 and height 120, the map
// turned by `rotation` degrees (and read as the texture object's further keys `more` say),
// expected to show the raised surface's normal for slopes (slopeU, slopeV) along u and v.
void expectRampPlane(const std::string& name, double rotation, double slopeU, double slopeV,
                     const std::string& more = "") {
  const fs::path dir = test::mapTestFolder(name);
  test::writeMappedPlane(dir / "plane.obj");
  writeRampMap(dir / "h.pfm", 0.1f, -0.05f);
  const double rho = 0.6, irradiance = 2;
  const test::RenderedWithNormals r = test::renderWithNormals(
      test::planeUnderSun(
          R"({"type": "diffuse", "color": )" + num(rho) +
              R"(, "bump_map": {"texture": "h.pfm", "scale": [3, 3], "rotation": )" +
              num(rotation) + R"(, "height": 120)" + more + "}}",
          kSun, irradiance),
      dir);
  const DVec3 n = unit(DVec3{-200 * slopeU, 40000, 200 * slopeV});
  const double cosine = -dot(n, unit(kSun));
  ASSERT_GT(cosine, 0.0);
  ASSERT_GT(std::fabs(cosine + unit(kSun).y), 0.05);  // the tilt shows (flat: 0.864)
  test::expectUniformPlane(r, rho * irradiance * cosine / kPi, n, 1e-5);
}

const double kHeight = 120, kScale = 3;

TEST(BumpMap, HeightsThatRiseSteadilyShadeAPlaneAsTheRaisedSurfacesNormal) {
  expectRampPlane("bump_map_ramp", 0, kHeight * kScale * 4 * 0.1, kHeight * kScale * 4 * -0.05);
}

// A map turned by 90 degrees reads heights f(s, t) at (s, t) = (sv v, -su u): dh/du = -su
// height f_t and dh/dv = sv height f_s, so the ramp's slopes trade places on the plane.
TEST(BumpMap, ATurnedMapTurnsItsSlopes) {
  expectRampPlane("bump_map_turned", 90, -kScale * kHeight * 4 * -0.05, kScale * kHeight * 4 * 0.1);
}

// The camera sees the plane's uv (0.5, 0.5), (1.5, 1.5) in the map's copies, the second copy in
// each direction: mirrored, its heights fall where they rose; clamped, they are level.
TEST(BumpMap, AMirroredCopyMirrorsItsSlopes) {
  expectRampPlane("bump_map_mirrored", 0, -kHeight * kScale * 4 * 0.1,
                  -kHeight * kScale * 4 * -0.05, R"(, "wrap": "mirror")");
  // Clamped above its top edge, the map is level along v.
  expectRampPlane("bump_map_mirrored_u", 0, -kHeight * kScale * 4 * 0.1, 0,
                  R"(, "wrap": ["mirror", "clamp"])");
}

// A sphere of radius R raised by heights h: its derivatives dp/du = 2 pi R (-d.z, 0, d.x) and
// dp/dv = pi R (y - d.y d) / sin(theta) at the unit direction d of a point (u along the azimuth,
// v towards +y), each raised by h's slope along d. Seen from -z (u near 0.5, away from the seam)
// the normal pass at each pixel's analytic hit is the raised surface's normal (its tilt mirrored
// where it turns from the eye).
TEST(BumpMap, ASphereRaisesItsOwnDerivatives) {
  const fs::path dir = test::mapTestFolder("bump_map_sphere");
  writeRampMap(dir / "h.pfm", 0.1f, 0.07f);
  const double radius = 2, height = 3;
  const test::RenderedWithNormals r = test::renderWithNormals(R"({
    "camera": {"width": 24, "height": 24, "fov": 40, "position": [0, 0, -10], "look_at": [0, 0, 0],
               "spp": 1},
    "render": {"antialiasing": false, "max_depth": 1},
    "spheres": [{"position": [0, 0, 0], "radius": 2,
                 "material": {"type": "diffuse", "bump_map": {"texture": "h.pfm", "height": 3}}}],
    "environment": {"color": 1}})",
                                                              dir);
  const double slopeU = height * 4 * 0.1, slopeV = height * 4 * 0.07;
  const DVec3 o = dvec3(r.data.camera.position);
  const int checked =
      test::forEachSphereHit(r.data.camera, radius, [&](uint32_t x, uint32_t y, const DVec3& d) {
        const double sinTheta = std::sqrt(d.x * d.x + d.z * d.z);
        const DVec3 dpdu = (2 * kPi * radius) * DVec3{-d.z, 0, d.x};
        const DVec3 dpdv = (kPi * radius / sinTheta) * (DVec3{0, 1, 0} - d.y * d);
        DVec3 n = unit(cross(dpdu + slopeU * d, dpdv + slopeV * d));
        if (dot(n, d) < 0) n = -1.0 * n;
        test::expectMappedNormal(r, x, y, n, d, unit(o - radius * d), 1e-4);
      });
  EXPECT_GT(checked, 100);
}

// Level heights tilt nothing: the image and normal pass are the plain plane's, whatever the
// height's scale.
TEST(BumpMap, LevelHeightsChangeNothing) {
  const fs::path dir = test::mapTestFolder("bump_map_level");
  test::writeMappedPlane(dir / "plane.obj");
  writeRampMap(dir / "h.pfm", 0.0f, 0.0f);
  const test::RenderedWithNormals plain = test::renderWithNormals(
      test::planeUnderSun(R"({"type": "diffuse", "color": 0.6})", kSun, 2), dir);
  const test::RenderedWithNormals bumped =
      test::renderWithNormals(test::planeUnderSun(R"({"type": "diffuse", "color": 0.6,
                              "bump_map": {"texture": "h.pfm", "height": -1000}})",
                                                  kSun, 2),
                              dir);
  for (uint32_t y = 0; y < 16; ++y)
    for (uint32_t x = 0; x < 24; ++x)
      EXPECT_NEAR(bumped.result.image.at(x, y).x, plain.result.image.at(x, y).x, 1e-6);
  ASSERT_EQ(bumped.layers[0].pixels.size(), plain.layers[0].pixels.size());
  for (size_t i = 0; i < plain.layers[0].pixels.size(); ++i)
    EXPECT_NEAR(bumped.layers[0].pixels[i], plain.layers[0].pixels[i], 1e-6);
}

// MTL `bump` (or `map_Bump`) names a bump map where the material has no `norm`, -bm its height
// (default 1) and -s its scale; beside a `norm` it is not read, and the scene says so.
TEST(BumpMap, MtlBumpReadsHeightsWithItsMultiplier) {
  const fs::path dir = test::mapTestFolder("bump_map_mtl");
  writeRampMap(dir / "h.pfm", 0.1f, 0.0f);
  std::ofstream(dir / "m.obj") << "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\n"
                                  "vt 0 1\nusemtl a\nf 1/1 2/2 3/3\nusemtl b\nf 1/1 2/2 3/3\n"
                                  "usemtl c\nf 1/1 2/2 3/3\n";
  std::ofstream(dir / "m.mtl") << "newmtl a\nKd 0.5 0.5 0.5\nmap_Bump -bm 0.25 -s 2 2 h.pfm\n"
                                  "newmtl b\nbump h.pfm\nnorm h.pfm\nnewmtl c\nbump h.pfm\n";
  const std::string json =
      R"({"camera": {"width": 4, "height": 4}, "objects": [{"file": "m.obj"}]})";
  const SceneDesc desc = parseSceneText(json, "s.json", dir.string());
  EXPECT_EQ(desc.warnings,
            std::vector<std::string>{
                "s.json: objects[0].file: m.mtl:5: \"bump\" is not read: material \"b\" has a "
                "normal map (\"norm\"), which it renders with instead"});
  const SceneData data = test::loadTestScene(json, dir.string());
  ASSERT_EQ(data.materials.size(), 3u);
  EXPECT_EQ(data.materials[0].bumpHeight, 0.25f);
  EXPECT_GE(data.materials[0].normalMap.index, 0);
  EXPECT_EQ(data.materials[0].normalMap.scaleU, 2.0f);
  EXPECT_EQ(data.materials[1].bumpHeight, 0.0f);  // the normal map
  EXPECT_GE(data.materials[1].normalMap.index, 0);
  EXPECT_EQ(data.materials[2].bumpHeight, 1.0f);

  const auto error = [&](const std::string& statement) {
    std::ofstream(dir / "m.mtl") << "newmtl a\n" << statement << "\n";
    return test::loadError(json, dir.string());
  };
  EXPECT_EQ(error("bump -bm 0 h.pfm"),
            "test.json: objects[0].file: m.mtl:2: bump -bm: expected a finite, non-zero "
            "multiplier, got \"0\"");
  EXPECT_EQ(error("map_Bump -bm h.pfm"),
            "test.json: objects[0].file: m.mtl:2: map_Bump -bm: expected a finite, non-zero "
            "multiplier, got \"h.pfm\"");
  EXPECT_EQ(error("bump -mm 0 1 h.pfm"),
            "test.json: objects[0].file: m.mtl:2: bump option \"-mm\" is not supported (only "
            "-s, -o, -clamp and -bm)");
}

// Blender's exporter writes tangent-space normal maps as `map_Bump`: a bump map whose texels are
// unit normals, not grey, is read as the normal map it is (the same material as `norm` makes),
// and the scene says so; grey heights, even ones whose texels happen to decode to unit length,
// stay heights.
TEST(BumpMap, MtlBumpOfUnitNormalsIsReadAsANormalMap) {
  const fs::path dir = test::mapTestFolder("bump_map_normals");
  // 2 x 2 normals tilted every way by 30 degrees, and a flat one: (0.5 n + 0.5) in 8 bits.
  ASSERT_TRUE(test::writeTestPng((dir / "n.png").string(), 2, 2, 3,
                                 {191, 128, 238, 64, 128, 238, 128, 191, 238, 128, 128, 255}));
  ASSERT_TRUE(test::writeTestPng((dir / "grey.png").string(), 1, 1, 3, {204, 204, 204}));
  std::ofstream(dir / "m.obj") << "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\n"
                                  "vt 0 1\nusemtl a\nf 1/1 2/2 3/3\nusemtl b\nf 1/1 2/2 3/3\n"
                                  "usemtl c\nf 1/1 2/2 3/3\n";
  std::ofstream(dir / "m.mtl") << "newmtl a\nmap_Bump -bm 0.5 n.png\nnewmtl b\nnorm n.png\n"
                                  "newmtl c\nbump grey.png\n";
  const std::string json =
      R"({"camera": {"width": 4, "height": 4}, "objects": [{"file": "m.obj"}]})";
  const SceneDesc desc = parseSceneText(json, "s.json", dir.string());
  EXPECT_EQ(desc.warnings,
            std::vector<std::string>{
                "s.json: objects[0].file: m.mtl:2: \"map_Bump\" names n.png, whose texels are "
                "unit normals: read as a tangent-space normal map (as Blender writes them there), "
                "its -bm not used; write it as \"norm\" to say so"});
  const SceneData data = test::loadTestScene(json, dir.string());
  ASSERT_EQ(data.materials.size(), 3u);
  EXPECT_EQ(data.materials[0].bumpHeight, 0.0f);
  EXPECT_EQ(data.materials[0].normalMap.index, data.materials[1].normalMap.index);
  EXPECT_GE(data.materials[0].normalMap.index, 0);
  EXPECT_EQ(data.materials[1].bumpHeight, 0.0f);
  EXPECT_EQ(data.materials[2].bumpHeight, 1.0f);  // grey 0.8 decodes to length 1.04, yet is grey
}

TEST(BumpMap, TheSceneFormatRefusesWhatItCannotBe) {
  const fs::path dir = test::mapTestFolder("bump_map_errors");
  writeRampMap(dir / "h.pfm", 0.1f, 0.0f);
  const auto error = [&](const std::string& material) {
    return test::materialError(dir, material);
  };
  EXPECT_EQ(error(R"({"type": "plastic", "bump_map": {"texture": "h.pfm", "height": 0.01}})"),
            "(no error)");
  EXPECT_EQ(error(R"({"type": "emissive", "radiance": 1, "bump_map": {"texture": "h.pfm"}})"),
            "s.json: materials.m.bump_map: not used by an \"emissive\" material");
  EXPECT_EQ(error(R"({"type": "diffuse", "bump_map": {"texture": "h.pfm"},
                      "normal_map": {"texture": "h.pfm"}})"),
            "s.json: materials.m: give a material a \"normal_map\" or a \"bump_map\", not both");
  EXPECT_EQ(error(R"({"type": "diffuse", "bump_map": {"texture": "h.pfm", "height": 0}})"),
            "s.json: materials.m.bump_map.height: expected a finite, non-zero number, got 0");
  EXPECT_EQ(error(R"({"type": "diffuse", "bump_map": {"texture": "h.pfm", "height": "1"}})"),
            "s.json: materials.m.bump_map.height: expected a finite, non-zero number, got a "
            "string \"1\"");
  EXPECT_EQ(
      error(R"({"type": "diffuse", "bump_map": {"texture": "h.pfm", "strength": 1}})"),
      "s.json: materials.m.bump_map.strength: unknown key, expected one of \"texture\", "
      "\"checkerboard\", \"scale\", \"offset\", \"rotation\", \"wrap\", \"filter\", \"height\"");
  EXPECT_EQ(error(R"({"type": "diffuse", "bump_map": "h.pfm"})"),
            "s.json: materials.m.bump_map: expected a texture object {\"texture\": file, "
            "\"scale\": [su, sv], \"height\": h}, got a string \"h.pfm\"");
}

}  // namespace
}  // namespace candela
