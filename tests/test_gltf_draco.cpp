// KHR_draco_mesh_compression (scene/read/gltf_draco.h): a grid encoded by Draco's own encoder
// reads back as the same triangles, each corner's position and uv within Draco's quantization
// step; a broken stream, or one that does not hold what the primitive names, is refused with the
// JSON path; a build without Draco refuses a file that requires it.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "gltf_test_util.h"
#include "scene/read/gltf_draco.h"
#include "scene/read/gltf_loader.h"
#include "scene/read/texture_reader.h"
#include "scene/scene_error.h"
#include "temp_dir.h"

#ifdef CANDELA_HAS_DRACO
#include <draco/compression/encode.h>
#include <draco/mesh/triangle_soup_mesh_builder.h>
#endif

namespace candela {
namespace {

using test::GltfFile;
using test::TempDir;

std::string loadError(const std::string& path) { return test::gltfLoadError(path, "m.glb"); }

// A file whose one primitive's POSITION and TEXCOORD_0 are the Draco `stream` (its attribute ids
// `position` and `uv`), its accessors without buffer views, as encoders write them.
GltfFile dracoFile(const std::string& stream, int position, int uv) {
  GltfFile f;
  f.addAccessor(std::vector<char>(stream.begin(), stream.end()), 5121, "SCALAR", stream.size());
  f.doc["accessors"] = nlohmann::json::array(
      {nlohmann::json{{"componentType", 5126}, {"count", 25}, {"type", "VEC3"}},
       nlohmann::json{{"componentType", 5126}, {"count", 25}, {"type", "VEC2"}},
       nlohmann::json{{"componentType", 5123}, {"count", 96}, {"type", "SCALAR"}}});
  const nlohmann::json draco = {{"bufferView", 0},
                                {"attributes", {{"POSITION", position}, {"TEXCOORD_0", uv}}}};
  f.doc["meshes"] = nlohmann::json::array(
      {nlohmann::json{{"primitives",
                       {{{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 1}}},
                         {"indices", 2},
                         {"extensions", {{"KHR_draco_mesh_compression", draco}}}}}}}});
  f.doc["nodes"] = nlohmann::json::array({nlohmann::json{{"mesh", 0}}});
  f.doc["extensionsUsed"] = {"KHR_draco_mesh_compression"};
  f.doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
  return f;
}

#ifdef CANDELA_HAS_DRACO
MeshDesc load(const std::string& path) { return test::loadGltfMesh(path, "m.glb"); }

// A 4 x 4 grid of cells over [0, 2] x [0, 1] in z = x y / 2, its uvs (x / 2, y): 32 triangles.
constexpr int kCells = 4;
std::array<float, 3> gridPoint(int i, int j) {
  const float x = 2.0f * float(i) / kCells, y = float(j) / kCells;
  return {x, y, x * y / 2};
}

// The grid as Draco's encoder writes it (edgebreaker, positions quantized to 14 bits, uvs to 12),
// and its attributes' ids.
std::string encodedGrid(int* position, int* uv) {
  draco::TriangleSoupMeshBuilder builder;
  builder.Start(2 * kCells * kCells);
  const int p = builder.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
  const int t = builder.AddAttribute(draco::GeometryAttribute::TEX_COORD, 2, draco::DT_FLOAT32);
  int face = 0;
  const auto add = [&](std::array<int, 2> a, std::array<int, 2> b, std::array<int, 2> c) {
    std::array<float, 3> xyz[3] = {gridPoint(a[0], a[1]), gridPoint(b[0], b[1]),
                                   gridPoint(c[0], c[1])};
    std::array<float, 2> st[3];
    for (int k = 0; k < 3; ++k) st[k] = {xyz[k][0] / 2, xyz[k][1]};
    builder.SetAttributeValuesForFace(p, draco::FaceIndex(face), &xyz[0], &xyz[1], &xyz[2]);
    builder.SetAttributeValuesForFace(t, draco::FaceIndex(face), &st[0], &st[1], &st[2]);
    ++face;
  };
  for (int i = 0; i < kCells; ++i)
    for (int j = 0; j < kCells; ++j) {
      add({i, j}, {i + 1, j}, {i + 1, j + 1});
      add({i, j}, {i + 1, j + 1}, {i, j + 1});
    }
  const std::unique_ptr<draco::Mesh> mesh = builder.Finalize();
  draco::Encoder encoder;
  encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, 14);
  encoder.SetAttributeQuantization(draco::GeometryAttribute::TEX_COORD, 12);
  draco::EncoderBuffer out;
  EXPECT_TRUE(encoder.EncodeMeshToBuffer(*mesh, &out).ok());
  *position = int(mesh->attribute(p)->unique_id());
  *uv = int(mesh->attribute(t)->unique_id());
  return std::string(out.data(), out.size());
}

