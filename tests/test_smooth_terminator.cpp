// The smooth shadow terminator (render/shadow_ray_origin.h): a coarse mesh of a ball, 12 x 6 faces
// shaded by the ball's own normals, under a sun from the side. Direct light only, one sample
// through each pixel's centre: every pixel is exactly Lambert's rho E max(0, n . l) / pi of the
// shading normal n that the normal pass shows, up to the terminator itself, whichever way the
// faces are wound; with render.smooth_terminator false, whole faces near it go dark (the stair
// of facets). A flat mesh is not raised: the two settings render it alike, to the bit.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "render_test_util.h"
#include "shading_normal_test_util.h"

namespace candela {
namespace {

namespace fs = std::filesystem;

// A unit ball of nu x nv faces (as quads split in two) with its exact normals at the vertices,
// its faces wound counter-clockwise seen from outside, or from inside with `inward`.
void writeCoarseBall(const fs::path& path, bool inward) {
  constexpr int nu = 12, nv = 6;
  std::ofstream obj(path);
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const double theta = kPi * j / nv, phi = 2 * kPi * i / nu;
      const double x = std::sin(theta) * std::cos(phi), y = std::cos(theta),
                   z = std::sin(theta) * std::sin(phi);
      obj << "v " << x << " " << y << " " << z << "\nvn " << x << " " << y << " " << z << "\n";
    }
  const auto index = [&](int i, int j) { return j * nu + i % nu + 1; };
  const auto face = [&](int a, int b, int c) {
    if (inward) std::swap(b, c);
    obj << "f " << a << "//" << a << " " << b << "//" << b << " " << c << "//" << c << "\n";
  };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const int a = index(i, j), b = index(i + 1, j), c = index(i + 1, j + 1), d = index(i, j + 1);
      face(a, b, c);
      face(a, c, d);
    }
}

constexpr double kRho = 0.8, kIrradiance = 3;
const DVec3 kToSun = unit(DVec3{1, 0.3, -0.25});

std::string ballUnderSun(bool smooth) {
  return R"({
    "camera": {"width": 64, "height": 64, "fov": 30, "position": [0, 0.5, 5],
               "look_at": [0, 0, 0], "spp": 1},
    "render": {"antialiasing": false, "max_depth": 1, "smooth_terminator": )" +
         std::string(smooth ? "true" : "false") + R"(},
    "objects": [{"file": "ball.obj", "color": )" +
         test::num(kRho) + R"(}],
    "lights": [{"type": "directional", "direction": [)" +
         test::num(-kToSun.x) + ", " + test::num(-kToSun.y) + ", " + test::num(-kToSun.z) +
         R"(], "intensity": )" + test::num(kIrradiance) + "}]}";
}

struct Count {
  int seen = 0, lit = 0, wrong = 0;
};

// How many pixels see the ball, how many its shading lights, and how many differ from Lambert's
// law of their shading normal by more than 1e-4 (relative) + 1e-6.
Count compareWithLambert(const test::RenderedWithNormals& r) {
  Count count;
  const uint32_t width = r.data.camera.width;
  for (uint32_t y = 0; y < r.data.camera.height; ++y)
    for (uint32_t x = 0; x < width; ++x) {
      const float* n = &r.layers[0].pixels[3 * (size_t(y) * width + x)];
      if (n[0] == 0 && n[1] == 0 && n[2] == 0) continue;
      ++count.seen;
      const double cosine = n[0] * kToSun.x + n[1] * kToSun.y + n[2] * kToSun.z;
      const double expected = kRho * kIrradiance * std::max(0.0, cosine) / kPi;
      count.lit += cosine > 0;
      count.wrong += std::fabs(r.result.image.at(x, y).x - expected) > 1e-4 * expected + 1e-6;
    }
  return count;
}

TEST(SmoothTerminator, ACoarseBallIsLitAsItsShadingNormalsSay) {
  for (const bool inward : {false, true}) {
    SCOPED_TRACE(inward ? "wound inwards" : "wound outwards");
    const fs::path dir = test::mapTestFolder(inward ? "terminator_in" : "terminator_out");
    writeCoarseBall(dir / "ball.obj", inward);
    const Count smooth = compareWithLambert(test::renderWithNormals(ballUnderSun(true), dir));
    EXPECT_GT(smooth.seen, 1500);
    EXPECT_GT(smooth.lit, smooth.seen / 4);
    EXPECT_EQ(smooth.wrong, 0);
    const Count faceted = compareWithLambert(test::renderWithNormals(ballUnderSun(false), dir));
    EXPECT_GT(faceted.wrong, 60);  // the stair of dark facets along the terminator
  }
}

TEST(SmoothTerminator, AFlatMeshIsNotRaised) {
  const fs::path dir = test::mapTestFolder("terminator_flat");
  // A floor with its normals given, and a ball above it casting its shadow there.
  std::ofstream(dir / "floor.obj") << "v -4 0 -4\nv 4 0 -4\nv 4 0 4\nv -4 0 4\nvn 0 1 0\n"
                                   << "f 1//1 4//1 3//1\nf 1//1 3//1 2//1\n";
  const auto render = [&](bool smooth) {
    return test::renderTestScene(R"({
      "camera": {"width": 32, "height": 24, "position": [0, 3, 6], "look_at": [0, 0, 0],
                 "spp": 4},
      "render": {"smooth_terminator": )" +
                                     std::string(smooth ? "true" : "false") + R"(},
      "objects": [{"file": "floor.obj", "color": 0.7}],
      "spheres": [{"position": [0, 1, 0], "radius": 1, "color": 0.5}],
      "lights": [{"position": [1, 4, 1], "intensity": 60}]})",
                                 0, dir.string())
        .image;
  };
  const ImageRGB smooth = render(true), faceted = render(false);
  for (uint32_t y = 0; y < 24; ++y)
    for (uint32_t x = 0; x < 32; ++x)
      for (int c = 0; c < 3; ++c) EXPECT_EQ(smooth.at(x, y)[c], faceted.at(x, y)[c]);
}

TEST(SmoothTerminator, TheSettingIsABoolean) {
  EXPECT_EQ(test::loadError(R"({"camera": {"width": 4, "height": 4},
                                "render": {"smooth_terminator": "yes"}})",
                            "."),
            "test.json: render.smooth_terminator: expected true or false, got a string \"yes\"");
}

}  // namespace
}  // namespace candela
