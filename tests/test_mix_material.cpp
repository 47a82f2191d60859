// Mix materials (render/material_mix.h): a path that meets a mix sees one of its two parts, the
// second with the chance the weight gives. Where the weight is 0 or 1 (a striped texture on a
// plane under the sun, one bounce, no noise) each pixel renders exactly as one part alone; where
// it lies between, a surface met once per path renders as the weighted sum of its parts' renders
// (a lone ball, and a ball reached by light subpaths, within the noise); nested mixes choose down
// the tree with the weights' product (against the closed form of a diffuse plane). Then how
// scenes say it (library names in any order, shorthands, inline objects), where the parts land
// when flattened, and the refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "render_test_util.h"
#include "shading_normal_test_util.h"
#include "texture_test_util.h"

namespace candela {
namespace {

namespace fs = std::filesystem;
using test::num;

const DVec3 kSun{0.3, -1, 0.5};

// writeMappedPlane's plane in `material` under the sun, seen from above (no antialiasing, one
// bounce, `spp` samples): every channel of every pixel.
std::vector<float> planeImage(const fs::path& dir, const std::string& material, int spp = 2) {
  std::string json = test::planeUnderSun(material, kSun, 2);
  const std::string samples = R"("spp": 2)";
  json.replace(json.find(samples), samples.size(), R"("spp": )" + std::to_string(spp));
  const RenderResult r = test::renderTestScene(json, 0, dir.string());
  std::vector<float> values;
  for (uint32_t y = 0; y < r.image.height; ++y)
    for (uint32_t x = 0; x < r.image.width; ++x)
      for (int c = 0; c < 3; ++c) values.push_back(r.image.at(x, y)[c]);
  return values;
}

const char* kCopper = R"({"type": "conductor", "metal": "Cu", "roughness": 0.3})";
const char* kRedPlastic = R"({"type": "plastic", "color": [0.7, 0.1, 0.1], "roughness": 0.2})";

// Stripes of weight 0 and 1 (in the texture's G; R and B the other way round) across the plane:
// each pixel renders as one part alone, to rounding, but where the lookup blends a stripe's edge,
// and each part in many pixels.
TEST(MixMaterial, AWeightOfZeroOrOneIsThatPartAlone) {
  const fs::path dir = test::mapTestFolder("mix_stripes");
  test::writeMappedPlane(dir / "plane.obj");
  const Vec3 zero(1, 0, 1), one(0, 1, 0);
  test::writeRowPfm(dir / "stripes.pfm", {zero, zero, zero, zero, one, one, one, one});
  const std::vector<float> first = planeImage(dir, kCopper);
  const std::vector<float> second = planeImage(dir, kRedPlastic);
  const std::vector<float> mixed = planeImage(
      dir, std::string(R"({"type": "mix", "materials": [)") + kCopper + ", " + kRedPlastic +
               R"(], "weight": {"texture": "stripes.pfm", "scale": [40, 1], "channel": "g"}})");
  test::expectEachPixelAsOneStripe(mixed, first, second, 0.05f);
}

// A diffuse plane under the sun reflects albedo * irradiance * cos / pi. A mix of a mix (albedos
// 0.2 and 0.6, weight 0.5) and albedo 0.9 (weight 0.25) has the mean albedo 0.75 * 0.4 + 0.25 *
// 0.9 = 0.525; choosing the inner part with the outer choice's number unrescaled would give 0.475.
TEST(MixMaterial, NestedMixesChooseWithTheProductOfTheirWeights) {
  const fs::path dir = test::mapTestFolder("mix_nested");
  test::writeMappedPlane(dir / "plane.obj");
  const std::vector<float> image = planeImage(dir,
                                              R"({"type": "mix", "weight": 0.25, "materials": [
            {"type": "mix", "weight": 0.5, "materials": [{"type": "diffuse", "color": 0.2},
                                                         {"type": "diffuse", "color": 0.6}]},
            {"type": "diffuse", "color": 0.9}]})",
                                              64);
  const double irradiance = 2, d = std::sqrt(kSun.x * kSun.x + 1 + kSun.z * kSun.z);
  const double perAlbedo = irradiance * (1 / d) / kPi;  // cos = -sun.y / |sun|
  // The choice's dimension is stratified over a pixel's 64 samples: each pixel's share of each
  // part is close to exact.
  for (size_t i = 0; i < image.size(); i += 3)
    ASSERT_NEAR(image[i] / perAlbedo, 0.525, 0.01) << "pixel " << i / 3;
}