TEST(GltfDraco, ACompressedGridReadsAsItsTrianglesWithinTheQuantizationStep) {
  ASSERT_TRUE(gltfDracoDecoding());
  TempDir dir;
  int position = 0, uv = 0;
  const std::string stream = encodedGrid(&position, &uv);
  const MeshDesc mesh = load(dir.write("grid.glb", dracoFile(stream, position, uv).glb()));
  ASSERT_EQ(mesh.triangles.size(), size_t(2 * kCells * kCells));
  EXPECT_EQ(mesh.positions.size(), 25u);  // Draco welds the corners into the grid's points
  // 14 bits over the grid's extent of 2: a step of 2 / 16383, half of it the largest error.
  const double step = 2.0 / 16383, uvStep = 1.0 / 4095;
  double area = 0;
  for (const MeshTriangle& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const Vec3 p = mesh.positions[t.v[k]];
      // Each corner a grid point, and its uv that point's (v turned as glTF's).
      const double i = std::round(p.x / 2 * kCells), j = std::round(p.y * kCells);
      const auto g = gridPoint(int(i), int(j));
      for (int a = 0; a < 3; ++a) EXPECT_NEAR(p[a], g[size_t(a)], step);
      const Vec2 st = mesh.uvs[size_t(t.t[k])];
      EXPECT_NEAR(st.x, g[0] / 2, uvStep);
      EXPECT_NEAR(st.y, 1 - g[1], uvStep);
    }
    const Vec3 a = mesh.positions[t.v[0]], b = mesh.positions[t.v[1]], c = mesh.positions[t.v[2]];
    area += 0.5 * double(length(cross(b - a, c - a)));
  }
  // The surface z = x y / 2 over [0, 2] x [0, 1], as flat triangles: their summed area is the
  // grid's (by the same arithmetic on the exact points).
  double expected = 0;
  for (int i = 0; i < kCells; ++i)
    for (int j = 0; j < kCells; ++j) {
      const auto corner = [&](int di, int dj) {
        const auto g = gridPoint(i + di, j + dj);
        return Vec3(g[0], g[1], g[2]);
      };
      const Vec3 a = corner(0, 0), b = corner(1, 0), c = corner(1, 1), d = corner(0, 1);
      expected +=
          0.5 * double(length(cross(b - a, c - a))) + 0.5 * double(length(cross(c - a, d - a)));
    }
  EXPECT_NEAR(area, expected, 1e-3);
  // A .gltf (text, its buffer a data URI) reads alike.
  const MeshDesc text = load(dir.write("grid.gltf", dracoFile(stream, position, uv).gltf()));
  ASSERT_EQ(text.triangles.size(), mesh.triangles.size());
  for (size_t v = 0; v < mesh.positions.size(); ++v)
    for (int a = 0; a < 3; ++a) EXPECT_EQ(text.positions[v][a], mesh.positions[v][a]);
  // Every triangle faces +z's side, as the grid's winding says.
  for (const MeshTriangle& t : mesh.triangles) {
    const Vec3 a = mesh.positions[t.v[0]], b = mesh.positions[t.v[1]], c = mesh.positions[t.v[2]];
    EXPECT_GT(cross(b - a, c - a).z, 0.0f);
  }
}

TEST(GltfDraco, AStreamThatDoesNotHoldWhatThePrimitiveNamesIsRefused) {
  TempDir dir;
  int position = 0, uv = 0;
  const std::string stream = encodedGrid(&position, &uv);
  const std::string at = "m.glb: meshes[0].primitives[0].extensions.KHR_draco_mesh_compression";
  std::string garbage = stream;
  for (size_t i = 0; i < garbage.size(); ++i) garbage[i] = char(i * 7);
  const std::string broken = loadError(dir.write("a.glb", dracoFile(garbage, position, uv).glb()));
  EXPECT_EQ(broken.rfind(at + ": Draco cannot decode buffer view 0 (", 0), 0u) << broken;
  EXPECT_EQ(loadError(dir.write("b.glb", dracoFile(stream, position, 7).glb())),
            at + ".attributes.TEXCOORD_0: the Draco stream has no attribute 7");
  EXPECT_EQ(loadError(dir.write("c.glb", dracoFile(stream, uv, position).glb())),
            at + ".attributes.POSITION: the Draco attribute has 2 components, its accessor 3");
  GltfFile unnamed = dracoFile(stream, position, uv);
  unnamed.doc["meshes"][0]["primitives"][0]["attributes"].erase("TEXCOORD_0");
  EXPECT_EQ(loadError(dir.write("d.glb", unnamed.glb())),
            at + ".attributes.TEXCOORD_0: the primitive has no attribute TEXCOORD_0");
  GltfFile pastView = dracoFile(stream, position, uv);
  pastView
      .doc["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["bufferView"] =
      3;
  EXPECT_EQ(loadError(dir.write("e.glb", pastView.glb())),
            at + ".bufferView: buffer view 3 does not exist (1 buffer views)");
  GltfFile points = dracoFile(stream, position, uv);
  points.doc["meshes"][0]["primitives"][0]["mode"] = 0;
  EXPECT_EQ(loadError(dir.write("f.glb", points.glb())),
            at + ": a compressed primitive holds triangles (mode 4 or 5), not mode 0");
}
#endif

TEST(GltfDraco, ABuildWithoutDracoRefusesAFileThatRequiresIt) {
  if (gltfDracoDecoding()) GTEST_SKIP() << "this build reads Draco (the tests above)";
  TempDir dir;
  EXPECT_EQ(loadError(dir.write("a.glb", dracoFile("not a stream", 0, 1).glb())),
            "m.glb: extensionsRequired: the file requires KHR_draco_mesh_compression, and this "
            "build of candela reads no such files (built without libdraco-dev)");
}

}  // namespace
}  // namespace candela
