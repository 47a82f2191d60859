// Ray–primitive intersection, surface reconstruction and ray spawning.
//
// References are computed in double precision from the same float inputs. The watertightness
// tests shoot dense sets of rays at shared edges and vertices and require that none passes
// through; the spawn tests require that a ray leaving a surface never re-hits it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "core/float_error.h"
#include "core/frame.h"
#include "core/sampling.h"
#include "geometry/bvh_traverse.h"
#include "geometry/sphere_intersect.h"
#include "geometry/surface.h"
#include "geometry/triangle_intersect.h"
#include "test_random.h"
#include "test_geometry_view.h"

namespace candela {
namespace {

using test::randomUnitVector;

Ray makeRay(const Vec3& origin, const Vec3& direction, float tMax = kInfinity) {
  Ray r;
  r.origin = origin;
  r.direction = direction;
  r.tMax = tMax;
  return r;
}

// Roots t0 <= t1 of the ray–sphere quadratic, in double precision.
bool sphereRootsDouble(const Sphere& s, const Ray& r, double* t0, double* t1) {
  const double ox = double(r.origin.x) - s.center.x, oy = double(r.origin.y) - s.center.y,
               oz = double(r.origin.z) - s.center.z;
  const double dx = r.direction.x, dy = r.direction.y, dz = r.direction.z;
  const double a = dx * dx + dy * dy + dz * dz;
  const double b = 2.0 * (ox * dx + oy * dy + oz * dz);
  const double c = ox * ox + oy * oy + oz * oz - double(s.radius) * s.radius;
  const double disc = b * b - 4.0 * a * c;
  if (disc < 0.0) return false;
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  *t0 = std::min(q / a, c / q);
  *t1 = std::max(q / a, c / q);
  return true;
}

double distanceToSphereDouble(const Sphere& s, const Vec3& p) {
  const double x = double(p.x) - s.center.x, y = double(p.y) - s.center.y,
               z = double(p.z) - s.center.z;
  return std::sqrt(x * x + y * y + z * z) - s.radius;
}

// A scene of one primitive, for surfaceAt.
struct OnePrimitive {
  std::vector<Sphere> spheres;
  std::vector<Vec3> positions, normals;  // normals are encoded by view()
  std::vector<Triangle> triangles;
  mutable std::vector<OctNormal> encodedNormals;

