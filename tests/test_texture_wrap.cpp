// Texture wrap modes and filters (core/texture.h): an image repeated, clamped to its edge texels
// or mirrored every other copy beyond [0, 1), per axis, read bilinearly or from the nearest
// texel. Lookups against the test's own arithmetic on a texture whose texels hold their own
// coordinates; a height map's slopes reversed in mirrored copies and flat where clamped or
// nearest; a textured emitter seen through every pixel centre as the test's texel choice says,
// for each wrap mode; the scene format's keys and refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/texture.h"
#include "render_test_util.h"
#include "temp_dir.h"
#include "texture_test_util.h"

namespace candela {
namespace {

// A 4 x 2 float texture whose texel (i, j) (j from the top row) holds (i, j, 0): a bilinear
// lookup returns the continuous texel coordinates it blends at, a nearest one the texel's.
class WrapLookup : public ::testing::Test {
 protected:
  WrapLookup() {
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 4; ++i) texels.insert(texels.end(), {float(i), float(j), 0.0f, 1.0f});
    texture.width = 4;
    texture.height = 2;
    texture.format = TextureFormat::Float;
    pool.textures = &texture;
    pool.texelsF = texels.data();
    ref.index = 0;
  }
  // The texel coordinates (x, y) the lookup of `ref` blends to at (u, v).
  std::pair<float, float> at(float u, float v) const {
    const TextureSample s = lookupTexture(pool, ref, u, v);
    return {s.rgb.x, s.rgb.y};
  }
  void wrap(TextureWrap s, TextureWrap t) {
    ref.wrapS = s;
    ref.wrapT = t;
  }

