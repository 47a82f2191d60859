// Roughness textures: a texture's value is the roughness of a conductor, glass or plastic at each
// point. A plane under a directional light, one bounce, renders without noise, so a textured
// roughness is held against the same material with the roughness as a number: a constant texture
// renders as that number, a striped one as each of its two numbers in its stripes. The rough
// plastic's coat tables, one per roughness level for a textured plastic, are checked against the
// quadrature they interpolate; MTL's Pr and map_Pr, and the refusals.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <tuple>
#include <vector>

#include "render/bsdf_plastic.h"
#include "render/material_prepare.h"
#include "render/surface_layers.h"
#include "render_test_util.h"
#include "shading_normal_test_util.h"
#include "texture_test_util.h"

namespace candela {
namespace {

namespace fs = std::filesystem;
using test::num;

// A grey PFM of `values.size()` x 1 texels, left to right.
void writeRowMap(const fs::path& path, const std::vector<float>& values) {
  std::vector<Vec3> texels;
  for (float value : values) texels.push_back(Vec3(value));
  test::writeRowPfm(path, texels);
}

const DVec3 kSun{0.3, -1, 0.5};

// The plane of writeMappedPlane in `material` under the sun, seen from above: its first channel.
std::vector<float> planeImage(const fs::path& dir, const std::string& material) {
  const test::RenderedWithNormals r =
      test::renderWithNormals(test::planeUnderSun(material, kSun, 2), dir);
  std::vector<float> values;
  for (uint32_t y = 0; y < r.data.camera.height; ++y)
    for (uint32_t x = 0; x < r.data.camera.width; ++x) values.push_back(r.result.image.at(x, y).x);
  return values;
}

// A constant texture renders every pixel as the same material with that roughness as a number:
// exactly (to rounding) for the conductor, glass, and the plastic at one of its table's levels;
// between levels the plastic's interpolated coat, within its tables' agreement (below).
TEST(RoughnessTexture, AConstantTextureRendersAsItsValue) {
  const fs::path dir = test::mapTestFolder("roughness_constant");
  test::writeMappedPlane(dir / "plane.obj");
  struct Case {
    const char* material;  // with the roughness left to add
    float roughness;
    float tolerance;  // relative, per pixel
  };
  const std::vector<Case> cases = {
      {R"("type": "conductor", "metal": "Au")", 0.4f, 1e-5f},
      {R"("type": "conductor", "color": 0.9)", 0.05f, 1e-5f},
      {R"("type": "glass", "ior": 1.5)", 0.3f, 1e-5f},
      {R"("type": "plastic", "color": [0.2, 0.4, 0.6])", plasticCoatLevelRoughness(5), 1e-5f},
      {R"("type": "plastic", "color": [0.2, 0.4, 0.6])", 0.42f, 2e-3f},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(std::string(c.material) + " roughness " + num(c.roughness));
    const std::string map = "r" + num(c.roughness) + ".pfm";
    writeRowMap(dir / map, {c.roughness, c.roughness});
    const std::vector<float> plain = planeImage(
        dir, std::string("{") + c.material + R"(, "roughness": )" + num(c.roughness) + "}");
    const std::vector<float> textured = planeImage(
        dir, std::string("{") + c.material + R"(, "roughness": {"texture": ")" + map + R"("}})");
    ASSERT_EQ(plain.size(), textured.size());
    ASSERT_GT(*std::max_element(plain.begin(), plain.end()), 0.0f);
    for (size_t i = 0; i < plain.size(); ++i)
      ASSERT_NEAR(textured[i], plain[i], c.tolerance * plain[i] + 1e-7f) << "pixel " << i;
  }
}

// Paths that meet light subpaths (the room under a lamp) evaluate the textured surface at both
// ends of each connection: the ball renders as with the roughness given as a number (a clear
// coat's and a sheen's too, whose light vertices keep the roughness and tables they met).
TEST(RoughnessTexture, LightSubpathsSeeTheTexturedRoughness) {
  const fs::path dir = test::mapTestFolder("roughness_light_paths");
  const float level = plasticCoatLevelRoughness(9);
  writeRowMap(dir / "level.pfm", {level, level});
  writeRowMap(dir / "r03.pfm", {0.3f, 0.3f});
  const float sheenLevel = sheenLevelRoughness(12);
  writeRowMap(dir / "sheen_level.pfm", {sheenLevel, sheenLevel});
  const auto render = [&](const std::string& ball) {
    std::string json =
        test::lampUnderTheCeiling(R"("width": 24, "height": 24, "spp": 4)", R"("max_depth": 4)");
    const std::string plain = R"("radius": 1, "color": 0.5})";
    json.replace(json.find(plain), plain.size(), R"("radius": 1, "material": )" + ball + "}");
    return test::renderTestScene(json, 0, dir.string()).image;
  };
  for (const auto& [material, key, roughness, map] :
       {std::tuple<std::string, std::string, float, std::string>{
            R"("type": "conductor", "metal": "Cu")", "roughness", 0.3f, "r03.pfm"},
        {R"("type": "plastic", "color": 0.5)", "roughness", level, "level.pfm"},
        {R"("type": "diffuse", "color": 0.5, "coat": 1)", "coat_roughness", level, "level.pfm"},
        {R"("type": "diffuse", "color": 0.3, "sheen": 0.9)", "sheen_roughness", sheenLevel,
         "sheen_level.pfm"}}) {
    SCOPED_TRACE(material);
    const std::string field = R"(, ")" + key + R"(": )";
    const ImageRGB plain = render("{" + material + field + num(roughness) + "}");
    const ImageRGB textured = render("{" + material + field + R"({"texture": ")" + map + R"("}})");
    for (uint32_t y = 0; y < plain.height; ++y)
      for (uint32_t x = 0; x < plain.width; ++x)
        for (int c = 0; c < 3; ++c)
          ASSERT_NEAR(textured.at(x, y)[c], plain.at(x, y)[c], 1e-4f * plain.at(x, y)[c] + 1e-6f)
              << x << "," << y;
  }
}

// A texture of two stripes, roughness 0.15 and 0.6, repeated across the plane: every pixel shades
// as one of the two numbers, but where the lookup blends the stripes' edges (a roughness between
// them, whose highlight may be brighter than either's), and each number in many.
TEST(RoughnessTexture, EachTexelGivesItsOwnRoughness) {
  const fs::path dir = test::mapTestFolder("roughness_stripes");
  test::writeMappedPlane(dir / "plane.obj");
  writeRowMap(dir / "stripes.pfm", {0.15f, 0.15f, 0.15f, 0.15f, 0.6f, 0.6f, 0.6f, 0.6f});
  const std::string metal = R"({"type": "conductor", "metal": "Cu", "roughness": )";
  const std::vector<float> smooth = planeImage(dir, metal + "0.15}");
  const std::vector<float> rough = planeImage(dir, metal + "0.6}");
  const std::vector<float> striped =
      planeImage(dir, metal + R"({"texture": "stripes.pfm", "scale": [40, 1]}})");
  int asSmooth = 0, asRough = 0;
  for (size_t i = 0; i < striped.size(); ++i) {
    ASSERT_GT(std::fabs(smooth[i] - rough[i]), 0.02f * rough[i]) << "pixel " << i;
    asSmooth += std::fabs(striped[i] - smooth[i]) <= 1e-5f * smooth[i];
    asRough += std::fabs(striped[i] - rough[i]) <= 1e-5f * rough[i];
  }
  // The 24 columns span 1.2 repeats of the 8 texels: three eighths of a repeat lie in each
  // stripe's middle, a quarter on the blended edges.
  EXPECT_GT(asSmooth, int(striped.size()) / 4);
  EXPECT_GT(asRough, int(striped.size()) / 4);
  EXPECT_GT(asSmooth + asRough, int(striped.size()) * 6 / 10);
}

// A textured plastic's coat between two of its table's levels is within 2e-3 of the quadrature
// at its own roughness (transmittance at every angle, internal reflectance), at both ends of the
// range and between; at a level it is that level's table.
TEST(RoughnessTexture, ThePlasticsCoatTablesInterpolateTheQuadrature) {
  for (float eta : {1.5f, 1.33f}) {
    const std::vector<float> tables = plasticCoatTable(eta);
    ASSERT_EQ(tables.size(), size_t(kPlasticCoatLevels * kPlasticCoatRow));
    Material m;
    m.type = MaterialType::Plastic;
    m.ior = eta;
    m.roughnessTexture.index = 0;
    m.plasticCoatTable = 0;
    for (float roughness = 0.0f; roughness <= 1.0f; roughness += 1.0f / 64) {
      SCOPED_TRACE("eta " + num(eta) + " roughness " + num(roughness));
      const float alpha = std::max(roughness * roughness, kSmoothAlpha);
      Material exact = m;
      exact.roughnessTexture = TextureRef();
      exact.plasticCoatTable = -1;
      exact.roughness = std::sqrt(alpha);
      prepareMaterial(&exact);
      const PlasticCoat coat = plasticCoatAt(m, tables.data(), roughness);
      const PlasticCoat reference = plasticCoatAt(exact, nullptr, exact.roughness);
      EXPECT_NEAR(coat.internalReflectance, reference.internalReflectance, 2e-3f);
      for (float mu = 0.0f; mu <= 1.0f; mu += 1.0f / 32)
        EXPECT_NEAR(plasticTransmittance(m, coat, mu), plasticTransmittance(exact, reference, mu),
                    2e-3f)
            << "cos " << mu;
    }
    const PlasticCoat atLevel = plasticCoatAt(m, tables.data(), plasticCoatLevelRoughness(7));
    EXPECT_NEAR(atLevel.blend, 0.0f, 1e-5f);
    EXPECT_EQ(atLevel.transmittance, tables.data() + 7 * kPlasticCoatRow);
  }
}

// A colour map's roughness is its luminance, or the channel "channel" names (glTF packs roughness
// into G): a map whose channels hold three roughnesses renders as each.
TEST(RoughnessTexture, AChannelOfAColourMapIsTheRoughness) {
  const fs::path dir = test::mapTestFolder("roughness_channel");
  test::writeMappedPlane(dir / "plane.obj");
  {
    std::ofstream pfm(dir / "rgb.pfm", std::ios::binary);
    pfm << "PF\n2 1\n-1\n";
    const float texel[3] = {0.1f, 0.45f, 0.8f};
    for (int i = 0; i < 2; ++i) pfm.write(reinterpret_cast<const char*>(texel), sizeof texel);
  }
  const std::string metal = R"({"type": "conductor", "metal": "Ag", "roughness": )";
  const float luminance = 0.212671f * 0.1f + 0.715160f * 0.45f + 0.072169f * 0.8f;
  for (const auto& [channel, roughness] : {std::pair<std::string, float>{"", luminance},
                                           {R"(, "channel": "luminance")", luminance},
                                           {R"(, "channel": "r")", 0.1f},
                                           {R"(, "channel": "g")", 0.45f},
                                           {R"(, "channel": "b")", 0.8f}}) {
    SCOPED_TRACE(channel);
    const std::vector<float> plain = planeImage(dir, metal + num(roughness) + "}");
    const std::vector<float> mapped =
        planeImage(dir, metal + R"({"texture": "rgb.pfm")" + channel + "}}");
    for (size_t i = 0; i < plain.size(); ++i)
      ASSERT_NEAR(mapped[i], plain[i], 1e-5f * plain[i] + 1e-7f) << "pixel " << i;
  }
  EXPECT_EQ(
      test::materialError(
          dir, R"({"type": "conductor", "roughness": {"texture": "rgb.pfm", "channel": "G"}})"),
      "s.json: materials.m.roughness.channel: expected one of \"r\", \"g\", \"b\", \"a\", "
      "\"luminance\", got a string \"G\", did you mean \"g\"?");
}

// MTL: Pr is a glossy material's roughness (in place of Ns's), map_Pr a texture of them, read
// linearly, -imfchan its channel; a Pr outside [0, 1] is refused with its line, and so are
// channels and options map_Pr cannot have.
TEST(RoughnessTexture, MtlPrAndMapPrSetTheRoughness) {
  const fs::path dir = test::mapTestFolder("roughness_mtl");
  writeRowMap(dir / "r.pfm", {0.3f, 0.3f});
  std::ofstream(dir / "m.obj") << "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\n"
                                  "vt 0 1\nusemtl a\nf 1/1 2/2 3/3\nusemtl b\nf 1/1 2/2 3/3\n"
                                  "usemtl c\nf 1/1 2/2 3/3\n";
  std::ofstream(dir / "m.mtl") << "newmtl a\nKd 0 0 0\nKs 0.9 0.9 0.9\nNs 100\nPr 0.35\n"
                                  "newmtl b\nKd 0.5 0.5 0.5\nKs 1 1 1\n"
                                  "map_Pr -imfchan g -s 2 2 r.pfm\n"
                                  "newmtl c\nKd 0.5 0.5 0.5\nPr 0.5\n";
  const std::string json =
      R"({"camera": {"width": 4, "height": 4}, "objects": [{"file": "m.obj"}]})";
  const SceneData data = test::loadTestScene(json, dir.string());
  ASSERT_EQ(data.materials.size(), 3u);
  EXPECT_EQ(data.materials[0].type, MaterialType::Conductor);
  EXPECT_EQ(data.materials[0].roughness, 0.35f);
  EXPECT_LT(data.materials[0].roughnessTexture.index, 0);
  EXPECT_EQ(data.materials[1].type, MaterialType::Plastic);
  EXPECT_GE(data.materials[1].roughnessTexture.index, 0);
  EXPECT_EQ(data.materials[1].roughnessTexture.scaleU, 2.0f);
  EXPECT_EQ(data.materials[1].roughnessChannel, 1u);
  EXPECT_EQ(data.materials[1].plasticCoatTable, 0);
  EXPECT_EQ(data.plasticCoats.size(), size_t(kPlasticCoatLevels * kPlasticCoatRow));
  EXPECT_EQ(data.materials[2].type, MaterialType::Diffuse);  // no Ks: not glossy

  const auto error = [&](const std::string& statement) {
    std::ofstream(dir / "m.mtl") << "newmtl a\nKs 1 1 1\n" << statement << "\n";
    return test::loadError(json, dir.string());
  };
  EXPECT_EQ(error("Pr 1.5"),
            "test.json: objects[0].file: m.mtl:3: expected Pr between 0 and 1, got \"1.5\"");
  EXPECT_EQ(error("map_Pr -imfchan z r.pfm"),
            "test.json: objects[0].file: m.mtl:3: map_Pr -imfchan: expected r, g, b, m or l, got "
            "\"z\"");
  EXPECT_EQ(error("map_Pr -imfchan l r.pfm"), "(no error)");
  EXPECT_EQ(error("map_Pr -bm 2 r.pfm"),
            "test.json: objects[0].file: m.mtl:3: map_Pr option \"-bm\" is not supported (only -s, "
            "-o, -clamp and -imfchan)");
}

TEST(RoughnessTexture, TheSceneFormatRefusesWhatItCannotBe) {
  const fs::path dir = test::mapTestFolder("roughness_errors");
  writeRowMap(dir / "r.pfm", {0.3f, 0.3f});
  const auto error = [&](const std::string& material) {
    return test::materialError(dir, material);
  };
  EXPECT_EQ(error(R"({"type": "glass", "roughness": {"texture": "r.pfm", "scale": [2, 2]}})"),
            "(no error)");
  EXPECT_EQ(error(R"({"type": "diffuse", "roughness": {"texture": "r.pfm"}})"),
            "s.json: materials.m.roughness: not used by a \"diffuse\" material");
  EXPECT_EQ(error(R"({"type": "conductor", "roughness": {"texture": "missing.pfm"}})"),
            "s.json: materials.m.roughness.texture: cannot read the texture: " +
                (dir / "missing.pfm").string() + ": cannot open: No such file or directory");
  EXPECT_EQ(
      error(R"({"type": "plastic", "roughness": {"texture": "r.pfm", "height": 1}})"),
      "s.json: materials.m.roughness.height: unknown key, expected one of \"texture\", "
      "\"checkerboard\", \"scale\", \"offset\", \"rotation\", \"wrap\", \"filter\", \"channel\"");
  EXPECT_EQ(error(R"({"type": "plastic", "roughness": [0.1, 0.2]})"),
            "s.json: materials.m.roughness: expected a roughness in [0, 1] or a texture object, "
            "got an array [0.1,0.2]");
}

}  // namespace
}  // namespace candela
