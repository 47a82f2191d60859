// glTF materials in tests: a unit quad whose primitive takes a material, loaded as a mesh, and a
// small RGBA texture whose channels can be told apart.
#pragma once

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "gltf_test_util.h"
#include "render/render_result.h"
#include "scene/read/gltf_loader.h"
#include "scene/scene_error.h"
#include "temp_dir.h"
#include "texture_test_util.h"

namespace candela::test {

// One unit quad in z = 0 facing +z (uvs across it), whose primitive takes `material` (-1: none)
// of the file's `materials`.
inline GltfFile quad(const nlohmann::json& materials, int material = 0) {
  GltfFile f;
  const int p = f.addFloats({-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0}, "VEC3", 3);
  const int t = f.addFloats({0, 1, 1, 1, 1, 0, 0, 0}, "VEC2", 2);
  const int i = f.addAccessor(std::vector<uint16_t>{0, 1, 2, 0, 2, 3}, 5123, "SCALAR", 6);
  nlohmann::json primitive = {{"attributes", {{"POSITION", p}, {"TEXCOORD_0", t}}}, {"indices", i}};
  if (material >= 0) primitive["material"] = material;
  f.doc["meshes"] = nlohmann::json::array({nlohmann::json{{"primitives", {primitive}}}});
  f.doc["nodes"] = nlohmann::json::array({nlohmann::json{{"mesh", 0}}});
  if (!materials.is_null()) f.doc["materials"] = materials;
  return f;
}

struct Loaded {
  std::vector<std::shared_ptr<const TextureDesc>> textures;
  MeshDesc mesh;
};

inline std::unique_ptr<Loaded> load(const std::string& path) {
  auto loaded = std::make_unique<Loaded>();
  TextureLoader loader(loaded->textures, ".");
  loaded->mesh = loadGltfFile(path, "m.gltf", loader);
  return loaded;
}

// The material of the file's one quad.
inline Material materialOf(const TempDir& dir, const nlohmann::json& material,
                           MeshDesc* mesh = nullptr) {
  const auto loaded = load(dir.write("m.gltf", quad(nlohmann::json::array({material})).gltf()));
  if (mesh) *mesh = loaded->mesh;
  return loaded->mesh.materials.at(0);
}

// The error loading a file whose one quad takes `material` gives, or "(no error)".
inline std::string materialError(const TempDir& dir, const nlohmann::json& material) {
  try {
    materialOf(dir, material);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

inline nlohmann::json pbr(double metallic, double roughness) {
  return {{"pbrMetallicRoughness",
           {{"baseColorFactor", {0.5, 0.25, 0.125, 1}},
            {"metallicFactor", metallic},
            {"roughnessFactor", roughness}}}};
}

// The quad of `quad` as an OBJ file, for the JSON material a glTF material maps to.
inline const char* kQuadObj =
    "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
    "f 1/1 2/2 3/3\nf 1/1 3/3 4/4\n";

// The glTF quad's render and the OBJ quad's under the JSON material agree pixel for pixel, and
// show something.
inline void expectSameImage(const RenderResult& gltf, const RenderResult& json) {
  ASSERT_EQ(gltf.image.pixels.size(), json.image.pixels.size());
  double sum = 0;
  for (size_t i = 0; i < gltf.image.pixels.size(); ++i) {
    EXPECT_FLOAT_EQ(gltf.image.pixels[i], json.image.pixels[i]) << "value " << i;
    sum += gltf.image.pixels[i];
  }
  EXPECT_GT(sum, 0.0);
}

// Texels of a 2 x 1 RGBA image: channel values the tests can tell apart.
inline const std::vector<uint8_t> kTexels = {10, 200, 40, 255, 250, 100, 160, 0};

inline std::string pngBytes(const TempDir& dir) {
  const std::string path = dir.file("t.png");
  EXPECT_TRUE(writeTestPng(path, 2, 1, 4, kTexels));
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace candela::test