  std::vector<float> texels;
  Texture texture;
  TexturePool pool;
  TextureRef ref;
};

using P = std::pair<float, float>;

// v = 0.75 and 0.25 are the centres of rows 0 (top) and 1; u = (i + 0.5) / 4 that of column i.
TEST_F(WrapLookup, RepeatBlendsAcrossTheSeam) {
  EXPECT_EQ(at(0.375f, 0.75f), P(1.0f, 0.0f));
  EXPECT_EQ(at(0.0f, 0.75f), P(1.5f, 0.0f));  // half the last column, half the first
  EXPECT_EQ(at(2.375f, -0.75f), P(1.0f, 1.0f));
  EXPECT_EQ(at(0.5f, 1.0f), P(1.5f, 0.5f));  // between the bottom row and the next copy's top
}

TEST_F(WrapLookup, ClampHoldsTheEdgeTexels) {
  wrap(TextureWrap::Clamp, TextureWrap::Clamp);
  EXPECT_EQ(at(0.375f, 0.75f), P(1.0f, 0.0f));  // inside, as repeating
  EXPECT_EQ(at(0.0f, 0.75f), P(0.0f, 0.0f));
  EXPECT_EQ(at(-7.0f, 0.75f), P(0.0f, 0.0f));
  EXPECT_EQ(at(1.0f, 0.75f), P(3.0f, 0.0f));
  EXPECT_EQ(at(3e38f, 5.0f), P(3.0f, 0.0f));    // above the top: the top row
  EXPECT_EQ(at(0.375f, -2.0f), P(1.0f, 1.0f));  // below the bottom: the bottom row
  // A NaN in uv reads the bottom-left texel, as repeating does (the turn of the image
  // coordinates makes both NaN); v = infinity clamps to the top and makes s NaN.
  EXPECT_EQ(at(NAN, 0.75f), P(0.0f, 1.0f));
  EXPECT_EQ(at(0.375f, NAN), P(0.0f, 1.0f));
  EXPECT_EQ(at(0.375f, INFINITY), P(0.0f, 0.0f));
}

// Copy k of the image (u in [k, k + 1)) is mirrored where k is odd: u = 1.25 reads where 0.75
// does, u = -0.25 where 0.25 does.
TEST_F(WrapLookup, MirrorReflectsEveryOtherCopy) {
  wrap(TextureWrap::Mirror, TextureWrap::Mirror);
  EXPECT_EQ(at(1.25f, 0.75f), at(0.75f, 0.75f));
  EXPECT_EQ(at(1.25f, 0.75f), P(2.5f, 0.0f));
  EXPECT_EQ(at(-0.25f, 0.75f), P(0.5f, 0.0f));
  EXPECT_EQ(at(1.0f, 0.75f), P(3.0f, 0.0f));  // the mirror meets the last column again
  EXPECT_EQ(at(2.0f, 0.75f), P(0.0f, 0.0f));  // and the next copy the first
  EXPECT_EQ(at(5.625f, 0.75f), at(0.375f, 0.75f));
  EXPECT_EQ(at(0.375f, 1.25f), P(1.0f, 0.0f));  // v mirrored too: the top row above the top
  EXPECT_EQ(at(0.375f, 1.75f), P(1.0f, 1.0f));
}

TEST_F(WrapLookup, EachAxisWrapsAsItsOwnModeSays) {
  wrap(TextureWrap::Clamp, TextureWrap::Mirror);
  EXPECT_EQ(at(1.25f, 1.25f), P(3.0f, 0.0f));
  wrap(TextureWrap::Mirror, TextureWrap::Repeat);
  EXPECT_EQ(at(1.25f, 1.25f), P(2.5f, 1.0f));
}

TEST_F(WrapLookup, NearestReadsTheTexelThePointLiesIn) {
  ref.filter = TextureFilter::Nearest;
  EXPECT_EQ(at(0.26f, 0.74f), P(1.0f, 0.0f));
  EXPECT_EQ(at(0.49f, 0.51f), P(1.0f, 0.0f));
  EXPECT_EQ(at(0.51f, 0.49f), P(2.0f, 1.0f));
  EXPECT_EQ(at(-0.01f, 0.0f), P(3.0f, 1.0f));  // repeating: the last column, the bottom row
  EXPECT_EQ(at(1.0f, 1.0f), P(0.0f, 1.0f));    // the next copy's first column and bottom row
  wrap(TextureWrap::Clamp, TextureWrap::Clamp);
  EXPECT_EQ(at(-0.01f, 1.0f), P(0.0f, 0.0f));
  EXPECT_EQ(at(1.0f, 0.0f), P(3.0f, 1.0f));
  wrap(TextureWrap::Mirror, TextureWrap::Mirror);
  EXPECT_EQ(at(1.01f, 0.49f), P(3.0f, 1.0f));
  EXPECT_EQ(at(1.3f, 1.3f), P(2.0f, 0.0f));
}

// The luminance's slope along u: the red channel's weight (0.212671) a texel, 4 texels a unit.
// A mirrored copy reads the image backwards, so its slope is the opposite; clamped beyond an
// edge, or read from the nearest texel, the texture is flat.
TEST_F(WrapLookup, SlopesFollowTheCopysDirection) {
  const auto slopeU = [&](float u) {
    float ddu = 0, ddv = 0;
    textureLuminanceGradient(pool, ref, u, 0.75f, &ddu, &ddv);
    return ddu;
  };
  const float slope = 0.212671f * 4;
  EXPECT_NEAR(slopeU(0.5f), slope, 1e-5f);
  wrap(TextureWrap::Mirror, TextureWrap::Repeat);
  EXPECT_NEAR(slopeU(0.5f), slope, 1e-5f);
  EXPECT_NEAR(slopeU(1.5f), -slope, 1e-5f);
  EXPECT_NEAR(slopeU(-0.5f), -slope, 1e-5f);
  float signS = 0, signT = 0;
  textureMirrorSigns(ref, 1.5f, 0.5f, &signS, &signT);
  EXPECT_EQ(signS, -1.0f);
  EXPECT_EQ(signT, 1.0f);  // t repeats
  textureMirrorSigns(ref, 2.5f, 0.5f, &signS, &signT);
  EXPECT_EQ(signS, 1.0f);
  wrap(TextureWrap::Clamp, TextureWrap::Repeat);
  EXPECT_NEAR(slopeU(0.5f), slope, 1e-5f);
  EXPECT_EQ(slopeU(1.5f), 0.0f);
  EXPECT_EQ(slopeU(-3.0f), 0.0f);
  ref.filter = TextureFilter::Nearest;
  EXPECT_EQ(slopeU(0.5f), 0.0f);
}

// The texel column (0-3 from the left) and row (0-1 from the top) that a nearest lookup under
// `wrapU` and `wrapV` reads at (u, v), by the modes' definitions (no point on a texel's edge).
int copyTexel(double a, int n, const std::string& wrap) {
  double f = a - std::floor(a);
  if (wrap == "clamp") f = std::fmin(std::fmax(a, 0.0), 0.999999);
  if (wrap == "mirror" && int64_t(std::floor(a)) % 2 != 0) f = 1 - f;
  return int(std::floor(f * n));
}

// An emitter whose radiance is a 4 x 2 texture, on a quad of uvs from -1 to 2 seen square by an
// orthographic camera of 24 x 24 pixels: pixel (x, y) sees uv (-1 + (x + 0.5) / 8, 2 - (y + 0.5)
// / 8), and shows exactly the texel the modes pick there.
TEST(TextureWrapRender, EachPixelShowsTheTexelItsWrapPicks) {
  test::TempDir dir;
  const std::vector<uint8_t> bytes = {200, 10,  10,  10,  200, 10,  10, 10, 200, 200, 200, 10,
                                      10,  200, 200, 200, 10,  200, 90, 90, 90,  250, 250, 250};
  ASSERT_TRUE(test::writeTestPng(dir.file("t.png"), 4, 2, 3, bytes));
  dir.write("quad.obj",
            "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt -1 -1\nvt 2 -1\nvt 2 2\nvt -1 2\n"
            "f 1/1 2/2 3/3 4/4\n");
  for (const auto& [wrapU, wrapV] : std::vector<std::pair<std::string, std::string>>{
           {"repeat", "repeat"}, {"clamp", "mirror"}, {"mirror", "clamp"}}) {
    SCOPED_TRACE(wrapU + ", " + wrapV);
    const std::string json = R"({
      "camera": {"width": 24, "height": 24, "projection": "orthographic", "view_width": 2,
                 "position": [0, 0, 3], "look_at": [0, 0, 0], "spp": 1},
      "render": {"max_depth": 1, "antialiasing": false},
      "objects": [{"file": "quad.obj", "material": {"type": "emissive", "radiance": {
        "texture": "t.png", "filter": "nearest", "wrap": [")" +
                             wrapU + R"(", ")" + wrapV + R"("]}}}]})";
    const RenderResult r = test::renderTestScene(json, 0, dir.path());
    for (uint32_t y = 0; y < 24; ++y)
      for (uint32_t x = 0; x < 24; ++x) {
        const int column = copyTexel(-1 + (x + 0.5) / 8, 4, wrapU);
        const int row = 1 - copyTexel(2 - (y + 0.5) / 8, 2, wrapV);
        const uint8_t* texel = &bytes[3 * size_t(4 * row + column)];
        const Vec3 seen = r.image.at(x, y);
        for (int c = 0; c < 3; ++c)
          ASSERT_NEAR(seen[c], srgbToLinearValue(texel[c] / 255.0f), 1e-6f)
              << "pixel " << x << ", " << y << " channel " << c;
      }
  }
}

