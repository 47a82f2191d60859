// Reading glTF meshes (scene/read/gltf_loader.h): positions placed by the node hierarchy's
// transforms (against the tests' own arithmetic), normals by their inverse transpose, uvs turned
// to candela's v, every index type, interleaved buffers, strips and fans; a .glb and a .gltf with
// its buffer beside it read as the same file; what is not read named in warnings; each kind of
// broken file refused with one message naming the file and the JSON path.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "gltf_test_util.h"
#include "scene/read/gltf_loader.h"
#include "scene/read/gltf_scene.h"
#include "scene/read/scene_loader.h"
#include "scene/scene_error.h"
#include "temp_dir.h"

namespace candela {
namespace {

using test::GltfFile;
using test::TempDir;

constexpr int kFloat = 5126, kByte = 5120, kUbyte = 5121, kShort = 5122, kUshort = 5123,
              kUint = 5125;

MeshDesc load(const std::string& path, const std::string& label = "m.gltf") {
  return test::loadGltfMesh(path, label);
}
std::string loadError(const std::string& path, const std::string& label = "m.gltf") {
  return test::gltfLoadError(path, label);
}

// A quad (0, 1, 2, 3) in z = 0 with normals tilted towards +x and uvs, under a node tree: the
// root translated by (1, 2, 3), turned 90 degrees about z and scaled by (2, 1, 0.5); its child, by
// a matrix, scaled by 3 and moved by (0, 0, 1).
GltfFile placedQuad() {
  GltfFile f;
  const std::vector<float> positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  const std::vector<float> normals = {0.6f, 0, 0.8f, 0.6f, 0, 0.8f, 0.6f, 0, 0.8f, 0.6f, 0, 0.8f};
  const std::vector<float> uvs = {0, 0, 1, 0, 1, 0.25f, 0, 0.25f};
  const int p = f.addFloats(positions, "VEC3", 3), n = f.addFloats(normals, "VEC3", 3),
            t = f.addFloats(uvs, "VEC2", 2);
  const int i = f.addAccessor(std::vector<uint16_t>{0, 1, 2, 0, 2, 3}, kUshort, "SCALAR", 6);
  const nlohmann::json primitive = {
      {"attributes", {{"POSITION", p}, {"NORMAL", n}, {"TEXCOORD_0", t}}}, {"indices", i}};
  f.doc["meshes"] = nlohmann::json::array({nlohmann::json{{"primitives", {primitive}}}});
  const double s = std::sqrt(0.5);
  f.doc["nodes"] = nlohmann::json::array(
      {nlohmann::json{{"translation", {1, 2, 3}},
                      {"rotation", {0, 0, s, s}},
                      {"scale", {2, 1, 0.5}},
                      {"children", {1}}},
       nlohmann::json{{"matrix", {3, 0, 0, 0, 0, 3, 0, 0, 0, 0, 3, 0, 0, 0, 1, 1}}, {"mesh", 0}}});
  f.doc["scenes"] = nlohmann::json::array({nlohmann::json{{"nodes", {0}}}});
  f.doc["scene"] = 0;
  return f;
}

// Where placedQuad's transforms take a point: child (3 p + (0, 0, 1)), scaled by (2, 1, 0.5),
// turned by 90 degrees about z ((x, y) -> (-y, x)), moved by (1, 2, 3).
std::array<double, 3> placed(double x, double y, double z) {
  x *= 3, y *= 3, z = 3 * z + 1;
  x *= 2, z *= 0.5;
  return {1 - y, 2 + x, 3 + z};
}

TEST(GltfLoader, NodeTransformsPlaceThePositionsNormalsAndUvs) {
  TempDir dir;
  const MeshDesc mesh = load(dir.write("quad.gltf", placedQuad().gltf()));
  ASSERT_EQ(mesh.positions.size(), 4u);
  const double corners[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int v = 0; v < 4; ++v) {
    const auto expected = placed(corners[v][0], corners[v][1], 0);
    for (int a = 0; a < 3; ++a)
      EXPECT_NEAR(mesh.positions[size_t(v)][a], expected[size_t(a)], 1e-5);
  }
  // The normal by the inverse transpose: (0.6, 0, 0.8) / (2, 1, 0.5) = (0.3, 0, 1.6), turned.
  const double len = std::sqrt(0.3 * 0.3 + 1.6 * 1.6);
  ASSERT_EQ(mesh.normals.size(), 4u);
  EXPECT_NEAR(mesh.normals[0].x, 0.0, 1e-6);
  EXPECT_NEAR(mesh.normals[0].y, 0.3 / len, 1e-6);
  EXPECT_NEAR(mesh.normals[0].z, 1.6 / len, 1e-6);
  // glTF's v runs down the image, candela's up.
  ASSERT_EQ(mesh.uvs.size(), 4u);
  EXPECT_EQ(mesh.uvs[2].x, 1.0f);
  EXPECT_EQ(mesh.uvs[2].y, 0.75f);
  ASSERT_EQ(mesh.triangles.size(), 2u);
  const uint32_t expected[2][3] = {{0, 1, 2}, {0, 2, 3}};
  for (int t = 0; t < 2; ++t)
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(mesh.triangles[size_t(t)].v[k], expected[t][k]);
      EXPECT_EQ(mesh.triangles[size_t(t)].n[k], int32_t(expected[t][k]));
      EXPECT_EQ(mesh.triangles[size_t(t)].t[k], int32_t(expected[t][k]));
    }
  EXPECT_TRUE(mesh.warnings.empty());
}

TEST(GltfLoader, AGlbAndAGltfWithItsBinBesideItReadAlike) {
  TempDir dir;
  const GltfFile f = placedQuad();
  dir.write("quad.bin", f.buffer);
  const MeshDesc text = load(dir.write("quad.gltf", f.gltf("quad.bin")));
  const MeshDesc binary = load(dir.write("quad.glb", f.glb()), "quad.glb");
  ASSERT_EQ(text.positions.size(), binary.positions.size());
  for (size_t v = 0; v < text.positions.size(); ++v)
    for (int a = 0; a < 3; ++a) {
      EXPECT_EQ(text.positions[v][a], binary.positions[v][a]);
      EXPECT_EQ(text.normals[v][a], binary.normals[v][a]);
    }
  EXPECT_EQ(text.triangles.size(), binary.triangles.size());
  // The buffer's file is an input (the command line refuses to write over it).
  EXPECT_EQ(text.bufferFiles, std::vector<std::string>{dir.file("quad.bin")});
  EXPECT_TRUE(binary.bufferFiles.empty());
  EXPECT_TRUE(isGltfPath("a/B.GLB"));
  EXPECT_TRUE(isGltfPath("a.gltf"));
  EXPECT_FALSE(isGltfPath("gltf.obj"));
}

// A mirroring scale reverses the faces' winding, as glTF says, so that each face's outside (by
// its winding) stays on the side its normals point to.
TEST(GltfLoader, AMirroringTransformKeepsTheOutsideOut) {
  TempDir dir;
  GltfFile f = placedQuad();
  f.doc["nodes"][0]["scale"] = {-2, 1, 0.5};
  const MeshDesc mesh = load(dir.write("mirror.gltf", f.gltf()));
  for (const MeshTriangle& t : mesh.triangles) {
    const Vec3 e1 = mesh.positions[t.v[1]] - mesh.positions[t.v[0]];
    const Vec3 e2 = mesh.positions[t.v[2]] - mesh.positions[t.v[0]];
    EXPECT_GT(dot(cross(e1, e2), mesh.normals[size_t(t.n[0])]), 0.0f);
  }
}

// Indices of each unsigned type, an interleaved buffer (positions and uvs in one view, uvs as
// normalized shorts), a strip, a fan and a primitive without indices.
TEST(GltfLoader, EveryIndexTypeInterleavedBuffersStripsAndFans) {
  TempDir dir;
  GltfFile f;
  // Five vertices, each x y z (floats) then u v (normalized shorts) and 4 bytes of padding.
  std::string interleaved;
  const float xyz[5][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5f, 2, 0}};
  for (int v = 0; v < 5; ++v) {
    interleaved.append(reinterpret_cast<const char*>(xyz[v]), 12);
    const uint16_t uv[2] = {uint16_t(v * 16383), 65535};
    interleaved.append(reinterpret_cast<const char*>(uv), 4);
    interleaved.append(4, '\0');
  }
  const int p = f.addAccessor(std::vector<char>(interleaved.begin(), interleaved.end()), kFloat,
                              "VEC3", 5, 20);
  f.doc["accessors"].push_back(f.doc["accessors"][p]);
  const int t = int(f.doc["accessors"].size() - 1);
  f.doc["accessors"][t]["componentType"] = kUshort;
  f.doc["accessors"][t]["type"] = "VEC2";
  f.doc["accessors"][t]["normalized"] = true;
  f.doc["accessors"][t]["byteOffset"] = 12;
  const nlohmann::json attributes = {{"POSITION", p}, {"TEXCOORD_0", t}};
  const int i8 = f.addAccessor(std::vector<uint8_t>{0, 1, 2}, kUbyte, "SCALAR", 3);
  const int i32 = f.addAccessor(std::vector<uint32_t>{0, 2, 3}, kUint, "SCALAR", 3);
  const int strip = f.addAccessor(std::vector<uint16_t>{0, 1, 3, 2, 4}, kUshort, "SCALAR", 5);
  const int fan = f.addAccessor(std::vector<uint16_t>{0, 1, 2, 3}, kUshort, "SCALAR", 4);
  const nlohmann::json primitives = nlohmann::json::array(
      {nlohmann::json{{"attributes", attributes}, {"indices", i8}},
       nlohmann::json{{"attributes", attributes}, {"indices", i32}},
       nlohmann::json{{"attributes", attributes}, {"indices", strip}, {"mode", 5}},
       nlohmann::json{{"attributes", attributes}, {"indices", fan}, {"mode", 6}},
       nlohmann::json{{"attributes", attributes}}});
  f.doc["meshes"] = nlohmann::json::array({nlohmann::json{{"primitives", primitives}}});
  f.doc["nodes"] = nlohmann::json::array({nlohmann::json{{"mesh", 0}}});
  const MeshDesc mesh = load(dir.write("kinds.gltf", f.gltf()));
  // Each primitive has its own copy of the five vertices.
  const std::vector<std::vector<uint32_t>> expected = {{0, 1, 2}, {0, 2, 3}, {0, 1, 3}, {3, 1, 2},
                                                       {3, 2, 4}, {0, 1, 2}, {0, 2, 3}, {0, 1, 2}};
  const std::vector<uint32_t> primitiveOf = {0, 1, 2, 2, 2, 3, 3, 4};
  ASSERT_EQ(mesh.triangles.size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = mesh.triangles[i].v[k] - 5 * primitiveOf[i];
      EXPECT_EQ(v, expected[i][size_t(k)]) << "triangle " << i;
      for (int a = 0; a < 3; ++a) EXPECT_EQ(mesh.positions[mesh.triangles[i].v[k]][a], xyz[v][a]);
      EXPECT_EQ(mesh.uvs[size_t(mesh.triangles[i].t[k])].x, float(v * 16383) / 65535.0f);
      EXPECT_EQ(mesh.uvs[size_t(mesh.triangles[i].t[k])].y, 0.0f);
      EXPECT_EQ(mesh.triangles[i].n[k], -1);
    }
}