  GeometryView view() const {
    encodedNormals.clear();
    for (const Vec3& n : normals) encodedNormals.push_back(encodeOctNormal(n));
    return test::geometryView(spheres, positions, encodedNormals, triangles);
  }
};

OnePrimitive oneTriangle(const Vec3& p0, const Vec3& p1, const Vec3& p2) {
  OnePrimitive s;
  s.positions = {p0, p1, p2};
  s.triangles.push_back(Triangle{{0, 1, 2}, 7});
  return s;
}

// A random unit vector whose angle with +axis or -axis (chosen at random) has cosine >= minCos.
Vec3 randomDirectionNear(const Vec3& axis, float minCos, std::mt19937& gen) {
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const Frame f(axis);
  const Vec3 local = sampleUniformCone(u(gen), u(gen), 1.0f - minCos);
  const Vec3 w = f.toWorld(local);
  return u(gen) < 0.5f ? w : -w;
}

// ---------------------------------------------------------------------------------------------
// Spheres

TEST(SphereIntersect, HitFromOutside) {
  const Sphere s{Vec3(0, 0, 5), 1.0f, 0};
  float t = 0;
  ASSERT_TRUE(intersectSphere(s, makeRay(Vec3(0), Vec3(0, 0, 1)), kInfinity, &t));
  EXPECT_FLOAT_EQ(t, 4.0f);
  // Directions need not be unit length: t scales inversely.
  ASSERT_TRUE(intersectSphere(s, makeRay(Vec3(0), Vec3(0, 0, 2)), kInfinity, &t));
  EXPECT_FLOAT_EQ(t, 2.0f);
  ASSERT_TRUE(intersectSphere(s, makeRay(Vec3(0.6f, 0, 0), Vec3(0, 0, 1)), kInfinity, &t));
  EXPECT_FLOAT_EQ(t, 4.2f);
}

TEST(SphereIntersect, FromInsideReturnsTheFarRoot) {
  const Sphere s{Vec3(1, 2, 3), 2.0f, 0};
  float t = 0;
  ASSERT_TRUE(intersectSphere(s, makeRay(Vec3(1, 2, 3), Vec3(0, 1, 0)), kInfinity, &t));
  EXPECT_FLOAT_EQ(t, 2.0f);
  ASSERT_TRUE(intersectSphere(s, makeRay(Vec3(1, 2, 4.5f), Vec3(0, 0, -1)), kInfinity, &t));
  EXPECT_FLOAT_EQ(t, 3.5f);
  ASSERT_TRUE(intersectSphere(s, makeRay(Vec3(1, 2, 4.5f), Vec3(0, 0, 1)), kInfinity, &t));
  EXPECT_FLOAT_EQ(t, 0.5f);
}

TEST(SphereIntersect, Misses) {
  const Sphere s{Vec3(0, 0, 5), 1.0f, 0};
  float t = 0;
  EXPECT_FALSE(intersectSphere(s, makeRay(Vec3(1.5f, 0, 0), Vec3(0, 0, 1)), kInfinity, &t));
  EXPECT_FALSE(intersectSphere(s, makeRay(Vec3(0), Vec3(0, 0, -1)), kInfinity, &t));  // behind
  EXPECT_FALSE(intersectSphere(s, makeRay(Vec3(0), Vec3(0, 1, 0)), kInfinity, &t));
  EXPECT_FALSE(intersectSphere(s, makeRay(Vec3(0, 0, 7), Vec3(0, 0, 1)), kInfinity, &t));
}

TEST(SphereIntersect, GrazingRays) {
  const Sphere s{Vec3(0, 0, 10), 2.0f, 0};
  float t = 0;
  const float inside = 2.0f * (1.0f - 1e-5f), outside = 2.0f * (1.0f + 1e-5f);
  ASSERT_TRUE(intersectSphere(s, makeRay(Vec3(inside, 0, 0), Vec3(0, 0, 1)), kInfinity, &t));
  EXPECT_NEAR(t, 10.0 - std::sqrt(4.0 - double(inside) * inside), 1e-3);
  EXPECT_FALSE(intersectSphere(s, makeRay(Vec3(outside, 0, 0), Vec3(0, 0, 1)), kInfinity, &t));
  // Exactly tangent: a hit, if reported, is at the touching point.
  if (intersectSphere(s, makeRay(Vec3(2, 0, 0), Vec3(0, 0, 1)), kInfinity, &t)) {
    EXPECT_NEAR(t, 10.0f, 1e-2f);
  }

  // Grazing a unit sphere 1e4 away, in a direction that is not axis aligned: b^2 - 4ac would
  // cancel to noise here.
  std::mt19937 gen(3);
  for (int i = 0; i < 1000; ++i) {
    const Vec3 u = randomUnitVector(gen);
    const Frame f(u);
    const Sphere far{u * 1e4f, 1.0f, 0};
    for (float offset : {0.995f, 1.005f}) {
      const Vec3 target = far.center + f.s * offset;
      const Ray r = makeRay(Vec3(0), target);
      double t0, t1;
      const bool expected = sphereRootsDouble(far, r, &t0, &t1);
      ASSERT_EQ(intersectSphere(far, r, kInfinity, &t), expected) << "offset " << offset;
      if (expected) {
        EXPECT_NEAR(t, t0, 1e-5 * t0);
      }
    }
  }
}

TEST(SphereIntersect, TMaxClipsHits) {
  const Sphere s{Vec3(0, 0, 5), 1.0f, 0};
  float t = 0;
  EXPECT_FALSE(intersectSphere(s, makeRay(Vec3(0), Vec3(0, 0, 1)), 3.9f, &t));
  EXPECT_FALSE(intersectSphere(s, makeRay(Vec3(0), Vec3(0, 0, 1)), 4.0f, &t));  // open interval
  ASSERT_TRUE(intersectSphere(s, makeRay(Vec3(0), Vec3(0, 0, 1)), 4.1f, &t));
  EXPECT_FLOAT_EQ(t, 4.0f);
  // From inside, only the far root counts.
  EXPECT_FALSE(intersectSphere(s, makeRay(Vec3(0, 0, 5), Vec3(0, 0, 1)), 0.9f, &t));
  EXPECT_TRUE(intersectSphere(s, makeRay(Vec3(0, 0, 5), Vec3(0, 0, 1)), 1.1f, &t));
}

TEST(SphereIntersect, HugeWallSpheresAreHitAccurately) {
  // The Cornell-box walls of smallpt-style scenes: spheres of radius 1e5 whose surfaces pass
  // through a room about 100 units wide.
  const Sphere walls[] = {
      {Vec3(1e5f + 1, 40.8f, 81.6f), 1e5f, 0}, {Vec3(-1e5f + 99, 40.8f, 81.6f), 1e5f, 0},
      {Vec3(50, 40.8f, 1e5f), 1e5f, 0},        {Vec3(50, 40.8f, -1e5f + 170), 1e5f, 0},
      {Vec3(50, 1e5f, 81.6f), 1e5f, 0},        {Vec3(50, -1e5f + 81.6f, 81.6f), 1e5f, 0}};
  std::mt19937 gen(5);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  // Float positions near 1e5 are only known to about ulp(1e5) = 0.008 units, so hit points are
  // checked to lie within a few of those of the exact surface, and rays passing within that
  // distance of a wall's silhouette may go either way.
  const double tolerance = 0.05;
  int hits = 0;
  for (int i = 0; i < 20000; ++i) {
    const Vec3 origin(5 + 90 * u(gen), 5 + 70 * u(gen), 5 + 160 * u(gen));
    const Ray r = makeRay(origin, randomUnitVector(gen));
    for (const Sphere& wall : walls) {
      double t0, t1;
      const bool expected = sphereRootsDouble(wall, r, &t0, &t1) && t1 > 0.0;
      if (expected) {
        // Distance from the centre to the ray's line, against the radius.
        const double tMid = 0.5 * (t0 + t1);
        const Vec3 mid = r.origin + float(tMid) * r.direction;
        if (distanceToSphereDouble(wall, mid) > -tolerance) continue;
      }
      float t = 0;
      ASSERT_EQ(intersectSphere(wall, r, kInfinity, &t), expected) << "ray " << i;
      if (!expected) continue;
      ++hits;
      const double tRef = t0 > 0.0 ? t0 : t1;
      EXPECT_NEAR(t, tRef, 0.25 * (t1 - t0)) << "ray " << i;  // the right root
      const Vec3 p(float(r.origin.x + double(t) * r.direction.x),
                   float(r.origin.y + double(t) * r.direction.y),
                   float(r.origin.z + double(t) * r.direction.z));
      EXPECT_NEAR(distanceToSphereDouble(wall, p), 0.0, tolerance) << "ray " << i;
    }
  }
  EXPECT_GT(hits, 20000);

  // A sphere of radius 1e5 whose surface is 1e5 away: relative accuracy.
  const Sphere distant{Vec3(0, 0, 2e5f), 1e5f, 0};
  for (int i = 0; i < 1000; ++i) {
    const Vec3 d = normalize(Vec3(0.5f * (u(gen) - 0.5f), 0.5f * (u(gen) - 0.5f), 1.0f));
    const Ray r = makeRay(Vec3(0), d);
    double t0, t1;
    ASSERT_TRUE(sphereRootsDouble(distant, r, &t0, &t1));
    float t = 0;
    ASSERT_TRUE(intersectSphere(distant, r, kInfinity, &t));
    EXPECT_NEAR(t, t0, 1e-5 * t0);
  }
}

// ---------------------------------------------------------------------------------------------
// Triangles

TEST(TriangleIntersect, CentreHitWithBarycentrics) {
  const Vec3 p0(0, 0, 5), p1(2, 0, 5), p2(0, 2, 5);
  TriangleHit h;
  ASSERT_TRUE(
      intersectTriangle(p0, p1, p2, makeRay(Vec3(0.5f, 0.5f, 0), Vec3(0, 0, 1)), kInfinity, &h));
  EXPECT_FLOAT_EQ(h.t, 5.0f);
  EXPECT_FLOAT_EQ(h.b0, 0.5f);
  EXPECT_FLOAT_EQ(h.b1, 0.25f);
  EXPECT_FLOAT_EQ(h.b2, 0.25f);
  // The barycentrics reproduce the hit point.
  const Vec3 p = h.b0 * p0 + h.b1 * p1 + h.b2 * p2;
  EXPECT_FLOAT_EQ(p.x, 0.5f);
  EXPECT_FLOAT_EQ(p.y, 0.5f);
}

TEST(TriangleIntersect, MissesOutsideBehindAndBeyondTMax) {
  const Vec3 p0(0, 0, 5), p1(2, 0, 5), p2(0, 2, 5);
  TriangleHit h;
  EXPECT_FALSE(
      intersectTriangle(p0, p1, p2, makeRay(Vec3(1.5f, 1.5f, 0), Vec3(0, 0, 1)), kInfinity, &h));
  EXPECT_FALSE(
      intersectTriangle(p0, p1, p2, makeRay(Vec3(-0.1f, 0.5f, 0), Vec3(0, 0, 1)), kInfinity, &h));
  EXPECT_FALSE(
      intersectTriangle(p0, p1, p2, makeRay(Vec3(0.5f, 0.5f, 0), Vec3(0, 0, -1)), kInfinity, &h));
  EXPECT_FALSE(
      intersectTriangle(p0, p1, p2, makeRay(Vec3(0.5f, 0.5f, 0), Vec3(0, 0, 1)), 4.9f, &h));
  EXPECT_FALSE(
      intersectTriangle(p0, p1, p2, makeRay(Vec3(0.5f, 0.5f, 0), Vec3(0, 0, 1)), 5.0f, &h));
  EXPECT_TRUE(intersectTriangle(p0, p1, p2, makeRay(Vec3(0.5f, 0.5f, 0), Vec3(0, 0, 1)), 5.1f, &h));
}

TEST(TriangleIntersect, BackFacesAreHit) {
  const Vec3 p0(0, 0, 0), p1(1, 0, 0), p2(0, 1, 0);  // faces +z
  TriangleHit h;
  ASSERT_TRUE(
      intersectTriangle(p0, p1, p2, makeRay(Vec3(0.2f, 0.2f, 3), Vec3(0, 0, -1)), kInfinity, &h));
  EXPECT_FLOAT_EQ(h.t, 3.0f);
  ASSERT_TRUE(
      intersectTriangle(p0, p1, p2, makeRay(Vec3(0.2f, 0.2f, -3), Vec3(0, 0, 1)), kInfinity, &h));
  EXPECT_FLOAT_EQ(h.t, 3.0f);
  EXPECT_FLOAT_EQ(h.b1, 0.2f);
  EXPECT_FLOAT_EQ(h.b2, 0.2f);
}

TEST(TriangleIntersect, ParallelAndDegenerateMiss) {
  const Vec3 p0(0, 0, 0), p1(1, 0, 0), p2(0, 1, 0);
  TriangleHit h;
  // Parallel above the plane, and lying in the plane across the triangle.
  EXPECT_FALSE(
      intersectTriangle(p0, p1, p2, makeRay(Vec3(-1, 0.2f, 1), Vec3(1, 0, 0)), kInfinity, &h));
  EXPECT_FALSE(
      intersectTriangle(p0, p1, p2, makeRay(Vec3(-1, 0.2f, 0), Vec3(1, 0, 0)), kInfinity, &h));
  // Collinear vertices have no area and no normal.
  EXPECT_FALSE(intersectTriangle(Vec3(0, 0, 0), Vec3(1, 1, 0), Vec3(2, 2, 0),
                                 makeRay(Vec3(1, 1, 1), Vec3(0, 0, -1)), kInfinity, &h));
}

TEST(TriangleIntersect, ExactEdgeAndVertexHitsOfSharedEdge) {
  // Two triangles sharing the diagonal (0,0)-(1,1) of the unit square, opposite windings.
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(1, 1, 0), d(0, 1, 0);
  TriangleHit h;
  for (int k = 0; k <= 16; ++k) {
    const float s = k / 16.0f;
    for (const Vec3& dir : {Vec3(0, 0, -1), Vec3(0.25f, -0.5f, -1)}) {
      const Ray r = makeRay(Vec3(s, s, 0) - 2.0f * dir, dir);
      EXPECT_TRUE(intersectTriangle(a, b, c, r, kInfinity, &h) ||
                  intersectTriangle(a, d, c, r, kInfinity, &h))
          << "diagonal point " << s;
    }
  }
  // A point on an outer edge belongs to its triangle.
  EXPECT_TRUE(intersectTriangle(a, b, c, makeRay(Vec3(0.5f, 0, 1), Vec3(0, 0, -1)), kInfinity, &h));
}

// An arbitrary rigid placement, so that coordinates are not round numbers.
struct Placement {
  Frame frame{normalize(Vec3(0.3f, -0.7f, 0.5f))};
  Vec3 offset{3.7f, -1.3f, 12.1f};