// Two seeds of `json` with "SEED" replaced by each.
test::SeedPair renderSeeds(const std::string& json, const fs::path& dir = ".") {
  const auto render = [&](int seed) {
    std::string text = json;
    text.replace(text.find("SEED"), 4, std::to_string(seed));
    return test::renderTestScene(text, 0, dir.string());
  };
  return {render(1), render(2)};
}

// (1 - w) a + w b, pixel by pixel, of two seeds' renders each.
test::SeedPair blend(const test::SeedPair& a, const test::SeedPair& b, float w) {
  test::SeedPair out = a;
  const auto mixInto = [w](RenderResult* r, const RenderResult& ofA, const RenderResult& ofB) {
    for (size_t i = 0; i < r->image.pixels.size(); ++i)
      r->image.pixels[i] = (1 - w) * ofA.image.pixels[i] + w * ofB.image.pixels[i];
  };
  mixInto(&out.a, a.a, b.a);
  mixInto(&out.b, a.b, b.b);
  return out;
}

// A ball alone under a sky and a sun: every path meets it at most once, so its render with a mix
// is, on average, the blend of its renders with each part (Mitsuba's blendbsdf). The parts: an
// anisotropic rough conductor and a rough plastic, weight 0.35; a mix that always took one part
// is far from it.
TEST(MixMaterial, ABallRendersAsTheBlendOfItsParts) {
  const auto scene = [](const std::string& material) {
    return R"({
      "camera": {"width": 32, "height": 32, "fov": 30, "position": [0, 0.5, 5], "look_at": [0, 0, 0],
                 "spp": 32},
      "render": {"seed": SEED, "max_depth": 6},
      "environment": {"color": [0.3, 0.45, 0.8]},
      "spheres": [{"position": [0, 0, 0], "radius": 1, "material": )" +
           material + R"(}],
      "lights": [{"type": "directional", "direction": [-1, -1, -0.5], "intensity": 3,
                  "angle": 8}]})";
  };
  const std::string conductor =
      R"({"type": "conductor", "metal": "Au", "roughness": 0.4, "anisotropy": 0.7})";
  const test::SeedPair a = renderSeeds(scene(conductor));
  const test::SeedPair b = renderSeeds(scene(kRedPlastic));
  const test::SeedPair mixed = renderSeeds(scene(
      R"({"type": "mix", "weight": 0.35, "materials": [)" + conductor + ", " + kRedPlastic + "]}"));
  test::expectSameImage(mixed, blend(a, b, 0.35f));
  // The test tells: the blend with another weight differs in some block.
  const test::SeedPair other = blend(a, b, 0.6f);
  double largest = 0;
  for (uint32_t y = 0; y < 32; ++y)
    for (uint32_t x = 0; x < 32; ++x)
      largest =
          std::max(largest, double(std::fabs(other.a.image.at(x, y).y - mixed.a.image.at(x, y).y)));
  EXPECT_GT(largest, 0.05);
}

// In the room under a lamp, up to two bounces, light subpaths reach the ceiling (a mix of
// diffuse and rough copper), the bright patch over the lamp from which most of the room is lit,
// and connect to the camera paths, as do the camera paths that meet it: the ceiling is met at
// most once per path, so again the room renders as the blend of its renders with each part.
// Light vertices that kept the mix instead of the part they met would connect nothing.
TEST(MixMaterial, LightSubpathsMeetTheChosenPart) {
  const auto scene = [](const std::string& ceiling) {
    std::string json = test::lampUnderTheCeiling(R"("width": 32, "height": 32, "spp": 16)",
                                                 R"("max_depth": 2, "light_paths": "on",
                                                    "seed": SEED)");
    const std::string plain = R"({"position": [0, 1006, 0], "radius": 1000, "color": 0.8})";
    json.replace(json.find(plain), plain.size(),
                 R"({"position": [0, 1006, 0], "radius": 1000, "material": )" + ceiling + "}");
    return json;
  };
  const std::string copper = R"({"type": "conductor", "metal": "Cu", "roughness": 0.7})";
  const std::string diffuse = R"({"type": "diffuse", "color": [0.2, 0.8, 0.3]})";
  const test::SeedPair a = renderSeeds(scene(copper));
  const test::SeedPair b = renderSeeds(scene(diffuse));
  const test::SeedPair mixed = renderSeeds(
      scene(R"({"type": "mix", "weight": 0.5, "materials": [)" + copper + ", " + diffuse + "]}"));
  test::expectSameImage(mixed, blend(a, b, 0.5f));
}

