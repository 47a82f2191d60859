// Directional lights: irradiance E along one direction from infinitely far (Mitsuba 3's
// `directional`), or from a disc of directions (a sun's angle). Against closed forms: the plane
// under a lone directional light pixel for pixel, a sphere's shadow on it, a few delta lights each
// sampled at the first hit, a directional light among picked lights, the plane under a disc and
// the disc seen; a disc's penumbra against a far sphere light's; the picks of the lights at
// infinity; the scene format's refusals and its animated directions.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/constants.h"
#include "render/light_selection.h"
#include "render_test_util.h"
#include "scene/animation.h"

namespace candela {
namespace {

constexpr double kZ = 5.0;

using test::lightsError;
using test::num;

// Where the ray through the centre of pixel (x, y) meets the plane y = 0, in double.
struct PlaneHit {
  double x, z;
};
PlaneHit planePointAt(const Camera& cam, uint32_t x, uint32_t y) {
  const Vec3 d = cam.cameraToWorld * (cam.inverseK * Vec3(x + 0.5f, y + 0.5f, 1.0f));
  const double t = -double(cam.position.y) / d.y;
  return {cam.position.x + t * d.x, cam.position.z + t * d.z};
}

// A directional light along `direction` (any length) of irradiance `irradiance`, and what a
// diffuse plane y = 0 of albedo rho reflects under it: rho E cos / pi (in double, apart from the
// renderer's code).
struct Sun {
  double dx, dy, dz, irradiance;
  std::string json() const {
    return R"({"type": "directional", "direction": [)" + num(dx) + ", " + num(dy) + ", " + num(dz) +
           R"(], "intensity": )" + num(irradiance) + "}";
  }
  double cosOnPlane() const { return -dy / std::sqrt(dx * dx + dy * dy + dz * dz); }
  double onPlane(double rho) const { return rho * irradiance * cosOnPlane() / kPi; }
};

// The plane, a sphere above it and a directional light, pixel centres, one bounce: every pixel of
// the plane is rho E cos / pi or, in the sphere's shadow, 0.
TEST(DirectionalLight, OverADiffusePlaneEveryPixelIsItsClosedFormOrShadow) {
  const std::string obj = test::writePlaneObj("directional_plane.obj", 100);
  const double rho = 0.6, cx = 1.5, cy = 1.2, cz = -0.5, radius = 0.8;
  const Sun sun{-0.6, -1.0, 0.3, 2.5};
  const SceneData data = test::loadTestScene(R"({
    "camera": {"width": 64, "height": 48, "fov": 70, "position": [0, 6, 0],
               "look_at": [0, 0, 0.001], "up": [0, 0, -1], "spp": 4},
    "render": {"antialiasing": false, "max_depth": 1},
    "objects": [{"file": ")" + obj + R"(", "color": )" +
                                             num(rho) + R"(}],
    "spheres": [{"position": [)" + num(cx) + ", " +
                                             num(cy) + ", " + num(cz) + R"(], "radius": )" +
                                             num(radius) + R"(}],
    "lights": [)" + sun.json() + "]}");
  EXPECT_TRUE(data.view().loneDeltaLight);
  const RenderResult r = renderCpu(data.view(), RenderOptions{});
  const double len = std::sqrt(sun.dx * sun.dx + sun.dy * sun.dy + sun.dz * sun.dz);
  const double ux = -sun.dx / len, uy = -sun.dy / len, uz = -sun.dz / len;  // towards the sun
  int lit = 0, shadowed = 0;
  for (uint32_t y = 0; y < 48; ++y)
    for (uint32_t x = 0; x < 64; ++x) {
      const PlaneHit at = planePointAt(data.camera, x, y);
      // Pixels that see the sphere, or nearly, are left out.
      const Vec3& eye = data.camera.position;
      const double ex = at.x - eye.x, ey = -double(eye.y), ez = at.z - eye.z;
      const double elen = std::sqrt(ex * ex + ey * ey + ez * ez);
      const double ox = cx - eye.x, oy = cy - eye.y, oz = cz - eye.z;
      const double onRay = (ox * ex + oy * ey + oz * ez) / elen;
      if (ox * ox + oy * oy + oz * oz - onRay * onRay < 1.1 * radius * radius) continue;
      // The distance from the sphere's centre to the ray from the plane point towards the sun.
      const double px = cx - at.x, py = cy, pz = cz - at.z;
      const double along = px * ux + py * uy + pz * uz;
      const double d2 = px * px + py * py + pz * pz - along * along;
      const double edge = std::sqrt(d2) - radius;
      if (std::fabs(edge) < 0.01) continue;  // the shadow's rim, where rounding decides
      const bool inShadow = along > 0 && edge < 0;
      (inShadow ? shadowed : lit) += 1;
      const double expected = inShadow ? 0.0 : sun.onPlane(rho);
      EXPECT_NEAR(r.image.at(x, y).x, expected, 2e-6 + 2e-6 * expected) << x << "," << y;
    }
  EXPECT_GT(lit, 1000);
  EXPECT_GT(shadowed, 50);
}

// Two to four delta lights, directional and point, are each sampled at the first hit
// (render/light.h, firstHitDeltaLights): with pixel centres every pixel shows the exact sum.
TEST(DirectionalLight, AFewDeltaLightsAreEachSampledAtTheFirstHit) {
  const std::string obj = test::writePlaneObj("directional_plane2.obj", 100);
  const double rho = 0.5;
  const Sun a{0.3, -1.0, 0.2, 1.5}, b{-0.2, -0.5, -0.4, 0.7};
  const double px = 1, py = 3, pz = -1, power = 400;
  const SceneData data = test::loadTestScene(R"({
    "camera": {"width": 32, "height": 24, "fov": 70, "position": [0, 6, 0],
               "look_at": [0, 0, 0.001], "up": [0, 0, -1], "spp": 4},
    "render": {"antialiasing": false, "max_depth": 1},
    "objects": [{"file": ")" + obj + R"(", "color": )" +
                                             num(rho) + R"(}],
    "lights": [)" + a.json() + "," + b.json() +
                                             R"(, {"position": [1, 3, -1], "intensity": 400}]})");
  EXPECT_EQ(data.view().firstHitDeltaLights, 3u);
  const RenderResult r = renderCpu(data.view(), RenderOptions{});
  EXPECT_EQ(r.rays.shadow, 3u * 32u * 24u * 4u);
  double worst = 0;
  for (uint32_t y = 0; y < 24; ++y)
    for (uint32_t x = 0; x < 32; ++x) {
      const PlaneHit at = planePointAt(data.camera, x, y);
      const double dx = px - at.x, dz = pz - at.z, d2 = dx * dx + py * py + dz * dz;
      const double point = rho * power * (py / std::sqrt(d2)) / (4 * kPi * kPi * d2);
      const double expected = a.onPlane(rho) + b.onPlane(rho) + point;
      worst = std::max(worst, std::fabs(r.image.at(x, y).x / expected - 1.0));
    }
  EXPECT_LT(worst, 2e-4);
}

// Beside the environment and a light tree, each light at infinity takes an equal share of the
// picks, as the tree does as a whole; a directional light without power takes none.
TEST(DirectionalLight, LightsAtInfinityTakeEqualSharesOfThePicks) {
  const SceneData data = test::loadTestScene(R"({
    "camera": {"width": 4, "height": 4, "fov": 40},
    "environment": {"color": 0.5},
    "lights": [{"type": "directional", "direction": [0, -1, 0], "intensity": 2},
               {"type": "sphere", "position": [0, 5, 0], "radius": 1, "intensity": 10},
               {"type": "directional", "direction": [1, -1, 0], "intensity": 0},
               {"type": "directional", "direction": [0, -1, 1], "intensity": 1}]})");
  const SceneView view = data.view();
  ASSERT_EQ(view.infiniteLightCount, 3u);  // the two with power and the environment
  EXPECT_EQ(view.infiniteLightShare, 0.25f);
  const Vec3 p(0, 1, 0), n(0, 1, 0);
  float sum = 0;
  for (uint32_t i = 0; i < view.lightCount; ++i) sum += lightSelectPmf(view, i, p, n);
  EXPECT_NEAR(sum, 1.0f, 1e-6f);
  EXPECT_EQ(lightSelectPmf(view, 2, p, n), 0.0f);  // no power: never picked
  EXPECT_EQ(lightSelectPmf(view, 0, p, n), 0.25f);
  float pmf = 0, remapped = 0;
  const int picked = selectLight(view, p, n, 0.3f, &pmf, &remapped);
  ASSERT_GE(picked, 0);
  EXPECT_EQ(uint32_t(picked), view.infiniteLights[1]);
  EXPECT_EQ(pmf, 0.25f);
  EXPECT_NEAR(remapped, 0.2f, 1e-6f);  // 0.3's place in the share [0.25, 0.5)
  EXPECT_EQ(uint32_t(selectLight(view, p, n, 0.9f, &pmf, &remapped)), 1u);  // the tree's sphere

  // Without a tree the lights at infinity take every pick, the last one up to 1.
  const SceneData two = test::loadTestScene(R"({
    "camera": {"width": 4, "height": 4, "fov": 40},
    "environment": {"color": 0.5},
    "lights": [{"type": "directional", "direction": [0, -1, 0], "intensity": 2}]})");
  EXPECT_FALSE(two.view().loneDeltaLight);
  EXPECT_EQ(two.view().infiniteLightShare, 0.5f);
  EXPECT_GE(selectLight(two.view(), p, n, 0.9999999f, &pmf, &remapped), 0);
  EXPECT_LT(remapped, 1.0f);
}

// A directional light among a point light, a sphere light and a uniform environment, one picked
// per sample: the plane shows the sum of the closed forms (rho Le from the environment's upper
// hemisphere, which nothing blocks).
TEST(DirectionalLight, AmongPickedLightsThePlaneShowsTheSum) {
  const std::string obj = test::writePlaneObj("directional_plane3.obj", 100);
  const double rho = 0.5, environment = 0.3;
  const Sun sun{0.4, -1.0, -0.2, 2.0};
  const double px = -2, py = 4, pz = 1, power = 600;
  const SceneData data = test::loadTestScene(R"({
    "camera": {"width": 24, "height": 24, "fov": 50, "position": [0, 8, 0],
               "look_at": [0, 0, 0.001], "up": [0, 0, -1], "spp": 256},
    "render": {"max_depth": 1, "antialiasing": false},
    "environment": {"color": )" + num(environment) +
                                             R"(},
    "objects": [{"file": ")" + obj + R"(", "color": )" +
                                             num(rho) + R"(}],
    "lights": [)" + sun.json() + R"(, {"position": [-2, 4, 1], "intensity": 600},
               {"position": [3, 5, 2], "intensity": 0}]})");
  EXPECT_EQ(data.view().firstHitDeltaLights, 0u);  // the environment is no delta light
  const RenderResult r = renderCpu(data.view(), RenderOptions{});
  ImageRGB ratios(24, 24);
  for (uint32_t y = 0; y < 24; ++y)
    for (uint32_t x = 0; x < 24; ++x) {
      const PlaneHit at = planePointAt(data.camera, x, y);
      const double dx = px - at.x, dz = pz - at.z, d2 = dx * dx + py * py + dz * dz;
      const double point = rho * power * (py / std::sqrt(d2)) / (4 * kPi * kPi * d2);
      const double expected = sun.onPlane(rho) + point + rho * environment;
      ratios.set(x, y, Vec3(float(r.image.at(x, y).x / expected)));
    }
  const test::RegionStats s = test::regionStats(ratios, 0, 0, 24, 24, 0);
  EXPECT_NEAR(s.mean, 1.0, kZ * s.standardError() + 1e-3);
}

// A sun with a disc (an angle): a surface facing it still receives its irradiance E, now from a
// cone of uniform radiance E / (pi sin^2 r), next-event estimation's samples and the BSDF's that
// find the disc weighted against each other. A disc wide enough for the BSDF's samples to find.
TEST(DirectionalLight, ADiscLightsThePlaneWithTheIrradianceOfItsDirection) {
  const std::string obj = test::writePlaneObj("directional_plane4.obj", 100);
  const double rho = 0.5;
  const Sun sun{0.5, -1.0, 0.0, 2.0};
  const SceneData data = test::loadTestScene(R"({
    "camera": {"width": 24, "height": 24, "fov": 50, "position": [0, 8, 0],
               "look_at": [0, 0, 0.001], "up": [0, 0, -1], "spp": 64},
    "render": {"max_depth": 1, "antialiasing": false},
    "objects": [{"file": ")" + obj + R"(", "color": )" +
                                             num(rho) + R"(}],
    "lights": [{"type": "directional", "direction": [0.5, -1, 0], "intensity": 2,
                "angle": 40}]})");
  EXPECT_FALSE(data.view().loneDeltaLight);
  EXPECT_TRUE(data.view().sunDiscs);
  const RenderResult r = renderCpu(data.view(), RenderOptions{});
  EXPECT_GT(r.rays.bounce, 0u);  // the BSDF's rays are traced: they may find the disc
  ImageRGB ratios(24, 24);
  for (uint32_t y = 0; y < 24; ++y)
    for (uint32_t x = 0; x < 24; ++x)
      ratios.set(x, y, Vec3(float(r.image.at(x, y).x / sun.onPlane(rho))));
  const test::RegionStats s = test::regionStats(ratios, 0, 0, 24, 24, 0);
  EXPECT_NEAR(s.mean, 1.0, kZ * s.standardError() + 1e-3);
  EXPECT_GT(s.standardError(), 0.0);  // noise, not a delta light's exact value
}

// Looking at the sun: every pixel whose ray lies within the disc shows its radiance
// E / (pi sin^2 r), every other pixel the black sky.
TEST(DirectionalLight, ItsDiscIsSeenWithTheRadianceOfItsIrradiance) {
  const double angle = 6, irradiance = 3;
  const SceneData data = test::loadTestScene(R"({
    "camera": {"width": 32, "height": 32, "fov": 10, "position": [0, 0, 0],
               "look_at": [0.3, 1, 0.2], "spp": 1},
    "render": {"max_depth": 1, "antialiasing": false},
    "lights": [{"type": "directional", "direction": [-0.3, -1, -0.2], "intensity": 3,
                "angle": 6}]})");
  const RenderResult r = renderCpu(data.view(), RenderOptions{});
  const double radius = angle / 2 * kPi / 180;
  const double radiance = irradiance / (kPi * std::sin(radius) * std::sin(radius));
  const double axisLength = std::sqrt(0.09 + 1 + 0.04);
  int inside = 0, outside = 0;
  for (uint32_t y = 0; y < 32; ++y)
    for (uint32_t x = 0; x < 32; ++x) {
      const Camera& cam = data.camera;
      const Vec3 d = cam.cameraToWorld * (cam.inverseK * Vec3(x + 0.5f, y + 0.5f, 1.0f));
      const double cosAngle =
          (0.3 * d.x + 1.0 * d.y + 0.2 * d.z) / (axisLength * std::sqrt(double(dot(d, d))));
      const double fromAxis = std::acos(std::min(1.0, cosAngle));
      if (std::fabs(fromAxis - radius) < 1e-4) continue;  // the rim, where rounding decides
      const bool in = fromAxis < radius;
      (in ? inside : outside) += 1;
      EXPECT_NEAR(r.image.at(x, y).y, in ? radiance : 0.0, 1e-5 * radiance) << x << "," << y;
    }
  EXPECT_GT(inside, 100);
  EXPECT_GT(outside, 100);
}

// A sun of 10 degrees and a sphere light that subtends the same cone from 1e6 away with the same
// radiance, each over a plane with a sphere (`material`) at `maxDepth`: two seeds of each. The far
// light's parallax and the spread of its distance over the scene move its irradiance by about
// 1e-6 of itself (at 1e4 away, by 1.6e-4, which the lit plane's noise of 1e-4 then showed).
struct SunAndFarSphere {
  test::SeedPair discs, spheres;
};
SunAndFarSphere renderSunAndFarSphere(const std::string& material, int maxDepth, int spp,
                                      const std::string& planeName) {
  const std::string obj = test::writePlaneObj(planeName, 100);
  const double angle = 10, irradiance = 2, distance = 1e6;
  const double radius = angle / 2 * kPi / 180;
  const double sphereRadius = distance * std::sin(radius);
  const double radiance = irradiance / (kPi * std::sin(radius) * std::sin(radius));
  const double power = radiance * 4 * kPi * kPi * sphereRadius * sphereRadius;
  const double len = std::sqrt(0.2 * 0.2 + 1 + 0.1 * 0.1);
  const std::string farSphere = R"({"type": "sphere", "position": [)" + num(-0.2 / len * distance) +
                                ", " + num(1 / len * distance) + ", " + num(-0.1 / len * distance) +
                                R"(], "radius": )" + num(sphereRadius) + R"(, "intensity": )" +
                                num(power) + "}";
  const std::string sun = R"({"type": "directional", "direction": [0.2, -1, 0.1], "intensity": )" +
                          num(irradiance) + R"(, "angle": )" + num(angle) + "}";
  const auto render = [&](const std::string& light, uint32_t seed) {
    return test::renderTestScene(R"({
      "camera": {"width": 32, "height": 32, "fov": 40, "position": [0, 6, 0.5],
                 "look_at": [0, 0, 0], "spp": )" +
                                 std::to_string(spp) + R"(},
      "render": {"max_depth": )" +
                                 std::to_string(maxDepth) + R"(, "seed": )" + std::to_string(seed) +
                                 R"(},
      "objects": [{"file": ")" + obj +
                                 R"(", "color": 0.6}],
      "spheres": [{"position": [0, 1.2, 0], "radius": 0.7, "material": )" +
                                 material + R"(}],
      "lights": [)" + light + "]}");
  };
  return {{render(sun, 1), render(sun, 2)}, {render(farSphere, 3), render(farSphere, 4)}};
}

// A sphere's shadow under the sun has a penumbra, the far sphere light's.
TEST(DirectionalLight, ItsPenumbraIsThatOfAFarSphereLightOfItsCone) {
  const SunAndFarSphere r = renderSunAndFarSphere(R"({"type": "diffuse", "color": 0.4})", 1, 64,
                                                  "directional_plane5.obj");
  test::expectSameImage(r.discs, r.spheres, 8);
  // The penumbra is there: pixels between lit and umbra.
  const double lit = 0.6 * 2.0 * (1 / std::sqrt(1.05)) / kPi;
  int between = 0;
  for (uint32_t y = 0; y < 32; ++y)
    for (uint32_t x = 0; x < 32; ++x) {
      const double v = (r.discs.a.image.at(x, y).x + r.discs.b.image.at(x, y).x) / 2;
      between += v > 0.15 * lit && v < 0.85 * lit;
    }
  EXPECT_GT(between, 20);
}

// Through a glass sphere the disc is found by paths that leave it (its caustic on the plane, the
// sun seen through the glass), weighted fully after the glass's smooth refractions: the far
// sphere light's image again. A caustic's rare bright paths need more samples, and larger blocks,
// for two seeds to tell its noise.
TEST(DirectionalLight, ItsCausticThroughGlassIsThatOfAFarSphereLight) {
  const SunAndFarSphere r =
      renderSunAndFarSphere(R"({"type": "glass", "ior": 1.5})", 6, 512, "directional_plane6.obj");
  test::expectSameImage(r.discs, r.spheres, 8);
}

std::string animated(const std::string& property, const std::string& keys) {
  return test::oneTrack("sun", property, keys);
}

TEST(DirectionalLight, TheSceneFormatRefusesWhatItCannotBe) {
  const std::string sun = R"("type": "directional", "intensity": 2)";
  EXPECT_EQ(lightsError("{" + sun + "}"), "s.json: lights[0]: missing required key \"direction\"");
  EXPECT_EQ(
      lightsError("{" + sun + R"(, "direction": [0, 0, 0]})"),
      "s.json: lights[0].direction: expected a direction of non-zero length, got an array [0,0,0]");
  // Any other vector has a direction, however short or long.
  for (const char* direction :
       {"[1e-30, 0, 0]", "[0, 1e-44, 0]", "[0, 0, 3e38]", "[3e38, 3e38, 0]"}) {
    const std::string scene = R"({"camera": {"width": 4, "height": 4}, "lights": [{)" + sun +
                              R"(, "direction": )" + direction + "}]}";
    const SceneData data = flattenScene(parseSceneText(scene, "s.json", "."));
    EXPECT_NEAR(length(data.lights[0].direction), 1.0f, 1e-6f) << direction;
  }
  EXPECT_EQ(lightsError("{" + sun + R"(, "direction": [0, -1, 0], "position": [0, 5, 0]})"),
            "s.json: lights[0].position: not used by a directional light (it shines from "
            "infinitely far along its \"direction\")");
  EXPECT_EQ(lightsError("{" + sun + R"(, "direction": [0, -1, 0], "cutoff_angle": 10})"),
            "s.json: lights[0].cutoff_angle: not used by a directional light (only \"spot\" "
            "lights have a cone)");
  EXPECT_EQ(lightsError("{" + sun + R"(, "direction": [0, -1, 0], "radius": 1})"),
            "s.json: lights[0].radius: not used by a directional light (only \"sphere\" lights "
            "have a radius)");
  EXPECT_EQ(lightsError(R"({"type": "directional", "direction": [0, -1, 0], "intensity": 1e30,
                      "color": [1e30, 1, 1]})"),
            "s.json: lights[0]: its irradiance, intensity 1e+30 times color [1e+30, 1, 1], is "
            "beyond single precision; expected a smaller intensity or color");
  EXPECT_EQ(lightsError("{" + sun + R"(, "direction": [0, -1, 0], "angle": 180})"),
            "s.json: lights[0].angle: expected an apparent diameter in degrees from 0, below 180, "
            "got 180");
  EXPECT_EQ(lightsError(R"({"type": "directional", "direction": [0, -1, 0], "intensity": 1e30,
                      "angle": 1e-15})"),
            "s.json: lights[0]: its disc's radiance, intensity 1e+30 times color [1, 1, 1] over a "
            "disc 1e-15 degrees across, is beyond single precision; expected a larger angle or a "
            "smaller intensity");
  EXPECT_EQ(lightsError(R"({"type": "spot", "position": [0, 2, 0], "intensity": 10,
                      "direction": [0, -1, 0], "angle": 10})"),
            "s.json: lights[0].angle: not used by a spot light (only \"directional\" lights have "
            "a disc's angle)");
  EXPECT_EQ(lightsError(R"({"position": [0, 2, 0], "intensity": 10, "direction": [0, -1, 0]})"),
            "s.json: lights[0].direction: not used by a point light (only \"spot\", "
            "\"rectangle\" and \"directional\" lights, and point lights with a \"profile\", "
            "have a direction)");

  const std::string named = "{" + sun + R"(, "id": "sun", "direction": [0, -1, 0]})";
  EXPECT_EQ(lightsError(named, animated("direction", "[[0, [1, -1, 0]], [2, [-1, 1, 0]]]")),
            "s.json: animation.tracks[0]: at frame 1 the light's direction is zero");
  EXPECT_EQ(lightsError(named, animated("direction", "[[0, [0, 0, 0]]]")),
            "s.json: animation.tracks[0].keys[0][1]: expected a direction of non-zero length, got "
            "an array [0,0,0]");
  EXPECT_EQ(lightsError(named, animated("position", "[[0, [0, 1, 0]]]")),
            "s.json: animation.tracks[0].property: \"position\" is not used by a directional "
            "light (it shines from infinitely far)");
  EXPECT_EQ(lightsError(named, animated("look_at", "[[0, [0, 1, 0]]]")),
            "s.json: animation.tracks[0].property: \"look_at\" is not used by a directional "
            "light (only a spot or rectangle light aimed with \"look_at\" has one)");
  const std::string spot =
      R"({"type": "spot", "id": "sun", "position": [0, 2, 0], "intensity": 10, "look_at": [0, 0, 0]})";
  EXPECT_EQ(lightsError(spot, animated("direction", "[[0, [0, -1, 0]]]")),
            "s.json: animation.tracks[0].property: \"direction\" is not used by a spot light aimed "
            "with \"look_at\"");
  EXPECT_EQ(lightsError(spot, animated("look_at", "[[0, [0, 0, 0]], [2, [0, 4, 0]]]")),
            "s.json: animation.tracks[0]: at frame 1 the spot light looks at its own position");
}

