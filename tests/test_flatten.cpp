// Flattening meshes into the renderer's arrays: world-space transforms, one normal per vertex
// (creases split), no normals ("none") where a mesh has none, and winding kept under mirroring.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>

#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "geometry/bvh_build.h"
#include "scene/flatten.h"
#include "scene/read/scene_loader.h"

namespace candela {
namespace {

std::string writeObj(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

SceneData flatten(const std::string& objects) {
  return flattenScene(parseSceneText(R"({"camera": {"width": 8, "height": 8}, "objects": )" +
                                         objects + "}",
                                     "flatten.json", "."));
}

Vec3 faceNormal(const SceneData& s, const Triangle& t) {
  return normalize(cross(s.positions[t.v[1]] - s.positions[t.v[0]],
                         s.positions[t.v[2]] - s.positions[t.v[0]]));
}

// Two faces share an edge but give its vertices different normals: those vertices are split.
const char* kCrease =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvn 0 0 1\nvn 0.6 0 0.8\n"
    "f 1//1 2//1 3//1\nf 2//2 4//2 3//2\n";

TEST(Flatten, CreaseVerticesAreSplitSoEachFaceKeepsItsNormals) {
  const std::string obj = writeObj("crease.obj", kCrease);
  const SceneData s = flatten(R"([{"file": ")" + obj + R"("}])");
  ASSERT_EQ(s.triangles.size(), 2u);
  EXPECT_EQ(s.positions.size(), 6u);  // 4 positions + 2 split
  ASSERT_EQ(s.normals.size(), s.positions.size());
  // Normals are stored octahedrally encoded (within 7e-5 radians).
  for (uint32_t v : s.triangles[0].v) EXPECT_NEAR(decodeOctNormal(s.normals[v]).z, 1.0f, 1e-6f);
  for (uint32_t v : s.triangles[1].v) {
    EXPECT_NEAR(decodeOctNormal(s.normals[v]).x, 0.6f, 1e-4f);
    EXPECT_NEAR(decodeOctNormal(s.normals[v]).z, 0.8f, 1e-4f);
  }
  // Split vertices sit where the originals are.
  EXPECT_EQ(s.positions[s.triangles[0].v[1]].x, s.positions[s.triangles[1].v[0]].x);
}

// Objects that place one mesh share how its vertices are laid out (scene/mesh_layout.h), but each
// gets its own vertices, split ones included, at its own place.
TEST(Flatten, ObjectsPlacingOneMeshEachGetItsSplitVerticesInPlace) {
  const std::string obj = writeObj("crease3.obj", kCrease);
  // The contents alone: their triangles in the description's order, not in a BVH's.
  const SceneData s = flattenSceneContents(
      parseSceneText(R"({"camera": {"width": 8, "height": 8}, "objects": [{"file": ")" + obj +
                         R"("}, {"file": ")" + obj + R"(", "position": [5, 0, 0]}]})",
                     "flatten.json", "."));
  ASSERT_EQ(s.triangles.size(), 4u);
  ASSERT_EQ(s.positions.size(), 12u);
  ASSERT_EQ(s.normals.size(), 12u);
  for (int k = 0; k < 2; ++k) {
    for (int c = 0; c < 3; ++c) {
      const uint32_t a = s.triangles[k].v[c], b = s.triangles[2 + k].v[c];
      EXPECT_EQ(b, a + 6);
      EXPECT_EQ(s.positions[b].x, s.positions[a].x + 5.0f);
      EXPECT_EQ(s.positions[b].y, s.positions[a].y);
      EXPECT_EQ(s.normals[b].bits, s.normals[a].bits);
    }
  }
  // The second object's split vertices copy its own positions, not the first object's.
  for (uint32_t v = 10; v < 12; ++v) EXPECT_GE(s.positions[v].x, 5.0f);
}

