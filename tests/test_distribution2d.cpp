// core/distribution2d.h. Inverting a cdf through its guide gives exactly the segment the full
// binary search gives, and a point inside that segment's cell, for cdfs with plateaus (cells of
// no mass), a single dominant cell, and u at every cutpoint k / n, every cdf value and their float
// neighbours; sampled points follow the density pdf() reports.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
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

TEST(Distribution2D, SampledDensityMatchesPdf) {
  const uint32_t columns = 5, rows = 3;
  const std::vector<double> f = {1, 0, 2, 3, 1, 0, 0, 0, 0, 0, 4, 1, 1, 1, 8};
  Distribution2DArrays d;
  buildDistribution2D(f, columns, rows, &d);
  const Distribution2D sampler{d.conditional.data(),   d.marginal.data(), d.conditionalGuide.data(),
                               d.marginalGuide.data(), columns,           rows};
  std::vector<double> counts(f.size(), 0.0);
  const int n = 200000;
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  for (int i = 0; i < n; ++i) {
    float x, y, pdf;
    ASSERT_TRUE(sampler.sample(uniform(rng), uniform(rng), &x, &y, &pdf));
    ASSERT_FLOAT_EQ(pdf, sampler.pdf(x, y));
    counts[size_t(y * rows) * columns + size_t(x * columns)] += 1.0;
  }
  const double total = 22.0;
  for (size_t c = 0; c < f.size(); ++c) {
    const double expected = f[c] / total;
    EXPECT_NEAR(counts[c] / n, expected, 5.0 * std::sqrt(expected / n) + 1e-12) << "cell " << c;
  }
}

}  // namespace
}  // namespace candela