// KHR_mesh_quantization, as gltfpack writes it: positions of plain unsigned shorts scaled back by
// their node (uniformly, so that the normals keep their directions), normals of normalized bytes
// (the most negative held at -1, as glTF says), texture coordinates of plain bytes and of
// normalized signed shorts; each element padded to 4 bytes.
TEST(GltfLoader, AQuantizedMeshReadsAsItsNumbers) {
  TempDir dir;
  GltfFile f;
  const int p = f.addAccessor(std::vector<uint16_t>{0, 0, 0, 0, 1000, 0, 0, 0, 1000, 1000, 0, 0},
                              kUshort, "VEC3", 3, 8);
  const int n = f.addAccessor(std::vector<int8_t>{-128, 127, 0, 0, 0, 0, 127, 0, 76, 0, 102, 0},
                              kByte, "VEC3", 3, 4, true);
  const int t =
      f.addAccessor(std::vector<uint8_t>{0, 0, 0, 0, 4, 0, 0, 0, 4, 1, 0, 0}, kUbyte, "VEC2", 3, 4);
  const int ts = f.addAccessor(std::vector<int16_t>{-32768, 0, 32767, 16384, 0, -32767}, kShort,
                               "VEC2", 3, 0, true);
  const nlohmann::json primitives = nlohmann::json::array(
      {nlohmann::json{{"attributes", {{"POSITION", p}, {"NORMAL", n}, {"TEXCOORD_0", t}}}},
       nlohmann::json{{"attributes", {{"POSITION", p}, {"TEXCOORD_0", ts}}}}});
  f.doc["meshes"] = nlohmann::json::array({nlohmann::json{{"primitives", primitives}}});
  f.doc["nodes"] =
      nlohmann::json::array({nlohmann::json{{"mesh", 0}, {"scale", {1e-3, 1e-3, 1e-3}}}});
  f.doc["extensionsUsed"] = {"KHR_mesh_quantization"};
  f.doc["extensionsRequired"] = {"KHR_mesh_quantization"};
  const MeshDesc mesh = load(dir.write("quantized.glb", f.glb()));
  ASSERT_EQ(mesh.positions.size(), 6u);
  const float xyz[3][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}};
  for (size_t v = 0; v < 6; ++v)
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(mesh.positions[v][a], xyz[v % 3][a], 1e-6);
  ASSERT_EQ(mesh.normals.size(), 3u);
  const double r = std::sqrt(0.5), len = std::hypot(76.0, 102.0);
  const double normals[3][3] = {{-r, r, 0}, {0, 0, 1}, {76 / len, 0, 102 / len}};
  for (size_t v = 0; v < 3; ++v)
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(mesh.normals[v][a], normals[v][a], 1e-6);
  ASSERT_EQ(mesh.uvs.size(), 6u);
  const float uvs[6][2] = {{0, 1}, {4, 1}, {4, 0}, {-1, 1}, {1, 1 - 16384 / 32767.0f}, {0, 2}};
  for (size_t v = 0; v < 6; ++v) {
    EXPECT_FLOAT_EQ(mesh.uvs[v].x, uvs[v][0]) << v;
    EXPECT_FLOAT_EQ(mesh.uvs[v].y, uvs[v][1]) << v;
  }
  EXPECT_TRUE(mesh.warnings.empty());
}

