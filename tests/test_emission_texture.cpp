// Emission textures from JSON: an emissive material's "radiance" may be a texture, times its
// "strength" (a screen, a sign, a lamp's printed shade). Seen directly, a textured emitter is its
// texel times the strength; as a light it is sampled at the texel the sample lands on: the plane
// under a sphere whose southern half is bright and northern half dark is lit by the southern half
// alone, as the closed form of a uniform sphere says, by next-event estimation and the rays that
// hit it alike; a constant texture lights a room as the plain radiance does, light subpaths
// included. And the refusals.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "core/constants.h"
#include "render_test_util.h"
#include "temp_dir.h"

namespace candela {
namespace {

using test::num;

// A PFM texture 1 texel wide and `rows` high: the southern (lower) half of its rows `south`, the
// northern half `north` (sphereUv puts v = 0 at a sphere's south pole, v = 1 at its north pole).
std::string writeHemispheresMap(const std::string& name, int rows, float south, float north) {
  // Written whole under a name of this process's, then renamed into place: the tests that share
  // a map run in processes of their own at once (ctest -j), and one read another's half-written
  // file (as test::writePlaneObj avoids).
  const std::string path = ::testing::TempDir() + name;
  const std::string own = path + "." + std::to_string(getpid()) + ".tmp";
  {
    std::ofstream pfm(own, std::ios::binary);
    pfm << "PF\n1 " << rows << "\n-1\n";
    for (int row = 0; row < rows; ++row) {  // PFM rows run from the bottom up
      const float v = row < rows / 2 ? south : north;
      const float texel[3] = {v, v, v};
      pfm.write(reinterpret_cast<const char*>(texel), sizeof texel);
    }
  }
  std::rename(own.c_str(), path.c_str());
  return path;
}

constexpr float kSouth = 0.6f, kNorth = 0.05f, kStrength = 3.0f;
constexpr double kRadius = 0.5, kHeight = 2.0;  // the lamp's, its centre above the plane

std::string lampMaterial(const std::string& map) {
  return R"({"type": "emissive", "radiance": {"texture": ")" + map + R"("}, "strength": )" +
         num(kStrength) + "}";
}

// The camera sees the lamp alone through pixel centres, from the side: each pixel on it is the
// strength times the texel of its hemisphere (away from the equator, where texels blend).
TEST(EmissionTexture, SeenItIsTheTexelTimesTheStrength) {
  const std::string map = writeHemispheresMap("emission_seen.pfm", 16, kSouth, kNorth);
  const SceneData data = test::loadTestScene(R"({
    "camera": {"width": 32, "height": 32, "fov": 20, "position": [0, 0, 5], "look_at": [0, 0, 0],
               "spp": 1},
    "render": {"antialiasing": false, "max_depth": 1},
    "spheres": [{"position": [0, 0, 0], "radius": 0.5, "material": )" +
                                             lampMaterial(map) + "}]}");
  const RenderResult r = renderCpu(data.view(), RenderOptions{});
  int south = 0, north = 0;
  for (uint32_t y = 0; y < 32; ++y)
    for (uint32_t x = 0; x < 32; ++x) {
      const Camera& c = data.camera;
      const Vec3 d = normalize(c.cameraToWorld * (c.inverseK * Vec3(x + 0.5f, y + 0.5f, 1.0f)));
      // The ray from (0, 0, 5) meets the sphere at the origin (radius 0.5) where, if anywhere?
      const double b = 5.0 * d.z, disc = b * b - (25.0 - 0.25);
      if (disc <= 0) continue;
      const double t = -b - std::sqrt(disc);
      const double hitY = t * d.y / 0.5;  // the normal's y
      if (std::fabs(hitY) < 0.25) continue;
      const float value = r.image.at(x, y).x;
      EXPECT_NEAR(value, kStrength * (hitY < 0 ? kSouth : kNorth), 1e-5) << x << "," << y;
      ++(hitY < 0 ? south : north);
    }
  EXPECT_GT(south, 60);
  EXPECT_GT(north, 60);
}

// The plane y = 0 under the lamp, seen through pixel centres, one bounce: where the part of the
// lamp that a point sees lies in its southern half (points within 0.45 of the axis), the point
// is lit as by a uniform sphere of that half's radiance L: rho L r^2 h / d^3 (d to the centre),
// within the noise of two seeds, with and without light subpaths.
void expectPlaneLitBySouthernHalf(const std::string& lightPaths) {
  const std::string map = writeHemispheresMap("emission_plane.pfm", 64, kSouth, kNorth);
  const std::string obj = test::writePlaneObj("emission_plane.obj", 100);
  const double rho = 0.7;
  const auto scene = [&](int seed) {
    return R"({
      "camera": {"width": 48, "height": 32, "fov": 30, "position": [0, 0.8, 2.5],
                 "look_at": [0, 0, 0], "spp": 128},
      "render": {"antialiasing": false, "max_depth": 2, "light_paths": ")" +
           lightPaths + R"(", "seed": )" + std::to_string(seed) + R"(},
      "objects": [{"file": ")" +
           obj + R"(", "color": )" + num(rho) + R"(}],
      "spheres": [{"position": [0, )" +
           num(kHeight) + R"(, 0], "radius": )" + num(kRadius) + R"(, "material": )" +
           lampMaterial(map) + "}]}";
  };
  const RenderResult a = test::renderTestScene(scene(1)), b = test::renderTestScene(scene(2));
  const Camera camera = test::loadTestScene(scene(1)).camera;
  const double radiance = kStrength * kSouth;
  double noise2 = 0, sum = 0;
  int count = 0;
  std::vector<std::pair<double, double>> seen;  // (measured, expected)
  for (uint32_t y = 0; y < 32; ++y)
    for (uint32_t x = 0; x < 48; ++x) {
      const Vec3 d = camera.cameraToWorld * (camera.inverseK * Vec3(x + 0.5f, y + 0.5f, 1.0f));
      const double t = -double(camera.position.y) / d.y;
      if (!(t > 0)) continue;
      const double px = camera.position.x + t * d.x, pz = camera.position.z + t * d.z;
      if (px * px + pz * pz > 0.45 * 0.45) continue;
      const double dist = std::sqrt(px * px + pz * pz + kHeight * kHeight);
      const double expected = rho * radiance * kRadius * kRadius * kHeight / (dist * dist * dist);
      const double va = a.image.at(x, y).x, vb = b.image.at(x, y).x;
      noise2 += (va - vb) * (va - vb) / 4 / (expected * expected);
      seen.push_back({(va + vb) / 2, expected});
      sum += (va + vb) / 2 / expected;
      ++count;
    }
  ASSERT_GT(count, 100);
  const double noise = std::sqrt(noise2 / count);  // of a pixel's two-seed mean, relative
  EXPECT_LT(noise, 0.03);
  for (const auto& [measured, expected] : seen)
    EXPECT_NEAR(measured / expected, 1.0, 6 * noise) << "noise " << noise;
  // The mean over the pixels; the texture's rows blend across its south pole's last half texel
  // (lookups repeat), a bias below 1e-3 here.
  EXPECT_NEAR(sum / count, 1.0, 4 * noise / std::sqrt(double(count)) + 1e-3);
}

TEST(EmissionTexture, ThePlaneUnderASphereIsLitByItsSouthernHalf) {
  expectPlaneLitBySouthernHalf("off");
}

TEST(EmissionTexture, ThePlaneUnderASphereIsTheSameWithLightSubpaths) {
  expectPlaneLitBySouthernHalf("on");
}

// A constant texture c at strength k lights the small room (a sphere lamp and a mesh panel) as the
// radiance k c does, light subpaths included: the same samples, so the same image to rounding.
TEST(EmissionTexture, AConstantTextureLightsARoomAsItsRadianceDoes) {
  const std::string map = writeHemispheresMap("emission_constant.pfm", 4, 0.4f, 0.4f);
  const std::string obj = test::writePlaneObj("emission_panel.obj", 0.5);
  const auto room = [&](const std::string& material) {
    return R"({
      "camera": {"width": 32, "height": 24, "fov": 70, "position": [0, 2, 9],
                 "look_at": [0, 2, 0], "spp": 16},
      "render": {"max_depth": 4, "light_paths": "on"},
      "spheres": [)" +
           std::string(test::kSmallRoomWalls) + R"(,
                  {"position": [-2, 4, -2], "radius": 0.4, "material": )" +
           material + R"(}],
      "objects": [{"file": ")" +
           obj + R"(", "position": [2, 5.9, 0], "rotation": [180, 0, 0], "material": )" + material +
           "}]}";
  };
  const RenderResult textured = test::renderTestScene(
      room(R"({"type": "emissive", "radiance": {"texture": ")" + map + R"("}, "strength": 20})"));
  const RenderResult plain = test::renderTestScene(room(R"({"type": "emissive", "radiance": 8})"));
  double total = 0;
  for (uint32_t y = 0; y < 24; ++y)
    for (uint32_t x = 0; x < 32; ++x)
      for (int c = 0; c < 3; ++c) {
        const double t = textured.image.at(x, y)[c], p = plain.image.at(x, y)[c];
        EXPECT_NEAR(t, p, 1e-5 * (1 + p)) << x << "," << y;
        total += p;
      }
  EXPECT_GT(total, 0.0);
}

TEST(EmissionTexture, TheSceneFormatRefusesWhatItCannotBe) {
  const auto error = [](const std::string& material) {
    return test::loadError(
        R"({"camera": {"width": 8, "height": 8, "fov": 40},
            "spheres": [{"position": [0, 0, -5], "radius": 1, "material": )" +
            material + "}]}",
        ".");
  };
  EXPECT_EQ(error(R"({"type": "emissive", "radiance": 1, "strength": -1})"),
            "test.json: spheres[0].material.strength: expected a non-negative number, got -1");
  EXPECT_EQ(error(R"({"type": "emissive", "radiance": 1e30, "strength": 1e20})"),
            "test.json: spheres[0].material.strength: the radiance [1e+30, 1e+30, 1e+30] times "
            "strength 1e+20 is beyond single precision; expected a smaller strength");
  EXPECT_EQ(error(R"({"type": "diffuse", "strength": 2})"),
            "test.json: spheres[0].material.strength: not used by a \"diffuse\" material");
  EXPECT_EQ(error(R"({"type": "emissive", "radiance": {"texture": "nowhere.png"}})"),
            "test.json: spheres[0].material.radiance.texture: cannot read the texture: "
            "./nowhere.png: cannot open: No such file or directory");
}

// A float texture's texels times the strength (an MTL's: times Ke) must stay within single
// precision, as a plain radiance times its strength must: else the light's power is infinite.
TEST(EmissionTexture, TexelsThatTheStrengthCarriesBeyondSinglePrecisionAreRefused) {
  // The bright row is the file's first, which PFM stores at the bottom: the image's row 1.
  const std::string hot = writeHemispheresMap("emission_hot.pfm", 2, 1e30f, 1.0f);
  const auto error = [&](float strength) {
    const std::string material = R"({"type": "emissive", "radiance": {"texture": ")" + hot +
                                 R"("}, "strength": )" + num(strength) + "}";
    return test::loadError(R"({"camera": {"width": 8, "height": 8, "fov": 40},
        "spheres": [{"position": [0, 0, -5], "radius": 1, "material": )" +
                               material + "}]}",
                           ".");
  };
  EXPECT_EQ(error(1.0f), "(no error)");
  EXPECT_EQ(error(1e20f),
            "test.json: spheres[0].material.strength: the radiance texture's texel (0, 1), "
            "[1e+30, 1e+30, 1e+30] times strength 1e+20 is beyond single precision; expected a "
            "smaller strength");

  test::TempDir dir;
  dir.write("quad.obj",
            "mtllib lamp.mtl\nv 0 0 -5\nv 1 0 -5\nv 0 1 -5\nvt 0 0\nvt 1 0\nvt 0 1\n"
            "usemtl lamp\nf 1/1 2/2 3/3\n");
  const auto mtlError = [&](const std::string& ke) {
    dir.write("lamp.mtl", "newmtl lamp\nKe " + ke + "\nmap_Ke " + hot + "\n");
    return test::loadError(R"({"camera": {"width": 8, "height": 8, "fov": 40},
        "objects": [{"file": "quad.obj"}]})",
                           dir.path());
  };
  EXPECT_EQ(mtlError("1 1 1"), "(no error)");
  EXPECT_EQ(mtlError("1e20 1 1"),
            "test.json: objects[0].file: lamp.mtl:3: map_Ke: the texture's texel (0, 1), [1e+30, "
            "1e+30, 1e+30] times Ke [1e+20, 1, 1] is beyond single precision; expected a smaller "
            "Ke");
}

}  // namespace
}  // namespace candela