// A library mix may name entries in any order (itself read before what it names), shorthands
// with their defaults, and inline objects; flattened, a mix's parts follow every material of its
// sphere or object, a mix part's own parts after it.
TEST(MixMaterial, PartsFollowTheirSurfacesMaterials) {
  const SceneData data = test::loadTestScene(R"({
    "camera": {"width": 4, "height": 4},
    "materials": {
      "a_rusty": {"type": "mix", "materials": ["z_steel", {"type": "diffuse", "color": 0.3}],
                  "weight": 0.4},
      "b_layered": {"type": "mix", "materials": ["mirror", "a_rusty"]},
      "z_steel": {"type": "conductor", "color": 0.6, "roughness": 0.2}
    },
    "spheres": [{"position": [0, 0, 0], "radius": 1, "material": "b_layered"},
                {"position": [3, 0, 0], "radius": 1, "color": 0.5}]})");
  const SceneView v = data.view();
  // Sphere 0: the mix, mirror, the rusty mix, steel, rust; sphere 1 after them.
  ASSERT_EQ(v.materialCount, 6u);
  ASSERT_EQ(v.spheres[0].material, 0u);
  EXPECT_EQ(v.spheres[1].material, 5u);
  const Material* m = v.materials;
  ASSERT_EQ(m[0].type, MaterialType::Mix);
  EXPECT_EQ(m[0].mixWeight, 0.5f);  // the default
  EXPECT_EQ(m[0].mixParts[0], 1u);
  EXPECT_EQ(m[0].mixParts[1], 2u);
  EXPECT_EQ(m[1].type, MaterialType::Conductor);
  EXPECT_EQ(m[1].color.x, 1.0f);
  ASSERT_EQ(m[2].type, MaterialType::Mix);
  EXPECT_EQ(m[2].mixWeight, 0.4f);
  EXPECT_EQ(m[2].mixParts[0], 3u);
  EXPECT_EQ(m[2].mixParts[1], 4u);
  EXPECT_EQ(m[3].type, MaterialType::Conductor);
  EXPECT_EQ(m[3].roughness, 0.2f);
  EXPECT_EQ(m[4].type, MaterialType::Diffuse);
  EXPECT_EQ(m[4].color.x, 0.3f);
  EXPECT_EQ(m[5].type, MaterialType::Diffuse);
  // Every surface's instance is its own; the parts carry their surface's.
  EXPECT_EQ(data.materialInstances[4], data.materialInstances[0]);
  EXPECT_NE(data.materialInstances[5], data.materialInstances[0]);
}

// An object's mix (given inline) flattens after the object's material, and its texture weight
// makes the mesh keep its uvs.
TEST(MixMaterial, AnObjectsMixReadsItsUvs) {
  const fs::path dir = test::mapTestFolder("mix_object");
  test::writeMappedPlane(dir / "plane.obj");
  test::writeRowPfm(dir / "w.pfm", {Vec3(0.0f), Vec3(1.0f)});
  const SceneData data = test::loadTestScene(R"({
    "camera": {"width": 4, "height": 4},
    "objects": [{"file": "plane.obj", "material": {"type": "mix", "weight": {"texture": "w.pfm"},
                 "materials": ["diffuse", "glass"]}}]})",
                                             dir.string());
  const SceneView v = data.view();
  ASSERT_EQ(v.materialCount, 3u);
  EXPECT_EQ(v.triangles[0].material, 0u);
  EXPECT_EQ(v.materials[0].mixWeightTexture.index, 0);
  EXPECT_EQ(v.materials[0].mixWeightChannel, kLuminanceChannel);
  EXPECT_EQ(v.materials[2].type, MaterialType::Glass);
  EXPECT_NE(v.uvs, nullptr);
}

std::string mixError(const std::string& mix, const std::string& more = "") {
  return test::loadError(
      R"({"camera": {"width": 4, "height": 4}, "materials": {"m": )" + mix + more + "}}", ".");
}

