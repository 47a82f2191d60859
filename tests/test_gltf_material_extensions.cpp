// KHR_materials_specular, KHR_materials_anisotropy, KHR_materials_diffuse_transmission and
// KHR_materials_unlit as
// candela's materials (scene/read/gltf_materials.h): the plastic's index reflects glTF's F0 times
// the specular colour and factor at normal incidence, a black plastic seen head-on under a white
// sky shows that F0; the conductor's and glass's alphas are glTF's mix(alpha, 1, strength^2) along
// the tangent and alpha across it; diffuse transmission is a mix of the plastic and a translucent
// sheet, and a glTF quad renders as the JSON mix the documentation names, pixel for pixel;
// KHR_materials_unlit is an emitter of the base colour, which the camera sees as it is.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/constants.h"
#include "gltf_material_test_util.h"
#include "render/fresnel.h"
#include "render/microfacet.h"
#include "render_test_util.h"
#include "scene/scene_error.h"
#include "temp_dir.h"

namespace candela {
namespace {

using test::materialOf;
using test::pbr;
using test::TempDir;

// glTF's dielectric F0 of index `ior` (0: an infinite index).
double gltfF0(double ior) { return ior == 0.0 ? 1.0 : std::pow((ior - 1.0) / (ior + 1.0), 2.0); }

nlohmann::json specular(double ior, double factor, const std::vector<double>& colour) {
  nlohmann::json m = pbr(0, 0);
  m["extensions"] = {
      {"KHR_materials_ior", {{"ior", ior}}},
      {"KHR_materials_specular", {{"specularFactor", factor}, {"specularColorFactor", colour}}}};
  return m;
}

TEST(GltfSpecular, ThePlasticsIndexReflectsGltfsF0TimesColourAndFactorHeadOn) {
  TempDir dir;
  struct Case {
    double ior, factor;
    std::vector<double> colour;
    double reflectance;  // at normal incidence, as glTF's dielectric_f0 gives it
  };
  const std::vector<Case> cases = {
      {1.5, 0.5, {1, 1, 1}, 0.5 * gltfF0(1.5)},
      {1.5, 0.8, {0.5, 0.5, 0.5}, 0.8 * 0.5 * gltfF0(1.5)},
      {1.5, 1.0, {3, 3, 3}, 3 * gltfF0(1.5)},
      {2.0, 1.0, {1, 0.5, 0.25}, luminance(Vec3(1, 0.5f, 0.25f)) * gltfF0(2.0)},
      // Specular-glossiness converted as the extension says: an ior of 0 and the colour as F0.
      {0.0, 1.0, {0.3, 0.3, 0.3}, 0.3},
      {0.0, 1.0, {40, 40, 40}, 0.998 * 0.998},  // F0 1, held below an index of 1000
  };
  for (const Case& c : cases) {
    SCOPED_TRACE("ior " + std::to_string(c.ior) + ", factor " + std::to_string(c.factor));
    const Material m = materialOf(dir, specular(c.ior, c.factor, c.colour));
    ASSERT_EQ(m.type, MaterialType::Plastic);
    EXPECT_NEAR(fresnelDielectric(1.0f, m.ior), c.reflectance, 2e-6 + 1e-5 * c.reflectance);
  }
  // Without the extension the file's index is kept to the bit.
  nlohmann::json plain = pbr(0, 0.3);
  plain["extensions"] = {{"KHR_materials_ior", {{"ior", 1.33}}}};
  EXPECT_EQ(materialOf(dir, plain).ior, 1.33f);
  // Nothing to reflect (a specular factor of 0, or an index of 1): the diffuse base alone, its
  // colour and layers kept.
  nlohmann::json none = specular(1.5, 0.0, {1, 1, 1});
  none["extensions"]["KHR_materials_clearcoat"] = {{"clearcoatFactor", 0.5}};
  const Material diffuse = materialOf(dir, none);
  EXPECT_EQ(diffuse.type, MaterialType::Diffuse);
  EXPECT_EQ(diffuse.color.y, 0.25f);
  EXPECT_EQ(diffuse.coatWeight, 0.5f);
  plain["extensions"]["KHR_materials_ior"]["ior"] = 1.0;
  EXPECT_EQ(materialOf(dir, plain).type, MaterialType::Diffuse);
}

// The mapping end to end: a smooth glTF plastic of black base colour, seen head-on through a
// narrow lens under a sky of radiance 1, shows the coat's reflectance alone, glTF's F0 times the
// specular colour's luminance and factor.
TEST(GltfSpecular, ABlackPlasticSeenHeadOnUnderAWhiteSkyShowsGltfsReflectance) {
  TempDir dir;
  nlohmann::json m = specular(1.6, 0.7, {1.2, 0.9, 0.6});
  m["pbrMetallicRoughness"]["baseColorFactor"] = {0, 0, 0, 1};
  dir.write("quad.gltf", test::quad(nlohmann::json::array({m})).gltf());
  const RenderResult r = test::renderTestScene(
      R"({"camera": {"position": [0, 0, 3], "look_at": [0, 0, 0], "fov": 2, "width": 4,
          "height": 4, "spp": 2}, "environment": {"color": 1},
          "objects": [{"file": "quad.gltf"}]})",
      1, dir.path());
  const double expected = 0.7 * luminance(Vec3(1.2f, 0.9f, 0.6f)) * gltfF0(1.6);
  ASSERT_EQ(r.image.pixels.size(), 4u * 4u * 3u);
  for (size_t i = 0; i < r.image.pixels.size(); ++i)
    EXPECT_NEAR(r.image.pixels[i], expected, 1e-5 * expected) << "value " << i;
}

