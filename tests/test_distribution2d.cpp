// core/distribution2d.h. Inverting a cdf through its guide gives exactly the segment the full
// binary search gives, and a point inside that segment's cell, for cdfs with plateaus (cells of
// no mass), a single dominant cell, and u at every cutpoint k / n, every cdf value and their float
// neighbours; sampled points follow the density pdf() reports, constant or bilinear within cells.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "core/distribution2d.h"

namespace candela {
namespace {

// The first segment o with cdf[o + 1] > u: what sampleCdf must find.
uint32_t searchAll(const std::vector<float>& cdf, float u) {
  const uint32_t n = uint32_t(cdf.size() - 1);
  uint32_t o = 0;
  while (o < n - 1 && cdf[o + 1] <= u) ++o;
  return o;
}

void expectGuidedSearchIsExact(const std::vector<double>& f) {
  const uint32_t n = uint32_t(f.size());
  Distribution2DArrays d;
  buildDistribution2D(f, n, 1, &d);
  const std::vector<float> cdf = d.conditional;
  std::vector<float> us;
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  for (int i = 0; i < 2000; ++i) us.push_back(uniform(rng));
  for (uint32_t k = 0; k <= n; ++k) {
    const float cut = float(k) / float(n);
    for (float u : {std::nextafter(cut, 0.0f), cut, std::nextafter(cut, 1.0f)})
      if (u >= 0.0f && u < 1.0f) us.push_back(u);
  }
  for (float c : cdf)
    for (float u : {std::nextafter(c, 0.0f), c}) us.push_back(u);
  for (float u : us) {
    if (!(u >= 0.0f && u < 1.0f)) continue;
    uint32_t segment;
    float pdf;
    const float x = sampleCdf(cdf.data(), d.conditionalGuide.data(), n, u, &segment, &pdf);
    ASSERT_EQ(segment, searchAll(cdf, u)) << "u = " << u << ", n = " << n;
    // The point lies in its segment's cell as the density lookup finds cells.
    ASSERT_EQ(uint32_t(x * float(n)), segment) << "u = " << u << ", x = " << x;
  }
}

TEST(Distribution2D, GuidedInversionFindsTheSegmentOfTheFullSearch) {
  expectGuidedSearchIsExact({1.0});
  expectGuidedSearchIsExact({1, 2, 3, 4, 5, 6, 7});
  expectGuidedSearchIsExact({0, 0, 5, 0, 0, 0, 1, 0});                // plateaus
  expectGuidedSearchIsExact({1e-9, 1e-9, 1e9, 1e-9, 0, 1e-9, 1e-9});  // one cell has it all
  std::mt19937 rng(3);
  std::exponential_distribution<double> sizes(1.0);
  for (uint32_t n : {2u, 3u, 64u, 255u, 1000u}) {
    std::vector<double> f(n);
    for (double& v : f) v = rng() % 4 == 0 ? 0.0 : std::pow(sizes(rng), 6.0);
    expectGuidedSearchIsExact(f);
  }
}

// Draws n points from `sampler` (uniform numbers seeded by `seed`), each of the density pdf()
// finds for it, and hands each to visit(cell, s, t): its cell (row-major) and where in it the
// point lies.
template <typename Visit>
void drawPoints(const Distribution2D& sampler, int n, uint32_t seed, const Visit& visit) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  for (int k = 0; k < n; ++k) {
    float x, y, pdf;
    ASSERT_TRUE(sampler.sample(uniform(rng), uniform(rng), &x, &y, &pdf));
    ASSERT_FLOAT_EQ(pdf, sampler.pdf(x, y));
    const size_t i = size_t(x * sampler.columns), j = size_t(y * sampler.rows);
    visit(j * sampler.columns + i, double(x) * sampler.columns - double(i),
          double(y) * sampler.rows - double(j));
  }
}

// Each cell drew its share of the n points: its mass over all cells' (within 5 sigma).
void expectCellShares(const std::vector<double>& counts, const std::vector<double>& mass, int n) {
  double total = 0.0;
  for (double m : mass) total += m;
  for (size_t c = 0; c < mass.size(); ++c) {
    const double expected = mass[c] / total;
    EXPECT_NEAR(counts[c] / n, expected, 5.0 * std::sqrt(expected / n) + 1e-12) << "cell " << c;
  }
}

TEST(Distribution2D, SampledDensityMatchesPdf) {
  const uint32_t columns = 5, rows = 3;
  const std::vector<double> f = {1, 0, 2, 3, 1, 0, 0, 0, 0, 0, 4, 1, 1, 1, 8};
  Distribution2DArrays d;
  buildDistribution2D(f, columns, rows, &d);
  const Distribution2D sampler{d.conditional.data(),   d.marginal.data(), d.conditionalGuide.data(),
                               d.marginalGuide.data(), columns,           rows};
  std::vector<double> counts(f.size(), 0.0);
  const int n = 200000;
  drawPoints(sampler, n, 11, [&](size_t cell, double, double) { counts[cell] += 1.0; });
  expectCellShares(counts, f, n);
}

// With weights at the cells' corners, sampled points follow the bilinear density pdf()
// reports: each cell gets its share (the mean of its corners times its row's factor), and within
// a cell the points' mean lies where the bilinear density's does.
TEST(Distribution2D, BilinearWithinCellsMatchesPdf) {
  const uint32_t columns = 3, rows = 2;
  const std::vector<float> corners = {1, 0, 0, 4,  //
                                      3, 0, 0, 1,  //
                                      0, 0, 5, 2};
  const std::vector<double> rowFactor = {1.0, 0.5};
  Distribution2DArrays d;
  buildBilinearDistribution2D(corners, rowFactor, columns, rows, &d);
  const Distribution2D sampler{d.conditional.data(),   d.marginal.data(), d.conditionalGuide.data(),
                               d.marginalGuide.data(), columns,           rows,
                               d.corners.data()};
  std::vector<double> mass(columns * rows);
  for (uint32_t j = 0; j < rows; ++j)
    for (uint32_t i = 0; i < columns; ++i) {
      const float* top = corners.data() + j * (columns + 1) + i;
      mass[j * columns + i] = 0.25 * (top[0] + top[1] + top[4] + top[5]) * rowFactor[j];
    }
  std::vector<double> counts(mass.size(), 0.0), sumS(mass.size(), 0.0), sumT(mass.size(), 0.0);
  const int n = 200000;
  drawPoints(sampler, n, 5, [&](size_t cell, double s, double t) {
    counts[cell] += 1.0;
    sumS[cell] += s;
    sumT[cell] += t;
  });
  expectCellShares(counts, mass, n);
  for (size_t c = 0; c < mass.size(); ++c) {
    if (counts[c] < 1000) continue;
    const size_t i = c % columns, j = c / columns;
    const float* top = corners.data() + j * (columns + 1) + i;
    const double w0 = top[0], w1 = top[1], w2 = top[4], w3 = top[5], sum = w0 + w1 + w2 + w3;
    // The mean of s over the bilinear density: (w0 + w2) / 3 + (w1 + w3) 2 / 3, over the sum /
    // 2 (each linear factor integrates so); likewise t.
    const double meanS = ((w0 + w2) / 6 + (w1 + w3) / 3) / (sum / 4) / 2;
    const double meanT = ((w0 + w1) / 6 + (w2 + w3) / 3) / (sum / 4) / 2;
    const double error = 5.0 * std::sqrt(1.0 / 12 / counts[c]);
    EXPECT_NEAR(sumS[c] / counts[c], meanS, error) << "cell " << c;
    EXPECT_NEAR(sumT[c] / counts[c], meanT, error) << "cell " << c;
  }
  EXPECT_EQ(sampler.pdf(0.5f, 0.25f), 0.0f);  // a cell whose corners are all 0
}

// sampleLinear inverts the cumulative distribution of the density (1 - x) a + x b, nearly equal
// weights and a weight of 0 included; sampleBilinear and bilinearPdf stay finite on a line of no
// mass, where the density is 0.
TEST(Distribution2D, LinearWarpInvertsItsCdf) {
  for (const auto& ab :
       {std::pair<float, float>{1, 3}, {3, 1}, {0, 2}, {2, 0}, {5, 5}, {1, 1.0001f}, {1e-6f, 7}}) {
    const double a = ab.first, b = ab.second;
    for (float u : {0.0f, 1e-7f, 0.1f, 0.5f, 0.9f, 0.99999994f}) {
      const double x = sampleLinear(u, ab.first, ab.second);
      ASSERT_GE(x, 0.0);
      ASSERT_LT(x, 1.0);
      const double cdf = (a * x + 0.5 * (b - a) * x * x) / (0.5 * (a + b));
      EXPECT_NEAR(cdf, u, 2e-6) << "a " << a << " b " << b << " u " << u;
    }
  }
  const float w[4] = {0, 0, 5, 0};  // only the corner (0, 1) has weight: y = 0 has no mass
  float x, y;
  sampleBilinear(0.3f, 0.0f, w, &x, &y);
  EXPECT_EQ(y, 0.0f);
  EXPECT_TRUE(std::isfinite(x));
  EXPECT_EQ(bilinearPdf(x, y, w), 0.0f);
  sampleBilinear(0.3f, 0.6f, w, &x, &y);
  EXPECT_GT(bilinearPdf(x, y, w), 0.0f);
  const float none[4] = {0, 0, 0, 0};
  EXPECT_EQ(bilinearPdf(0.5f, 0.5f, none), 0.0f);
}

}  // namespace
}  // namespace candela