  Vec3 operator()(float x, float y, float z) const {
    return offset + frame.s * x + frame.t * y + frame.n * z;
  }
};

TEST(TriangleIntersect, QuadSharedEdgeIsWatertight) {
  const Placement place;
  const Vec3 a = place(0, 0, 0), b = place(2, 0, 0), c = place(2, 1.5f, 0), d = place(0, 1.5f, 0);
  std::mt19937 gen(17);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (bool sameWinding : {true, false}) {
    const Vec3 q0 = sameWinding ? a : c, q2 = sameWinding ? c : a;  // second triangle (q0,q2,d)
    int doubleHits = 0;
    for (int i = 0; i < 100000; ++i) {
      // Mostly targets on the shared diagonal, the rest anywhere inside the quad's outline.
      const Vec3 target = i % 4 != 0 ? a + (0.01f + 0.98f * u(gen)) * (c - a)
                                     : place(0.02f + 1.96f * u(gen), 0.02f + 1.46f * u(gen), 0);
      const Vec3 origin =
          target + randomDirectionNear(place.frame.n, 0.2f, gen) * (0.1f + 10 * u(gen));
      const Ray r = makeRay(origin, target - origin);
      TriangleHit h0, h1;
      const bool hit0 = intersectTriangle(a, b, c, r, kInfinity, &h0);
      const bool hit1 = intersectTriangle(q0, q2, d, r, kInfinity, &h1);
      ASSERT_TRUE(hit0 || hit1) << "ray " << i << " leaked between the two triangles";
      doubleHits += hit0 && hit1;
    }
    EXPECT_LT(doubleHits, 1000);  // both only right on the edge
  }
}

TEST(TriangleIntersect, VertexFanIsWatertight) {
  // Seven triangles around a shared apex, raised into a shallow cone.
  const Placement place;
  const int kSpokes = 7;
  const Vec3 apex = place(0, 0, 0.2f);
  std::vector<Vec3> ring;
  for (int k = 0; k < kSpokes; ++k) {
    const float phi = 2.0f * kPi * (k + 0.15f * std::sin(3.0f * k)) / kSpokes;
    ring.push_back(place(std::cos(phi), std::sin(phi), 0));
  }
  std::mt19937 gen(23);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int i = 0; i < 100000; ++i) {
    const int k = static_cast<int>(u(gen) * kSpokes) % kSpokes;
    const Vec3& r0 = ring[k];
    const Vec3& r1 = ring[(k + 1) % kSpokes];
    Vec3 target;
    switch (i % 3) {
      case 0:
        target = apex;
        break;  // the shared vertex
      case 1:
        target = apex + (0.9f * u(gen)) * (r0 - apex);
        break;    // a shared edge
      default: {  // anywhere, away from the rim
        const float s = 0.98f * u(gen), w = u(gen);
        target = apex + s * ((1 - w) * (r0 - apex) + w * (r1 - apex));
      }
    }
    const Vec3 origin =
        target + randomDirectionNear(place.frame.n, 0.5f, gen) * (0.1f + 10 * u(gen));
    const Ray r = makeRay(origin, target - origin);
    bool hit = false;
    TriangleHit h;
    for (int j = 0; j < kSpokes && !hit; ++j)
      hit = intersectTriangle(apex, ring[j], ring[(j + 1) % kSpokes], r, kInfinity, &h);
    ASSERT_TRUE(hit) << "ray " << i << " leaked through the fan";
  }
}

// ---------------------------------------------------------------------------------------------
// Surfaces

TEST(Surface, SphereNormalPointsOutwardFromBothSides) {
  OnePrimitive scene;
  scene.spheres.push_back(Sphere{Vec3(1, -2, 3), 0.5f, 4});
  const auto view = scene.view();
  for (const Vec3& origin : {Vec3(1, -2, 0), Vec3(1.1f, -2.1f, 3)}) {  // outside, inside
    const Ray r = makeRay(origin, Vec3(0, 0, 1));
    Hit hit;
    ASSERT_TRUE(intersectClosestBruteForce(view, r, &hit));
    const SurfacePoint sp = surfaceAt(view, r, hit);
    EXPECT_NEAR(length(sp.ng), 1.0f, 1e-6f);
    EXPECT_GT(dot(sp.ng, sp.p - scene.spheres[0].center), 0.0f);
    EXPECT_NEAR(std::fabs(distanceToSphereDouble(scene.spheres[0], sp.p)), 0.0, 1e-6);
    EXPECT_EQ(sp.ns.x, sp.ng.x);
    EXPECT_EQ(sp.ns.z, sp.ng.z);
    EXPECT_EQ(sp.material, 4u);
  }
}

TEST(Surface, TriangleNormalFollowsTheRightHandRule) {
  const Vec3 p0(0, 0, 0), p1(1, 0, 0), p2(0, 1, 0);
  for (float side : {1.0f, -1.0f}) {  // the normal never flips towards the ray
    const OnePrimitive ccw = oneTriangle(p0, p1, p2), cw = oneTriangle(p0, p2, p1);
    const Ray r = makeRay(Vec3(0.25f, 0.25f, 2 * side), Vec3(0, 0, -side));
    Hit hit;
    ASSERT_TRUE(intersectClosestBruteForce(ccw.view(), r, &hit));
    SurfacePoint sp = surfaceAt(ccw.view(), r, hit);
    EXPECT_EQ(sp.ng.z, 1.0f);
    EXPECT_EQ(sp.ns.z, 1.0f);
    EXPECT_EQ(sp.material, 7u);
    EXPECT_FLOAT_EQ(sp.p.x, 0.25f);
    EXPECT_FLOAT_EQ(sp.p.y, 0.25f);
    EXPECT_EQ(sp.p.z, 0.0f);
    ASSERT_TRUE(intersectClosestBruteForce(cw.view(), r, &hit));
    sp = surfaceAt(cw.view(), r, hit);
    EXPECT_EQ(sp.ng.z, -1.0f);
  }
}

TEST(Surface, ShadingNormalInterpolatesInTheGeometricHemisphere) {
  OnePrimitive scene = oneTriangle(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0));
  scene.normals = {Vec3(0, 0, 1), normalize(Vec3(1, 0, 1)), normalize(Vec3(0, 1, 1))};
  const Ray r = makeRay(Vec3(0.25f, 0.25f, 1), Vec3(0, 0, -1));
  Hit hit;
  ASSERT_TRUE(intersectClosestBruteForce(scene.view(), r, &hit));
  SurfacePoint sp = surfaceAt(scene.view(), r, hit);
  const Vec3 expected =
      normalize(0.5f * scene.normals[0] + 0.25f * scene.normals[1] + 0.25f * scene.normals[2]);
  // The vertex normals are stored octahedrally encoded, to within 7e-5 radians.
  EXPECT_NEAR(sp.ns.x, expected.x, 1e-4f);
  EXPECT_NEAR(sp.ns.y, expected.y, 1e-4f);
  EXPECT_NEAR(sp.ns.z, expected.z, 1e-4f);
  EXPECT_EQ(sp.ng.z, 1.0f);