TEST(GltfSpecular, WhatThePlasticCannotHoldIsNamedAndBadFactorsRefused) {
  TempDir dir;
  MeshDesc mesh;
  nlohmann::json m = specular(1.5, 0.5, {1, 0.5, 1});
  m["extensions"]["KHR_materials_specular"]["specularTexture"] = {{"index", 0}};
  m["extensions"]["KHR_materials_transmission"] = {{"transmissionFactor", 0.5}};
  materialOf(dir, m, &mesh);
  const std::string at = "m.gltf: materials[0].extensions.";
  const std::vector<std::string> expected = {
      at + "KHR_materials_specular.specularTexture is not rendered (a plastic has one index): "
           "read as white",
      at + "KHR_materials_specular.specularColorFactor [1, 0.5, 1] tints the reflection by its "
           "luminance alone (candela's plastic reflects white)",
      at + "KHR_materials_transmission: the transmitted part reflects as its index says "
           "(KHR_materials_specular scales the plastic's reflection alone)"};
  EXPECT_EQ(mesh.warnings, expected);
  const Material& glass = mesh.mixParts.at(1);
  ASSERT_EQ(glass.type, MaterialType::Glass);
  EXPECT_EQ(glass.ior, 1.5f);  // refraction keeps the file's index
  // At glTF's defaults the extension scales nothing, and nothing is said.
  nlohmann::json defaults = specular(1.5, 1, {1, 1, 1});
  defaults["extensions"]["KHR_materials_transmission"] = {{"transmissionFactor", 0.5}};
  materialOf(dir, defaults, &mesh);
  EXPECT_TRUE(mesh.warnings.empty());
  const auto error = [&](const nlohmann::json& material) {
    return test::materialError(dir, material);
  };
  EXPECT_EQ(error(specular(1.5, 1.5, {1, 1, 1})),
            at + "KHR_materials_specular.specularFactor: expected a number between 0 and 1, got "
                 "1.5");
  EXPECT_EQ(error(specular(1.5, 1, {1, -1, 1})),
            at + "KHR_materials_specular.specularColorFactor: expected three finite, non-negative "
                 "numbers");
  nlohmann::json shortColour = specular(1.5, 1, {1, 1, 1});
  shortColour["extensions"]["KHR_materials_specular"]["specularColorFactor"] = {1, 1};
  EXPECT_EQ(error(shortColour), at + "KHR_materials_specular.specularColorFactor: expected three "
                                     "finite, non-negative numbers");
  EXPECT_EQ(error(specular(0.5, 1, {1, 1, 1})), "(no error)");  // read as 1.5, with a warning
}