TEST(MixMaterial, RefusesWhatCannotBeMixed) {
  EXPECT_EQ(mixError(R"({"type": "mix", "materials": ["diffuse"]})"),
            "test.json: materials.m.materials: expected an array of two materials, each a name or "
            "a material object, got an array [\"diffuse\"]");
  EXPECT_EQ(mixError(R"({"type": "mix"})"),
            "test.json: materials.m: missing required key \"materials\"");
  EXPECT_EQ(mixError(R"({"type": "mix", "materials": ["diffuse", 3]})"),
            "test.json: materials.m.materials[1]: expected a material name or a material object, "
            "got 3");
  EXPECT_EQ(mixError(R"({"type": "mix", "materials": ["diffuse", {"type": "emissive",
                                                                   "radiance": 1}]})"),
            "test.json: materials.m.materials[1]: an emissive material in a mix; expected a "
            "material that reflects or transmits (an emitting surface is an \"emissive\" "
            "material of its own)");
  EXPECT_EQ(mixError(R"({"type": "mix", "materials": [{"type": "thin_glass"}, "diffuse"]})"),
            "test.json: materials.m.materials[0]: a \"thin_glass\" material in a mix; expected it "
            "on a surface of its own");
  EXPECT_EQ(mixError(R"({"type": "mix", "materials": [{"type": "diffuse", "alpha": 0.5},
                                                      "diffuse"]})"),
            "test.json: materials.m.materials[0]: a material with an \"alpha\" in a mix; expected "
            "the \"alpha\" on the mix, which masks the whole surface");
  EXPECT_EQ(mixError(R"({"type": "mix", "materials": ["diffuse", "mirror"], "weight": 1.5})"),
            "test.json: materials.m.weight: expected a weight in [0, 1], got 1.5");
  EXPECT_EQ(mixError(R"({"type": "mix", "materials": ["diffuse", "mirror"], "weight": "x"})"),
            "test.json: materials.m.weight: expected a weight in [0, 1] or a texture object, got "
            "a string \"x\"");
  EXPECT_EQ(mixError(R"({"type": "mix", "materials": ["diffuse", "mirror"], "ior": 1.5})"),
            "test.json: materials.m.ior: not used by a \"mix\" material");
  EXPECT_EQ(mixError(R"({"type": "diffuse", "weight": 0.5})"),
            "test.json: materials.m.weight: not used by a \"diffuse\" material");
  EXPECT_EQ(mixError(R"({"type": "mix", "materials": ["diffuse", "m"]})"),
            "test.json: materials.m.materials[1]: the mix \"m\" contains itself; expected parts "
            "that are other materials");
  EXPECT_EQ(mixError(R"({"type": "mix", "materials": ["diffuse", "n"]})",
                     R"(, "n": {"type": "mix", "materials": ["m", "mirror"]})"),
            "test.json: materials.n.materials[0]: the mix \"m\" contains itself; expected parts "
            "that are other materials");
  EXPECT_EQ(mixError(R"({"type": "mix", "materials": ["diffuse", "stele"]})",
                     R"(, "steel": {"type": "conductor"})"),
            "test.json: materials.m.materials[1]: unknown material \"stele\", did you mean "
            "\"steel\"?");
  // On a sphere an alpha is refused as any sphere's; a track cannot animate a mix.
  EXPECT_EQ(test::sphereMaterialError(
                R"({"type": "mix", "materials": ["diffuse", "mirror"], "alpha": 0.5})"),
            "test.json: spheres[0].material: a material with an \"alpha\" on a sphere; expected "
            "it on mesh faces (spheres are not masked)");
  EXPECT_EQ(
      test::lightsError("", R"(, "spheres": [{"id": "ball", "position": [0, 0, 0], "radius": 1,
      "material": {"type": "mix", "materials": ["diffuse", "mirror"]}}])" +
                                test::oneTrack("ball", "color", "[[0, 1], [2, 0]]")),
      "s.json: animation.tracks[0].property: \"color\" is not used by a \"mix\" material");
}

