// Light profiles from IES files (scene/read/ies_profile.h, render/light_profile.h): the LM-63
// reader and its symmetries, its refusals with the file's line, and lights that shine as their
// profile says: a diffuse plane under a profiled light, held pixel by pixel against the closed
// form (the profile's piecewise-linear intensity, normalised by the test's own integral, over
// the squared distance), in every C-plane for a profile that varies around its axis and for an
// `up` that turns it; and a room lit by one, whose light subpaths weigh their directions by the
// profile (the same image with them as without).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "render/aov_layers.h"
#include "render_test_util.h"
#include "scene/animation.h"
#include "scene/read/ies_profile.h"
#include "shading_normal_test_util.h"

namespace candela {
namespace {

namespace fs = std::filesystem;
using test::num;

// An IES file of type C photometry with the given angles and candela values (one run of
// vertical values per horizontal angle), spread over lines as exporters do.
std::string iesText(const std::vector<double>& vertical, const std::vector<double>& horizontal,
                    const std::vector<double>& candela, double multiplier = 1) {
  std::string t = "IESNA:LM-63-2002\n[TEST] candela\n[MANUFAC] none\nTILT=NONE\n";
  t += "1 1000 " + num(multiplier) + " " + std::to_string(vertical.size()) + " " +
       std::to_string(horizontal.size()) + " 1 2 0 0 0\n1 1 100\n";
  for (double v : vertical) t += num(v) + " ";
  t += "\n";
  for (double h : horizontal) t += num(h) + ", ";
  t += "\n";
  for (size_t i = 0; i < candela.size(); ++i) t += num(candela[i]) + (i % 5 == 4 ? "\n" : " ");
  return t + "\n";
}

fs::path writeIes(const fs::path& dir, const std::string& name, const std::string& text) {
  std::ofstream(dir / name) << text;
  return dir / name;
}

TEST(LightProfile, ReadsAnIesFileAndUnfoldsItsSymmetry) {
  const fs::path dir = test::mapTestFolder("profile_read");
  // Axial: one plane; the multiplier scales every value.
  IesProfile axial = readIesProfile(
      writeIes(dir, "axial.ies", iesText({0, 60, 120, 180}, {0}, {2, 2, 0, 0}, 3)).string(), "a");
  EXPECT_DOUBLE_EQ(iesValue(axial, 30, 0), 6);
  EXPECT_DOUBLE_EQ(iesValue(axial, 90, 123), 3);
  EXPECT_DOUBLE_EQ(iesValue(axial, 150, 7), 0);
  // A downlight's range, 0 to 90: nothing above it.
  IesProfile down =
      readIesProfile(writeIes(dir, "down.ies", iesText({0, 90}, {0}, {4, 2})).string(), "d");
  EXPECT_DOUBLE_EQ(iesValue(down, 45, 0), 3);
  EXPECT_DOUBLE_EQ(iesValue(down, 91, 0), 0);
  // Quadrant symmetry (0 to 90): phi folds into [0, 90] about both planes.
  IesProfile quadrant = readIesProfile(
      writeIes(dir, "q.ies", iesText({0, 180}, {0, 90}, {1, 1, 3, 3})).string(), "q");
  EXPECT_DOUBLE_EQ(iesValue(quadrant, 10, 45), 2);
  EXPECT_DOUBLE_EQ(iesValue(quadrant, 10, 135), 2);
  EXPECT_DOUBLE_EQ(iesValue(quadrant, 10, 180), 1);
  EXPECT_DOUBLE_EQ(iesValue(quadrant, 10, 270), 3);
  EXPECT_DOUBLE_EQ(iesValue(quadrant, 10, 330), 1.0 + 2.0 * 30 / 90);
  // Bilateral (0 to 180): mirrored about the 0-180 plane.
  IesProfile bilateral = readIesProfile(
      writeIes(dir, "b.ies", iesText({0, 180}, {0, 90, 180}, {1, 1, 2, 2, 4, 4})).string(), "b");
  EXPECT_DOUBLE_EQ(iesValue(bilateral, 5, 270), 2);
  EXPECT_DOUBLE_EQ(iesValue(bilateral, 5, 225), 3);
  // Bilateral about the 90-270 plane.
  IesProfile across = readIesProfile(
      writeIes(dir, "c.ies", iesText({0, 180}, {90, 180, 270}, {1, 1, 2, 2, 4, 4})).string(), "c");
  EXPECT_DOUBLE_EQ(iesValue(across, 5, 0), 2);
  EXPECT_DOUBLE_EQ(iesValue(across, 5, 45), 1.5);
  EXPECT_DOUBLE_EQ(iesValue(across, 5, 315), 3);
  // Full (0 to 360).
  IesProfile full = readIesProfile(
      writeIes(dir, "f.ies", iesText({0, 180}, {0, 180, 360}, {1, 1, 5, 5, 1, 1})).string(), "f");
  EXPECT_DOUBLE_EQ(iesValue(full, 5, 90), 3);
  EXPECT_DOUBLE_EQ(iesValue(full, 5, 270), 3);
  // The texture's rows and columns sample those values; its mean is the sphere's.
  const TextureDesc t = profileTexture(quadrant, "q.ies");
  ASSERT_EQ(t.width, kProfileColumns);
  ASSERT_EQ(t.height, kProfileRows);
  EXPECT_FLOAT_EQ(t.texelsF[4 * (10 * t.width + 36)], 1.0f);  // phi 90: 3, the largest
  EXPECT_FLOAT_EQ(t.texelsF[4 * (10 * t.width + 0)], 1.0f / 3);
  EXPECT_EQ(profileTexture(axial, "a.ies").width, 1u);
  // The mean of 1/3 + 2/3 sin^2(phi)... is that of its average over phi, 2/3.
  EXPECT_NEAR(profileTextureMean(t, 0, 180), 2.0 / 3, 1e-4);
  // The downlight's, over its lower half alone: 1 - theta / pi relative to its largest value
  // (4 at the nadir, 2 at 90 degrees), whose mean over the sphere is (1 - 1 / pi) / 2.
  EXPECT_NEAR(profileTextureMean(profileTexture(down, "d.ies"), 0, 90), 0.5 * (1 - 1 / kPi), 1e-5);
}

std::string iesError(const std::string& text) {
  const fs::path dir = test::mapTestFolder("profile_errors");
  try {
    readIesProfile(writeIes(dir, "bad.ies", text).string(), "bad.ies");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(LightProfile, RefusesWhatIsNotATypeCFileWithItsLine) {
  EXPECT_EQ(iesError("IESNA:LM-63-2002\n1 2 3\n"),
            "bad.ies: no TILT line; expected an IES (LM-63) photometric file");
  EXPECT_EQ(iesError("IESNA:LM-63-2002\nTILT=INCLUDE\n"),
            "bad.ies:2: expected TILT=NONE (a lamp whose output does not change with its tilt), "
            "got \"TILT=INCLUDE\"");
  const std::string good = iesText({0, 90}, {0}, {1, 1});
  std::string typeB = good;
  typeB.replace(typeB.find(" 1 2 0 0 0"), 10, " 2 2 0 0 0");
  EXPECT_EQ(iesError(typeB),
            "bad.ies:5: expected photometric type 1 (type C, as luminaires are measured), got 2");
  EXPECT_EQ(iesError(good.substr(0, good.rfind("1 1"))),
            "bad.ies:9: the file ends where a candela value was expected");
  EXPECT_EQ(iesError(iesText({0, 90}, {0}, {1, -1})),
            "bad.ies:9: expected non-negative candela values, got -1");
  EXPECT_EQ(iesError(iesText({0, 90}, {0}, {0, 0})),
            "bad.ies:9: every candela value is 0; expected a lamp that emits");
  EXPECT_EQ(iesError(iesText({0, 60, 50, 90}, {0}, {1, 1, 1, 1})),
            "bad.ies:7: expected vertical angles in increasing order, got 50 after 60");
  EXPECT_EQ(iesError(iesText({10, 90}, {0}, {1, 1})),
            "bad.ies:7: expected vertical angles from 0 or 90 to 90 or 180 degrees, got 10 to "
            "90");
  EXPECT_EQ(iesError(iesText({0, 90}, {0, 45}, {1, 1, 1, 1})),
            "bad.ies:8: expected horizontal angles 0 alone, or from 0 to 90, 180 or 360, or from "
            "90 to 270 degrees, got 0 to 45");
  std::string word = good;
  word.replace(word.find("1 1 100"), 7, "1 x 100");
  EXPECT_EQ(iesError(word), "bad.ies:6: expected the ballast-lamp factor, got \"x\"");
}

// The profile of `text` as an analytic function of (theta, phi) in degrees: the test's own.
using Profile = std::function<double(double, double)>;

// Its integral over the sphere, by the midpoint rule on a fine grid.
double integral(const Profile& profile) {
  const int rows = 3600, columns = 720;
  double sum = 0;
  for (int j = 0; j < rows; ++j) {
    const double theta = (j + 0.5) * 180.0 / rows;
    double ring = 0;
    for (int i = 0; i < columns; ++i) ring += profile(theta, (i + 0.5) * 360.0 / columns);
    sum += ring / columns * std::sin(theta * kPi / 180) * (kPi / rows) * 2 * kPi;
  }
  return sum;
}

// The plane of writeMappedPlane (diffuse, albedo 0.5) seen from above through 24 x 16 pixel
// centres, lit only by a light of power 40 one unit above its centre with the profile `file` and
// the JSON `more` fields: each pixel against rho / pi * 40 * I / total * cos / r^2 (total the
// integral of I over the sphere, or of the profile a spot's cone limits), with d from the light
// to the pixel's point, (theta, phi) the angles from the light's axis (straight
// down) and its C0 plane `c0` towards `c90`.
void expectLitAsTheProfileSays(const fs::path& dir, const std::string& file,
                               const std::string& more, const Profile& profile, const DVec3& c0,
                               const DVec3& c90, double total) {
  test::writeMappedPlane(dir / "plane.obj");
  const std::string json = R"({
    "camera": {"width": 24, "height": 16, "fov": 100, "position": [0, 3, 0],
               "look_at": [0, 0, 0.001], "up": [0, 0, -1], "spp": 1},
    "render": {"antialiasing": false, "max_depth": 1},
    "objects": [{"file": "plane.obj", "material": {"type": "diffuse", "color": 0.5}}],
    "lights": [{"position": [0, 1, 0], "intensity": 40, "profile": ")" +
                           file + "\"" + more + "}]}";
  SceneData data = test::loadTestScene(json, dir.string());
  RenderOptions options;
  options.aovs = true;
  const RenderResult rendered = renderCpu(data.view(), options);
  const std::vector<ImageLayer> layers =
      makeAovLayers(data, parseAovList("position"), rendered.aovs);
  ASSERT_EQ(layers.size(), 1u);
  int lit = 0, dark = 0;
  for (uint32_t y = 0; y < 16; ++y)
    for (uint32_t x = 0; x < 24; ++x) {
      const float* p = &layers[0].pixels[3 * (y * 24 + x)];
      const DVec3 d{p[0], p[1] - 1.0, p[2]};  // from the light
      const double r2 = dot(d, d), r = std::sqrt(r2);
      const double theta = std::acos(-d.y / r) * 180 / kPi;
      double phi = std::atan2(dot(d, c90), dot(d, c0)) * 180 / kPi;
      if (phi < 0) phi += 360;
      const double expected = 0.5 / kPi * 40 * profile(theta, phi) / total * (1.0 / r) / r2;
      const double got = rendered.image.at(x, y).x;
      ASSERT_NEAR(got, expected, 2e-3 * expected + 1e-7)
          << "pixel " << x << "," << y << " theta " << theta << " phi " << phi;
      (expected > 1e-6 ? lit : dark)++;
    }
  EXPECT_GT(lit, 40);
}

// Linear between (a, va) and (b, vb) at x.
double lerp(double x, double a, double va, double b, double vb) {
  return va + (x - a) / (b - a) * (vb - va);
}

// An axial profile, 2 up to 60 degrees from the nadir, falling linearly to 0 at 120 (the plane's
// far pixels lie beyond 60), seen over the whole of it.
TEST(LightProfile, APlaneIsLitAsAnAxialProfileSays) {
  const fs::path dir = test::mapTestFolder("profile_axial");
  writeIes(dir, "spread.ies", iesText({0, 60, 120, 180}, {0}, {2, 2, 0, 0}));
  const Profile profile = [](double theta, double) {
    return theta <= 60 ? 2.0 : theta <= 120 ? lerp(theta, 60, 2, 120, 0) : 0.0;
  };
  expectLitAsTheProfileSays(dir, "spread.ies", "", profile, {0, 0, 1}, {1, 0, 0},
                            integral(profile));
}

// A profile that varies around its axis, 4 in its C0 plane, 3 at C90, 1 at C180, 1.5 at C270
// (linear between; mirrored, it would differ): by default C0 faces +z and C90 +x for a light
// pointing down (counter-clockwise seen from above, the IES convention); with "up": [1, 0, 0] C0
// faces +x and C90 -z.
TEST(LightProfile, CPlanesTurnCounterClockwiseFromUp) {
  const fs::path dir = test::mapTestFolder("profile_planes");
  writeIes(dir, "planes.ies",
           iesText({0, 90}, {0, 90, 180, 270, 360}, {4, 4, 3, 3, 1, 1, 1.5, 1.5, 4, 4}));
  const Profile profile = [](double theta, double phi) {
    if (theta > 90) return 0.0;
    if (phi <= 90) return lerp(phi, 0, 4, 90, 3);
    if (phi <= 180) return lerp(phi, 90, 3, 180, 1);
    if (phi <= 270) return lerp(phi, 180, 1, 270, 1.5);
    return lerp(phi, 270, 1.5, 360, 4);
  };
  const double total = integral(profile);
  expectLitAsTheProfileSays(dir, "planes.ies", "", profile, {0, 0, 1}, {1, 0, 0}, total);
  expectLitAsTheProfileSays(dir, "planes.ies", R"(, "up": [1, 0, 0])", profile, {1, 0, 0},
                            {0, 0, -1}, total);
}

// A spot takes a profile too, its cone's falloff times the profile's, about the same axis.
TEST(LightProfile, ASpotsConeAndProfileMultiply) {
  const fs::path dir = test::mapTestFolder("profile_spot");
  writeIes(dir, "spread.ies", iesText({0, 60, 120, 180}, {0}, {2, 2, 0, 0}));
  // Cone: full within 30 degrees, nothing beyond 50, linear in the angle between.
  const Profile profile = [](double theta, double) {
    const double ies = theta <= 60 ? 2.0 : theta <= 120 ? lerp(theta, 60, 2, 120, 0) : 0.0;
    return ies * (theta <= 30 ? 1.0 : theta >= 50 ? 0.0 : (50 - theta) / 20);
  };
  // The power is that of the point light the spot limits: the profile alone is normalised.
  const Profile alone = [](double theta, double) {
    return theta <= 60 ? 2.0 : theta <= 120 ? lerp(theta, 60, 2, 120, 0) : 0.0;
  };
  expectLitAsTheProfileSays(dir, "spread.ies",
                            R"(, "type": "spot", "direction": [0, -1, 0], "cutoff_angle": 50,
                               "beam_width": 30)",
                            profile, {0, 0, 1}, {1, 0, 0}, integral(alone));
}

// A room lit by a profiled lamp under its ceiling renders the same image with light subpaths as
// without: the subpaths' directions, drawn over the sphere, carry the profile's weight.
TEST(LightProfile, LightSubpathsCarryTheProfile) {
  const fs::path dir = test::mapTestFolder("profile_room");
  writeIes(dir, "up.ies",
           iesText({0, 90, 180}, {0, 90, 180, 270, 360},
                   {0.2, 1, 3, 0.2, 1, 2, 0.2, 1, 1, 0.2, 1, 2, 0.2, 1, 3}));
  const auto render = [&](bool lightPaths, int seed) {
    std::string json = test::lampUnderTheCeiling(
        R"("width": 32, "height": 32, "spp": 64)",
        std::string(R"("max_depth": 3, "seed": )") + std::to_string(seed));
    const std::string lamp = R"("intensity": 400})";
    json.replace(json.find(lamp), lamp.size(), R"("intensity": 400, "profile": "up.ies"})");
    const SceneData data = test::loadTestScene(json, dir.string());
    RenderOptions options;
    options.adjust.lightPaths = lightPaths;
    return renderCpu(data.view(), options);
  };
  const test::SeedPair with{render(true, 1), render(true, 2)};
  const test::SeedPair without{render(false, 1), render(false, 2)};
  test::expectSameImage(with, without);
}

// A profiled point light is aimed, so a direction track turns its profile's axis with it (its
// C0 plane kept towards the default up); a plain point light's direction track is refused.
TEST(LightProfile, ADirectionTrackTurnsTheProfile) {
  const fs::path dir = test::mapTestFolder("profile_track");
  writeIes(dir, "p.ies", iesText({0, 90}, {0}, {1, 1}));
  const auto scene = [&](const std::string& profile) {
    return R"({"camera": {"width": 4, "height": 4},
      "lights": [{"id": "lamp", "position": [0, 2, 0], "intensity": 1)" +
           profile + R"(}],
      "animation": {"frames": 3, "tracks": [{"target": "lamp", "property": "direction",
                                             "keys": [[0, [0, -1, 0]], [2, [2, 0, 0]]]}]}})";
  };
  const SceneDesc desc = parseSceneText(scene(R"(, "profile": "p.ies")"), "s.json", dir.string());
  const LightProfile first = flattenScene(sceneAtFrame(desc, 0)).lights[0].profile;
  const LightProfile last = flattenScene(sceneAtFrame(desc, 2)).lights[0].profile;
  EXPECT_EQ(first.axis.y, -1.0f);
  EXPECT_EQ(first.c0.z, 1.0f);  // +z, the axis running along the default up
  EXPECT_EQ(last.axis.x, 1.0f);
  EXPECT_EQ(last.c0.y, 1.0f);             // the default up itself
  EXPECT_NEAR(last.c90.z, -1.0f, 1e-6f);  // C0 x axis = y x x
  EXPECT_EQ(test::loadError(scene(""), dir.string()),
            "test.json: animation.tracks[0].property: \"direction\" is not used by a point light "
            "(only \"spot\", \"rectangle\" and \"directional\" lights, and point lights with a "
            "\"profile\", have a direction)");
}

std::string lightError(const fs::path& dir, const std::string& light) {
  return test::loadError(R"({"camera": {"width": 4, "height": 4}, "lights": [)" + light + "]}",
                         dir.string());
}

TEST(LightProfile, RefusesAProfileWhereNoneIsRead) {
  const fs::path dir = test::mapTestFolder("profile_refusals");
  writeIes(dir, "p.ies", iesText({0, 90}, {0}, {1, 1}));
  EXPECT_EQ(lightError(dir, R"({"type": "sphere", "position": [0, 0, 0], "radius": 1,
                                "intensity": 1, "profile": "p.ies"})"),
            "test.json: lights[0].profile: not used by a sphere light (only \"point\" and "
            "\"spot\" lights have a profile)");
  EXPECT_EQ(lightError(dir, R"({"position": [0, 0, 0], "intensity": 1, "up": [0, 1, 0]})"),
            "test.json: lights[0].up: not used by a point light (only \"rectangle\" lights and "
            "lights with a \"profile\" have an up)");
  EXPECT_EQ(lightError(dir, R"({"position": [0, 0, 0], "intensity": 1, "direction": [0, 1, 0]})"),
            "test.json: lights[0].direction: not used by a point light (only \"spot\", "
            "\"rectangle\" and \"directional\" lights, and point lights with a \"profile\", have "
            "a direction)");
  EXPECT_EQ(lightError(dir, R"({"position": [0, 0, 0], "intensity": 1, "profile": "p.ies",
                                "up": [0, -2, 0]})"),
            "test.json: lights[0].up: expected a direction that is not parallel to where the "
            "light points, got an array [0,-2,0]");
  EXPECT_EQ(lightError(dir, R"({"position": [0, 0, 0], "intensity": 1, "profile": "none.ies"})"),
            "test.json: lights[0].profile: none.ies: cannot read: No such file or directory");
  EXPECT_EQ(lightError(dir, R"({"position": [0, 0, 0], "intensity": 1, "profile": "p.ies",
                                "look_at": [0, 0, 0]})"),
            "test.json: lights[0].look_at: the point light looks at its own position");
}

}  // namespace
}  // namespace candela