// Sparse accessors (as exporters write small edits of a base): the base's elements with those
// the sparse part names substituted, and, without a base buffer view, zeros under them.
TEST(GltfLoader, SparseAccessorsSubstituteTheirElements) {
  TempDir dir;
  GltfFile f = placedQuad();
  f.doc["nodes"] = nlohmann::json::array({nlohmann::json{{"mesh", 0}}});
  f.doc["scenes"] = nlohmann::json::array({nlohmann::json{{"nodes", {0}}}});
  // Vertex 2 of the positions moves to (2, 3, 0).
  f.addAccessor(std::vector<uint16_t>{2}, kUshort, "SCALAR", 1);
  f.addFloats({2, 3, 0}, "VEC3", 3);
  const size_t views = f.doc["bufferViews"].size();
  f.doc["accessors"][0]["sparse"] = {
      {"count", 1},
      {"indices", {{"bufferView", views - 2}, {"componentType", kUshort}}},
      {"values", {{"bufferView", views - 1}}}};
  // The uvs: zeros but for vertices 1 and 3.
  f.addAccessor(std::vector<uint8_t>{1, 3}, kUbyte, "SCALAR", 2);
  f.addFloats({0.5f, 0.25f, 1, 1}, "VEC2", 2);
  f.doc["accessors"][2].erase("bufferView");
  f.doc["accessors"][2]["sparse"] = {
      {"count", 2},
      {"indices", {{"bufferView", views}, {"componentType", kUbyte}}},
      {"values", {{"bufferView", views + 1}}}};
  const MeshDesc mesh = load(dir.write("sparse.glb", f.glb()));
  ASSERT_EQ(mesh.positions.size(), 4u);
  const float xyz[4][3] = {{0, 0, 0}, {1, 0, 0}, {2, 3, 0}, {0, 1, 0}};
  for (size_t v = 0; v < 4; ++v)
    for (int a = 0; a < 3; ++a) EXPECT_EQ(mesh.positions[v][a], xyz[v][a]) << v;
  ASSERT_EQ(mesh.uvs.size(), 4u);
  const float uvs[4][2] = {{0, 1}, {0.5f, 0.75f}, {0, 1}, {1, 0}};  // v = 1 - glTF's v
  for (size_t v = 0; v < 4; ++v) {
    EXPECT_EQ(mesh.uvs[v].x, uvs[v][0]) << v;
    EXPECT_EQ(mesh.uvs[v].y, uvs[v][1]) << v;
  }

  struct Case {
    const char* name;
    std::function<void(GltfFile&)> breakIt;
    std::string expected;
  };
  const std::string at = "m.gltf: meshes[0].primitives[0].attributes.TEXCOORD_0: accessor 2";
  const std::vector<Case> cases = {
      {"indices that do not rise",
       [&](GltfFile& g) { g.buffer[g.doc["bufferViews"][views]["byteOffset"].get<size_t>()] = 3; },
       at + ": sparse.indices: index 1 is 3; expected indices that rise, below 4"},
      {"an index past the count",
       [&](GltfFile& g) {
         g.buffer[g.doc["bufferViews"][views]["byteOffset"].get<size_t>() + 1] = 4;
       },
       at + ": sparse.indices: index 1 is 4; expected indices that rise, below 4"},
      {"more substitutes than elements",
       [](GltfFile& g) { g.doc["accessors"][2]["sparse"]["count"] = 5; },
       at + ": sparse.count: expected from 1 to the accessor's count (4), got 5"},
      {"indices of floats",
       [](GltfFile& g) { g.doc["accessors"][2]["sparse"]["indices"]["componentType"] = kFloat; },
       at + ": sparse.indices.componentType: expected UNSIGNED_BYTE, UNSIGNED_SHORT or "
            "UNSIGNED_INT, got 5126"},
      {"values past their view",
       [](GltfFile& g) { g.doc["accessors"][2]["sparse"]["values"]["byteOffset"] = 4; },
       at + ": sparse.values: 2 elements of 8 bytes from byte 4 do not fit buffer view " +
           std::to_string(views + 1) + " (16 bytes)"},
      {"no such view",
       [](GltfFile& g) { g.doc["accessors"][2]["sparse"]["values"]["bufferView"] = 99; },
       at + ": sparse.values: buffer view 99 does not exist (" + std::to_string(views + 2) +
           " buffer views)"},
      {"a zero-filled count beyond reason",
       [](GltfFile& g) { g.doc["accessors"][2]["count"] = 1u << 30; },
       at + " has no buffer view and 1073741824 elements; candela fills at most 16777216 with "
            "zeros"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    GltfFile broken = f;
    c.breakIt(broken);
    EXPECT_EQ(loadError(dir.write("broken.gltf", broken.gltf())), c.expected);
  }
}

// EXT_mesh_gpu_instancing: the node's mesh copied to each instance, placed by its T R S under the
// node's transform (rotations as floats or normalized shorts); a bare file is framed around all
// the copies.
TEST(GltfLoader, InstancedMeshesAreCopiedToEachInstance) {
  TempDir dir;
  GltfFile f = placedQuad();
  const double h = std::sqrt(0.5);
  const int t = f.addFloats({0, 0, 0, 10, 0, 0, 0, 5, 0}, "VEC3", 3);
  const int r = f.addFloats({0, 0, 0, 1, 0, 0, float(h), float(h), 0, 0, 0, 1}, "VEC4", 4);
  const int16_t k = int16_t(std::lround(h * 32767));
  const int rs = f.addAccessor(std::vector<int16_t>{0, 0, 0, 32767, 0, 0, k, k, 0, 0, 0, 32767},
                               kShort, "VEC4", 3, 0, true);
  const int sc = f.addFloats({1, 1, 1, 2, 2, 2, 1, 1, 1}, "VEC3", 3);
  // Node 1 (the quad, under node 0) drawn three times.
  f.doc["nodes"][1]["extensions"] = {
      {"EXT_mesh_gpu_instancing",
       {{"attributes", {{"TRANSLATION", t}, {"ROTATION", r}, {"SCALE", sc}}}}}};
  f.doc["extensionsUsed"] = {"EXT_mesh_gpu_instancing"};
  // Instance i takes a quad corner (x, y, 0) to node 1's space as T_i R_i S_i, then on as before.
  const auto instance = [](int i, double x, double y) {
    if (i == 1) return placed(10 - 2 * y, 2 * x, 0);  // scaled by 2, turned 90 degrees about z
    return placed(x, y + (i == 2 ? 5 : 0), 0);
  };
  for (const int rotations : {r, rs}) {
    SCOPED_TRACE(rotations == r ? "float rotations" : "normalized short rotations");
    f.doc["nodes"][1]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"]["ROTATION"] =
        rotations;
    const MeshDesc mesh = load(dir.write("instanced.glb", f.glb()));
    ASSERT_EQ(mesh.positions.size(), 12u);
    ASSERT_EQ(mesh.triangles.size(), 6u);
    const double corners[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (int i = 0; i < 3; ++i)
      for (int v = 0; v < 4; ++v) {
        const auto expected = instance(i, corners[v][0], corners[v][1]);
        for (int a = 0; a < 3; ++a)
          EXPECT_NEAR(mesh.positions[size_t(4 * i + v)][a], expected[size_t(a)], 1e-4)
              << "instance " << i << ", corner " << v;
      }
  }
  // A bare file is framed around every copy: the far instance moves the bounds' centre.
  const auto centre = [&](const GltfFile& file, const char* name) {
    const nlohmann::json scene =
        nlohmann::json::parse(gltfSceneText(dir.write(name, file.glb()), name));
    return scene["camera"]["look_at"].get<std::vector<double>>();
  };
  // Node 1's x runs along the world's y, 6 to 1 (placed()): the copies span x from 0 to 10, the
  // quad alone 0 to 1, so the centre moves by 6 (5 - 0.5) = 27.
  EXPECT_NEAR(centre(f, "bare.glb")[1] - centre(placedQuad(), "once.glb")[1], 27.0, 1e-6);

  const std::string at = "m.gltf: nodes[1].extensions.EXT_mesh_gpu_instancing";
  GltfFile uneven = f;
  uneven.doc["nodes"][1]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"]["SCALE"] =
      uneven.addFloats({1, 1, 1}, "VEC3", 3);
  EXPECT_EQ(loadError(dir.write("uneven.gltf", uneven.gltf())),
            at + ".attributes.SCALE: 1 instances, where the other attributes have 3");
  GltfFile zero = f;
  zero.doc["nodes"][1]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"]["ROTATION"] =
      zero.addFloats({0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 1}, "VEC4", 4);
  EXPECT_EQ(loadError(dir.write("zero.gltf", zero.gltf())),
            at + ".attributes.ROTATION: instance 1: expected a unit quaternion, got 0");
  // 2^24 instances (zeros: no buffer view) of the 4-vertex quad and a 60-vertex second primitive.
  GltfFile many = placedQuad();
  many.doc["accessors"].push_back(
      {{"componentType", kFloat}, {"count", 1 << 24}, {"type", "VEC3"}});
  many.doc["accessors"].push_back({{"componentType", kFloat}, {"count", 60}, {"type", "VEC3"}});
  const size_t n = many.doc["accessors"].size();
  many.doc["meshes"][0]["primitives"].push_back({{"attributes", {{"POSITION", n - 1}}}});
  many.doc["nodes"][1]["extensions"] = {
      {"EXT_mesh_gpu_instancing", {{"attributes", {{"TRANSLATION", n - 2}}}}}};
  EXPECT_EQ(loadError(dir.write("many.gltf", many.gltf())),
            at + ": 16777216 instances of a mesh of 64 vertices are more than candela copies "
                 "(268435456 vertices)");
}

TEST(GltfLoader, WhatIsNotRenderedIsNamedInWarnings) {
  TempDir dir;
  GltfFile f = placedQuad();
  f.doc["cameras"] = nlohmann::json::array(
      {nlohmann::json{{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.1}}}}});
  f.doc["meshes"][0]["primitives"].push_back(f.doc["meshes"][0]["primitives"][0]);
  f.doc["meshes"][0]["primitives"][1]["mode"] = 1;  // lines
  const MeshDesc mesh = load(dir.write("extra.gltf", f.gltf()));
  EXPECT_EQ(mesh.triangles.size(), 2u);
  const std::vector<std::string> expected = {
      "m.gltf: points and lines are not rendered (meshes[0].primitives[1] is one)"};
  EXPECT_EQ(mesh.warnings, expected);
  EXPECT_TRUE(mesh.holdsCameras);  // the scene names them (test_gltf_camera.cpp)
}