  // Vertex normals facing away from ng are flipped into its hemisphere.
  const std::vector<Vec3> vertexNormals = scene.normals;
  scene.normals.assign(3, Vec3(0, 0, -1));
  sp = surfaceAt(scene.view(), r, hit);
  EXPECT_EQ(sp.ns.z, 1.0f);

  // One missing vertex normal (a zero vector): the face normal is used.
  scene.normals = vertexNormals;
  scene.normals[1] = Vec3(0.0f);
  sp = surfaceAt(scene.view(), r, hit);
  EXPECT_EQ(sp.ns.z, sp.ng.z);
}

// ---------------------------------------------------------------------------------------------
// Spawned rays

constexpr float kScales[] = {1e-3f, 1.0f, 1e4f};

TEST(SpawnOffset, RaysLeavingASphereDoNotRehitIt) {
  std::mt19937 gen(31);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (float scale : kScales) {
    int farHits = 0;
    for (int i = 0; i < 4000; ++i) {
      OnePrimitive scene;
      const Vec3 center = scale * Vec3(4 * u(gen) - 2, 4 * u(gen) - 2, 4 * u(gen) - 2);
      const float radius = scale * (0.2f + 0.8f * u(gen));
      scene.spheres.push_back(Sphere{center, radius, 0});
      const Sphere& s = scene.spheres[0];
      const auto view = scene.view();
      // Alternate hits from outside and from inside.
      const Vec3 origin = i % 2 == 0
                              ? center + randomUnitVector(gen) * (radius * (1.5f + 3 * u(gen)))
                              : center + randomUnitVector(gen) * (radius * 0.9f * u(gen));
      const Vec3 aim = center + randomUnitVector(gen) * (radius * 0.7f * u(gen));
      const Ray r = makeRay(origin, aim - origin);
      Hit hit;
      ASSERT_TRUE(intersectClosestBruteForce(view, r, &hit));
      const SurfacePoint sp = surfaceAt(view, r, hit);
      // The error bound holds: the point is within it of the true surface.
      ASSERT_LE(std::fabs(distanceToSphereDouble(s, sp.p)), dot(abs(sp.ng), sp.error));

      const Vec3 w = randomUnitVector(gen);
      // Leaving outwards: no hit at all. Leaving inwards: only the far side, never t ~ 0.
      for (const Vec3& dir : {faceForward(w, sp.ng), -faceForward(w, sp.ng)}) {
        const Ray spawned = makeRay(offsetRayOrigin(sp.p, sp.error, sp.ng, dir), dir);
        float t = 0;
        const bool again = intersectSphere(s, spawned, kInfinity, &t);
        if (dot(dir, sp.ng) > 0.0f) {
          ASSERT_FALSE(again) << "scale " << scale << " t " << t;
          continue;
        }
        double t0, t1;
        ASSERT_TRUE(sphereRootsDouble(s, spawned, &t0, &t1));
        ASSERT_LE(t0, 0.0) << "spawned origin is not inside";
        if (t1 < 1e-3 * radius) continue;  // too grazing to tell the far root from the near
        ASSERT_TRUE(again);
        ASSERT_GT(t, 0.5 * t1) << "scale " << scale << ": re-hit the surface it left";
        ++farHits;
      }
    }
    EXPECT_GT(farHits, 3900);
  }
}