nlohmann::json anisotropic(double metallic, double roughness, double strength, double rotation) {
  nlohmann::json m = pbr(metallic, roughness);
  m["extensions"] = {{"KHR_materials_anisotropy",
                      {{"anisotropyStrength", strength}, {"anisotropyRotation", rotation}}}};
  return m;
}

// glTF's alphas at roughness r and strength s: along the tangent mix(r^2, 1, s^2), across it r^2.
void expectGltfAlphas(const Material& m, double r, double s) {
  const GgxAlpha alpha = pointAlpha(m, m.roughness);
  const double a = r * r;
  EXPECT_NEAR(alpha.x, a + s * s * (1 - a), 1e-6);
  EXPECT_NEAR(alpha.y, std::max(a, double(kSmoothAlpha)), 1e-6);
}

TEST(GltfAnisotropy, TheConductorsAndGlasssAlphasAreGltfsAlongAndAcrossTheTangent) {
  TempDir dir;
  for (const double r : {0.0, 0.3, 0.7}) {
    for (const double s : {0.2, 0.6, 1.0}) {
      SCOPED_TRACE("roughness " + std::to_string(r) + ", strength " + std::to_string(s));
      const Material metal = materialOf(dir, anisotropic(1, r, s, 1.25));
      ASSERT_EQ(metal.type, MaterialType::Conductor);
      expectGltfAlphas(metal, r, s);
      EXPECT_FLOAT_EQ(metal.anisotropyRotation, 1.25f);  // radians from the tangent, both
      nlohmann::json clear = anisotropic(0, r, s, 0);
      clear["extensions"]["KHR_materials_transmission"] = {{"transmissionFactor", 1}};
      const Material glass = materialOf(dir, clear);
      ASSERT_EQ(glass.type, MaterialType::Glass);
      expectGltfAlphas(glass, r, s);
    }
  }
  // A rotation past a full turn is the same direction; no strength, no anisotropy.
  EXPECT_NEAR(materialOf(dir, anisotropic(1, 0.3, 0.5, 2 * kPiDouble + 0.5)).anisotropyRotation,
              0.5f, 1e-6);
  EXPECT_EQ(materialOf(dir, anisotropic(1, 0.3, 0, 1)).anisotropy, 0.0f);
  // Roughness 1 cannot grow: glTF's alphas are 1 both ways.
  EXPECT_EQ(materialOf(dir, anisotropic(1, 1, 0.5, 0)).anisotropy, 0.0f);
}

// Half metal: the conductor is anisotropic, the plastic keeps its isotropic coat and says so.
TEST(GltfAnisotropy, ThePlasticStaysIsotropicWithAWarning) {
  TempDir dir;
  MeshDesc mesh;
  nlohmann::json m = anisotropic(0.5, 0.4, 0.8, 0);
  m["extensions"]["KHR_materials_anisotropy"]["anisotropyTexture"] = {{"index", 0}};
  const Material mix = materialOf(dir, m, &mesh);
  ASSERT_EQ(mix.type, MaterialType::Mix);
  const Material& plastic = mesh.mixParts.at(mix.mixParts[0]);
  const Material& metal = mesh.mixParts.at(mix.mixParts[1]);
  ASSERT_EQ(plastic.type, MaterialType::Plastic);
  EXPECT_EQ(plastic.anisotropy, 0.0f);
  EXPECT_FLOAT_EQ(plastic.roughness, 0.4f);
  expectGltfAlphas(metal, 0.4, 0.8);
  const std::string at = "m.gltf: materials[0].extensions.KHR_materials_anisotropy";
  const std::vector<std::string> expected = {
      at + ".anisotropyTexture is not rendered: the anisotropy lies along the tangent turned by "
           "anisotropyRotation, of strength anisotropyStrength",
      at + ": the dielectric's reflection stays isotropic (candela's plastic takes no "
           "anisotropy)"};
  EXPECT_EQ(mesh.warnings, expected);
  EXPECT_EQ(test::materialError(dir, anisotropic(1, 0.5, -0.5, 0)),
            at + ".anisotropyStrength: expected a number between 0 and 1, got -0.5");
}

