// The CPU's triangle blocks (backends/cpu/triangle_blocks.h) against candela's own watertight
// triangle test, one triangle at a time: the same nearest triangle, distance and barycentrics up
// to the rounding of two different tests, the same shadow answers but for rays that graze an edge,
// ties to the lower index, and no hit on padding, degenerate triangles or a ray's own start.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "backends/cpu/triangle_blocks.h"
#include "geometry/triangle_intersect.h"
#include "test_geometry_view.h"
#include "test_random.h"

namespace candela {
namespace {

constexpr uint32_t kNone = 0xffffffffu;

struct Mesh {
  std::vector<Vec3> positions;
  std::vector<Triangle> triangles;
  uint32_t count() const { return uint32_t(triangles.size()); }
};

struct Nearest {
  bool found = false;
  float t = 0;
  uint32_t triangle = kNone;
  float b1 = 0, b2 = 0;
};

Nearest closestOneByOne(const Mesh& mesh, const Ray& ray) {
  Nearest n;
  float tMax = ray.tMax;
  for (uint32_t i = 0; i < mesh.count(); ++i) {
    const Triangle& tri = mesh.triangles[i];
    TriangleHit hit;
    if (!intersectTriangle(mesh.positions[tri.v[0]], mesh.positions[tri.v[1]],
                           mesh.positions[tri.v[2]], ray, tMax, &hit))
      continue;
    tMax = hit.t;
    n = Nearest{true, hit.t, i, hit.b1, hit.b2};
  }
  return n;
}

bool anyOneByOne(const Mesh& mesh, const Ray& ray, uint32_t skip) {
  for (uint32_t i = 0; i < mesh.count(); ++i) {
    const Triangle& tri = mesh.triangles[i];
    TriangleHit hit;
    if (i != skip && intersectTriangle(mesh.positions[tri.v[0]], mesh.positions[tri.v[1]],
                                       mesh.positions[tri.v[2]], ray, ray.tMax, &hit))
      return true;
  }
  return false;
}

Nearest closestInBlocks(const TriangleBlocks& blocks, const Ray& ray) {
  Nearest n;
  n.found = closestTriangle(blocks.view(), ray, ray.tMax, &n.t, &n.triangle, &n.b1, &n.b2);
  return n;
}

// `count` triangles in a box of side 8: pairs that share an edge (quads, as meshes have), and
// loose ones of all sizes and orientations.
Mesh randomMesh(std::mt19937& gen, uint32_t count) {
  std::uniform_real_distribution<float> u(-4.0f, 4.0f), size(0.05f, 3.0f);
  Mesh mesh;
  while (mesh.count() < count) {
    const Vec3 a(u(gen), u(gen), u(gen));
    const Vec3 b = a + test::randomUnitVector(gen) * size(gen);
    const Vec3 c = a + test::randomUnitVector(gen) * size(gen);
    const uint32_t first = uint32_t(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), {a, b, c, b + c - a});
    mesh.triangles.push_back(Triangle{{first, first + 1, first + 2}, 0});
    if (mesh.count() < count && gen() % 2 == 0)
      mesh.triangles.push_back(Triangle{{first + 1, first + 3, first + 2}, 0});
  }
  return mesh;
}

TriangleBlocks blocksOf(const Mesh& mesh) {
  TriangleBlocks blocks;
  blocks.assign(mesh.positions.data(), mesh.triangles.data(), mesh.count());
  return blocks;
}

class TriangleBlocksTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (widestTriangleBlock() == 0)
      GTEST_SKIP() << "this CPU has no triangle blocks (AVX2 and FMA)";
  }
};

TEST_F(TriangleBlocksTest, MatchTheWatertightTestUpToRounding) {
  std::mt19937 gen(3);
  std::uniform_real_distribution<float> u(-5.0f, 5.0f), unit(0.0f, 1.0f);
  for (uint32_t count : {1u, 7u, 8u, 9u, 33u, kTriangleBlocksUpTo}) {
    const Mesh mesh = randomMesh(gen, count);
    const TriangleBlocks blocks = blocksOf(mesh);
    EXPECT_EQ(blocks.view().width, 8u);
    EXPECT_EQ(blocks.view().blockCount, (count + 7) / 8);
    int hits = 0, disagree = 0, occluded = 0, occludedDisagree = 0;
    for (int i = 0; i < 20000; ++i) {
      Ray ray;
      ray.origin = Vec3(u(gen), u(gen), u(gen));
      ray.direction = test::randomUnitVector(gen) * (i % 5 == 0 ? 0.3f + 2.0f * unit(gen) : 1.0f);
      if (i % 4 == 1) ray.tMax = 0.5f + 6.0f * unit(gen);
      const Nearest expected = closestOneByOne(mesh, ray);
      const Nearest got = closestInBlocks(blocks, ray);
      if (got.found != expected.found) {
        ++disagree;  // a ray through an edge, or at tMax, within rounding
        continue;
      }
      if (!got.found) continue;
      ++hits;
      EXPECT_NEAR(got.t, expected.t, 1e-4f * expected.t + 1e-6f)
          << count << " triangles, ray " << i;
      if (got.triangle == expected.triangle) {
        EXPECT_NEAR(got.b1, expected.b1, 1e-4f) << "ray " << i;
        EXPECT_NEAR(got.b2, expected.b2, 1e-4f) << "ray " << i;
        const Triangle& tri = mesh.triangles[got.triangle];
        const Vec3 p = (1.0f - got.b1 - got.b2) * mesh.positions[tri.v[0]] +
                       got.b1 * mesh.positions[tri.v[1]] + got.b2 * mesh.positions[tri.v[2]];
        const Vec3 along = ray.origin + got.t * ray.direction;
        EXPECT_NEAR(length(p - along), 0.0f, 1e-4f) << "ray " << i;
      } else {
        ++disagree;  // two triangles crossing, or sharing an edge, at that distance
      }
      const uint32_t skip = i % 3 == 0 ? kNone : i % 3 == 1 ? expected.triangle : gen() % count;
      const bool blocked = anyOneByOne(mesh, ray, skip);
      occluded += blocked;
      occludedDisagree += anyTriangle(blocks.view(), ray, skip) != blocked;
    }
    EXPECT_GT(hits, int(std::min(25 * count, 1000u))) << count << " triangles";
    EXPECT_GT(occluded, int(std::min(15 * count, 500u))) << count << " triangles";
    // Only rays within rounding of an edge or of tMax may be answered differently.
    EXPECT_LE(disagree, 4) << count << " triangles";
    EXPECT_LE(occludedDisagree, 4) << count << " triangles";
  }
}

