// The alpha pass (docs/aovs.md): the share of a pixel's samples that saw something, so that the
// image is premultiplied by it; and its files, a PNG's alpha channel (straight colour) and an
// EXR's A.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "image/image_io.h"
#include "render/aov_layers.h"
#include "render_test_util.h"

namespace candela {
namespace {

using test::loadTestScene;

constexpr uint32_t kSize = 48;
constexpr uint32_t kSpp = 64;
constexpr float kFovDegrees = 40.0f;
constexpr float kCameraDistance = 5.0f;

// A unit sphere of `material` seen head-on from kCameraDistance on a kSize-square image,
// antialiased, with the scene's `more` top-level members (",\"environment\": ...").
std::string sphereScene(const std::string& material, const std::string& more = "") {
  return R"({"camera": {"width": )" + std::to_string(kSize) + R"(, "height": )" +
         std::to_string(kSize) + R"(, "fov": )" + test::num(kFovDegrees) + R"(, "spp": )" +
         std::to_string(kSpp) + R"(, "position": [0, 0, )" + test::num(kCameraDistance) +
         R"(]}, "spheres": [{"position": [0, 0, 0], "radius": 1, "material": )" + material + "}]" +
         more + "}";
}

struct AlphaRender {
  ImageRGB image;
  ImageLayer alpha;
  float at(uint32_t x, uint32_t y) const { return alpha.pixels[size_t(y) * alpha.width + x]; }
  double sum() const {
    double s = 0.0;
    for (float a : alpha.pixels) s += a;
    return s;
  }
};

AlphaRender renderAlpha(const std::string& json) {
  const SceneData scene = loadTestScene(json);
  RenderOptions options;
  options.threads = 2;
  options.aovs = true;
  RenderResult result = renderCpu(scene.view(), options);
  return {std::move(result.image), makeAovLayers(scene, {Aov::Alpha}, result.aovs)[0]};
}

const char* kEmitter = R"({"type": "emissive", "radiance": 1})";

// An emitter of radiance 1 over nothing: each sample carries 1 where it hits and 0 where it does
// not, so the image is the alpha exactly, and the alpha sums to the sphere's silhouette, a disc of
// radius f R / sqrt(d^2 - R^2) pixels.
TEST(AlphaPass, AnEmitterOverNothingIsItsOwnAlphaAndCoversItsSilhouette) {
  const AlphaRender r = renderAlpha(sphereScene(kEmitter));
  ASSERT_EQ(r.alpha.channels, std::vector<std::string>{"A"});
  for (size_t i = 0; i < r.alpha.pixels.size(); ++i) {
    ASSERT_NEAR(r.image.pixels[3 * i], r.alpha.pixels[i], 1e-6f) << i;
    ASSERT_GE(r.alpha.pixels[i], 0.0f);
    ASSERT_LE(r.alpha.pixels[i], 1.0f);
  }
  EXPECT_EQ(r.at(kSize / 2, kSize / 2), 1.0f);
  EXPECT_EQ(r.at(0, 0), 0.0f);
  const double f = 0.5 * kSize / std::tan(0.5 * kFovDegrees * M_PI / 180.0);
  const double radius = f / std::sqrt(kCameraDistance * kCameraDistance - 1.0);
  const double area = M_PI * radius * radius;
  // Each edge pixel's alpha is a mean of kSpp samples of 0 or 1 (variance at most 1/4 each; the
  // stratified samples do better), about 2 pi r of them.
  const double sigma = std::sqrt(2.0 * M_PI * radius * 0.25 / kSpp);
  EXPECT_NEAR(r.sum(), area, 5.0 * sigma) << "radius " << radius << " px";
}

// What lies behind decides: a visible environment is a backdrop (every sample saw something); a
// hidden one, a black one or none leaves the background transparent, with the same coverage.
TEST(AlphaPass, AVisibleEnvironmentIsOpaqueAndAHiddenOrBlackOneIsNothing) {
  const char* grey = R"({"type": "diffuse", "color": 0.5})";
  const AlphaRender alone = renderAlpha(sphereScene(kEmitter));
  const AlphaRender visible =
      renderAlpha(sphereScene(grey, R"(, "environment": {"color": [0.5, 0.7, 1]})"));
  for (float a : visible.alpha.pixels) ASSERT_EQ(a, 1.0f);
  for (const char* environment : {R"(, "environment": {"color": [0.5, 0.7, 1], "visible": false})",
                                  R"(, "environment": {"color": 0})"}) {
    const AlphaRender hidden = renderAlpha(sphereScene(grey, environment));
    EXPECT_EQ(hidden.alpha.pixels, alone.alpha.pixels) << environment;
    EXPECT_EQ(hidden.at(0, 0), 0.0f);
    // Premultiplied: where nothing was seen the image is black.
    EXPECT_EQ(hidden.image.pixels[0], 0.0f);
  }
}

// The camera sees mirrors and glass (and through them), not what it is told to pass by: an
// emitter hidden from the camera, glass of index 1 (the bound of a medium, with none inside).
TEST(AlphaPass, MirrorsAndGlassAreOpaqueWhatTheCameraPassesByIsNot) {
  const char* environment = R"(, "environment": {"color": 1, "visible": false})";
  for (const char* material : {R"("mirror")", R"({"type": "glass", "ior": 1.5})"}) {
    const AlphaRender r = renderAlpha(sphereScene(material, environment));
    EXPECT_EQ(r.at(kSize / 2, kSize / 2), 1.0f) << material;
    EXPECT_EQ(r.at(0, 0), 0.0f) << material;
  }
  for (const char* material : {R"({"type": "emissive", "radiance": 1, "visible": false})",
                               R"({"type": "glass", "ior": 1})"}) {
    const AlphaRender r = renderAlpha(sphereScene(material, environment));
    EXPECT_EQ(r.sum(), 0.0) << material;
  }
  // A medium inside glass of index 1 is seen where the camera's rays scatter in it.
  const AlphaRender fog =
      renderAlpha(sphereScene(R"({"type": "glass", "ior": 1, "scattering": 2})", environment));
  const float centre = fog.at(kSize / 2, kSize / 2);
  EXPECT_GT(centre, 0.9f);  // 1 - exp(-2 * 2) = 0.98 of the rays through the centre scatter
  EXPECT_LT(centre, 1.0f);
  EXPECT_EQ(fog.at(0, 0), 0.0f);
}

// A sun's disc is something to see, unless it is hidden from the camera.
TEST(AlphaPass, ASunsDiscSeenIsOpaque) {
  const auto sky = [](const char* visible) {
    return renderAlpha(R"({"camera": {"width": 16, "height": 16, "fov": 60, "spp": 16,
      "position": [0, 0, 0]},
      "lights": [{"type": "directional", "direction": [0, 0, 1], "intensity": 10, "angle": 20)" +
                       std::string(visible) + "}]}");
  };
  const AlphaRender seen = sky("");
  EXPECT_EQ(seen.at(8, 8), 1.0f);
  EXPECT_EQ(seen.at(0, 0), 0.0f);
  EXPECT_EQ(sky(R"(, "visible": false)").sum(), 0.0);
}

ImageRGB grey(uint32_t width, uint32_t height, float value) {
  ImageRGB image(width, height);
  for (float& v : image.pixels) v = value;
  return image;
}

ImageLayer alphaLayer(const std::vector<float>& values) {
  ImageLayer alpha("alpha", {"A"}, false, uint32_t(values.size()), 1);
  alpha.pixels = values;
  return alpha;
}

// A PNG's alpha is straight: the premultiplied image divided by alpha, then the tone curve.
TEST(AlphaOutput, APngHoldsStraightColourAndItsAlpha) {
  // Colours 0.5, 0.25, none and 1, each premultiplied by its alpha.
  ImageRGB premultiplied = grey(4, 1, 0.25f);
  const std::vector<float> alpha = {0.5f, 1.0f, 0.0f, 0.25f};
  premultiplied.pixels[6] = premultiplied.pixels[7] = premultiplied.pixels[8] = 0.0f;
  OutputDesc linear;
  linear.gamma = 1.0f;
  const std::string path = ::testing::TempDir() + "candela_alpha.png";
  const ImageLayer a = alphaLayer(alpha);
  writeImage(path, premultiplied, linear, &a);
  const ImageRgba png = readImageRgba(path);
  ASSERT_EQ(png.channels, 4u);
  const uint8_t expected[4][4] = {
      {128, 128, 128, 128}, {64, 64, 64, 255}, {0, 0, 0, 0}, {255, 255, 255, 64}};
  for (int i = 0; i < 4; ++i)
    for (int c = 0; c < 4; ++c) EXPECT_EQ(png.pixels8[4 * i + c], expected[i][c]) << i << c;
}

TEST(AlphaOutput, AnExrHoldsAlphaAsABesideRgbAndAPfmRefusesIt) {
  const ImageLayer a = alphaLayer({0.5f, 1.0f, 0.0f});
  const std::string exr = ::testing::TempDir() + "candela_alpha.exr";
  writeImage(exr, grey(3, 1, 0.2f), OutputDesc(), &a);
  const ExrChannels channels = readExrChannels(exr);
  std::vector<std::string> names;
  for (const ExrChannel& c : channels.channels) names.push_back(c.name);
  EXPECT_EQ(names, (std::vector<std::string>{"A", "B", "G", "R"}));
  EXPECT_EQ(channels.channels[0].pixels, a.pixels);
  try {
    writeImage(::testing::TempDir() + "candela_alpha.pfm", grey(3, 1, 0.2f), OutputDesc(), &a);
    FAIL() << "a .pfm took an alpha channel";
  } catch (const ImageWriteError& e) {
    EXPECT_NE(std::string(e.what()).find("a .pfm has no alpha channel"), std::string::npos)
        << e.what();
  }
  const ImageLayer wrongSize = alphaLayer({1.0f, 1.0f});
  EXPECT_THROW(writeImage(exr, grey(3, 1, 0.2f), OutputDesc(), &wrongSize), ImageWriteError);
}

}  // namespace
}  // namespace candela