TEST(SpawnOffset, RaysLeavingATriangleDoNotRehitIt) {
  std::mt19937 gen(37);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (float scale : kScales) {
    for (int i = 0; i < 4000; ++i) {
      const Vec3 base = scale * Vec3(8 * u(gen) - 4, 8 * u(gen) - 4, 8 * u(gen) - 4);
      const float size = scale * (0.05f + u(gen));
      const OnePrimitive scene =
          oneTriangle(base + size * randomUnitVector(gen), base + size * randomUnitVector(gen),
                      base + size * randomUnitVector(gen));
      const auto view = scene.view();
      const Vec3* p = scene.positions.data();
      float b1 = u(gen), b2 = u(gen);
      if (b1 + b2 > 1.0f) b1 = 1.0f - b1, b2 = 1.0f - b2;
      const Vec3 target = p[0] + b1 * (p[1] - p[0]) + b2 * (p[2] - p[0]);
      const Vec3 origin = target + randomUnitVector(gen) * (scale * (0.5f + 3 * u(gen)));
      const Ray r = makeRay(origin, target - origin);
      Hit hit;
      if (!intersectClosestBruteForce(view, r, &hit)) continue;  // near-degenerate or grazing
      const SurfacePoint sp = surfaceAt(view, r, hit);
      const Vec3 w = randomUnitVector(gen);
      for (const Vec3& dir : {w, -w}) {
        const Ray spawned = makeRay(offsetRayOrigin(sp.p, sp.error, sp.ng, dir), dir);
        TriangleHit th;
        ASSERT_FALSE(intersectTriangle(p[0], p[1], p[2], spawned, kInfinity, &th))
            << "scale " << scale << " t " << th.t;
      }
    }
  }
}