TEST(GltfLoader, ASceneObjectNamesAGltfFile) {
  TempDir dir;
  dir.write("quad.glb", placedQuad().glb());
  const SceneDesc scene =
      parseSceneText(R"({"camera": {"width": 4, "height": 4}, "objects": [{"file": "quad.glb"}]})",
                     "s.json", dir.path());
  EXPECT_EQ(scene.objects[0].mesh->triangles.size(), 2u);
  try {
    parseSceneText(R"({"camera": {}, "objects": [{"file": "missing.gltf"}]})", "s.json",
                   dir.path());
    ADD_FAILURE() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()),
              "s.json: objects[0].file: cannot open \"missing.gltf\" (No "
              "such file or directory)");
  }
}

// Every kind of broken file, refused with one message naming the file and where in it.
TEST(GltfLoader, BrokenFilesAreRefusedWithTheirJsonPath) {
  TempDir dir;
  struct Case {
    const char* name;
    std::function<void(GltfFile&)> breakIt;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {"accessor out of range",
       [](GltfFile& f) { f.doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 40; },
       "m.gltf: meshes[0].primitives[0].attributes.POSITION: accessor 40 does not exist (4 "
       "accessors)"},
      {"view past its buffer", [](GltfFile& f) { f.doc["bufferViews"][1]["byteLength"] = 4000; },
       "m.gltf: meshes[0].primitives[0].attributes.NORMAL: accessor 1: buffer view 1 ends at "
       "byte 4048 of buffer 0, which holds 140"},
      {"elements past their view", [](GltfFile& f) { f.doc["accessors"][0]["count"] = 5; },
       "m.gltf: meshes[0].primitives[0].attributes.POSITION: accessor 0: 5 elements of 12 bytes "
       "from byte 0 do not fit buffer view 0 (48 bytes)"},
      {"index past the vertices", [](GltfFile& f) { f.buffer[128 + 2 * 5] = 9; },
       "m.gltf: meshes[0].primitives[0].indices: index 5 is 9, past the 4 vertices"},
      {"no positions",
       [](GltfFile& f) { f.doc["meshes"][0]["primitives"][0]["attributes"].erase("POSITION"); },
       "m.gltf: meshes[0].primitives[0].attributes: expected a POSITION"},
      {"positions of ints", [](GltfFile& f) { f.doc["accessors"][0]["componentType"] = kUint; },
       "m.gltf: meshes[0].primitives[0].attributes.POSITION: accessor 0 holds UNSIGNED_INT; "
       "expected FLOAT, or BYTE, UNSIGNED_BYTE, SHORT or UNSIGNED_SHORT, normalized or not"},
      {"normals of plain shorts",
       [](GltfFile& f) { f.doc["accessors"][1]["componentType"] = kShort; },
       "m.gltf: meshes[0].primitives[0].attributes.NORMAL: accessor 1 holds SHORT; expected "
       "FLOAT or normalized BYTE or SHORT"},
      {"a node reached twice", [](GltfFile& f) { f.doc["nodes"][1]["children"] = {0}; },
       "m.gltf: nodes[0] is reached twice (a node may have one parent and appear once)"},
      {"a required extension",
       [](GltfFile& f) { f.doc["extensionsRequired"] = {"KHR_texture_basisu"}; },
       "m.gltf: extensionsRequired: the file requires KHR_texture_basisu, which candela does not "
       "read"},
      {"a material out of range",
       [](GltfFile& f) { f.doc["meshes"][0]["primitives"][0]["material"] = 3; },
       "m.gltf: meshes[0].primitives[0].material: material 3 does not exist (0 materials)"},
      {"no triangles", [](GltfFile& f) { f.doc["meshes"][0]["primitives"][0]["mode"] = 0; },
       "m.gltf: expected at least one triangle, got none"},
      {"a zero rotation",
       [](GltfFile& f) {
         f.doc["nodes"][0]["rotation"] = {0, 0, 0, 0};
       },
       "m.gltf: nodes[0].rotation: expected a unit quaternion, got 0"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    GltfFile f = placedQuad();
    c.breakIt(f);
    EXPECT_EQ(loadError(dir.write("broken.gltf", f.gltf())), c.expected);
  }
  // Not glTF at all, a .glb cut short, a buffer file that is not there.
  EXPECT_EQ(loadError(dir.write("text.gltf", "{\"asset\": ")).rfind("m.gltf: ", 0), 0u);
  const std::string glb = placedQuad().glb();
  EXPECT_EQ(loadError(dir.write("short.glb", glb.substr(0, glb.size() / 2))).rfind("m.gltf: ", 0),
            0u);
  const std::string missingBin = loadError(dir.write("nobin.gltf", placedQuad().gltf("gone.bin")));
  EXPECT_EQ(missingBin.rfind("m.gltf: ", 0), 0u) << missingBin;
  EXPECT_NE(missingBin.find("gone.bin"), std::string::npos) << missingBin;
}

}  // namespace
}  // namespace candela
