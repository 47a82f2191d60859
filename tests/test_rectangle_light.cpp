// Rectangle lights: a rectangle of uniform radiance P / (pi w h) that shines along its direction
// (Mitsuba 3's `rectangle` shape with an `area` emitter; Blender's and Kubric's rectangle area
// lights), or P / (2 pi w h) from both sides (pbrt-v4's two-sided diffuse area light). Against
// closed forms: the plane under one, pixel for pixel, is Lambert's irradiance of a polygon, also
// from a two-sided one's back; seen from the front it is its radiance, from behind black (or its
// radiance, two-sided); its corners follow its aim, up and size. Its pose and flow, its frames'
// changes, and the scene format's refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/constants.h"
#include "render/aov_layers.h"
#include "render_test_util.h"
#include "scene/animation.h"
#include "scene/flow_motion.h"
#include "scene/frame_scene.h"
#include "scene/instance_poses.h"
#include "scene/light_emission_desc.h"

namespace candela {
namespace {

using test::lightsError;
using test::num;

struct D3 {
  double x, y, z;
};
D3 operator-(const D3& a, const D3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
D3 operator+(const D3& a, const D3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
D3 operator*(double s, const D3& a) { return {s * a.x, s * a.y, s * a.z}; }
double dot(const D3& a, const D3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
D3 cross(const D3& a, const D3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
D3 unit(const D3& a) { return (1.0 / std::sqrt(dot(a, a))) * a; }
D3 d3(const Vec3& v) { return {v.x, v.y, v.z}; }

// A rectangle light as the test writes it, and its corners worked out apart from the renderer:
// the height along up made perpendicular to the normal, the width completing a right-handed frame.
struct Rect {
  D3 centre, direction, up;
  double width, height, power;
  bool twoSided = false;
  std::string json() const {
    return R"({"type": "rectangle", "position": [)" + num(centre.x) + ", " + num(centre.y) + ", " +
           num(centre.z) + R"(], "direction": [)" + num(direction.x) + ", " + num(direction.y) +
           ", " + num(direction.z) + R"(], "up": [)" + num(up.x) + ", " + num(up.y) + ", " +
           num(up.z) + R"(], "size": [)" + num(width) + ", " + num(height) + R"(], "intensity": )" +
           num(power) + (twoSided ? R"(, "two_sided": true})" : "}");
  }
  // Its power spread over one side, or over both.
  double radiance() const { return power / ((twoSided ? 2 : 1) * kPi * width * height); }
  void corners(D3 out[4]) const {
    const D3 n = unit(direction);
    const D3 v = unit(up - dot(up, n) * n), u = cross(v, n);
    const double signs[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (int k = 0; k < 4; ++k)
      out[k] = centre + (signs[k][0] * width / 2) * u + (signs[k][1] * height / 2) * v;
  }
  // Lambert's irradiance at x, facing +y, from the rectangle (all of it above x's horizon):
  // L / 2 times the sum over its edges of the angle each subtends times the cosine of its
  // plane's normal with +y.
  double irradianceAt(const D3& x) const {
    D3 c[4];
    corners(c);
    double sum = 0;
    for (int k = 0; k < 4; ++k) {
      const D3 a = unit(c[k] - x), b = unit(c[(k + 1) % 4] - x);
      sum += std::acos(std::min(1.0, dot(a, b))) * unit(cross(a, b)).y;
    }
    return radiance() * std::fabs(sum) / 2;
  }
};

// The slanted rectangle of unequal sides that lights the plane below it.
const Rect kOverThePlane{{0.3, 1.4, -0.2}, {0.3, -1, 0.2}, {1, 0.2, 0.4}, 2.4, 0.5, 40};

// The plane y = 0 seen from above through pixel centres, lit only by `rect` above it, one bounce:
// every pixel is rho E / pi, E by Lambert's formula, within the noise of two seeds (light paths
// on or off, one light sample at the first hit or more: the estimate is the same, only its noise
// differs).
void expectPlaneUnderTheRectangle(const std::string& lightPaths, const Rect& rect = kOverThePlane,
                                  int firstHitLightSamples = 1) {
  const std::string obj = test::writePlaneObj("rectangle_plane.obj", 100);
  const double rho = 0.7;
  const std::string scene = R"({
    "camera": {"width": 48, "height": 32, "fov": 100, "position": [0, 1, 0],
               "look_at": [0, 0, 0.001], "up": [0, 0, -1], "spp": 64},
    "render": {"antialiasing": false, "max_depth": 2, "light_paths": ")" +
                            lightPaths + R"(", "seed": SEED, "first_hit_light_samples": )" +
                            std::to_string(firstHitLightSamples) + R"(},
    "objects": [{"file": ")" +
                            obj + R"(", "color": )" + num(rho) +
                            R"(}],
    "lights": [)" + rect.json() +
                            "]}";
  const auto withSeed = [&](int seed) {
    std::string text = scene;
    return text.replace(text.find("SEED"), 4, std::to_string(seed));
  };
  const RenderResult a = test::renderTestScene(withSeed(1)), b = test::renderTestScene(withSeed(2));
  const Camera camera = test::loadTestScene(withSeed(1)).camera;
  double noise2 = 0, sumRatio = 0, worst = 0, least = 1e30, most = 0;
  const uint32_t pixels = 48 * 32;
  std::vector<double> ratios;
  for (uint32_t y = 0; y < 32; ++y)
    for (uint32_t x = 0; x < 48; ++x) {
      const Vec3 d = camera.cameraToWorld * (camera.inverseK * Vec3(x + 0.5f, y + 0.5f, 1.0f));
      const double t = -double(camera.position.y) / d.y;
      const D3 at{camera.position.x + t * d.x, 0.0, camera.position.z + t * d.z};
      const double expected = rho * rect.irradianceAt(at) / kPi;
      least = std::min(least, expected);
      most = std::max(most, expected);
      const double va = a.image.at(x, y).x, vb = b.image.at(x, y).x;
      noise2 += (va - vb) * (va - vb) / 4 / (expected * expected);
      ratios.push_back((va + vb) / 2 / expected);
      sumRatio += ratios.back();
    }
  const double noise = std::sqrt(noise2 / pixels);  // of a pixel's two-seed mean, relative
  EXPECT_LT(noise, 0.02);
  EXPECT_GT(most / least, 3.0);  // the irradiance varies over the view: the test can see a shift
  for (double r : ratios) worst = std::max(worst, std::fabs(r - 1));
  EXPECT_LT(worst, 7 * noise) << "noise " << noise;
  EXPECT_NEAR(sumRatio / pixels, 1.0, 4 * noise / std::sqrt(double(pixels)) + 1e-5);
}

TEST(RectangleLight, ThePlaneUnderItIsLambertsIrradianceOfAPolygon) {
  expectPlaneUnderTheRectangle("off");
}

TEST(RectangleLight, ThePlaneUnderItIsTheSameWithLightPaths) { expectPlaneUnderTheRectangle("on"); }

// Four light samples at the first hit, each weighed as one of four against the BSDF's sample
// that finds the rectangle (render.first_hit_light_samples): weighed as one, the plane would be
// several percent too bright near the light.
TEST(RectangleLight, ThePlaneUnderItIsTheSameWithFourLightSamplesAtTheFirstHit) {
  expectPlaneUnderTheRectangle("off", kOverThePlane, 4);
  expectPlaneUnderTheRectangle("on", kOverThePlane, 4);
}

// Turned to shine up, away from the plane, a two-sided rectangle lights the plane from its back
// with half its power: every pixel is rho E / pi for the radiance P / (2 pi w h), with and without
// light subpaths (which start from either side).
TEST(RectangleLight, TwoSidedItLightsThePlaneFromItsBackWithHalfItsPower) {
  Rect turned = kOverThePlane;
  turned.direction = -1.0 * turned.direction;
  turned.twoSided = true;
  expectPlaneUnderTheRectangle("off", turned);
  expectPlaneUnderTheRectangle("on", turned);
}

// A camera facing a rectangle 2 wide and 1 high at the origin, through pixel centres: from its
// front (it shines along +z) every pixel within it is its radiance and of its instance, every
// pixel beside it black; from behind it is black before a grey environment, or, two-sided, its
// radiance (half the one-sided one's) again.
void expectRectangleSeenFromBothSides(bool twoSided) {
  const double power = 30;
  const std::string light = R"({"type": "rectangle", "position": [0, 0, 0], "direction": [0, 0, 1],
                                "size": [2, 1], "two_sided": )" +
                            std::string(twoSided ? "true" : "false") + R"(, "intensity": )" +
                            num(power) + "}";
  const auto scene = [&](double cameraZ) {
    return R"({"camera": {"width": 40, "height": 30, "fov": 40, "position": [0, 0, )" +
           num(cameraZ) + R"(], "look_at": [0, 0, 0], "spp": 2},
               "render": {"antialiasing": false, "max_depth": 1},
               "environment": {"color": )" +
           num(cameraZ < 0 ? 0.25 : 0) + R"(},
               "lights": [)" +
           light + "]}";
  };
  const double radiance = power / ((twoSided ? 2 : 1) * kPi * 2 * 1);
  for (const double cameraZ : {5.0, -5.0}) {
    const bool seen = cameraZ > 0 || twoSided;
    const SceneData data = test::loadTestScene(scene(cameraZ));
    RenderOptions options;
    options.aovs = true;
    const RenderResult r = renderCpu(data.view(), options);
    const std::vector<ImageLayer> layers = makeAovLayers(data, parseAovList("instance"), r.aovs);
    ASSERT_EQ(layers.size(), 1u);
    int inside = 0, outside = 0;
    for (uint32_t y = 0; y < 30; ++y)
      for (uint32_t x = 0; x < 40; ++x) {
        const Camera& c = data.camera;
        const Vec3 d = c.cameraToWorld * (c.inverseK * Vec3(x + 0.5f, y + 0.5f, 1.0f));
        const double t = -double(c.position.z) / d.z;
        const double hx = c.position.x + t * d.x, hy = c.position.y + t * d.y;
        const double margin = std::min(1 - std::fabs(hx), 0.5 - std::fabs(hy));
        if (std::fabs(margin) < 0.01) continue;
        const float value = r.image.at(x, y).y;
        const float instance = layers[0].pixels[size_t(y) * 40 + x];
        if (margin > 0) {
          ++inside;
          EXPECT_NEAR(value, seen ? radiance : 0.0, 1e-6 * radiance) << x << "," << y;
          EXPECT_EQ(instance, 1.0f) << x << "," << y;  // lights[0], the scene's only instance
        } else {
          ++outside;
          EXPECT_EQ(value, cameraZ > 0 ? 0.0f : 0.25f) << x << "," << y;
          EXPECT_EQ(instance, 0.0f) << x << "," << y;
        }
      }
    EXPECT_GT(inside, 200);
    EXPECT_GT(outside, 200);
  }
}

TEST(RectangleLight, SeenFromTheFrontItIsItsRadianceFromBehindBlack) {
  expectRectangleSeenFromBothSides(false);
}

TEST(RectangleLight, TwoSidedItIsItsRadianceSeenFromEitherSide) {
  expectRectangleSeenFromBothSides(true);
}

// Its corners as flattening places them: the width across and the height along up made
// perpendicular to where it shines (by default y, or z where it shines along y), the faces
// turned towards where it shines; a look_at aims it as a direction does.
TEST(RectangleLight, ItsCornersFollowItsAimUpAndSize) {
  const auto corners = [](const std::string& light) {
    const SceneData data =
        test::loadTestScene(R"({"camera": {"width": 4, "height": 4}, "lights": [)" + light + "]}");
    EXPECT_EQ(data.positions.size(), 4u);
    EXPECT_EQ(data.triangles.size(), 2u);
    EXPECT_EQ(data.lights.size(), 2u);  // its two triangles
    return data;
  };
  const auto expectCorners = [](const SceneData& data, const Rect& rect) {
    D3 expected[4];
    rect.corners(expected);
    for (const D3& e : expected) {
      double nearest = 1e30;
      for (const Vec3& p : data.positions) {
        const D3 d = d3(p) - e;
        nearest = std::min(nearest, std::sqrt(dot(d, d)));
      }
      EXPECT_LT(nearest, 1e-6) << e.x << " " << e.y << " " << e.z;
    }
    const D3 n = unit(rect.direction);
    for (const Triangle& t : data.triangles) {
      const D3 p0 = d3(data.positions[t.v[0]]);
      const D3 face = unit(cross(d3(data.positions[t.v[1]]) - p0, d3(data.positions[t.v[2]]) - p0));
      EXPECT_NEAR(dot(face, n), 1.0, 1e-6);
    }
  };
  const Rect slanted{{1, 2, 3}, {0.3, -1, 0.2}, {1, 0.2, 0.4}, 2.4, 0.5, 10};
  expectCorners(corners(slanted.json()), slanted);
  // Default up: y; shining along y, z.
  expectCorners(corners(R"({"type": "rectangle", "position": [1, 2, 3], "direction": [1, 0, 0],
                            "size": [3, 1], "intensity": 1})"),
                Rect{{1, 2, 3}, {1, 0, 0}, {0, 1, 0}, 3, 1, 1});
  expectCorners(corners(R"({"type": "rectangle", "position": [1, 2, 3], "direction": [0, -2, 0],
                            "size": [3, 1], "intensity": 1})"),
                Rect{{1, 2, 3}, {0, -1, 0}, {0, 0, 1}, 3, 1, 1});
  expectCorners(corners(R"({"type": "rectangle", "position": [1, 2, 3], "look_at": [4, 2, 7],
                            "size": 2, "intensity": 1})"),
                Rect{{1, 2, 3}, {3, 0, 4}, {0, 1, 0}, 2, 2, 1});
}

// Its pose (docs/aovs.md): the unit square of the model's xy plane, scaled to its size, turned to
// its axes and placed at its centre.
TEST(RectangleLight, ItsPoseIsTheUnitSquareTurnedScaledAndPlaced) {
  const Rect rect{{1, 2, 3}, {0.3, -1, 0.2}, {1, 0.2, 0.4}, 2.4, 0.5, 10};
  const SceneDesc desc = parseSceneText(
      R"({"camera": {"width": 4, "height": 4}, "lights": [)" + rect.json() + "]}", "s.json", ".");
  const std::vector<InstancePose> poses = instancePoses(desc);
  ASSERT_EQ(poses.size(), 1u);
  D3 corners[4];
  rect.corners(corners);
  const double model[4][2] = {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};
  for (int k = 0; k < 4; ++k) {
    const Vec3 placed =
        poses[0].linear * Vec3(float(model[k][0]), float(model[k][1]), 0.0f) + poses[0].position;
    const D3 d = d3(placed) - corners[k];
    EXPECT_LT(std::sqrt(dot(d, d)), 1e-6) << k;
  }
  const D3 z = unit(d3(poses[0].linear.column(2)));
  EXPECT_NEAR(dot(z, unit(rect.direction)), 1.0, 1e-6);  // the model's +z: where it shines
}

// The flow pass carries each point of a rectangle light by its motion: its corners at one frame
// go to its corners at the next, as it moves, turns, tilts its up and grows.
TEST(RectangleLight, ItsFlowMotionCarriesItsCornersToTheNextFrame) {
  const SceneDesc desc = parseSceneText(R"({
    "camera": {"width": 4, "height": 4},
    "lights": [{"type": "rectangle", "id": "panel", "position": [0, 3, 0], "direction": [0, -1, 0],
                "size": [2, 1], "intensity": 10}],
    "animation": {"frames": 2, "tracks": [
      {"target": "panel", "property": "position", "keys": [[0, [0, 3, 0]], [1, [1, 2.5, -1]]]},
      {"target": "panel", "property": "direction", "keys": [[0, [0, -1, 0]], [1, [0.5, -1, 0.3]]]},
      {"target": "panel", "property": "up", "keys": [[0, [0, 0, 1]], [1, [0.2, 0, 1]]]},
      {"target": "panel", "property": "size", "keys": [[0, [2, 1]], [1, [3, 0.5]]]}]}})",
                                        "s.json", ".");
  const SceneDesc now = sceneAtFrame(desc, 0), next = sceneAtFrame(desc, 1);
  const FlowMotion flow = flowMotion(now, next);
  const uint32_t number = instanceNumbering(desc).firstLight;
  ASSERT_LT(number, flow.instances.size());
  const InstanceMotion& m = flow.instances[number];
  const Rect before{{0, 3, 0}, {0, -1, 0}, {0, 0, 1}, 2, 1, 10};
  const Rect after{{1, 2.5, -1}, {0.5, -1, 0.3}, {0.2, 0, 1}, 3, 0.5, 10};
  D3 from[4], to[4];
  before.corners(from);
  after.corners(to);
  for (int k = 0; k < 4; ++k) {
    const Vec3 moved =
        m.linear * Vec3(float(from[k].x), float(from[k].y), float(from[k].z)) + m.offset;
    const D3 d = d3(moved) - to[k];
    EXPECT_LT(std::sqrt(dot(d, d)), 1e-5) << k;
  }
}

// A frame where only its intensity changes keeps the geometry (values); one where it moves refits
// the BVH over its two triangles (motion); each frame is the scene flattened afresh.
TEST(RectangleLight, ItsFramesRefitWhenItMovesAndKeepTheGeometryWhenItBrightens) {
  const SceneDesc desc = parseSceneText(R"({
    "camera": {"width": 4, "height": 4},
    "spheres": [{"position": [0, 0, 0], "radius": 1}],
    "lights": [{"type": "rectangle", "id": "panel", "position": [0, 3, 0], "direction": [0, -1, 0],
                "size": [2, 1], "intensity": 10}],
    "animation": {"frames": 3, "tracks": [
      {"target": "panel", "property": "intensity", "keys": [[0, 10], [1, 20]]},
      {"target": "panel", "property": "size", "keys": [[1, [2, 1]], [2, [2, 3]]]}]}})",
                                        "s.json", ".");
  FrameScene frames;
  const SceneChange expected[3] = {SceneChange::Structure, SceneChange::Values,
                                   SceneChange::Motion};
  for (uint32_t f = 0; f < 3; ++f) {
    const SceneDesc still = sceneAtFrame(desc, f);
    const SceneData& data = frames.prepare(still);
    EXPECT_EQ(frames.change(), expected[f]) << f;
    const SceneData fresh = flattenScene(still);
    ASSERT_EQ(data.positions.size(), fresh.positions.size());
    for (size_t i = 0; i < data.positions.size(); ++i)
      for (int k = 0; k < 3; ++k) EXPECT_EQ(data.positions[i][k], fresh.positions[i][k]) << f;
    ASSERT_EQ(data.lights.size(), 2u);
    const Vec3 radiance = data.materials[data.triangles[0].material].radiance;
    const Vec3 freshRadiance = fresh.materials[fresh.triangles[0].material].radiance;
    for (int k = 0; k < 3; ++k) EXPECT_EQ(radiance[k], freshRadiance[k]) << f;
  }
}

