// Emission on materials that reflect ("emission" on diffuse, conductor, plastic, glass and mix
// materials; MTL Ke beside a Kd): the surface adds its radiance where a path meets it and goes on
// scattering, and it is a light. Against closed forms: a glowing ball alone under a sky shows its
// emission plus what it reflects of the sky (convex: it sees none of itself), and inside a closed
// box whose walls glow and reflect, the radiance Le / (1 - rho) of the infinite series of bounces
// holds everywhere, with next-event estimation, BSDF hits and light subpaths all finding the
// walls (a mix's walls too, whose emission is the mix's own). Then reading: refusals, and MTL.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "render/aov_layers.h"
#include "render/bsdf.h"
#include "render_test_util.h"
#include "shading_normal_test_util.h"

namespace candela {
namespace {

namespace fs = std::filesystem;
using test::num;
using test::regionStats;

constexpr double kZ = 5.0;  // as test_render_closed_form.cpp: a correct renderer never fails

const std::array<double, 3> kSky = {0.3, 0.45, 0.8};
const std::array<double, 3> kGlow = {1.0, 0.5, 0.25};

// A ball of `material` (JSON) alone under the constant sky kSky, seen from 5 units away; pixels
// 10..22 of the 32 x 32 image lie on it.
std::string ballUnderTheSky(const std::string& material, int spp) {
  return R"({
    "camera": {"width": 32, "height": 32, "fov": 30, "position": [0, 0, 5], "look_at": [0, 0, 0],
               "spp": )" +
         std::to_string(spp) + R"(},
    "render": {"max_depth": 8},
    "environment": {"color": [)" +
         num(kSky[0]) + ", " + num(kSky[1]) + ", " + num(kSky[2]) + R"(]},
    "spheres": [{"position": [0, 0, 0], "radius": 1, "material": )" +
         material + "}]}";
}

// A convex diffuse ball of albedo rho and emission Le under a constant sky L sees only the sky
// over every point's hemisphere: it shows Le + rho L. Its emission pass is Le and its albedo rho,
// and it is a light (sampled from its own surface too, where it must add nothing).
TEST(SurfaceEmission, AGlowingBallShowsItsEmissionAndTheSkyItReflects) {
  const double rho = 0.5;
  const std::string scene = ballUnderTheSky(
      R"({"type": "diffuse", "color": )" + num(rho) + R"(, "emission": [)" + num(kGlow[0] / 2) +
          ", " + num(kGlow[1] / 2) + ", " + num(kGlow[2] / 2) + R"(], "emission_strength": 2})",
      64);
  const SceneData data = test::loadTestScene(scene);
  ASSERT_EQ(data.view().lightCount, 2u);  // the sky and the ball
  RenderOptions options;
  options.aovs = true;
  const RenderResult r = renderCpu(data.view(), options);
  const std::vector<ImageLayer> passes = makeAovLayers(data, {Aov::Emission, Aov::Albedo}, r.aovs);
  for (int c = 0; c < 3; ++c) {
    const auto s = regionStats(r.image, 12, 12, 20, 20, c);
    const double expected = kGlow[c] + rho * kSky[c];
    EXPECT_NEAR(s.mean, expected, kZ * s.standardError() + 1e-4) << "channel " << c;
    EXPECT_LT(s.stddev, 0.05 * expected) << "channel " << c;  // the sky's NEE and BSDF samples
    const size_t centre = 3 * (16 * 32 + 16) + c;
    EXPECT_NEAR(passes[0].pixels[centre], kGlow[c], 1e-5) << "channel " << c;
    EXPECT_NEAR(passes[1].pixels[centre], rho, 1e-6) << "channel " << c;
  }
  EXPECT_NEAR(r.image.at(0, 0).x, kSky[0], 1e-6);  // the sky beside it
}

// Writes a closed box [-1, 1]^3 whose faces run counter-clockwise seen from inside (so its
// "outside", the side that emits, faces in) into `path`.
void writeInwardBox(const fs::path& path) {
  std::ofstream obj(path);
  for (int i = 0; i < 8; ++i)
    obj << "v " << (i & 1 ? 1 : -1) << " " << (i & 2 ? 1 : -1) << " " << (i & 4 ? 1 : -1) << "\n";
  // Each face's corners run counter-clockwise about +axis, which faces in at -1; at +1 reversed.
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      const int a = 1 << axis, b = 1 << ((axis + 1) % 3), c = 1 << ((axis + 2) % 3);
      const int base = side ? a : 0;
      int quad[4] = {base, base | b, base | b | c, base | c};
      if (side == 1) std::swap(quad[1], quad[3]);
      obj << "f " << quad[0] + 1 << " " << quad[1] + 1 << " " << quad[2] + 1 << "\nf "
          << quad[0] + 1 << " " << quad[2] + 1 << " " << quad[3] + 1 << "\n";
    }
}

// Inside a closed box whose walls all reflect with albedo rho and emit Le towards the inside,
// the radiance everywhere is Le + rho (Le + rho (...)) = Le / (1 - rho): the walls are lights met
// by BSDF samples and next-event estimation at once, weighted by MIS, and light subpaths start
// from them and connect to camera paths on them. Walls of diffuse 0.5, and of a mix of diffuse
// 0.2 and 0.8 (mean 0.5) whose emission is the mix's, both give 2 Le.
TEST(SurfaceEmission, AGlowingBoxHoldsTheSeriesOfItsBounces) {
  const fs::path dir = test::mapTestFolder("glowing_box");
  writeInwardBox(dir / "box.obj");
  const std::string glow = R"("emission": [1.0, 0.5, 0.25])";
  for (const std::string& walls :
       {R"({"type": "diffuse", "color": 0.5, )" + glow + "}",
        R"({"type": "mix", "materials": [{"type": "diffuse", "color": 0.2},
                                         {"type": "diffuse", "color": 0.8}], )" +
            glow + "}"}) {
    const std::string scene = R"({
      "camera": {"width": 16, "height": 16, "fov": 90, "position": [0.2, -0.1, 0.3],
                 "look_at": [1, 0.5, -1], "spp": 64},
      "render": {"max_depth": 200},
      "objects": [{"file": "box.obj", "material": )" +
                              walls + "}]}";
    const SceneData data = test::loadTestScene(scene, dir.string());
    EXPECT_EQ(data.view().lightCount, 12u) << walls;
    EXPECT_GT(data.view().lightPathLights, 0u) << walls;  // the connections run
    const RenderResult r = test::renderTestScene(scene, 0, dir.string());
    for (int c = 0; c < 3; ++c) {
      const auto s = regionStats(r.image, 0, 0, 16, 16, c);
      EXPECT_NEAR(s.mean, 2 * kGlow[c], kZ * s.standardError() + 1e-4)
          << "channel " << c << ", walls " << walls;
    }
  }
}

std::string materialError(const std::string& material) {
  return test::loadError(
      R"({"camera": {"width": 4, "height": 4}, "materials": {"m": )" + material + "}}", ".");
}

TEST(SurfaceEmission, RefusesWhatCannotEmit) {
  EXPECT_EQ(materialError(R"({"type": "plastic", "emission_strength": 2})"),
            "test.json: materials.m.emission_strength: not used without an \"emission\" beside "
            "it");
  EXPECT_EQ(materialError(R"({"type": "diffuse", "emission": [1, -1, 0]})"),
            "test.json: materials.m.emission[1]: expected a non-negative number, got -1");
  EXPECT_EQ(materialError(R"({"type": "diffuse", "emission": 1, "alpha": 0.5})"),
            "test.json: materials.m.emission: makes a light of a surface with an \"alpha\", which "
            "lights sample over all their area; expected no \"alpha\" on an emitting material");
  EXPECT_EQ(materialError(R"({"type": "thin_glass", "emission": 1})"),
            "test.json: materials.m.emission: not used by a \"thin_glass\" material");
  EXPECT_EQ(materialError(R"({"type": "emissive", "radiance": 1, "emission": 1})"),
            "test.json: materials.m.emission: not used by an \"emissive\" material (it emits "
            "its \"radiance\" times its \"strength\")");
  EXPECT_EQ(materialError(R"({"type": "diffuse", "emission": 1e20, "emission_strength": 1e20})"),
            "test.json: materials.m.emission_strength: the radiance [1e+20, 1e+20, 1e+20] times "
            "emission_strength 1e+20 is beyond single precision; expected a smaller "
            "emission_strength");
  EXPECT_EQ(materialError(R"({"type": "mix", "materials": ["diffuse",
                                                           {"type": "diffuse", "emission": 1}]})"),
            "test.json: materials.m.materials[1]: a material with an \"emission\" in a mix; "
            "expected the \"emission\" on the mix, which emits from the whole surface");
  // A black emission is none: no light.
  EXPECT_EQ(test::loadTestScene(ballUnderTheSky(R"({"type": "diffuse", "emission": 0})", 1))
                .view()
                .lightCount,
            1u);
}

