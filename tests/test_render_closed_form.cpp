// Image tests against answers known in closed form. Tolerances come from the noise of the
// render itself: a region's mean must lie within a few standard errors of the exact value.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "core/constants.h"
#include "render/aov_layers.h"
#include "render_test_util.h"

namespace candela {
namespace {

using test::num;
using test::regionStats;
using test::renderTestScene;

// z-score for a two-sided test at significance ~1e-6: a correct renderer practically never fails.
constexpr double kZ = 5.0;

// Where the ray through the centre of pixel (x, y) meets the plane y = 0, computed independently
// of the renderer's camera code.
struct PlanePoint {
  double x, z;
};
PlanePoint planePointAt(const Camera& cam, uint32_t x, uint32_t y) {
  const Vec3 d = cam.cameraToWorld * (cam.inverseK * Vec3(x + 0.5f, y + 0.5f, 1.0f));
  const double t = -cam.position.y / d.y;
  return {cam.position.x + t * d.x, cam.position.z + t * d.z};
}

// Radiance a diffuse plane y = 0 of albedo rho reflects at `at` under a sphere light of radiance
// L and radius r centred at (lx, ly, lz), wholly above the plane (ly > r): the sphere's
// irradiance is pi L r^2 cos / d^2, and the plane reflects rho / pi of it.
double sphereLightOnPlane(double rho, double L, double r, double lx, double ly, double lz,
                          const PlanePoint& at) {
  const double dx = lx - at.x, dz = lz - at.z, d2 = dx * dx + ly * ly + dz * dz;
  return rho * L * r * r / d2 * (ly / std::sqrt(d2));
}

// A point light above the plane y = 0 (y > 0): its JSON, and the radiance that a diffuse plane
// of albedo rho reflects at `at` in colour channel c, rho P cos / (4 pi^2 d^2) times the colour.
struct PointLight {
  double x, y, z, power;
  Vec3 color;
  std::string json() const {
    return R"({"position": [)" + num(x) + ", " + num(y) + ", " + num(z) + R"(], "intensity": )" +
           num(power) + R"(, "color": [)" + num(color.x) + ", " + num(color.y) + ", " +
           num(color.z) + "]}";
  }
  double onPlane(double rho, const PlanePoint& at, int c) const {
    const double dx = x - at.x, dz = z - at.z, d2 = dx * dx + y * y + dz * dz;
    return rho * power * (y / std::sqrt(d2)) / (4 * kPi * kPi * d2) * color[c];
  }
};

// (a) Inside a diffuse sphere of albedo 0.5 lit by a point light at its centre: the direct
// radiance rho*P/(4 pi^2 R^2) is 0.5 and every bounce adds half again, so L = 1 everywhere.
TEST(ClosedForm, FurnaceInsideDiffuseSphereIsOne) {
  const double radius = 10, power = 4 * kPi * kPi * radius * radius;  // rho P / (4pi^2R^2) = 0.5
  const std::string scene = R"({
    "camera": {"width": 32, "height": 32, "fov": 90, "position": [0, 0, 3], "spp": 64},
    "render": {"max_depth": 200},
    "spheres": [{"position": [0, 0, 0], "radius": )" + num(radius) + R"(, "color": 0.5}],
    "lights": [{"position": [0, 0, 0], "intensity": )" + num(power) + R"(}]})";
  const RenderResult r = renderTestScene(scene);
  for (int c = 0; c < 3; ++c) {
    const auto s = regionStats(r.image, 0, 0, 32, 32, c);
    EXPECT_NEAR(s.mean, 1.0, kZ * s.standardError() + 1e-4) << "channel " << c;
    // Every pixel is an independent estimate of 1; roulette gives the estimates a long tail,
    // so the per-pixel bound is wide, yet far tighter than any real bias would need.
    for (uint32_t y = 0; y < 32; ++y)
      for (uint32_t x = 0; x < 32; ++x)
        ASSERT_NEAR(r.image.at(x, y)[c], 1.0, 2 * kZ * s.stddev + 1e-4) << x << "," << y;
  }
}

