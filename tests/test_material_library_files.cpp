// Material libraries in files of their own ("materials": "lib.json" or an array of files and
// objects): their materials read as the scene's own, a texture named relative to its library's
// folder, a mix naming a material of another file; errors naming the library file and the
// material's path in it; a name defined twice refused with where it was first.
#include <gtest/gtest.h>

#include <string>

#include "render_test_util.h"
#include "scene/read/texture_reader.h"
#include "temp_dir.h"
#include "texture_test_util.h"

namespace candela {
namespace {

using test::TempDir;

// lib/common.json: "wood", textured by lib/wood.pfm (one texel, [0.6, 0.3, 0.1]), and "half", a
// mix of "wood" and the scene's own "paint".
void writeLibrary(const TempDir& dir) {
  test::writeRowPfm(dir.file("lib/wood.pfm"), {Vec3(0.6f, 0.3f, 0.1f)});
  dir.write("lib/common.json", R"({
    "wood": {"type": "diffuse", "color": {"texture": "wood.pfm"}},
    "half": {"type": "mix", "materials": ["wood", "paint"], "weight": 0.5}})");
}

TEST(MaterialLibraryFiles, ReadAsTheScenesOwnWithTexturesBesideThem) {
  TempDir dir;
  std::filesystem::create_directories(dir.file("lib"));
  writeLibrary(dir);
  const SceneDesc scene = parseSceneText(R"({"camera": {"width": 4, "height": 4},
      "materials": ["lib/common.json", {"paint": {"type": "diffuse", "color": [0, 0, 0.8]}}],
      "spheres": [{"position": [0, 0, -3], "radius": 1, "material": "wood"},
                  {"position": [3, 0, -3], "radius": 1, "material": "half"}]})",
                                         "s.json", dir.path());
  const Material& wood = scene.spheres.at(0).material;
  ASSERT_GE(wood.colorTexture.index, 0);
  const TextureDesc& texture = *scene.textures.at(size_t(wood.colorTexture.index));
  EXPECT_NE(texture.file.find("lib"), std::string::npos);
  EXPECT_FLOAT_EQ(texelValue(texture, 0, 0), 0.6f);
  EXPECT_FLOAT_EQ(texelValue(texture, 0, 2), 0.1f);
  // The mix's parts: the library's wood and the scene's paint.
  const SphereDesc& half = scene.spheres.at(1);
  ASSERT_EQ(half.mixParts.size(), 2u);
  EXPECT_EQ(half.mixParts[0].colorTexture.index, wood.colorTexture.index);
  EXPECT_FLOAT_EQ(half.mixParts[1].color.z, 0.8f);
  // One file alone, by its path.
  dir.write("lib/wood.json", R"({"wood": {"type": "diffuse", "color": {"texture": "wood.pfm"}}})");
  const SceneDesc alone = parseSceneText(R"({"camera": {"width": 4, "height": 4},
      "materials": "lib/wood.json",
      "spheres": [{"position": [0, 0, -3], "radius": 1, "material": "wood"}]})",
                                         "s.json", dir.path());
  EXPECT_GE(alone.spheres.at(0).material.colorTexture.index, 0);
}

std::string errorOf(const std::string& materials, const TempDir& dir) {
  return test::loadError(R"({"camera": {"width": 4, "height": 4}, "materials": )" + materials + "}",
                         dir.path());
}

TEST(MaterialLibraryFiles, ErrorsNameTheLibraryFile) {
  TempDir dir;
  std::filesystem::create_directories(dir.file("lib"));
  writeLibrary(dir);
  const std::string lib = dir.file("lib/common.json");
  EXPECT_EQ(errorOf(R"(["lib/none.json"])", dir),
            "test.json: materials[0]: cannot open the material library lib/none.json (No such file "
            "or directory)");
  EXPECT_EQ(errorOf(R"(["lib/common.json", {"wood": {"type": "mirror"}}])", dir),
            "test.json: materials[1].wood: the material \"wood\" is defined twice, first at " +
                lib + ": wood");
  dir.write("lib/bad.json", R"({"rough": {"type": "conductor", "roughness": 2}})");
  EXPECT_EQ(errorOf(R"("lib/bad.json")", dir).substr(0, dir.file("lib/bad.json").size() + 25),
            dir.file("lib/bad.json") + ": rough.roughness: expect");
  dir.write("lib/broken.json", "{\"a\": ");
  EXPECT_EQ(errorOf(R"("lib/broken.json")", dir).substr(0, dir.file("lib/broken.json").size() + 5),
            dir.file("lib/broken.json") + ":1:7:");
  EXPECT_EQ(errorOf("3", dir),
            "test.json: materials: expected an object (material name -> material), the path of a "
            "JSON file of them, or an array of those, got 3");
}

}  // namespace
}  // namespace candela
