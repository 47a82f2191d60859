// Spot lights (render/spot_cone.h): a point light limited to a cone, its falloff linear in angle
// between its beam and its cutoff (Mitsuba 3's `spot`). Against closed forms: the plane under a
// lone spot pixel for pixel, the spot among lights picked through the light tree, the power that
// leaves the cone; light subpaths from a spot against paths without them; and the scene format's
// refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>

#include "core/constants.h"
#include "render/spot_cone.h"
#include "render_test_util.h"
#include "scene/light_emission_desc.h"

namespace candela {
namespace {

constexpr double kZ = 5.0;

using test::lightsError;
using test::num;

// Where the ray through the centre of pixel (x, y) meets the plane y = 0.
Vec3 planePointAt(const Camera& cam, uint32_t x, uint32_t y) {
  const Vec3 d = cam.cameraToWorld * (cam.inverseK * Vec3(x + 0.5f, y + 0.5f, 1.0f));
  const double t = -cam.position.y / d.y;
  return Vec3(float(cam.position.x + t * d.x), 0.0f, float(cam.position.z + t * d.z));
}

// A spot light at `position` pointing straight down, and what a diffuse plane y = 0 of albedo
// rho reflects under it at `at`: the point light's rho P cos / (4 pi^2 d^2) times the falloff at
// the angle theta from the axis, 1 within the beam, (cutoff - theta) / (cutoff - beam) to the
// cutoff, 0 beyond (computed here in double, apart from the renderer's code).
struct DownSpot {
  Vec3 position;
  double power, cutoffDegrees, beamDegrees;
  std::string json() const {
    return R"({"type": "spot", "position": [)" + num(position.x) + ", " + num(position.y) + ", " +
           num(position.z) + R"(], "direction": [0, -1, 0], "intensity": )" + num(power) +
           R"(, "cutoff_angle": )" + num(cutoffDegrees) + R"(, "beam_width": )" + num(beamDegrees) +
           "}";
  }
  double falloff(const Vec3& at) const {
    const double dx = at.x - position.x, dz = at.z - position.z, h = position.y;
    const double theta = std::atan2(std::sqrt(dx * dx + dz * dz), h) * 180 / kPi;
    if (theta >= cutoffDegrees) return 0;
    if (theta <= beamDegrees) return 1;
    return (cutoffDegrees - theta) / (cutoffDegrees - beamDegrees);
  }
  // What the point light at its place would give, without the cone.
  double pointLightOnPlane(double rho, const Vec3& at) const {
    const double dx = at.x - position.x, dz = at.z - position.z, h = position.y;
    const double d2 = dx * dx + h * h + dz * dz;
    return rho * power * (h / std::sqrt(d2)) / (4 * kPi * kPi * d2);
  }
  double onPlane(double rho, const Vec3& at) const {
    return pointLightOnPlane(rho, at) * falloff(at);
  }
};

// Nothing but the plane and the spot, pixel centres, one bounce: every pixel is exact.
TEST(SpotLight, OverADiffusePlaneEveryPixelIsItsClosedForm) {
  const std::string obj = test::writePlaneObj("spot_plane.obj", 100);
  const double rho = 0.6;
  const DownSpot spot{Vec3(1, 4, 0), 1000, 30, 15};
  const std::string scene = R"({
    "camera": {"width": 64, "height": 48, "fov": 70, "position": [0, 6, 0],
               "look_at": [0, 0, 0.001], "up": [0, 0, -1], "spp": 4},
    "render": {"antialiasing": false, "max_depth": 1},
    "objects": [{"file": ")" +
                            obj + R"(", "color": )" + num(rho) + R"(}],
    "lights": [)" + spot.json() +
                            "]}";
  const SceneData data = test::loadTestScene(scene);
  const RenderResult r = renderCpu(data.view(), RenderOptions{});
  int inBeam = 0, between = 0, outside = 0;
  for (uint32_t y = 0; y < 48; ++y)
    for (uint32_t x = 0; x < 64; ++x) {
      const Vec3 at = planePointAt(data.camera, x, y);
      const double share = spot.falloff(at);
      (share == 1 ? inBeam : share > 0 ? between : outside) += 1;
      const double expected = spot.onPlane(rho, at);
      // Where the falloff slopes (1/15 of the share per degree), the float rounding of the hit
      // point and its angle (about 1e-6) moves it by a few millionths of the point light's value.
      EXPECT_NEAR(r.image.at(x, y).x, expected,
                  2e-4 * expected + 2e-5 * spot.pointLightOnPlane(rho, at))
          << x << "," << y;
    }
  EXPECT_GT(inBeam, 100);
  EXPECT_GT(between, 300);
  EXPECT_GT(outside, 300);
}

// A spot among point lights and a sphere light, one light picked per sample through the light
// tree, whose cones must not leave out the spot where it shines: the plane shows the sum.
TEST(SpotLight, AmongPickedLightsThePlaneShowsTheSum) {
  const std::string obj = test::writePlaneObj("spot_plane2.obj", 100);
  const double rho = 0.5;
  const DownSpot spot{Vec3(-1, 3, 1), 900, 40, 10};
  const DownSpot point{Vec3(3, 5, -1), 300, 180, 180};  // for its pointLightOnPlane
  const std::string scene = R"({
    "camera": {"width": 24, "height": 24, "fov": 50, "position": [0, 8, 0],
               "look_at": [0, 0, 0.001], "up": [0, 0, -1], "spp": 256},
    "render": {"max_depth": 1, "antialiasing": false},
    "objects": [{"file": ")" +
                            obj + R"(", "color": )" + num(rho) + R"(}],
    "lights": [)" + spot.json() +
                            R"(, {"position": [3, 5, -1], "intensity": 300},
               {"position": [-4, 6, 4], "intensity": 0}]})";
  const SceneData data = test::loadTestScene(scene);
  EXPECT_FALSE(data.view().loneDeltaLight);
  const RenderResult r = renderCpu(data.view(), RenderOptions{});
  ImageRGB ratios(24, 24);
  for (uint32_t y = 0; y < 24; ++y)
    for (uint32_t x = 0; x < 24; ++x) {
      const Vec3 at = planePointAt(data.camera, x, y);
      const double expected = spot.onPlane(rho, at) + point.pointLightOnPlane(rho, at);
      ratios.set(x, y, Vec3(float(r.image.at(x, y).x / expected)));
    }
  const test::RegionStats s = test::regionStats(ratios, 0, 0, 24, 24, 0);
  EXPECT_NEAR(s.mean, 1.0, kZ * s.standardError() + 1e-3);
}