TEST(SpawnOffset, TriangleRejectsHitsWithinItsOwnErrorBound) {
  // Origins exactly on the triangle's plane (planes z = c and z = x hold float points exactly),
  // so the true t is 0: whatever the rounding makes of it, the deltaT bound must reject it.
  std::mt19937 gen(41);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (float scale : kScales) {
    for (bool tilted : {false, true}) {
      const float c = scale * 4 * u(gen);
      auto onPlane = [&](float x, float y) { return Vec3(x, y, tilted ? x : c); };
      int rehits = 0;
      for (int i = 0; i < 20000; ++i) {
        const float bx = scale * 4 * u(gen), by = scale * 4 * u(gen);
        const Vec3 p0 = onPlane(bx + scale * u(gen), by + scale * u(gen));
        const Vec3 p1 = onPlane(bx + scale * u(gen), by + scale * u(gen));
        const Vec3 p2 = onPlane(bx + scale * u(gen), by + scale * u(gen));
        const Vec3 origin = onPlane(bx + 0.3f * scale * u(gen), by + 0.3f * scale * u(gen));
        TriangleHit th;
        rehits +=
            intersectTriangle(p0, p1, p2, makeRay(origin, randomUnitVector(gen)), kInfinity, &th);
      }
      EXPECT_EQ(rehits, 0) << "scale " << scale << (tilted ? " plane z = x" : " plane z = c");
    }
  }
}

}  // namespace
}  // namespace candela
