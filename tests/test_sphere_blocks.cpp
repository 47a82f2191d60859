// The CPU's sphere blocks (backends/cpu/sphere_blocks.h) against intersectSphere, one sphere at a
// time: the same nearest sphere and bit for bit the same distance, the same shadow answers, on
// room-sized wall spheres, rays from inside, grazing rays and rays limited by tMax.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "backends/cpu/sphere_blocks.h"
#include "geometry/sphere_intersect.h"
#include "test_geometry_view.h"
#include "test_random.h"

namespace candela {
namespace {

constexpr uint32_t kNone = 0xffffffffu;

bool closestOneByOne(const std::vector<Sphere>& spheres, const Ray& ray, float* t, uint32_t* prim) {
  float tMax = ray.tMax;
  bool found = false;
  for (uint32_t i = 0; i < spheres.size(); ++i) {
    float ti;
    if (!intersectSphere(spheres[i], ray, tMax, &ti)) continue;
    tMax = *t = ti;
    *prim = i;
    found = true;
  }
  return found;
}

bool anyOneByOne(const std::vector<Sphere>& spheres, const Ray& ray, uint32_t skip) {
  float t;
  for (uint32_t i = 0; i < spheres.size(); ++i)
    if (i != skip && intersectSphere(spheres[i], ray, ray.tMax, &t)) return true;
  return false;
}

uint32_t bits(float x) {
  uint32_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

// The walls of the room scenes, a few spheres inside it, and `extra` random ones.
std::vector<Sphere> roomSpheres(std::mt19937& gen, int extra) {
  std::vector<Sphere> s = {
      {Vec3(-1000, 0, 0), 940}, {Vec3(1000, 0, 0), 940}, {Vec3(0, 0, -1000), 940},
      {Vec3(0, 0, 1000), 940},  {Vec3(0, -1000, 0), 990}, {Vec3(0, 1000, 0), 940},
      {Vec3(-10, 0, -25), 10},  {Vec3(9, -1, -38), 9},    {Vec3(-15, -3, 15), 7}};
  std::uniform_real_distribution<float> u(-40.0f, 40.0f), r(0.5f, 12.0f);
  for (int i = 0; i < extra; ++i) s.push_back(Sphere{Vec3(u(gen), u(gen), u(gen)), r(gen)});
  return s;
}

Ray randomRay(std::mt19937& gen, const std::vector<Sphere>& spheres, int i) {
  std::uniform_real_distribution<float> u(-50.0f, 50.0f), unit(0.0f, 1.0f);
  Ray ray;
  ray.origin = Vec3(u(gen), u(gen), u(gen));
  ray.direction = test::randomUnitVector(gen) * (i % 5 == 0 ? 0.3f + 2.0f * unit(gen) : 1.0f);
  if (i % 7 == 3) {
    // Aimed at a sphere's silhouette: |perp| within a few ulp of the radius.
    const Sphere& s = spheres[gen() % spheres.size()];
    const Vec3 toCentre = s.center - ray.origin;
    Vec3 side = cross(toCentre, test::randomUnitVector(gen));
    side = normalize(side) * (s.radius * (1.0f + 2e-7f * float(int(gen() % 11) - 5)));
    ray.direction = normalize(toCentre + side);
  }
  if (i % 4 == 1) ray.tMax = 1.0f + 60.0f * unit(gen);
  return ray;
}

class SphereBlocksOfWidth : public ::testing::TestWithParam<uint32_t> {
 protected:
  void SetUp() override {
    if (GetParam() > widestSphereBlock())
      GTEST_SKIP() << "this CPU has no " << GetParam() << "-wide sphere blocks (AVX2)";
  }
};

TEST_P(SphereBlocksOfWidth, MatchOneSphereAtATimeBitForBit) {
  const uint32_t width = GetParam();
  std::mt19937 gen(5);
  for (int extra : {0, 1, 3, 7, 23}) {
    const std::vector<Sphere> spheres = roomSpheres(gen, extra);
    SphereBlocks blocks;
    blocks.assign(spheres.data(), uint32_t(spheres.size()), width);
    const SphereBlocksView view = blocks.view();
    // The narrowest block that holds them all, within `width`.
    uint32_t expectedWidth = 4;
    while (expectedWidth < width && expectedWidth < spheres.size()) expectedWidth *= 2;
    EXPECT_EQ(view.width, expectedWidth);
    EXPECT_EQ(view.blockCount, (spheres.size() + expectedWidth - 1) / expectedWidth);
    int hits = 0, occluded = 0, grazing = 0;
    for (int i = 0; i < 20000; ++i) {
      const Ray ray = randomRay(gen, spheres, i);
      float tExpected = 0, tGot = 0;
      uint32_t expected = kNone, got = kNone;
      const bool found = closestOneByOne(spheres, ray, &tExpected, &expected);
      ASSERT_EQ(closestSphere(view, ray, ray.tMax, &tGot, &got), found)
          << extra << " extra spheres, ray " << i;
      if (found) {
        ++hits;
        EXPECT_EQ(got, expected) << "ray " << i;
        EXPECT_EQ(bits(tGot), bits(tExpected)) << "ray " << i << ": " << tGot << " vs " << tExpected;
      }
      const uint32_t skip = i % 3 == 0 ? kNone : i % 3 == 1 && found ? expected
                                                                     : uint32_t(gen() % spheres.size());
      const bool blocked = anyOneByOne(spheres, ray, skip);
      EXPECT_EQ(anySphere(view, ray, skip), blocked) << "ray " << i << " skipping " << skip;
      occluded += blocked;
      grazing += i % 7 == 3 && found;
    }
    EXPECT_GT(hits, 10000);
    EXPECT_GT(occluded, 5000);
    EXPECT_GT(grazing, 100);
  }
}

using test::rayDownMinusZ;  // towards the shapes at z = -5 of the tests below

TEST_P(SphereBlocksOfWidth, ATieGoesToTheLowerIndexANearerHitToAnyIndex) {
  // Copies of one sphere in several blocks and lanes at every width, the rest out of the way:
  // the first copy is reported; a nearer sphere wins wherever it sits.
  const Sphere s{Vec3(0, 0, -5), 1};
  std::vector<Sphere> spheres;
  for (uint32_t i = 0; i < 20; ++i) spheres.push_back(Sphere{Vec3(9.0f + float(i), 9, 9), 0.5f});
  for (uint32_t i : {1, 2, 3, 4, 5, 9, 13, 18}) spheres[i] = s;
  SphereBlocks blocks;
  blocks.assign(spheres.data(), uint32_t(spheres.size()), GetParam());
  const Ray ray = rayDownMinusZ();
  float t;
  uint32_t prim;
  ASSERT_TRUE(closestSphere(blocks.view(), ray, ray.tMax, &t, &prim));
  EXPECT_EQ(prim, 1u);
  EXPECT_FLOAT_EQ(t, 4.0f);

  spheres[17] = Sphere{Vec3(0, 0, -3), 0.5f};
  blocks.assign(spheres.data(), uint32_t(spheres.size()), GetParam());
  ASSERT_TRUE(closestSphere(blocks.view(), ray, ray.tMax, &t, &prim));
  EXPECT_EQ(prim, 17u);
  EXPECT_FLOAT_EQ(t, 2.5f);
}

INSTANTIATE_TEST_SUITE_P(SphereBlocks, SphereBlocksOfWidth, ::testing::Values(4u, 8u),
                         [](const ::testing::TestParamInfo<uint32_t>& param) {
                           return "Width" + std::to_string(param.param);
                         });

TEST(SphereBlocks, NoSpheresAndDegenerateRaysHitNothing) {
  SphereBlocks none;
  none.assign(nullptr, 0);
  Ray ray = rayDownMinusZ();
  float t;
  uint32_t prim;
  EXPECT_FALSE(closestSphere(none.view(), ray, ray.tMax, &t, &prim));
  EXPECT_FALSE(anySphere(none.view(), ray, kNone));

  const Sphere s{Vec3(0, 0, -5), 1};
  SphereBlocks one;
  one.assign(&s, 1);
  ray.direction = Vec3(0.0f);  // no direction: a = 0 makes NaN, which fails every test
  EXPECT_FALSE(closestSphere(one.view(), ray, ray.tMax, &t, &prim));
  EXPECT_FALSE(anySphere(one.view(), ray, kNone));
  // The skipped sphere alone blocks nothing.
  ray.direction = Vec3(0, 0, -1);
  EXPECT_TRUE(anySphere(one.view(), ray, kNone));
  EXPECT_FALSE(anySphere(one.view(), ray, 0));
}

}  // namespace
}  // namespace candela