// A direction track turns a directional light (and a spot light's aim) from frame to frame,
// linearly between its keys' unit vectors; the kernel's light gets the unit direction.
TEST(DirectionalLight, AnAnimatedDirectionTurnsTheLight) {
  const SceneDesc desc = parseSceneText(R"({"camera": {"width": 4, "height": 4},
    "lights": [{"type": "directional", "id": "sun", "direction": [1, -1, 0], "intensity": 2},
               {"type": "spot", "id": "lamp", "position": [0, 3, 0], "direction": [0, -1, 0],
                "intensity": 10}],
    "animation": {"frames": 3, "tracks": [
      {"target": "sun", "property": "direction", "keys": [[0, [1, -1, 0]], [2, [-1, -1, 0]]]},
      {"target": "lamp", "property": "direction", "keys": [[0, [0, -1, 0]], [2, [0, -1, 2]]]}]}})",
                                        "s.json", ".");
  const SceneData middle = flattenScene(sceneAtFrame(desc, 1));
  EXPECT_EQ(middle.lights[0].type, LightType::Directional);
  EXPECT_NEAR(middle.lights[0].direction.x, 0.0f, 1e-7f);
  EXPECT_NEAR(middle.lights[0].direction.y, -1.0f, 1e-7f);
  const SceneData last = flattenScene(sceneAtFrame(desc, 2));
  EXPECT_NEAR(last.lights[0].direction.x, -std::sqrt(0.5f), 1e-6f);
  EXPECT_NEAR(last.lights[1].spot.axis.z, 2.0f / std::sqrt(5.0f), 1e-6f);
  // Between the keys' unit vectors (0, -1, 0) and (0, -1, 2) / sqrt 5, halfway, made unit.
  const double y = (-1 - 1 / std::sqrt(5.0)) / 2, z = (2 / std::sqrt(5.0)) / 2;
  EXPECT_NEAR(middle.lights[1].spot.axis.z, z / std::sqrt(y * y + z * z), 1e-6);
}

