// Pixel filters (render "filter"): each sample of a pixel lands about its centre with the
// filter's density, so a pixel is the filter's weighted mean of the image plane. Checked where
// that mean has a closed form: an emitter of radiance 1 that covers the image plane beyond a
// corner at a known sub-pixel place is, in each pixel, the share of the filter beyond the corner,
// (1 - F(u0 - x)) (1 - F(v0 - y)) with F the filter's distribution along one axis and (x, y) the
// pixel's centre. And the inverse distributions the samples are drawn by, and the refusals.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/erf_inverse.h"
#include "render/pixel_filter.h"
#include "render_test_util.h"

namespace candela {
namespace {

using test::num;

constexpr double kPiDouble = 3.14159265358979323846;

// The filter's cumulative distribution along one axis at offset x (pixels from the centre).
double filterCdf(const PixelFilter& f, double x) {
  const double r = filterRadius(f);
  if (x <= -r) return 0.0;
  if (x >= r) return 1.0;
  switch (f.type) {
    case FilterType::Tent:
      return x < 0.0 ? (x + r) * (x + r) / (2.0 * r * r) : 1.0 - (r - x) * (r - x) / (2.0 * r * r);
    case FilterType::Gaussian:
      return 0.5 + 0.5 * std::erf(x / (f.width * std::sqrt(2.0))) / std::erf(2.0 * std::sqrt(2.0));
    default:
      return x + 0.5;
  }
}

const std::vector<PixelFilter> kFilters = {{FilterType::Box, 0.5f},
                                           {FilterType::Tent, 1.0f},
                                           {FilterType::Tent, 1.5f},
                                           {FilterType::Gaussian, 0.5f},
                                           {FilterType::Gaussian, 1.0f}};

std::string describe(const PixelFilter& f) {
  const char* names[] = {"box", "tent", "gaussian"};
  return std::string(names[size_t(f.type)]) + " " + num(f.width);
}

// Giles' polynomials against the inverse in double precision (Newton's method on std::erf).
TEST(PixelFilter, ErfInverseIsWithinAFewRoundingsOfTheExactValue) {
  double worst = 0.0;
  for (int k = -9999; k <= 9999; ++k) {
    const float x = float(k) / 10000.0f * 0.99999f;
    const double y = erfInverse(x);
    double exact = y;
    for (int i = 0; i < 4; ++i)  // erf'(y) = 2 / sqrt(pi) exp(-y^2)
      exact -=
          (std::erf(exact) - double(x)) / (2.0 / std::sqrt(kPiDouble) * std::exp(-exact * exact));
    if (x != 0.0f) worst = std::max(worst, std::fabs(y - exact) / std::fabs(exact));
  }
  EXPECT_LT(worst, 5e-7);  // 2.6e-7 measured over a million points
}

// Each filter's samples follow its distribution: F(sample(u)) = u, every offset within reach.
TEST(PixelFilter, SamplesFollowTheFiltersDistribution) {
  for (const PixelFilter& f : kFilters)
    for (int k = 0; k < 4096; ++k) {
      const float u = (float(k) + 0.5f) / 4096.0f;
      const float x = sampleFilter(f, u) - 0.5f;
      ASSERT_LE(std::fabs(x), filterRadius(f)) << describe(f) << " u " << u;
      ASSERT_NEAR(filterCdf(f, x), u, 2e-6) << describe(f) << " u " << u;
    }
}

constexpr int kSize = 48, kSpp = 1024;
constexpr double kFocal = 64.0, kDepth = 10.0;
constexpr double kU0 = 20.3, kV0 = 21.7;  // the emitter's corner in the image, in pixels

// The emitter, a rectangle light of radiance 1 facing the camera, covers the image plane to the
// right of u = kU0 and below v = kV0, to well beyond the image's edges.
RenderResult renderCorner(const PixelFilter& f) {
  const double x0 = (kU0 - kSize / 2.0) * kDepth / kFocal,
               y0 = (kV0 - kSize / 2.0) * kDepth / kFocal;
  const double far = 12.0, w = far - x0, h = far - y0;
  const char* names[] = {"\"box\"", "\"tent\", \"radius\": ", "\"gaussian\", \"stddev\": "};
  const std::string filter = R"({"type": )" + std::string(names[size_t(f.type)]) +
                             (f.type == FilterType::Box ? "" : num(f.width)) + "}";
  return test::renderTestScene(
      R"({"camera": {"width": )" + std::to_string(kSize) + R"(, "height": )" +
      std::to_string(kSize) + R"(, "spp": )" + std::to_string(kSpp) + R"(, "intrinsics": {"fx": )" +
      num(kFocal) + R"(, "fy": )" + num(kFocal) + R"(, "cx": 24,
         "cy": 24}, "extrinsics": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]},
        "render": {"max_depth": 1, "filter": )" +
      filter + R"(},
        "lights": [{"type": "rectangle", "position": [)" +
      num((x0 + far) / 2) + ", " + num((y0 + far) / 2) + ", " + num(kDepth) + R"(], "size": [)" +
      num(w) + ", " + num(h) + R"(], "direction": [0, 0, -1], "intensity": )" +
      num(kPiDouble * w * h) + "}]}");
}

// Four standard errors of the mean of n samples that are 1 with chance p and else 0, the pixels'
// noise at most (the sampler's stratification makes it far less), and one sample's worth, 1 / n,
// for where p n is too small for the normal bound.
double bound(double p, double n) { return 4.0 * std::sqrt(p * (1.0 - p) / n) + 1.0 / n; }

TEST(PixelFilter, APixelIsTheFiltersShareOfAnEmitterBeyondACorner) {
  for (const PixelFilter& f : kFilters) {
    const RenderResult r = renderCorner(f);
    const double reach = filterRadius(f);
    const auto beyond = [&](double edge, int pixel) {
      return 1.0 - filterCdf(f, edge - pixel - 0.5);
    };
    // Columns across the vertical edge, averaged over the rows that lie wholly below the other.
    const int firstFullRow = int(std::ceil(kV0 + reach));
    for (int x = int(kU0 - reach) - 1; x <= int(kU0 + reach) + 1; ++x) {
      double sum = 0.0;
      for (int y = firstFullRow; y < kSize; ++y) sum += r.image.at(x, y).x;
      const double rows = kSize - firstFullRow, expected = beyond(kU0, x);
      EXPECT_NEAR(sum / rows, expected, bound(expected, rows * kSpp)) << describe(f) << " x " << x;
    }
    // Rows across the horizontal edge, likewise.
    const int firstFullColumn = int(std::ceil(kU0 + reach));
    for (int y = int(kV0 - reach) - 1; y <= int(kV0 + reach) + 1; ++y) {
      double sum = 0.0;
      for (int x = firstFullColumn; x < kSize; ++x) sum += r.image.at(x, y).y;
      const double columns = kSize - firstFullColumn, expected = beyond(kV0, y);
      EXPECT_NEAR(sum / columns, expected, bound(expected, columns * kSpp))
          << describe(f) << " y " << y;
    }
    // The pixels about the corner, each the product of the two axes' shares.
    for (int y = int(kV0 - reach) - 1; y <= int(kV0 + reach) + 1; ++y)
      for (int x = int(kU0 - reach) - 1; x <= int(kU0 + reach) + 1; ++x) {
        const double expected = beyond(kU0, x) * beyond(kV0, y);
        EXPECT_NEAR(r.image.at(x, y).z, expected, bound(expected, kSpp))
            << describe(f) << " pixel " << x << ", " << y;
      }
  }
}

TEST(PixelFilter, TheSceneFormatRefusesWhatItCannotBe) {
  const auto error = [](const std::string& render) {
    return test::loadError(
        R"({"camera": {"width": 8, "height": 8, "fov": 40}, "render": )" + render + "}", ".");
  };
  EXPECT_EQ(error(R"({"filter": "tent"})"), "(no error)");
  EXPECT_EQ(error(R"({"filter": {"type": "gaussian", "stddev": 4}})"), "(no error)");
  EXPECT_EQ(error(R"({"filter": "gauss"})"),
            "test.json: render.filter: expected one of \"box\", \"tent\", \"gaussian\", got a "
            "string \"gauss\"");
  EXPECT_EQ(error(R"({"filter": {"type": "gaussian", "radius": 2}})"),
            "test.json: render.filter.radius: only a \"tent\" filter has one");
  EXPECT_EQ(error(R"({"filter": {"type": "tent", "radius": 0}})"),
            "test.json: render.filter.radius: expected a positive number, got 0");
  EXPECT_EQ(error(R"({"filter": {"type": "tent", "radius": 17}})"),
            "test.json: render.filter.radius: expected a radius of at most 16 pixels, got 17");
  EXPECT_EQ(error(R"({"filter": {"type": "gaussian", "stddev": 4.5}})"),
            "test.json: render.filter.stddev: expected a standard deviation of at most 4 pixels "
            "(the filter reaches 4 of them from the centre), got 4.5");
  EXPECT_EQ(error(R"({"filter": {"stddev": 1}})"),
            "test.json: render.filter: missing required key \"type\"");
  EXPECT_EQ(error(R"({"antialiasing": false, "filter": "box"})"),
            "test.json: render.filter: not used with \"antialiasing\": false (every sample goes "
            "through the pixel centre)");
}

// The intrinsics' x axis maps the image's right edge, pixel 16, to a direction of length 1.5e19,
// whose square is still a float; a filter's samples beyond the edge go further, past that.
TEST(PixelFilter, TheCameraMustGiveFiniteRaysWhereTheFilterReaches) {
  const auto error = [](const std::string& filter) {
    return test::loadError(R"({"camera": {"width": 16, "height": 16, "intrinsics": )"
                           R"({"fx": 1.0666667e-18, "fy": 16, "cx": 0, "cy": 8}},)"
                           R"( "render": {"filter": )" +
                               filter + "}}",
                           ".");
  };
  EXPECT_EQ(error(R"("box")"), "(no error)");
  EXPECT_EQ(error(R"("tent")"), "(no error)");
  EXPECT_EQ(error(R"({"type": "gaussian", "stddev": 4})"),
            "test.json: render.filter: reaches pixel (31.5, -15.5) beyond the image, where "
            "camera.intrinsics gives rays that are not finite; expected a narrower filter");
}

}  // namespace
}  // namespace candela