// (a') The same furnace lit instead by a large sphere light of radius r = 5 and the same power at
// its centre (which light subpaths start from too, render/light_path.h; large, so that next-event
// estimation, BSDF samples and connections all find it). From outside, a sphere light lights like
// a point light of its power, so the direct radiance is again rho P / (4 pi^2 R^2) = 0.5; the
// light covers f = (r / R)^2 of every wall point's cosine-weighted view and reflects nothing, so
// each bounce returns rho (1 - f) of the last, alike everywhere: L = 0.5 / (1 - rho (1 - f)) =
// 0.8. The camera, between the light and the wall, looks at the wall.
TEST(ClosedForm, FurnaceAroundASphereLightMatchesItsSeries) {
  const double radius = 10, power = 4 * kPi * kPi * radius * radius;
  const double expected = 0.5 / (1 - 0.5 * (1 - 0.25));
  const std::string scene = R"({
    "camera": {"width": 32, "height": 32, "fov": 90, "position": [0, 0, 7],
               "look_at": [0, 0, 10], "spp": 64},
    "render": {"max_depth": 200},
    "spheres": [{"position": [0, 0, 0], "radius": )" + num(radius) + R"(, "color": 0.5}],
    "lights": [{"type": "sphere", "position": [0, 0, 0], "radius": 5, "intensity": )" +
                            num(power) + R"(}]})";
  EXPECT_GT(test::loadTestScene(scene).view().lightPathLights, 0u);  // the connections run
  const RenderResult r = renderTestScene(scene);
  for (int c = 0; c < 3; ++c) {
    const auto s = regionStats(r.image, 0, 0, 32, 32, c);
    EXPECT_NEAR(s.mean, expected, kZ * s.standardError() + 1e-4) << "channel " << c;
  }
}

// (a'') The furnace lit by a small emissive triangle at its centre (side 0.2, radiance Le, facing
// +z; light subpaths start from it too). Inside a sphere every wall patch sends a diffuse wall
// point the same share of its light, dA / (4 pi R^2), so all light after one bounce arrives
// alike everywhere: E_ind = rho Phi / (4 pi R^2) / (1 - rho), Phi = pi Le A. The direct part at
// wall point p is Le A cos(theta_p) / R^2, theta_p between the triangle's normal and p (a small
// triangle: within (0.2 / R)^2 of the exact integral, as is its shadow over the walls' exchange).
// So each pixel, whose samples all pass through its centre, shows
// rho / pi (Le A max(0, cos theta_p) / R^2 + E_ind) at the wall point the position pass gives.
TEST(ClosedForm, FurnaceAroundATriangleLightMatchesItsSeries) {
  const double radius = 10, rho = 0.5, side = 0.2, area = side * side * std::sqrt(3.0) / 4;
  const double le = 4000;
  const std::string obj = ::testing::TempDir() + "furnace_triangle.obj";
  std::ofstream(obj) << "v " << -side / 2 << " " << -side * std::sqrt(3.0) / 6 << " 0\nv "
                     << side / 2 << " " << -side * std::sqrt(3.0) / 6 << " 0\nv 0 "
                     << side * std::sqrt(3.0) / 3 << " 0\nf 1 2 3\n";
  const std::string scene = R"({
    "camera": {"width": 32, "height": 32, "fov": 100, "position": [0, 4, 0],
               "look_at": [0, 4, 10], "spp": 256},
    "render": {"max_depth": 200, "antialiasing": false},
    "spheres": [{"position": [0, 0, 0], "radius": )" + num(radius) + R"(, "color": )" +
                            num(rho) + R"(}],
    "objects": [{"file": ")" + obj + R"(", "material": {"type": "emissive", "radiance": )" +
                            num(le) + R"(}}]})";
  const SceneData data = test::loadTestScene(scene);
  EXPECT_GT(data.view().lightPathLights, 0u);  // the connections run
  RenderOptions options;
  options.aovs = true;
  const RenderResult r = renderCpu(data.view(), options);
  const ImageLayer position = makeAovLayers(data, {Aov::Position}, r.aovs)[0];
  const double indirect = rho * kPi * le * area / (4 * kPi * radius * radius) / (1 - rho);
  double sumDifference = 0, sumSquares = 0;
  const int n = 32 * 32;
  for (int i = 0; i < n; ++i) {
    const double px = position.pixels[3 * i], py = position.pixels[3 * i + 1],
                 pz = position.pixels[3 * i + 2];
    const double cosTheta = pz / std::sqrt(px * px + py * py + pz * pz);
    const double expected =
        rho / kPi * (le * area * std::max(0.0, cosTheta) / (radius * radius) + indirect);
    const double d = r.image.pixels[3 * i] / expected - 1;  // the channels are alike
    sumDifference += d;
    sumSquares += d * d;
  }
  const double mean = sumDifference / n;
  const double standardError = std::sqrt((sumSquares / n - mean * mean) / n);
  EXPECT_NEAR(mean, 0.0, kZ * standardError + 2e-3);
}

// (b) A point light over a diffuse plane, no other geometry: the plane cannot see itself, so a
// pixel shows exactly rho * color * P * cos(theta) / (4 pi^2 d^2) of the point it sees.
TEST(ClosedForm, PointLightOverDiffusePlaneMatchesContractFormula) {
  const std::string obj = test::writePlaneObj("plane_b.obj", 100);
  const double rho = 0.6, power = 1000, lightY = 4, lightX = 1;
  const std::string scene = R"({
    "camera": {"width": 64, "height": 48, "fov": 70, "position": [0, 6, 0],
               "look_at": [0, 0, 0.001], "up": [0, 0, -1], "spp": 4},
    "render": {"antialiasing": false},
    "objects": [{"file": ")" + obj + R"(", "color": )" + num(rho) + R"(}],
    "lights": [{"position": [)" + num(lightX) + ", " + num(lightY) + R"(, 0],
                "intensity": )" + num(power) + R"(, "color": [1, 0.5, 0.25]}]})";
  const SceneData data = test::loadTestScene(scene);
  RenderOptions options;
  const RenderResult r = renderCpu(data.view(), options);
  const Vec3 tint(1.0f, 0.5f, 0.25f);
  int checked = 0;
  for (uint32_t y = 4; y < 48; y += 9)
    for (uint32_t x = 3; x < 64; x += 11) {
      const PlanePoint p = planePointAt(data.camera, x, y);
      const double dx = lightX - p.x, dy = lightY, dz = -p.z;
      const double d2 = dx * dx + dy * dy + dz * dz;
      const double cosTheta = dy / std::sqrt(d2);
      const double expected = rho * power * cosTheta / (4 * kPi * kPi * d2);
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(r.image.at(x, y)[c], expected * tint[c], 2e-4 * expected) << x << "," << y;
      ++checked;
    }
  EXPECT_GT(checked, 20);
  // With nothing emissive and a black environment no ray is scattered from the last interaction:
  // it could only find emission. At max_depth 1 that leaves the shadow rays alone, and the
  // same image.
  EXPECT_FALSE(data.view().emissionReachable);
  EXPECT_GT(r.rays.bounce, 0u);
  std::string direct = scene;
  direct.replace(direct.find(R"("antialiasing": false)"), 21,
                 R"("antialiasing": false, "max_depth": 1)");
  const RenderResult d = renderCpu(test::loadTestScene(direct).view(), options);
  EXPECT_EQ(d.rays.bounce, 0u);
  EXPECT_EQ(d.rays.shadow, 64u * 48u * 4u);  // one per sample: every pixel sees the plane
  for (uint32_t y = 0; y < 48; ++y)
    for (uint32_t x = 0; x < 64; ++x)
      for (int c = 0; c < 3; ++c) EXPECT_EQ(d.image.at(x, y)[c], r.image.at(x, y)[c]);
}

// (b') Two to four point lights and nothing else: a path's first interaction samples each with a
// shadow ray of its own (render/light.h, firstHitDeltaLights), so with pixel centres every pixel
// shows the sum of their exact contributions, without the noise of a pick; five are picked from.
void expectPointLightsSampledEachAtTheFirstHit(int count) {
  const std::string obj = test::writePlaneObj("plane_each.obj", 100);
  const double rho = 0.6;
  std::vector<PointLight> points;
  for (int i = 0; i < count; ++i)
    points.push_back({-3.0 + 1.7 * i, 3.0 + i, 1.0 - i, 900.0 / (i + 1),
                      Vec3(1.0f, 0.3f + 0.15f * i, 1.0f - 0.2f * i)});
  std::string lights;
  for (const PointLight& p : points) lights += (lights.empty() ? "" : ",") + p.json();
  const SceneData data = test::loadTestScene(R"({
    "camera": {"width": 32, "height": 24, "fov": 70, "position": [0, 6, 0],
               "look_at": [0, 0, 0.001], "up": [0, 0, -1], "spp": 4},
    "render": {"antialiasing": false, "max_depth": 1},
    "objects": [{"file": ")" + obj + R"(", "color": )" + num(rho) + R"(}],
    "lights": [)" + lights + "]}");
  const bool each = count <= 4;
  EXPECT_EQ(data.view().firstHitDeltaLights, each ? uint32_t(count) : 0u);
  const RenderResult r = renderCpu(data.view(), RenderOptions{});
  EXPECT_EQ(r.rays.shadow, (each ? uint64_t(count) : 1u) * 32u * 24u * 4u);
  double worst = 0;
  for (uint32_t y = 0; y < 24; ++y)
    for (uint32_t x = 0; x < 32; ++x) {
      const PlanePoint at = planePointAt(data.camera, x, y);
      for (int c = 0; c < 3; ++c) {
        double expected = 0;
        for (const PointLight& p : points) expected += p.onPlane(rho, at, c);
        worst = std::max(worst, std::fabs(r.image.at(x, y)[c] / expected - 1.0));
      }
    }
  if (each)
    EXPECT_LT(worst, 2e-4) << count << " lights";
  else
    EXPECT_GT(worst, 0.05) << "a pick among five lights leaves noise at 4 spp";
}

TEST(ClosedForm, TwoToFourPointLightsAreEachSampledAtTheFirstHit) {
  for (int count : {2, 3, 4, 5}) expectPointLightsSampledEachAtTheFirstHit(count);
}

// (c) Under a uniform environment of radiance 1 a convex object never sees itself: a diffuse
// sphere shows its albedo, a mirror its colour, and clear glass conserves energy (every path's
// weight is exactly 1 once it leaves). Each sphere is alone so that none sees another.
RenderResult renderAloneInFurnace(const std::string& sphere) {
  return renderTestScene(R"({
    "camera": {"width": 32, "height": 32, "fov": 30, "position": [0, 0, 6], "spp": 16},
    "render": {"max_depth": 64},
    "environment": {"color": 1},
    "spheres": [)" + sphere + "]}");
}