TEST(TextureWrapErrors, KeysAreCheckedWithTheirPath) {
  test::TempDir dir;
  ASSERT_TRUE(test::writeTestPng(dir.file("ok.png"), 1, 1, 3, {1, 2, 3}));
  const auto error = [&](const std::string& material) {
    return test::loadError(
        R"({"camera": {}, "spheres": [{"position": [0, 0, 0], "radius": 1, "material": )" +
            material + "}]}",
        dir.path());
  };
  const SceneData data = test::loadTestScene(
      R"({"camera": {}, "spheres": [{"position": [0, 0, 0], "radius": 1, "material":
          {"type": "diffuse", "color": {"texture": "ok.png", "wrap": ["mirror", "clamp"],
                                        "filter": "nearest"}}}]})",
      dir.path());
  const TextureRef& ref = data.materials[0].colorTexture;
  EXPECT_EQ(ref.wrapS, TextureWrap::Mirror);
  EXPECT_EQ(ref.wrapT, TextureWrap::Clamp);
  EXPECT_EQ(ref.filter, TextureFilter::Nearest);
  EXPECT_EQ(error(R"({"type": "diffuse", "color": {"texture": "ok.png", "wrap": "clamp"}})"),
            "(no error)");
  EXPECT_EQ(error(R"({"type": "diffuse", "color": {"texture": "ok.png", "wrap": "border"}})"),
            "test.json: spheres[0].material.color.wrap: expected one of \"repeat\", \"clamp\", "
            "\"mirror\", got a string \"border\"");
  EXPECT_EQ(error(R"({"type": "diffuse", "color": {"texture": "ok.png", "wrap": ["clamp"]}})"),
            "test.json: spheres[0].material.color.wrap: expected \"repeat\", \"clamp\" or "
            "\"mirror\", or an array of two of them, got an array [\"clamp\"]");
  EXPECT_EQ(error(R"({"type": "diffuse", "color": {"texture": "ok.png", "wrap": ["clamp", 1]}})"),
            "test.json: spheres[0].material.color.wrap[1]: expected one of \"repeat\", \"clamp\", "
            "\"mirror\", got 1");
  EXPECT_EQ(error(R"({"type": "diffuse", "color": {"texture": "ok.png", "filter": "cubic"}})"),
            "test.json: spheres[0].material.color.filter: expected \"bilinear\" or \"nearest\", "
            "got a string \"cubic\"");
  // A bump map's slopes are those of the bilinear interpolation.
  EXPECT_EQ(error(R"({"type": "diffuse", "bump_map": {"texture": "ok.png", "filter": "nearest"}})"),
            "test.json: spheres[0].material.bump_map.filter: expected \"bilinear\" (a bump map of "
            "the nearest texels would be flat), got a string \"nearest\"");
  EXPECT_EQ(error(R"({"type": "diffuse", "normal_map": {"texture": "ok.png", "filter": "nearest",
                      "wrap": "mirror"}})"),
            "(no error)");
}

}  // namespace
}  // namespace candela