// MTL's PBR metalness, as Blender writes it: `Pm` 1 makes a material with a diffuse colour a
// conductor of that colour (its roughness Pr's), 0 leaves it as it is, and between them it is a
// mix of the two, the mix holding the alpha and both parts the bump map; `map_Pm` is a weight
// texture in Pm's place (its channel by -imfchan). Flattened, the mesh's parts follow its
// materials. A Pm outside [0, 1] is refused at its line.
TEST(MixMaterial, MtlMetalnessMixesAMetalIn) {
  const fs::path dir = test::mapTestFolder("mix_mtl");
  test::writeRowPfm(dir / "metal.pfm", {Vec3(0, 0, 1), Vec3(0, 0, 0)});
  test::writeRowPfm(dir / "bumps.pfm", {Vec3(0.2f), Vec3(0.7f)});
  std::ofstream(dir / "quad.obj") << "mtllib quad.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                  << "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                                  << "usemtl gold\nf 1/1 2/2 3/3\nusemtl paint\nf 1/1 3/3 4/4\n"
                                  << "usemtl worn\nf 1/1 2/2 4/4\nusemtl matte\nf 2/2 3/3 4/4\n";
  const auto load = [&](const std::string& paintPm) {
    std::ofstream(dir / "quad.mtl")
        << "newmtl gold\nKd 0.9 0.6 0.2\nKs 0.5 0.5 0.5\nPr 0.3\nPm 1\n"
        << "newmtl paint\nKd 0.5 0.1 0.1\nKs 0.5 0.5 0.5\nPr 0.2\naniso 0.5\nd 0.5\n"
        << "bump -bm 0.01 bumps.pfm\nPm " << paintPm << "\n"
        << "newmtl worn\nKd 0.3 0.3 0.3\nNs 100\nmap_Pm -imfchan b metal.pfm\n"
        << "newmtl matte\nKd 0.4 0.4 0.4\nPm 0\n";
    return parseSceneText(R"({"camera": {"width": 4, "height": 4},
                              "objects": [{"file": "quad.obj"}]})",
                          "s.json", dir.string());
  };
  const SceneDesc scene = load("0.3");
  EXPECT_TRUE(scene.warnings.empty());  // the paint's aniso is its metal's
  const MeshDesc& mesh = *scene.objects[0].mesh;
  ASSERT_EQ(mesh.materials.size(), 4u);
  ASSERT_EQ(mesh.mixParts.size(), 4u);
  const Material& gold = mesh.materials[0];
  EXPECT_EQ(gold.type, MaterialType::Conductor);
  EXPECT_FLOAT_EQ(gold.color.y, 0.6f);
  EXPECT_FLOAT_EQ(gold.roughness, 0.3f);
  const Material& paint = mesh.materials[1];
  ASSERT_EQ(paint.type, MaterialType::Mix);
  EXPECT_FLOAT_EQ(paint.mixWeight, 0.3f);
  EXPECT_FLOAT_EQ(paint.alpha.constant, 0.5f);
  const Material& plastic = mesh.mixParts[paint.mixParts[0]];
  const Material& metal = mesh.mixParts[paint.mixParts[1]];
  EXPECT_EQ(plastic.type, MaterialType::Plastic);
  EXPECT_EQ(metal.type, MaterialType::Conductor);
  for (const Material* part : {&plastic, &metal}) {
    EXPECT_FLOAT_EQ(part->color.x, 0.5f);
    EXPECT_FLOAT_EQ(part->roughness, 0.2f);
    EXPECT_FLOAT_EQ(part->alpha.constant, 1.0f);
    EXPECT_GE(part->normalMap.index, 0);
    EXPECT_FLOAT_EQ(part->bumpHeight, 0.01f);
  }
  EXPECT_FLOAT_EQ(metal.anisotropy, 0.5f);
  EXPECT_EQ(plastic.anisotropy, 0.0f);
  const Material& worn = mesh.materials[2];
  ASSERT_EQ(worn.type, MaterialType::Mix);
  EXPECT_GE(worn.mixWeightTexture.index, 0);
  EXPECT_EQ(worn.mixWeightChannel, 2u);
  EXPECT_EQ(mesh.mixParts[worn.mixParts[0]].type, MaterialType::Diffuse);
  EXPECT_EQ(mesh.mixParts[worn.mixParts[1]].type, MaterialType::Conductor);
  EXPECT_FLOAT_EQ(mesh.mixParts[worn.mixParts[1]].roughness,
                  std::sqrt(std::sqrt(2.0f / 102.0f)));  // Ns 100's
  EXPECT_EQ(mesh.materials[3].type, MaterialType::Diffuse);

  // Flattened: the four materials, then the parts, each mix's indices moved there.
  const SceneData data = flattenScene(SceneDesc(scene));
  ASSERT_EQ(data.materials.size(), 8u);
  EXPECT_EQ(data.materials[1].mixParts[0], 4 + paint.mixParts[0]);
  EXPECT_EQ(data.materials[2].mixParts[1], 4 + worn.mixParts[1]);
  EXPECT_EQ(data.materials[4 + paint.mixParts[1]].type, MaterialType::Conductor);

  try {
    load("1.5");
    ADD_FAILURE() << "no error";
  } catch (const SceneError& e) {
    EXPECT_STREQ(e.what(),
                 "s.json: objects[0].file: quad.mtl:13: expected Pm between 0 and 1, got \"1.5\"");
  }
}

}  // namespace
}  // namespace candela