// A spot shining up at the ceiling of a small room lights it all through that patch: light
// subpaths from the spot (its cone sampled, their MIS weights against next-event estimation)
// must give the image that paths without them give.
TEST(SpotLight, LightSubpathsFromASpotGiveTheImageOfPathsWithout) {
  const auto render = [](const char* lightPaths, uint32_t seed) {
    const std::string scene = R"({
      "camera": {"width": 32, "height": 32, "fov": 70, "position": [0, 2, 9],
                 "look_at": [0, 2, 0], "spp": 64},
      "render": {"max_depth": 4, "light_paths": ")" +
                              std::string(lightPaths) + R"(", "seed": )" + std::to_string(seed) +
                              R"(},
      "spheres": [)" + std::string(test::kSmallRoomWalls) +
                              R"(,
                  {"position": [1, 1, -1], "radius": 1, "color": 0.5}],
      "lights": [{"type": "spot", "position": [-2, 1, -2], "look_at": [-2.5, 6, -3],
                  "intensity": 400, "cutoff_angle": 35}]})";
    return test::renderTestScene(scene);
  };
  const test::SeedPair with{render("on", 1), render("on", 2)};
  const test::SeedPair without{render("off", 3), render("off", 4)};
  test::expectSameImage(with, without);
}

// The power that leaves the cone, the falloff's mean over the sphere, numerically.
TEST(SpotLight, ItsFluxShareIsTheFalloffsMeanOverTheSphere) {
  for (const auto& [beam, cutoff] :
       {std::pair<double, double>{15, 20}, {0, 30}, {30, 30}, {60, 120}, {10, 180}}) {
    SpotCone cone;
    cone.axis = Vec3(0, 0, 1);
    cone.cutoff = float(cutoff * kPi / 180);
    cone.cosCutoff = float(std::cos(cutoff * kPi / 180));
    cone.cosBeam = float(std::cos(beam * kPi / 180));
    cone.invTransition = cutoff > beam ? float(180 / (kPi * (cutoff - beam))) : 0.0f;
    double sum = 0;
    const int n = 20000;
    for (int i = 0; i < n; ++i) {  // midpoints in cos theta: uniform over the sphere
      const double c = 1 - 2 * (i + 0.5) / n;
      sum += coneFalloff(cone, Vec3(float(std::sqrt(1 - c * c)), 0.0f, float(c)));
    }
    EXPECT_NEAR(sum / n, coneFluxShare(beam * kPi / 180, cutoff * kPi / 180), 2e-4)
        << beam << " " << cutoff;
  }
}