// MTL: a Ke beside a Kd (as Blender writes a material with an emission), a map_Kd or a Ks makes
// the material it would be without Ke emit as well; a Ke alone (or beside a black Kd) is an
// emissive material, as before. With a Pm the emission is the mix's; an alpha is not used, with a
// warning at its line.
TEST(SurfaceEmission, MtlKeBesideAKdReflectsAndEmits) {
  const fs::path dir = test::mapTestFolder("emission_mtl");
  std::ofstream(dir / "quad.obj") << "mtllib quad.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                  << "usemtl screen\nf 1 2 3\nusemtl lamp\nf 1 3 4\n"
                                  << "usemtl metal\nf 1 2 4\nusemtl bulb\nf 2 3 4\n";
  std::ofstream(dir / "quad.mtl") << "newmtl screen\nKd 0.1 0.1 0.1\nKs 0.5 0.5 0.5\nNs 200\n"
                                  << "Ke 2 3 4\nd 0.5\n"
                                  << "newmtl lamp\nKd 0 0 0\nKe 5 5 5\n"
                                  << "newmtl metal\nKd 0.9 0.6 0.2\nKe 1 0 0\nPm 0.5\n"
                                  << "newmtl bulb\nKe 7 7 7\n";
  const SceneDesc scene =
      parseSceneText(R"({"camera": {"width": 4, "height": 4}, "objects": [{"file": "quad.obj"}]})",
                     "s.json", dir.string());
  const MeshDesc& mesh = *scene.objects[0].mesh;
  ASSERT_EQ(mesh.materials.size(), 4u);
  const Material& screen = mesh.materials[0];
  EXPECT_EQ(screen.type, MaterialType::Plastic);
  EXPECT_FLOAT_EQ(screen.radiance.z, 4.0f);
  EXPECT_FALSE(isMasked(screen.alpha));
  EXPECT_EQ(mesh.warnings,
            std::vector<std::string>{"quad.mtl:6: the alpha is not used: the material emits (Ke), "
                                     "and an emitting surface is a light over all its area"});
  EXPECT_EQ(mesh.materials[1].type, MaterialType::Emissive);
  const Material& metal = mesh.materials[2];
  ASSERT_EQ(metal.type, MaterialType::Mix);
  EXPECT_FLOAT_EQ(metal.radiance.x, 1.0f);
  ASSERT_EQ(mesh.mixParts.size(), 2u);
  for (const Material& part : mesh.mixParts) EXPECT_FALSE(hasEmission(part));
  EXPECT_EQ(mesh.materials[3].type, MaterialType::Emissive);
  EXPECT_FLOAT_EQ(mesh.materials[3].radiance.y, 7.0f);
  // All four faces are lights.
  EXPECT_EQ(flattenScene(scene).view().lightCount, 4u);
}

}  // namespace
}  // namespace candela