TEST(RectangleLight, TheSceneFormatRefusesWhatItCannotBe) {
  const std::string at = R"("type": "rectangle", "position": [0, 2, 0], "intensity": 10)";
  EXPECT_EQ(lightsError("{" + at + R"(, "direction": [0, -1, 0]})"),
            "s.json: lights[0]: missing required key \"size\"");
  EXPECT_EQ(lightsError("{" + at + R"(, "size": 1})"),
            "s.json: lights[0]: missing \"direction\" or \"look_at\" (where the rectangle light "
            "points)");
  EXPECT_EQ(lightsError("{" + at + R"(, "direction": [0, -1, 0], "size": 0})"),
            "s.json: lights[0].size: expected a positive number, got 0");
  EXPECT_EQ(lightsError("{" + at + R"(, "direction": [0, -1, 0], "size": [1, -2]})"),
            "s.json: lights[0].size[1]: expected a positive number, got -2");
  EXPECT_EQ(lightsError("{" + at + R"(, "direction": [0, -1, 0], "size": [1, 2, 3]})"),
            "s.json: lights[0].size: expected a positive number or [width, height], each "
            "positive, got an array [1,2,3]");
  EXPECT_EQ(lightsError("{" + at + R"(, "direction": [0, -1, 0], "size": 1, "up": [0, 2, 0]})"),
            "s.json: lights[0].up: expected a direction that is not parallel to where the light "
            "points, got an array [0,2,0]");
  EXPECT_EQ(lightsError("{" + at + R"(, "look_at": [0, 2, 0], "size": 1})"),
            "s.json: lights[0].look_at: the rectangle light looks at its own position");
  EXPECT_EQ(lightsError("{" + at + R"(, "direction": [0, -1, 0], "size": 1, "radius": 1})"),
            "s.json: lights[0].radius: not used by a rectangle light (only \"sphere\" lights have "
            "a radius)");
  EXPECT_EQ(lightsError("{" + at + R"(, "direction": [0, -1, 0], "size": 1, "cutoff_angle": 9})"),
            "s.json: lights[0].cutoff_angle: not used by a rectangle light (only \"spot\" lights "
            "have a cone)");
  EXPECT_EQ(lightsError(R"({"position": [0, 2, 0], "intensity": 10, "size": 1})"),
            "s.json: lights[0].size: not used by a point light (only \"rectangle\" lights have a "
            "size)");
  EXPECT_EQ(lightsError("{" + at + R"(, "direction": [0, -1, 0], "size": 1, "two_sided": 1})"),
            "s.json: lights[0].two_sided: expected true or false, got 1");
  EXPECT_EQ(lightsError(R"({"position": [0, 2, 0], "intensity": 10, "two_sided": true})"),
            "s.json: lights[0].two_sided: not used by a point light (only \"rectangle\" lights "
            "have two sides)");
  EXPECT_EQ(lightsError(R"({"position": [0, 2, 0], "intensity": 10, "look_at": [0, 0, 0]})"),
            "s.json: lights[0].look_at: not used by a point light (only \"spot\" and "
            "\"rectangle\" lights, and point lights with a \"profile\", point at a place)");
  EXPECT_EQ(lightsError(R"({"type": "directional", "intensity": 10, "look_at": [0, 0, 0]})"),
            "s.json: lights[0].look_at: not used by a directional light (it shines along its "
            "\"direction\", from infinitely far)");
  EXPECT_EQ(lightsError("{" + at.substr(0, at.size() - 2) +
                        R"(1e30, "direction": [0, -1, 0], "size": 1e-10})"),
            "s.json: lights[0]: its surface's radiance, intensity 1e+30 times color [1, 1, 1] "
            "over a rectangle of 1e-10 by 1e-10, is beyond single precision; expected a larger "
            "size or a smaller intensity");
  EXPECT_EQ(lightsError(R"({"type": "rectangle", "position": [0, 2, 0], "intensity": 10,
                           "direction": [0, -1, 0], "size": 1e30})"),
            "s.json: lights[0]: the light reaches 7.07107e+29 from the origin; expected geometry "
            "within 1e+18 (single precision cannot intersect it further out)");

  const std::string panel = "{" + at + R"(, "id": "panel", "direction": [0, -1, 0], "size": 1})";
  const auto animated = [](const std::string& property, const std::string& keys) {
    return test::oneTrack("panel", property, keys);
  };
  EXPECT_EQ(lightsError(panel, animated("up", "[[0, [1, 0, 0]], [2, [-1, -2, 0]]]")),
            "s.json: animation.tracks[0]: at frame 1 the rectangle light points along its up");
  EXPECT_EQ(lightsError(panel, animated("size", "[[0, [1, 0]]]")),
            "s.json: animation.tracks[0].keys[0][1][1]: expected a positive number, got 0");
  EXPECT_EQ(lightsError(R"({"id": "panel", "position": [0, 2, 0], "intensity": 10})",
                        animated("size", "[[0, 1]]")),
            "s.json: animation.tracks[0].property: \"size\" is not used by a point light (only "
            "\"rectangle\" lights have a size and an up)");
}

}  // namespace
}  // namespace candela