// An angle track widens a sun's disc from frame to frame: at 0 it is a delta light again.
TEST(DirectionalLight, AnAnimatedAngleWidensTheDisc) {
  const SceneDesc desc = parseSceneText(R"({"camera": {"width": 4, "height": 4},
    "lights": [{"type": "directional", "id": "sun", "direction": [0, -1, 0], "intensity": 2}],
    "animation": {"frames": 3, "tracks": [
      {"target": "sun", "property": "angle", "keys": [[0, 0], [2, 10]]}]}})",
                                        "s.json", ".");
  const SceneData first = flattenScene(sceneAtFrame(desc, 0));
  EXPECT_TRUE(first.view().loneDeltaLight);
  EXPECT_EQ(first.lights[0].sunOneMinusCos, 0.0f);
  const SceneData middle = flattenScene(sceneAtFrame(desc, 1));
  EXPECT_FALSE(middle.view().loneDeltaLight);
  EXPECT_NEAR(middle.lights[0].sunOneMinusCos, 1 - std::cos(2.5 * kPi / 180), 1e-9);
  const std::string sun = R"({"type": "directional", "id": "sun", "direction": [0, -1, 0],
                              "intensity": 1e30})";
  EXPECT_EQ(lightsError(sun, animated("angle", "[[0, 1], [2, 1e-15]]")),
            "s.json: lights[0]: at frame 2, its disc's radiance, intensity 1e+30 times color [1, "
            "1, 1] over a disc 1e-15 degrees across, is beyond single precision; expected a larger "
            "angle or a smaller intensity");
  EXPECT_EQ(lightsError(sun, animated("angle", "[[0, 180]]")),
            "s.json: animation.tracks[0].keys[0][1]: expected an apparent diameter in degrees from "
            "0, below 180, got 180");
  EXPECT_EQ(lightsError(R"({"id": "sun", "position": [0, 2, 0], "intensity": 10})",
                        animated("angle", "[[0, 1]]")),
            "s.json: animation.tracks[0].property: \"angle\" is not used by a point light (only "
            "\"directional\" lights have a disc's angle)");
}

}  // namespace
}  // namespace candela
