// Triangulation of large OBJ faces: n - 2 triangles that tile the polygon with its winding, in
// near-linear time for convex faces of any size, and a refusal for huge concave ones.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <random>
#include <vector>

#include "scene/read/polygon_triangulation.h"

namespace candela {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Twice the signed area of the triangle in the xy plane.
double area2(const Vec3& a, const Vec3& b, const Vec3& c) {
  return (double(b.x) - a.x) * (double(c.y) - a.y) - (double(b.y) - a.y) * (double(c.x) - a.x);
}

double polygonArea2(const std::vector<Vec3>& p) {
  double sum = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    const Vec3& a = p[i];
    const Vec3& b = p[(i + 1) % p.size()];
    sum += double(a.x) * b.y - double(b.x) * a.y;
  }
  return sum;
}

std::vector<CornerTriangle> triangulate(const std::vector<Vec3>& corners) {
  std::vector<CornerTriangle> triangles;
  EXPECT_TRUE(triangulatePolygon(corners, &triangles));
  return triangles;
}

// A star-shaped (so simple) polygon around the origin, counter-clockwise in xy: random radii
// make it concave.
std::vector<Vec3> randomStar(size_t n, std::mt19937& gen) {
  std::uniform_real_distribution<float> radius(0.2f, 1.0f);
  std::vector<Vec3> corners;
  for (size_t i = 0; i < n; ++i) {
    const double angle = 2 * kPi * double(i) / double(n);
    const float r = radius(gen);
    corners.push_back(Vec3(r * float(std::cos(angle)), r * float(std::sin(angle)), 0));
  }
  return corners;
}

// Every triangle winds as the polygon does (but for slivers within the rounding slack) and
// together they cover its area.
void expectTiling(const std::vector<Vec3>& corners, const std::vector<CornerTriangle>& triangles) {
  ASSERT_EQ(triangles.size(), corners.size() - 2);
  const double area = polygonArea2(corners);
  double sum = 0, backwards = 0;
  for (const CornerTriangle& t : triangles) {
    for (const uint32_t c : t) ASSERT_LT(c, corners.size());
    const double a = area2(corners[t[0]], corners[t[1]], corners[t[2]]);
    sum += a;
    backwards += std::min(a, 0.0);
  }
  EXPECT_GT(backwards, -1e-4 * area) << "triangles wind against the polygon";
  EXPECT_NEAR(sum, area, 1e-6 * area);
}

TEST(PolygonTriangulation, RandomConcaveStarsAreTiled) {
  std::mt19937 gen(7);
  for (const size_t n : {5u, 6u, 9u, 40u, 300u}) {
    for (int round = 0; round < 20; ++round) {
      const std::vector<Vec3> corners = randomStar(n, gen);
      expectTiling(corners, triangulate(corners));
    }
  }
}

TEST(PolygonTriangulation, PlaneAndWindingFollowTheNormal) {
  // A concave "L" in the yz plane, clockwise seen from +x: the triangles are clockwise too.
  const float l[][2] = {{0, 0}, {0, 2}, {1, 2}, {1, 1}, {2, 1}, {2, 0}};
  std::vector<Vec3> corners;
  for (const auto& c : l) corners.push_back(Vec3(5, c[0], c[1]));
  const std::vector<CornerTriangle> triangles = triangulate(corners);
  ASSERT_EQ(triangles.size(), 4u);
  for (const CornerTriangle& t : triangles) {
    const Vec3 n = cross(corners[t[1]] - corners[t[0]], corners[t[2]] - corners[t[0]]);
    EXPECT_LE(n.x, 0);
  }
}

TEST(PolygonTriangulation, DegenerateAndSelfCrossingPolygonsKeepEveryCorner) {
  const std::vector<Vec3> line = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0), Vec3(3, 0, 0),
                                  Vec3(4, 0, 0)};
  EXPECT_EQ(triangulate(line).size(), 3u);
  const std::vector<Vec3> same(7, Vec3(1, 2, 3));
  EXPECT_EQ(triangulate(same).size(), 5u);
  const std::vector<Vec3> bowTie = {Vec3(0, 0, 0), Vec3(2, 2, 0), Vec3(2, 0, 0),
                                    Vec3(0, 2, 0), Vec3(1, 3, 0), Vec3(-1, 1, 0)};
  EXPECT_EQ(triangulate(bowTie).size(), 4u);
  const std::vector<Vec3> huge = {Vec3(3e38f, 0, 0), Vec3(-3e38f, 3e38f, 0), Vec3(0, -3e38f, 0),
                                  Vec3(3e38f, 3e38f, 3e38f), Vec3(1, 1, 1)};
  EXPECT_EQ(triangulate(huge).size(), 3u);
}

// A regular polygon of a million corners was quadratic in tinyobjloader (and lost).
TEST(PolygonTriangulation, HugeConvexPolygonIsFannedInLinearTime) {
  const size_t n = 1000000;
  std::vector<Vec3> corners;
  for (size_t i = 0; i < n; ++i) {
    const double angle = 2 * kPi * double(i) / double(n);
    corners.push_back(Vec3(float(std::cos(angle)), float(std::sin(angle)), 0));
  }
  const auto start = std::chrono::steady_clock::now();
  const std::vector<CornerTriangle> triangles = triangulate(corners);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
  EXPECT_EQ(triangles.size(), n - 2);
}

TEST(PolygonTriangulation, ConcavePolygonsUpToTheLimitAreClippedQuickly) {
  std::mt19937 gen(3);
  const std::vector<Vec3> corners = randomStar(kMaxConcaveFaceCorners, gen);
  const auto start = std::chrono::steady_clock::now();
  const std::vector<CornerTriangle> triangles = triangulate(corners);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
  expectTiling(corners, triangles);

  std::vector<CornerTriangle> refused;
  EXPECT_FALSE(triangulatePolygon(randomStar(kMaxConcaveFaceCorners + 1, gen), &refused));
}

}  // namespace
}  // namespace candela