// With a roughness texture, a texel at the factor's roughness gets glTF's alphas exactly; every
// texel keeps glTF's alpha across the tangent.
TEST(GltfAnisotropy, ARoughnessTextureKeepsGltfsAlphaAcrossTheTangent) {
  TempDir dir;
  nlohmann::json m = anisotropic(1, 0.6, 0.7, 0);
  m["pbrMetallicRoughness"]["metallicRoughnessTexture"] = {{"index", 0}};
  test::GltfFile f = test::quad(nlohmann::json::array({m}));
  f.addImage(test::pngBytes(dir));
  f.doc["textures"] = nlohmann::json::array({nlohmann::json{{"source", 0}}});
  const auto loaded = test::load(dir.write("r.glb", f.glb()));
  const Material& mix = loaded->mesh.materials.at(0);  // metalness textured: a mix
  ASSERT_EQ(mix.type, MaterialType::Mix);
  const Material& metal = loaded->mesh.mixParts.at(mix.mixParts[1]);
  ASSERT_EQ(metal.type, MaterialType::Conductor);
  const TextureDesc& rough = *loaded->textures.at(size_t(metal.roughnessTexture.index));
  for (size_t texel = 0; texel < 2; ++texel) {
    const float green = test::kTexels[4 * texel + 1] / 255.0f;
    const float value = rough.texelsF[4 * texel + metal.roughnessChannel];
    const GgxAlpha alpha = pointAlpha(metal, value);
    const float gltfAlpha = (0.6f * green) * (0.6f * green);
    EXPECT_NEAR(alpha.y, gltfAlpha, 1e-6) << "texel " << texel;
    EXPECT_GT(alpha.x, alpha.y);
  }
  expectGltfAlphas(metal, 0.6, 0.7);            // a texel at the factor's roughness: exactly glTF's
  EXPECT_EQ(loaded->mesh.warnings.size(), 2u);  // the ratio, and the isotropic plastic
}

nlohmann::json translucent(double factor, const std::vector<double>& colour) {
  nlohmann::json m = pbr(0, 0.4);
  m["extensions"] = {
      {"KHR_materials_diffuse_transmission",
       {{"diffuseTransmissionFactor", factor}, {"diffuseTransmissionColorFactor", colour}}}};
  return m;
}

TEST(GltfDiffuseTransmission, AMixOfThePlasticAndATranslucentSheetByTheFactor) {
  TempDir dir;
  MeshDesc mesh;
  const Material mix = materialOf(dir, translucent(0.4, {1, 0.5, 0.2}), &mesh);
  ASSERT_EQ(mix.type, MaterialType::Mix);
  EXPECT_FLOAT_EQ(mix.mixWeight, 0.4f);
  const Material& plastic = mesh.mixParts.at(mix.mixParts[0]);
  const Material& sheet = mesh.mixParts.at(mix.mixParts[1]);
  EXPECT_EQ(plastic.type, MaterialType::Plastic);
  ASSERT_EQ(sheet.type, MaterialType::Translucent);
  EXPECT_EQ(sheet.color.x, 0.0f);  // glTF's diffuse_btdf reflects nothing
  EXPECT_EQ(sheet.transmittance.y, 0.5f);
  EXPECT_EQ(mesh.warnings,
            std::vector<std::string>{
                "m.gltf: materials[0].extensions.KHR_materials_diffuse_transmission: the diffusely "
                "transmitted share has no specular reflection (candela's translucent surface takes "
                "no coat)"});
  // All of it transmitted: the sheet alone; none: the plastic alone.
  EXPECT_EQ(materialOf(dir, translucent(1, {1, 1, 1})).type, MaterialType::Translucent);
  EXPECT_EQ(materialOf(dir, translucent(0, {1, 1, 1})).type, MaterialType::Plastic);
  // With KHR_materials_transmission, the glass mixed over the two, as glTF's transmission
  // overrides its diffuse transmission.
  nlohmann::json both = translucent(0.5, {1, 1, 1});
  both["extensions"]["KHR_materials_transmission"] = {{"transmissionFactor", 0.25}};
  MeshDesc parts;
  const Material outer = materialOf(dir, both, &parts);
  ASSERT_EQ(outer.type, MaterialType::Mix);
  EXPECT_FLOAT_EQ(outer.mixWeight, 0.25f);
  EXPECT_EQ(parts.mixParts.at(outer.mixParts[0]).type, MaterialType::Mix);
  EXPECT_EQ(parts.mixParts.at(outer.mixParts[1]).type, MaterialType::Glass);
  EXPECT_EQ(test::materialError(dir, translucent(0.5, {1, 2, 1})),
            "m.gltf: materials[0].extensions.KHR_materials_diffuse_transmission."
            "diffuseTransmissionColorFactor: expected three numbers in [0, 1]");
}