TEST(ClosedForm, UniformEnvironmentDiffuseMirrorGlass) {
  const RenderResult diffuse =
      renderAloneInFurnace(R"({"position": [0, 0, 0], "radius": 1, "color": [0.2, 0.5, 0.8]})");
  const RenderResult mirror = renderAloneInFurnace(
      R"({"position": [0, 0, 0], "radius": 1, "material": "mirror", "color": [0.9, 0.6, 0.3]})");
  const RenderResult glass = renderAloneInFurnace(
      R"({"position": [0, 0, 0], "radius": 1, "material": "glass", "ior": 1.5})");
  const Vec3 albedo(0.2f, 0.5f, 0.8f), tint(0.9f, 0.6f, 0.3f);
  // The sphere covers a disc of radius ~11 pixels around the centre (16, 16).
  for (int c = 0; c < 3; ++c) {
    const auto sd = regionStats(diffuse.image, 11, 11, 21, 21, c);
    EXPECT_NEAR(sd.mean, albedo[c], kZ * sd.standardError() + 1e-5);
    const auto sm = regionStats(mirror.image, 11, 11, 21, 21, c);
    EXPECT_NEAR(sm.mean, tint[c], 1e-5);
    const auto sg = regionStats(glass.image, 0, 0, 32, 32, c);  // sphere and background alike
    EXPECT_NEAR(sg.mean, 1.0, kZ * sg.standardError() + 1e-4);
    const auto bg = regionStats(diffuse.image, 0, 0, 32, 2, c);  // top rows see only the sky
    EXPECT_NEAR(bg.mean, 1.0, 1e-6);
  }
}

