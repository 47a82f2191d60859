// Every emitter is a light: emissive triangles and spheres are sampled by next-event estimation
// and weighted against BSDF sampling by multiple importance sampling. Checked against closed
// forms (Lambert's polygon formula, a sphere's irradiance), against an independent estimate by
// cosine sampling, and for the consistency of the pdfs that multiple importance sampling needs.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "core/constants.h"
#include "core/frame.h"
#include "core/sampling.h"
#include "geometry/spherical_triangle.h"
#include "geometry/triangle_intersect.h"
#include "render/light_sample.h"
#include "render/light_selection.h"
#include "render_test_util.h"
#include "scene/flatten.h"
#include "scene/read/obj_loader.h"
#include "scene/read/scene_loader.h"
#include "scene/scene_error.h"

namespace candela {
namespace {

constexpr double kZ = 5.0;  // z-score of the closed-form checks: a correct renderer never fails

struct DVec {
  double x, y, z;
};
DVec sub(const DVec& a, const DVec& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
double dot(const DVec& a, const DVec& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
DVec cross(const DVec& a, const DVec& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
DVec unit(const DVec& a) {
  const double l = std::sqrt(dot(a, a));
  return {a.x / l, a.y / l, a.z / l};
}

// Irradiance at point x with normal n from a polygon of uniform radiance L wholly above x's
// tangent plane (Lambert 1760): E = L/2 sum_i theta_i (n . unit(u_i x u_i+1)), u_i = unit(v_i - x).
double lambertIrradiance(const std::vector<DVec>& polygon, const DVec& x, const DVec& n, double L) {
  double sum = 0;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const DVec a = unit(sub(polygon[i], x)), b = unit(sub(polygon[(i + 1) % polygon.size()], x));
    sum += std::acos(std::max(-1.0, std::min(1.0, dot(a, b)))) * dot(n, unit(cross(a, b)));
  }
  return 0.5 * L * std::fabs(sum);
}

std::string writeObj(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

// A diffuse floor y = 0 (facing +y) and an emissive quad at y = 2 facing down, x in [-0.5, 1],
// z in [-1, 0.5]; a camera at y = 1 with a 0.2 degree field of view sees the floor around the
// origin. At max_depth 1 a pixel shows rho / pi times the quad's irradiance, found by light
// sampling and by the scattered ray, weighted by MIS.
TEST(AreaLights, EmissiveQuadOverFloorMatchesLambertsFormula) {
  const std::string floor =
      writeObj("area_floor.obj", "v -50 0 -50\nv -50 0 50\nv 50 0 50\nv 50 0 -50\nf 1 2 3 4\n");
  const std::string lamp =
      writeObj("area_lamp.obj", "v -0.5 2 -1\nv 1 2 -1\nv 1 2 0.5\nv -0.5 2 0.5\nf 1 2 3 4\n");
  const double rho = 0.5, L = 5;
  const RenderResult r = test::renderTestScene(R"({
    "camera": {"width": 8, "height": 8, "fov": 0.2, "position": [0, 1, 0], "look_at": [0, 0, 0],
               "up": [0, 0, -1], "spp": 512},
    "render": {"max_depth": 1},
    "objects": [{"file": ")" + floor + R"(", "color": 0.5},
                {"file": ")" + lamp + R"(", "material": {"type": "emissive", "radiance": 5}}]})");
  const double E = lambertIrradiance({{-0.5, 2, -1}, {1, 2, -1}, {1, 2, 0.5}, {-0.5, 2, 0.5}},
                                     {0, 0, 0}, {0, 1, 0}, L);
  const double expected = rho / kPi * E;
  for (int c = 0; c < 3; ++c) {
    const test::RegionStats s = test::regionStats(r.image, 0, 0, 8, 8, c);
    EXPECT_NEAR(s.mean, expected, kZ * s.standardError() + 1e-3 * expected) << "channel " << c;
  }
  EXPECT_GT(r.rays.shadow, 0u);  // the quad was light-sampled, not only found by chance
}

// An emissive sphere that is not declared as a light is one: over a floor point straight below
// it, a sphere of radiance L and radius r at distance d gives irradiance pi L r^2 / d^2.
TEST(AreaLights, EmissiveSphereIsALightWithItsClosedFormIrradiance) {
  const std::string floor =
      writeObj("area_floor2.obj", "v -50 0 -50\nv -50 0 50\nv 50 0 50\nv 50 0 -50\nf 1 2 3 4\n");
  const std::string json = R"({
    "camera": {"width": 8, "height": 8, "fov": 0.2, "position": [0, 1, 0], "look_at": [0, 0, 0],
               "up": [0, 0, -1], "spp": 256},
    "render": {"max_depth": 1},
    "spheres": [{"position": [0, 3, 0], "radius": 0.5,
                 "material": {"type": "emissive", "radiance": [4, 2, 1]}}],
    "objects": [{"file": ")" +
                           floor + R"(", "color": 0.5}]})";
  const SceneData data = test::loadTestScene(json);
  ASSERT_EQ(data.lights.size(), 1u);
  EXPECT_EQ(data.lights[0].type, LightType::Sphere);
  EXPECT_EQ(data.spheres[0].light, 0);
  const RenderResult r = renderCpu(data.view(), RenderOptions{});
  const double radiance[3] = {4, 2, 1};
  for (int c = 0; c < 3; ++c) {
    const double expected = 0.5 * radiance[c] * 0.25 / 9.0;  // rho/pi * pi L r^2 / d^2
    const test::RegionStats s = test::regionStats(r.image, 0, 0, 8, 8, c);
    EXPECT_NEAR(s.mean, expected, kZ * s.standardError() + 1e-3 * expected) << "channel " << c;
  }
}

// The scene of one emissive triangle, as flattened: a light per emissive triangle, named back by
// its primitive.
SceneData oneEmissiveTriangle(const std::string& name, const std::string& vertices) {
  const std::string obj = writeObj(name, vertices + "f 1 2 3\n");
  return test::loadTestScene(R"({"camera": {"width": 4, "height": 4},
      "objects": [{"file": ")" +
                             obj + R"(", "material": {"type": "emissive", "radiance": 2}}]})");
}

// Light sampling of a triangle against an independent estimate of the same irradiance by cosine
// sampling of the hemisphere, and its pdf against emitterPdf, which MIS evaluates for a
// BSDF-sampled ray that hits the triangle. A near, large triangle is sampled by solid angle, a
// far, small one by area: both must be unbiased and consistent.
void expectTriangleSamplingAgreesWithCosineSampling(const std::string& name,
                                                    const std::vector<DVec>& corners,
                                                    bool bySolidAngle) {
  std::string obj;
  for (const DVec& c : corners)
    obj +=
        "v " + std::to_string(c.x) + " " + std::to_string(c.y) + " " + std::to_string(c.z) + "\n";
  const SceneData data = oneEmissiveTriangle(name, obj);
  ASSERT_EQ(data.lights.size(), 1u);
  const SceneView view = data.view();
  const Light& light = view.lights[0];
  ASSERT_EQ(light.type, LightType::Triangle);
  EXPECT_EQ(lightOfPrimitive(view, view.sphereCount + light.shape), 0);
  const Triangle& tri = view.triangles[light.shape];
  const Vec3 p0 = view.positions[tri.v[0]], p1 = view.positions[tri.v[1]],
             p2 = view.positions[tri.v[2]];
  const Vec3 x(0.2f, 0.0f, 0.1f), n(0.0f, 1.0f, 0.0f);
  const Vec3 ng = normalize(cross(p1 - p0, p2 - p0));
  ASSERT_LT(dot(ng, Vec3(0, 1, 0)), 0.0f) << "the triangle must face the point below it";
  float solidAngle;
  EXPECT_EQ(sampledBySolidAngle(p0, p1, p2, 0.5f * length(cross(p1 - p0, p2 - p0)), x, &solidAngle),
            bySolidAngle);

  std::mt19937 gen(7);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const int draws = 400000;
  double lightSum = 0, lightSum2 = 0, cosineSum = 0, cosineSum2 = 0;
  for (int i = 0; i < draws; ++i) {
    LightSample ls;
    if (sampleLight(view, light, x, 0.0f, u(gen), u(gen), &ls)) {
      const double v = ls.radiance.x * std::max(0.0f, dot(ls.wi, n)) / ls.pdf;
      lightSum += v;
      lightSum2 += v * v;
      // The pdf MIS uses for this direction when a scattered ray finds the same point.
      const float pdf = emitterPdf(view, light, x, 0.0f, ls.wi, ls.distance, ng);
      ASSERT_NEAR(pdf, ls.pdf, 1e-3f * ls.pdf) << i;
    }
    const Vec3 wi = Frame(n).toWorld(sampleCosineHemisphere(u(gen), u(gen)));
    Ray ray;
    ray.origin = x;
    ray.direction = wi;
    TriangleHit hit;
    if (intersectTriangle(p0, p1, p2, ray, kInfinity, &hit)) {
      const double v = 2.0 * kPi;  // L cos / (cos / pi)
      cosineSum += v;
      cosineSum2 += v * v;
    }
  }
  const auto meanAndError = [&](double sum, double sum2, double* error) {
    const double mean = sum / draws;
    *error = std::sqrt(std::max(0.0, sum2 / draws - mean * mean) / draws);
    return mean;
  };
  double lightError, cosineError;
  const double byLight = meanAndError(lightSum, lightSum2, &lightError);
  const double byCosine = meanAndError(cosineSum, cosineSum2, &cosineError);
  const double exact = lambertIrradiance(corners, {0.2, 0, 0.1}, {0, 1, 0}, 2.0);
  EXPECT_NEAR(byLight, exact, kZ * lightError + 1e-4 * exact);
  EXPECT_NEAR(byCosine, exact, kZ * cosineError + 1e-4 * exact);
  EXPECT_LT(lightError, cosineError) << "light sampling should be the better estimator here";
}

TEST(AreaLights, TriangleSamplingBySolidAngleAgreesWithCosineSamplingAndItsPdf) {
  expectTriangleSamplingAgreesWithCosineSampling(
      "area_near.obj", {{-1, 1.5, -1}, {2, 1.25, -0.5}, {0, 1.75, 2}}, true);
}

TEST(AreaLights, TriangleSamplingByAreaAgreesWithCosineSamplingAndItsPdf) {
  expectTriangleSamplingAgreesWithCosineSampling("area_far.obj",
                                                 {{0, 40, 0}, {0.5, 40, 0}, {0.3, 40, 0.6}}, false);
}

// Sampling by solid angle lands on the triangle, and spreads its directions evenly: the share of
// samples in a sub-triangle is that sub-triangle's share of the solid angle.
TEST(AreaLights, SphericalTriangleSamplingIsUniformInSolidAngle) {
  const Vec3 p0(-1, 2, -1), p1(2, 1.5f, -0.5f), p2(0, 2.5f, 2), x(0.1f, 0, 0.2f);
  const Vec3 mid01 = 0.5f * (p0 + p1), mid02 = 0.5f * (p0 + p2);  // sub-triangle (p0, m01, m02)
  const auto solidAngle = [&x](const Vec3& a, const Vec3& b, const Vec3& c) {
    return sphericalTriangleArea(normalize(a - x), normalize(b - x), normalize(c - x));
  };
  const float share = solidAngle(p0, mid01, mid02) / solidAngle(p0, p1, p2);
  std::mt19937 gen(11);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const int draws = 200000;
  int inside = 0;
  for (int i = 0; i < draws; ++i) {
    float b[3], pdf;
    ASSERT_TRUE(sampleSphericalTriangle(p0, p1, p2, x, u(gen), u(gen), b, &pdf));
    for (float w : b) ASSERT_TRUE(w >= 0.0f && w <= 1.0f) << i;
    ASSERT_NEAR(pdf, 1.0f / solidAngle(p0, p1, p2), 1e-3f * pdf);
    inside += b[1] + b[2] <= 0.5f;  // the sub-triangle at p0: b1 + b2 <= 1/2
  }
  const double expected = share * draws, sigma = std::sqrt(draws * share * (1 - share));
  EXPECT_NEAR(inside, expected, kZ * sigma);
}

// A triangle emits from its outside only: behind it, light sampling finds nothing.
TEST(AreaLights, TriangleEmitsFromItsOutsideOnly) {
  const SceneData data = oneEmissiveTriangle("area_back.obj", "v -1 3 -1\nv 0 3 2\nv 2 3 -1\n");
  const SceneView view = data.view();
  LightSample ls;
  EXPECT_TRUE(
      sampleLight(view, view.lights[0], Vec3(0, 5, 0), 0.0f, 0.3f, 0.6f, &ls));  // above: front
  EXPECT_FALSE(sampleLight(view, view.lights[0], Vec3(0, 0, 0), 0.0f, 0.3f, 0.6f, &ls));
}

// Many emissive triangles: each is a light, found back from its primitive. Far along their
// common normal, the light tree picks each in proportion to its power (area times radiance):
// its distance and orientation terms agree for all of them there; behind them, none.
TEST(AreaLights, EveryEmissiveTriangleIsALightPickedByPowerFromAfar) {
  std::string obj;
  for (int i = 0; i < 12; ++i) {
    const double s = 1 + i % 3;  // three sizes: areas 1/2, 2, 9/2
    obj += "v " + std::to_string(3 * i) + " 2 0\nv " + std::to_string(3 * i) + " 2 " +
           std::to_string(s) + "\nv " + std::to_string(3 * i + s) + " 2 0\n";
  }
  for (int i = 0; i < 12; ++i)
    obj += "f " + std::to_string(3 * i + 1) + " " + std::to_string(3 * i + 2) + " " +
           std::to_string(3 * i + 3) + "\n";
  const std::string path = writeObj("area_many.obj", obj);
  const SceneData data = test::loadTestScene(R"({"camera": {"width": 4, "height": 4},
      "spheres": [{"position": [0, -100, 0], "radius": 99}],
      "objects": [{"file": ")" + path + R"(", "material": {"type": "emissive", "radiance": 1}}]})");
  const SceneView view = data.view();
  ASSERT_EQ(view.lightCount, 12u);
  EXPECT_EQ(view.firstTriangleLight, 0u);
  EXPECT_EQ(lightOfPrimitive(view, 0), -1);  // the plain sphere
  for (uint32_t i = 0; i < view.lightCount; ++i) {
    const Light& l = view.lights[i];
    ASSERT_EQ(l.type, LightType::Triangle);
    EXPECT_EQ(lightOfPrimitive(view, view.sphereCount + l.shape), int32_t(i));
  }
  auto area = [&](uint32_t i) {  // the BVH build orders the triangles its own way
    const Triangle& t = view.triangles[view.lights[i].shape];
    return 0.5 * length(cross(view.positions[t.v[1]] - view.positions[t.v[0]],
                              view.positions[t.v[2]] - view.positions[t.v[0]]));
  };
  double total = 0;
  for (uint32_t i = 0; i < view.lightCount; ++i) total += area(i);
  for (uint32_t i = 0; i < view.lightCount; ++i) {
    EXPECT_NEAR(lightSelectPmf(view, i, Vec3(18, 1e4f, 1), Vec3(0, -1, 0)), area(i) / total, 1e-4)
        << i;
    EXPECT_EQ(lightSelectPmf(view, i, Vec3(18, -1e4f, 1), Vec3(0, 1, 0)), 0.0f) << i;
  }
}