// The factor's texture (alpha times the factor) weighs the mix, the colour's (sRGB) tints the
// sheet's transmittance.
TEST(GltfDiffuseTransmission, TexturesWeighTheMixAndTintTheSheet) {
  TempDir dir;
  nlohmann::json m = translucent(0.5, {1, 1, 1});
  m["extensions"]["KHR_materials_diffuse_transmission"]["diffuseTransmissionTexture"] = {
      {"index", 0}};
  m["extensions"]["KHR_materials_diffuse_transmission"]["diffuseTransmissionColorTexture"] = {
      {"index", 0}};
  test::GltfFile f = test::quad(nlohmann::json::array({m}));
  f.addImage(test::pngBytes(dir));
  f.doc["textures"] = nlohmann::json::array({nlohmann::json{{"source", 0}}});
  const auto loaded = test::load(dir.write("t.glb", f.glb()));
  const Material& mix = loaded->mesh.materials.at(0);
  ASSERT_EQ(mix.type, MaterialType::Mix);
  const TextureDesc& weight = *loaded->textures.at(size_t(mix.mixWeightTexture.index));
  EXPECT_FLOAT_EQ(weight.texelsF[4 * 0 + mix.mixWeightChannel], 0.5f * 255 / 255);
  EXPECT_FLOAT_EQ(weight.texelsF[4 * 1 + mix.mixWeightChannel], 0.0f);
  const Material& sheet = loaded->mesh.mixParts.at(mix.mixParts[1]);
  ASSERT_EQ(sheet.type, MaterialType::Translucent);
  EXPECT_EQ(loaded->textures.at(size_t(sheet.transmittanceTexture.index))->format,
            TextureFormat::Srgb8);
}

// The mapping as the documentation states it: a glTF quad under a sun from behind and a lamp in
// front renders as the same quad in OBJ under the JSON mix, pixel for pixel.
TEST(GltfDiffuseTransmission, AGltfQuadRendersAsTheJsonMixTheDocsMapItTo) {
  TempDir dir;
  dir.write("quad.gltf",
            test::quad(nlohmann::json::array({translucent(0.4, {1, 0.6, 0.3})})).gltf());
  dir.write("quad.obj", test::kQuadObj);
  const std::string common =
      R"({"camera": {"position": [0.3, 0.5, 3], "look_at": [0, 0, 0], "fov": 50, "width": 24,
          "height": 24, "spp": 16}, "environment": {"color": [0.1, 0.1, 0.1]},
          "lights": [{"type": "point", "position": [1, 2, 2], "intensity": 20},
                     {"type": "directional", "direction": [0.2, 0.1, 1], "intensity": 2}],
          "objects": [)";
  const RenderResult gltf =
      test::renderTestScene(common + R"({"file": "quad.gltf"}]})", 1, dir.path());
  const RenderResult json = test::renderTestScene(
      common + R"({"file": "quad.obj", "material": {"type": "mix", "weight": 0.4, "materials": [
          {"type": "plastic", "color": [0.5, 0.25, 0.125], "roughness": 0.4, "ior": 1.5},
          {"type": "diffuse", "color": 0, "transmittance": [1, 0.6, 0.3]}]}}]})",
      1, dir.path());
  test::expectSameImage(gltf, json);
}