// One triangle facing +z at z = -5, both windings, translated by `offset`.
Mesh facing(const std::vector<Vec3>& offsets) {
  Mesh mesh;
  for (const Vec3& offset : offsets) {
    const uint32_t first = uint32_t(mesh.positions.size());
    mesh.positions.insert(
        mesh.positions.end(),
        {offset + Vec3(-1, -1, -5), offset + Vec3(2, -1, -5), offset + Vec3(-1, 2, -5)});
    mesh.triangles.push_back(Triangle{{first, first + 1, first + 2}, 0});
  }
  return mesh;
}

using test::rayDownMinusZ;  // towards the shapes at z = -5 of the tests below

TEST_F(TriangleBlocksTest, ATieGoesToTheLowerIndexANearerHitToAnyIndex) {
  // Copies of one triangle in several blocks and lanes, the rest out of the way: the first copy
  // is reported; a nearer triangle wins wherever it sits.
  std::vector<Vec3> offsets(20, Vec3(50, 50, 0));
  for (uint32_t i : {3, 4, 9, 13, 18}) offsets[i] = Vec3(0.0f);
  Mesh mesh = facing(offsets);
  const Ray ray = rayDownMinusZ();
  Nearest n = closestInBlocks(blocksOf(mesh), ray);
  ASSERT_TRUE(n.found);
  EXPECT_EQ(n.triangle, 3u);
  EXPECT_FLOAT_EQ(n.t, 5.0f);
  EXPECT_FLOAT_EQ(n.b1, 1.0f / 3.0f);
  EXPECT_FLOAT_EQ(n.b2, 1.0f / 3.0f);

  offsets[17] = Vec3(0, 0, 2);
  mesh = facing(offsets);
  n = closestInBlocks(blocksOf(mesh), ray);
  ASSERT_TRUE(n.found);
  EXPECT_EQ(n.triangle, 17u);
  EXPECT_FLOAT_EQ(n.t, 3.0f);
  // Only the skipped triangle in the way: nothing blocks; any other copy does.
  EXPECT_TRUE(anyTriangle(blocksOf(mesh).view(), ray, 17));
  EXPECT_FALSE(anyTriangle(blocksOf(facing({Vec3(0.0f)})).view(), ray, 0));
  EXPECT_TRUE(anyTriangle(blocksOf(facing({Vec3(0.0f)})).view(), ray, kNone));
}

TEST_F(TriangleBlocksTest, NothingHitsPaddingDegenerateTrianglesOrTheRaysStart) {
  TriangleBlocks none;
  none.assign(nullptr, nullptr, 0);
  EXPECT_EQ(none.view().blockCount, 0u);

  // One triangle in a block of 8: the padding lanes (all zeros, so at the origin) are not hit by
  // a ray through the origin.
  Mesh one = facing({Vec3(0.0f)});
  Ray through;
  through.origin = Vec3(0, 0, 1);
  through.direction = Vec3(0.05f, 0.05f, -1.0f);
  Nearest n = closestInBlocks(blocksOf(one), through);
  ASSERT_TRUE(n.found);
  EXPECT_EQ(n.triangle, 0u);

  // A degenerate triangle (its vertices on a line) is never hit, not even along its line.
  Mesh line;
  line.positions = {Vec3(-1, 0, -5), Vec3(0, 0, -5), Vec3(1, 0, -5)};
  line.triangles = {Triangle{{0, 1, 2}, 0}};
  Ray along;
  along.origin = Vec3(-3, 0, -5);
  along.direction = Vec3(1, 0, 0);
  for (const Ray& ray : {rayDownMinusZ(), along}) {
    EXPECT_FALSE(closestInBlocks(blocksOf(line), ray).found);
    EXPECT_FALSE(anyTriangle(blocksOf(line).view(), ray, kNone));
  }

  // A ray leaving the triangle's plane, from on it or just off it, and a ray that stops short.
  Ray leaving;
  leaving.origin = Vec3(0, 0, -5);
  leaving.direction = Vec3(0.2f, 0.1f, 1.0f);
  EXPECT_FALSE(closestInBlocks(blocksOf(one), leaving).found);
  Ray shortRay = rayDownMinusZ();
  shortRay.tMax = 4.99f;
  EXPECT_FALSE(closestInBlocks(blocksOf(one), shortRay).found);
  EXPECT_FALSE(anyTriangle(blocksOf(one).view(), shortRay, kNone));

  // No direction: nothing.
  Ray still = rayDownMinusZ();
  still.direction = Vec3(0.0f);
  EXPECT_FALSE(closestInBlocks(blocksOf(one), still).found);
}

}  // namespace
}  // namespace candela