// Glass of index 1 bends no ray whatever its roughness: a sphere of it is not there, every pixel
// the environment's radiance, rough (which used to end each path through it black) or smooth.
TEST(ClosedForm, GlassOfIndexOneIsInvisibleRoughOrSmooth) {
  for (const char* roughness : {"0", "0.3", "1"}) {
    SCOPED_TRACE(std::string("roughness ") + roughness);
    const RenderResult glass =
        renderAloneInFurnace(R"({"position": [0, 0, 0], "radius": 1, "material": {"type": "glass",
                                 "ior": 1, "roughness": )" +
                             std::string(roughness) + "}}");
    for (float v : glass.image.pixels) EXPECT_NEAR(v, 1.0f, 1e-5f);
  }
}

// (d) A sphere light seen directly shows its radiance color * I / (4 pi^2 r^2); seen in a mirror
// it shows the same radiance (specular paths take the emission at full weight).
TEST(ClosedForm, SphereLightSeenDirectlyAndInMirror) {
  const double radius = 0.5, intensity = 300;
  const double radiance = intensity / (4 * kPi * kPi * radius * radius);
  const std::string scene = R"({
    "camera": {"width": 48, "height": 48, "fov": 40, "position": [0, 0, 5], "spp": 4},
    "lights": [{"type": "sphere", "position": [0, 0, 0], "radius": )" + num(radius) +
                            R"(, "intensity": )" + num(intensity) + R"(, "color": [1, 0.5, 0.2]}]})";
  const RenderResult r = renderTestScene(scene);
  const Vec3 tint(1.0f, 0.5f, 0.2f);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(r.image.at(24, 24)[c], radiance * tint[c], 1e-4 * radiance);
  EXPECT_EQ(r.image.at(0, 0).x, 0.0f);

  // The same light behind the camera, seen in a large mirror sphere ahead.
  const std::string mirrored = R"({
    "camera": {"width": 48, "height": 48, "fov": 40, "position": [0, 0, 5], "spp": 4},
    "spheres": [{"position": [0, 0, -100], "radius": 50, "material": "mirror", "color": 1}],
    "lights": [{"type": "sphere", "position": [0, 0, 40], "radius": 20, "intensity": 1e6}]})";
  const RenderResult m = renderTestScene(mirrored);
  const double mirroredRadiance = 1e6 / (4 * kPi * kPi * 400.0);
  EXPECT_NEAR(m.image.at(24, 24).x, mirroredRadiance, 1e-4 * mirroredRadiance);
}