nlohmann::json unlit() {
  nlohmann::json m = pbr(1, 0.2);  // unlit: the metalness and roughness are a fallback's
  m["extensions"] = {{"KHR_materials_unlit", nlohmann::json::object()}};
  return m;
}

TEST(GltfUnlit, AnEmitterOfTheBaseColourAndItsTexture) {
  TempDir dir;
  nlohmann::json m = unlit();
  m["doubleSided"] = true;
  m["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
  test::GltfFile f = test::quad(nlohmann::json::array({m}));
  f.addImage(test::pngBytes(dir));
  f.doc["textures"] = nlohmann::json::array({nlohmann::json{{"source", 0}}});
  const auto loaded = test::load(dir.write("t.glb", f.glb()));
  const Material& e = loaded->mesh.materials.at(0);
  EXPECT_EQ(e.type, MaterialType::Emissive);
  EXPECT_EQ(e.radiance.x, 0.5f);
  EXPECT_EQ(e.radiance.y, 0.25f);
  EXPECT_EQ(e.radiance.z, 0.125f);
  ASSERT_GE(e.emissionTexture.index, 0);
  EXPECT_EQ(loaded->textures.at(size_t(e.emissionTexture.index))->format, TextureFormat::Srgb8);
  EXPECT_TRUE(e.twoSided);
  EXPECT_TRUE(loaded->mesh.warnings.empty());
  EXPECT_FALSE(materialOf(dir, unlit()).twoSided);
}

// Seen head-on under a white sky, an unlit quad shows its colour and nothing else: it reflects
// none of the sky.
TEST(GltfUnlit, TheCameraSeesTheBaseColourUnderAnySky) {
  TempDir dir;
  dir.write("quad.gltf", test::quad(nlohmann::json::array({unlit()})).gltf());
  const RenderResult r = test::renderTestScene(
      R"({"camera": {"position": [0, 0, 3], "look_at": [0, 0, 0], "fov": 20, "width": 4,
          "height": 4, "spp": 4}, "environment": {"color": 1},
          "lights": [{"type": "point", "position": [0, 1, 2], "intensity": 50}],
          "objects": [{"file": "quad.gltf"}]})",
      1, dir.path());
  const float expected[3] = {0.5f, 0.25f, 0.125f};
  ASSERT_EQ(r.image.pixels.size(), 4u * 4u * 3u);
  for (size_t i = 0; i < r.image.pixels.size(); ++i)
    EXPECT_NEAR(r.image.pixels[i], expected[i % 3], 1e-6) << "value " << i;
}

// Vertex colours tint glTF's unlit colour, not candela's emitters; an emitter has no alpha.
TEST(GltfUnlit, VertexColoursAndAlphaAreNamedInWarnings) {
  TempDir dir;
  nlohmann::json m = unlit();
  m["alphaMode"] = "MASK";
  m["pbrMetallicRoughness"]["baseColorFactor"] = {0.5, 0.25, 0.125, 0.2};
  test::GltfFile f = test::quad(nlohmann::json::array({m}));
  const int c = f.addFloats({1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0}, "VEC3", 3);
  f.doc["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] = c;
  const auto loaded = test::load(dir.write("c.gltf", f.gltf()));
  const std::vector<std::string> expected = {
      "m.gltf: materials[0]: the alpha is not used: the material emits, and an emitting surface "
      "is a light over all its area",
      "m.gltf: meshes[0].primitives[0].attributes.COLOR_0: vertex colours do not tint an unlit "
      "material (materials[0])"};
  EXPECT_EQ(loaded->mesh.warnings, expected);
}

}  // namespace
}  // namespace candela