TEST(Flatten, FlatMeshesAndUnsmoothedObjectsCarryNoNormals) {
  const std::string crease = writeObj("crease2.obj", kCrease);
  const std::string flat = writeObj("flat.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const SceneData s = flatten(R"([{"file": ")" + flat + R"("},
                                  {"file": ")" + crease + R"("},
                                  {"file": ")" + crease + R"(", "smooth": false},
                                  {"file": ")" + flat + R"("}])");
  ASSERT_EQ(s.normals.size(), s.positions.size());
  EXPECT_EQ(s.triangles.size(), 6u);
  for (uint32_t v : s.triangles[0].v) EXPECT_TRUE(s.normals[v].isNone());  // before a smooth mesh
  for (uint32_t v : s.triangles[3].v) EXPECT_TRUE(s.normals[v].isNone());  // smooth: false
  for (uint32_t v : s.triangles[5].v) EXPECT_TRUE(s.normals[v].isNone());  // after it
  for (uint32_t v : s.triangles[1].v) EXPECT_FALSE(s.normals[v].isNone());
}

TEST(Flatten, NoNormalsStoredWhenNoMeshHasThem) {
  const std::string flat = writeObj("flat2.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const SceneData s = flatten(R"([{"file": ")" + flat + R"("}])");
  EXPECT_TRUE(s.normals.empty());
  EXPECT_EQ(sizeof(Triangle), 16u);
}

TEST(Flatten, MirroringScaleKeepsTheOutsideAndTransformsNormals) {
  // Counter-clockwise seen from +z: the outside is +z, and so is the vertex normal.
  const std::string obj =
      writeObj("ccw.obj", "v 1 0 0\nv 2 0 0\nv 1 1 0\nvn 0.6 0 0.8\nf 1//1 2//1 3//1\n");
  const SceneData s = flatten(R"([{"file": ")" + obj + R"(", "scale": [-1, 1, 1]}])");
  ASSERT_EQ(s.triangles.size(), 1u);
  EXPECT_NEAR(faceNormal(s, s.triangles[0]).z, 1.0f, 1e-6f);
  EXPECT_LT(s.positions[s.triangles[0].v[0]].x, 0.0f);
  // Normals follow the inverse transpose: mirrored in x.
  EXPECT_NEAR(decodeOctNormal(s.normals[s.triangles[0].v[0]]).x, -0.6f, 1e-4f);
}

TEST(Flatten, TrianglesAreNumberedInLeafOrder) {
  // A mesh listed in scrambled order comes out numbered as the BVH's leaves list it, and the
  // permutation keeps every triangle.
  std::string text;
  const int n = 20;
  for (int i = 0; i < n; ++i) text += "v " + std::to_string(i) + " 0 0\nv " + std::to_string(i) +
                                      " 1 0\nv " + std::to_string(i) + ".5 0 1\n";
  for (int k = 0; k < n; ++k) {
    const int i = (k * 7) % n;  // scrambled
    text += "f " + std::to_string(3 * i + 1) + " " + std::to_string(3 * i + 2) + " " +
            std::to_string(3 * i + 3) + "\n";
  }
  const std::string obj = writeObj("scrambled.obj", text);
  const SceneData s = flatten(R"([{"file": ")" + obj + R"("}])");
  ASSERT_EQ(s.triangles.size(), size_t(n));
  ASSERT_EQ(s.primIndices.size(), size_t(n));
  for (uint32_t k = 0; k < n; ++k) EXPECT_EQ(s.primIndices[k], k);
  std::vector<bool> seen(n, false);
  for (const Triangle& t : s.triangles) seen[t.v[0] / 3] = true;
  for (int i = 0; i < n; ++i) EXPECT_TRUE(seen[i]) << "triangle " << i;
  // The tree splits the row along x and lists left children first, so memory follows space:
  // triangle k sits at x = k, give or take its place inside a leaf.
  for (int k = 0; k < n; ++k) {
    const int x = int(s.triangles[k].v[0] / 3);
    EXPECT_LE(std::abs(x - k), int(kBvhMaxLeafSize) - 1) << "triangle " << k << " at x = " << x;
  }
}

template <typename T, class Allocator>
bool sameBytes(const std::vector<T, Allocator>& a, const std::vector<T, Allocator>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

TEST(Flatten, AConsumedDescriptionGivesTheSameSceneAndReleasesOnlyItsMeshes) {
  const std::string obj = writeObj("consumed.obj", kCrease);
  SceneDesc desc = parseSceneText(
      R"({"camera": {"width": 8, "height": 8}, "render": {"exposure": -3},
          "spheres": [{"position": [0, 0, -5], "radius": 1}],
          "objects": [{"file": ")" + obj + R"(", "position": [1, 2, 3]},
                      {"file": ")" + obj + R"(", "scale": 2}]})",
      "consumed.json", ".");
  const SceneData kept = flattenScene(desc);
  const SceneData consumed = flattenScene(std::move(desc));
  EXPECT_TRUE(sameBytes(kept.positions, consumed.positions));
  EXPECT_TRUE(sameBytes(kept.normals, consumed.normals));
  EXPECT_TRUE(sameBytes(kept.triangles, consumed.triangles));
  EXPECT_TRUE(sameBytes(kept.spheres, consumed.spheres));
  EXPECT_TRUE(sameBytes(kept.nodes, consumed.nodes));
  EXPECT_TRUE(sameBytes(kept.primIndices, consumed.primIndices));
  ASSERT_EQ(desc.objects.size(), 2u);  // NOLINT(bugprone-use-after-move): documented state
  for (const ObjectDesc& o : desc.objects) {
    EXPECT_TRUE(o.mesh->positions.empty());
    EXPECT_TRUE(o.mesh->triangles.empty());
  }
  EXPECT_EQ(desc.objects[0].position.z, 3.0f);
  EXPECT_EQ(desc.output.exposure, -3.0f);
  EXPECT_EQ(desc.spheres.size(), 1u);
}

}  // namespace
}  // namespace candela
