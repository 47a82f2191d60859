// KHR_materials_variants (scene/read/gltf_variants.h): an object's "gltf_variant" picks each
// primitive's material by the file's mappings, a primitive it does not map keeps its own, objects
// of one file and variant share one mesh; a variant the file does not have, a mapping glTF does
// not allow, and the key where it means nothing are refused with their JSON paths.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <tuple>
#include <vector>

#include "gltf_material_test_util.h"
#include "scene/read/scene_loader.h"
#include "scene/scene_error.h"
#include "temp_dir.h"

namespace candela {
namespace {

using test::TempDir;

nlohmann::json plastic(double r, double g, double b) {
  return {{"pbrMetallicRoughness",
           {{"baseColorFactor", {r, g, b, 1}}, {"metallicFactor", 0}, {"roughnessFactor", 0.5}}}};
}

// A quad of material 0 (red) whose primitive maps variant "Blue" to material 1 and "Green" and
// "Lime" to material 2, beside a second quad that maps nothing.
test::GltfFile variantQuads() {
  test::GltfFile f =
      test::quad(nlohmann::json::array({plastic(1, 0, 0), plastic(0, 0, 1), plastic(0, 1, 0)}));
  nlohmann::json& primitives = f.doc["meshes"][0]["primitives"];
  primitives.push_back(primitives[0]);
  primitives[0]["extensions"] = {
      {"KHR_materials_variants",
       {{"mappings",
         {{{"material", 1}, {"variants", {0}}}, {{"material", 2}, {"variants", {1, 2}}}}}}}};
  f.doc["extensions"] = {
      {"KHR_materials_variants",
       {{"variants", {{{"name", "Blue"}}, {{"name", "Green"}}, {{"name", "Lime"}}}}}}};
  f.doc["extensionsUsed"] = {"KHR_materials_variants"};
  return f;
}

std::string sceneOf(const std::string& objects) {
  return R"({"camera": {"width": 4, "height": 4}, "objects": [)" + objects + "]}";
}

// The colour of the material of the mesh's triangle t.
Vec3 colourOf(const MeshDesc& mesh, size_t t) {
  return mesh.materials.at(mesh.triangles.at(t).material).color;
}

TEST(GltfVariants, AnObjectsVariantPicksItsPrimitivesMaterials) {
  TempDir dir;
  dir.write("q.gltf", variantQuads().gltf());
  const SceneDesc scene =
      parseSceneText(sceneOf(R"({"file": "q.gltf"}, {"file": "q.gltf", "gltf_variant": "Blue"},
                 {"file": "q.gltf", "gltf_variant": "Lime"},
                 {"file": "q.gltf", "gltf_variant": "Blue", "position": [3, 0, 0]})"),
                     "s.json", dir.path());
  // Each quad's two triangles share its material (in whatever order spatial ordering left them).
  const auto colours = [&](size_t object) {
    std::vector<float> reds, blues, greens;
    for (size_t t = 0; t < 4; ++t) {
      const Vec3 c = colourOf(*scene.objects[object].mesh, t);
      reds.push_back(c.x);
      greens.push_back(c.y);
      blues.push_back(c.z);
    }
    return std::make_tuple(reds, greens, blues);
  };
  // Without a variant: red everywhere.
  const auto [r0, g0, b0] = colours(0);
  EXPECT_EQ(r0, std::vector<float>(4, 1.0f));
  // "Blue": the mapped quad blue, the other red.
  const auto [r1, g1, b1] = colours(1);
  EXPECT_EQ(std::count(b1.begin(), b1.end(), 1.0f), 2);
  EXPECT_EQ(std::count(r1.begin(), r1.end(), 1.0f), 2);
  // "Lime" (the mapping's second variant): green and red.
  const auto [r2, g2, b2] = colours(2);
  EXPECT_EQ(std::count(g2.begin(), g2.end(), 1.0f), 2);
  EXPECT_EQ(std::count(r2.begin(), r2.end(), 1.0f), 2);
  // One mesh per (file, variant).
  EXPECT_EQ(scene.objects[1].mesh, scene.objects[3].mesh);
  EXPECT_NE(scene.objects[0].mesh, scene.objects[1].mesh);
}

TEST(GltfVariants, WhatMeansNothingOrIsNotThereIsRefusedWithItsPath) {
  TempDir dir;
  dir.write("q.gltf", variantQuads().gltf());
  dir.write("q.obj", test::kQuadObj);
  const auto error = [&](const std::string& objects) {
    try {
      parseSceneText(sceneOf(objects), "s.json", dir.path());
    } catch (const SceneError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_EQ(error(R"({"file": "q.gltf", "gltf_variant": "Blu"})"),
            "s.json: objects[0].gltf_variant: q.gltf: the file has no variant \"Blu\" (did you "
            "mean \"Blue\"?); its variants: \"Blue\", \"Green\", \"Lime\"");
  EXPECT_EQ(error(R"({"file": "q.obj", "gltf_variant": "Blue"})"),
            "s.json: objects[0].gltf_variant: a glTF file's variant, and \"q.obj\" is not a glTF "
            "file");
  EXPECT_EQ(error(R"({"file": "q.gltf", "gltf_variant": "Blue", "color": 0.5})"),
            "s.json: objects[0].gltf_variant: not used: the object's material replaces the "
            "file's, whatever the variant");
  test::GltfFile plain = test::quad(nlohmann::json::array({plastic(1, 0, 0)}));
  dir.write("plain.gltf", plain.gltf());
  EXPECT_EQ(error(R"({"file": "plain.gltf", "gltf_variant": "Blue"})"),
            "s.json: objects[0].gltf_variant: plain.gltf: the file has no variants "
            "(KHR_materials_variants), so none is \"Blue\"");
  test::GltfFile broken = variantQuads();
  broken.doc["meshes"][0]["primitives"][0]["extensions"]["KHR_materials_variants"]["mappings"][1]
            ["variants"] = {1, 5};
  dir.write("broken.gltf", broken.gltf());
  EXPECT_EQ(error(R"({"file": "broken.gltf", "gltf_variant": "Lime"})"),
            "s.json: objects[0].file: broken.gltf: meshes[0].primitives[0].extensions."
            "KHR_materials_variants.mappings[1].variants[1]: expected a variant from 0 to 2");
  broken.doc["meshes"][0]["primitives"][0]["extensions"]["KHR_materials_variants"]["mappings"][1]
            ["material"] = 3;
  dir.write("broken.gltf", broken.gltf());
  EXPECT_EQ(error(R"({"file": "broken.gltf", "gltf_variant": "Green"})"),
            "s.json: objects[0].file: broken.gltf: meshes[0].primitives[0].extensions."
            "KHR_materials_variants.mappings[1].material: expected a material from 0 to 2");
  // Without a variant the mappings are not read.
  EXPECT_EQ(error(R"({"file": "broken.gltf"})"), "(no error)");
}

}  // namespace
}  // namespace candela