// MTL Ke makes a face group emissive with that radiance; a negative Ke is refused.
TEST(AreaLights, MtlKeMakesFacesEmissive) {
  writeObj("area_lamp.mtl", "newmtl lamp\nKd 0 0 0\nKe 3 2 1\nnewmtl wall\nKd 0.5 0.5 0.5\n");
  const std::string obj =
      writeObj("area_lamp_mtl.obj",
               "mtllib area_lamp.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nusemtl lamp\nf 1 2 3\n"
               "usemtl wall\nf 2 4 3\n");
  std::vector<std::shared_ptr<const TextureDesc>> textures;
  TextureLoader loader(textures, ".");
  const MeshDesc mesh = loadObjFile(obj, "lamp.obj", loader);
  ASSERT_EQ(mesh.triangles.size(), 2u);
  const Material& lamp = mesh.materials[mesh.triangles[0].material];
  EXPECT_EQ(lamp.type, MaterialType::Emissive);
  EXPECT_EQ(lamp.radiance.x, 3.0f);
  EXPECT_EQ(lamp.radiance.z, 1.0f);
  EXPECT_EQ(mesh.materials[mesh.triangles[1].material].type, MaterialType::Diffuse);

  writeObj("area_bad.mtl", "newmtl lamp\nKe 1 -2 1\n");
  const std::string bad = writeObj("area_bad.obj",
                                   "mtllib area_bad.mtl\nv 0 0 0\nv 1 0 0\n"
                                   "v 0 1 0\nusemtl lamp\nf 1 2 3\n");
  try {
    loadObjFile(bad, "bad.obj", loader);
    FAIL() << "a negative Ke was accepted";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()),
              "bad.obj: material \"lamp\": expected a finite, non-negative Ke, got 1 -2 1");
  }
}

}  // namespace
}  // namespace candela