// (e) A sphere light over a diffuse plane: the irradiance from a uniform sphere of radiance L
// fully above the horizon is pi L (r/d)^2 cos(theta), so the plane shows rho L (r/d)^2 cos.
// Light sampling and BSDF sampling share the estimate (MIS), so this checks their weights.
TEST(ClosedForm, SphereLightOverDiffusePlaneMatchesIrradiance) {
  const std::string obj = test::writePlaneObj("plane_e.obj", 100);
  const double rho = 0.7, radius = 0.5, intensity = 500, lightX = 3, lightY = 2;
  const double L = intensity / (4 * kPi * kPi * radius * radius);
  // The light sits outside the camera's view, which looks straight down at the origin.
  const std::string scene = R"({
    "camera": {"width": 24, "height": 24, "fov": 20, "position": [0, 8, 0],
               "look_at": [0, 0, 0.001], "up": [0, 0, -1], "spp": 128},
    "render": {"max_depth": 1, "antialiasing": false},
    "objects": [{"file": ")" + obj + R"(", "color": )" + num(rho) + R"(}],
    "lights": [{"type": "sphere", "position": [)" + num(lightX) + ", " + num(lightY) +
                            R"(, 0], "radius": )" + num(radius) + R"(, "intensity": )" +
                            num(intensity) + R"(}]})";
  const SceneData data = test::loadTestScene(scene);
  const RenderResult r = renderCpu(data.view(), RenderOptions{});
  // Each pixel's ratio to its exact value is an independent estimate of 1.
  ImageRGB ratios(24, 24);
  for (uint32_t y = 0; y < 24; ++y)
    for (uint32_t x = 0; x < 24; ++x) {
      const double expected = sphereLightOnPlane(rho, L, radius, lightX, lightY, 0,
                                                 planePointAt(data.camera, x, y));
      ratios.set(x, y, r.image.at(x, y) / float(expected));
    }
  for (int c = 0; c < 3; ++c) {
    const auto s = regionStats(ratios, 0, 0, 24, 24, c);
    EXPECT_NEAR(s.mean, 1.0, kZ * s.standardError() + 1e-3);
    EXPECT_LT(s.stddev, 0.1);  // antialiasing jitter and sampling noise only
  }
}

// (f) Several lights: a plane under two point lights of different power and colour, a sphere
// light, a light of no power and `extraLights` weak point lights must show the sum of their
// direct contributions (the sphere light's through MIS with the BSDF), each light picked through
// the light tree, among few lights or many.
void expectLightsSumToEveryContribution(int extraLights) {
  const std::string obj = test::writePlaneObj("plane_f.obj", 100);
  const double rho = 0.5;
  std::vector<PointLight> points = {{2, 3, 0, 900, Vec3(1, 0.5f, 0.25f)},
                                    {-3, 5, 1, 300, Vec3(0.2f, 0.6f, 1)}};
  for (int i = 0; i < extraLights; ++i) points.push_back({-4.0 + i, 6, 4.0 - i, 40, Vec3(1.0f)});
  // A big, near sphere light, so that BSDF sampling finds it often and a wrong MIS weight shows.
  const double sx = 0, sy = 2, sz = -5, radius = 1.5, intensity = 400;
  const double L = intensity / (4 * kPi * kPi * radius * radius);
  std::string lights;
  for (const PointLight& p : points) lights += p.json() + ",";
  lights += R"({"type": "sphere", "position": [)" + num(sx) + ", " + num(sy) + ", " + num(sz) +
            R"(], "radius": )" + num(radius) + R"(, "intensity": )" + num(intensity) + "},";
  lights += R"({"position": [0, 1, 0], "intensity": 0})";
  const std::string scene = R"({
    "camera": {"width": 24, "height": 24, "fov": 40, "position": [0, 8, 0],
               "look_at": [0, 0, 0.001], "up": [0, 0, -1], "spp": 256},
    "render": {"max_depth": 1, "antialiasing": false},
    "objects": [{"file": ")" + obj + R"(", "color": )" + num(rho) + R"(}],
    "lights": [)" + lights + "]}";
  const SceneData data = test::loadTestScene(scene);
  const RenderResult r = renderCpu(data.view(), RenderOptions{});
  ImageRGB ratios(24, 24);
  for (uint32_t y = 0; y < 24; ++y)
    for (uint32_t x = 0; x < 24; ++x) {
      const PlanePoint at = planePointAt(data.camera, x, y);
      double expected[3] = {0, 0, 0};
      for (const PointLight& p : points)
        for (int c = 0; c < 3; ++c) expected[c] += p.onPlane(rho, at, c);
      const double e = sphereLightOnPlane(rho, L, radius, sx, sy, sz, at);
      for (int c = 0; c < 3; ++c) expected[c] += e;
      const Vec3 v = r.image.at(x, y);
      ratios.set(x, y, Vec3(float(v.x / expected[0]), float(v.y / expected[1]),
                            float(v.z / expected[2])));
    }
  for (int c = 0; c < 3; ++c) {
    const auto s = regionStats(ratios, 0, 0, 24, 24, c);
    EXPECT_NEAR(s.mean, 1.0, kZ * s.standardError() + 1e-3) << "channel " << c;
  }
}

TEST(ClosedForm, FewPickedLightsSumToEveryContribution) { expectLightsSumToEveryContribution(0); }

TEST(ClosedForm, ManyPickedLightsSumToEveryContribution) { expectLightsSumToEveryContribution(8); }

}  // namespace
}  // namespace candela