// A look_at a hair from the spot (1e-30 along x) still aims it, along x: its axis is taken in
// double, where float's square of the offset would vanish and leave a NaN axis (a dark spot, and
// null in the poses file).
TEST(SpotLight, ALookAtAHairFromTheSpotStillAimsIt) {
  const SceneData data = test::loadTestScene(R"({"camera": {"width": 4, "height": 4},
    "lights": [{"type": "spot", "position": [0, 3, 0], "look_at": [1e-30, 3, 0],
                "intensity": 10}]})");
  const SpotCone& cone = data.lights[0].spot;
  EXPECT_EQ(cone.axis.x, 1.0f);
  EXPECT_EQ(cone.axis.y, 0.0f);
  EXPECT_EQ(cone.axis.z, 0.0f);
}

TEST(SpotLight, TheSceneFormatRefusesWhatASpotCannotBe) {
  const std::string at = R"("type": "spot", "position": [0, 2, 0], "intensity": 10)";
  EXPECT_EQ(
      lightsError("{" + at + "}"),
      "s.json: lights[0]: missing \"direction\" or \"look_at\" (where the spot light points)");
  EXPECT_EQ(lightsError("{" + at + R"(, "direction": [0, -1, 0], "look_at": [0, 0, 0]})"),
            "s.json: lights[0]: expected either \"direction\" or \"look_at\", got both");
  EXPECT_EQ(
      lightsError("{" + at + R"(, "direction": [0, 0, 0]})"),
      "s.json: lights[0].direction: expected a direction of non-zero length, got an array [0,0,0]");
  EXPECT_EQ(lightsError("{" + at + R"(, "look_at": [0, 2, 0]})"),
            "s.json: lights[0].look_at: the spot light looks at its own position");
  EXPECT_EQ(
      lightsError("{" + at + R"(, "direction": [0, -1, 0], "cutoff_angle": 0})"),
      "s.json: lights[0].cutoff_angle: expected an angle in degrees above 0, up to 180, got 0");
  EXPECT_EQ(
      lightsError("{" + at + R"(, "direction": [0, -1, 0], "cutoff_angle": 30, "beam_width": 45})"),
      "s.json: lights[0].beam_width: expected an angle in degrees from 0 to the "
      "cutoff_angle, 30, got 45");
  EXPECT_EQ(
      lightsError("{" + at + R"(, "direction": [0, -1, 0], "radius": 1})"),
      "s.json: lights[0].radius: not used by a spot light (only \"sphere\" lights have a radius)");
  EXPECT_EQ(lightsError(R"({"position": [0, 2, 0], "intensity": 10, "cutoff_angle": 30})"),
            "s.json: lights[0].cutoff_angle: not used by a point light (only \"spot\" lights have "
            "a cone)");
  EXPECT_EQ(lightsError("{" + at + R"(, "id": "lamp", "look_at": [0, 0, 0]})",
                        R"(, "animation": {"frames": 3, "tracks": [{"target": "lamp",
                       "property": "position", "keys": [[0, [0, 2, 0]], [2, [0, -2, 0]]]}]})"),
            "s.json: animation.tracks[0]: at frame 1 the spot light looks at its own position");
  // Under an open shutter, at every time of a frame's exposure too (the light is blurred).
  EXPECT_EQ(lightsError("{" + at + R"(, "id": "lamp", "look_at": [0, 0, 0]})",
                        R"(, "animation": {"frames": 2, "shutter": [0, 1], "tracks": [{"target":
                       "lamp", "property": "position", "keys": [[0, [0, 2, 0]], [1, [0, -2, 0]]]}]})"),
            "s.json: animation.tracks[0]: at time 0.5 (frame 0's exposure) the spot light looks at "
            "its own position");
  EXPECT_EQ(lightsError("{" + at + R"(, "id": "lamp", "direction": [0, -1, 0]})",
                        R"(, "animation": {"frames": 3, "tracks": [{"target": "lamp",
                       "property": "radius", "keys": [[0, 1]]}]})"),
            "s.json: animation.tracks[0].property: \"radius\" is not used by a spot light (only "
            "\"sphere\" lights have a radius)");
  // A spot light's beam defaults to three quarters of its cutoff.
  const SceneDesc s = parseSceneText(R"({"camera": {"width": 4, "height": 4}, "lights": [{)" + at +
                                         R"(, "direction": [0, -1, 0], "cutoff_angle": 40}]})",
                                     "s.json", ".");
  ASSERT_TRUE(s.lights[0].spot.has_value());
  EXPECT_EQ(s.lights[0].spot->beamDegrees, 30.0f);
}

}  // namespace
}  // namespace candela
