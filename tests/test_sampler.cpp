// The padded Owen-scrambled Sobol sampler: exact stratification, bijective permutations,
// uniformity, decorrelation, purity, and a lower integration error than independent sampling.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <vector>

#include "core/rng.h"
#include "core/sobol_sampler.h"

namespace candela {
namespace {

TEST(Sampler, PermutationIsABijectionForAnyCount) {
  for (uint32_t n : {1u, 2u, 3u, 7u, 64u, 100u, 257u, 1000u}) {
    for (uint32_t seed : {0u, 1u, 0xdeadbeefu}) {
      std::set<uint32_t> seen;
      for (uint32_t i = 0; i < n; ++i) {
        const uint32_t p = permutationElement(i, n, seed);
        ASSERT_LT(p, n);
        seen.insert(p);
      }
      EXPECT_EQ(seen.size(), n) << "n=" << n << " seed=" << seed;
    }
  }
}

// A pixel's spp = 2^k samples of one 2D dimension put exactly one point in each cell of a
// 2^(k/2) x 2^(k/2) grid and in each 1/spp interval of either axis: the (0,2)-sequence property,
// which permutation and Owen scrambling preserve.
TEST(Sampler, TwoDimensionalSamplesAreStratified) {
  const uint32_t spp = 256;
  for (uint64_t pixel : {0ull, 5ull, 123456ull}) {
    for (int dimension = 0; dimension < 6; ++dimension) {
      std::vector<int> grid(256, 0), rows(256, 0), cols(256, 0);
      for (uint32_t s = 0; s < spp; ++s) {
        SampleStream stream(7, pixel, s, spp);
        float u = 0, v = 0;
        for (int d = 0; d <= dimension; ++d) stream.next2D(&u, &v);
        ASSERT_GE(u, 0.0f);
        ASSERT_LT(u, 1.0f);
        ASSERT_GE(v, 0.0f);
        ASSERT_LT(v, 1.0f);
        ++grid[int(u * 16) * 16 + int(v * 16)];
        ++rows[int(u * 256)];
        ++cols[int(v * 256)];
      }
      for (int c = 0; c < 256; ++c) {
        ASSERT_EQ(grid[c], 1) << "pixel " << pixel << " dimension " << dimension << " cell " << c;
        ASSERT_EQ(rows[c], 1);
        ASSERT_EQ(cols[c], 1);
      }
    }
  }
}

TEST(Sampler, OneDimensionalSamplesAreStratified) {
  const uint32_t spp = 64;
  std::vector<int> bins(64, 0);
  for (uint32_t s = 0; s < spp; ++s) {
    SampleStream stream(3, 99, s, spp);
    stream.next1D();
    ++bins[int(stream.next1D() * 64)];
  }
  for (int b : bins) EXPECT_EQ(b, 1);
}

// Across pixels (the independent estimates a pixel-variance test relies on), values are uniform
// and the dimensions of one sample are uncorrelated.
TEST(Sampler, UniformAndDecorrelatedAcrossPixels) {
  const int n = 100000, bins = 64;
  std::vector<int> hist(bins, 0);
  double sx = 0, sy = 0, sxy = 0, sxx = 0, syy = 0;
  for (int i = 0; i < n; ++i) {
    SampleStream stream(11, uint64_t(i), 3, 16);
    const float x = stream.next1D();
    float y, unused;
    stream.next2D(&y, &unused);
    ++hist[int(x * bins)];
    sx += x, sy += y, sxy += double(x) * y, sxx += double(x) * x, syy += double(y) * y;
  }
  double chi2 = 0;
  const double expected = double(n) / bins;
  for (int h : hist) chi2 += (h - expected) * (h - expected) / expected;
  EXPECT_LT(chi2, 120.0);  // 63 degrees of freedom: p ~ 1e-5
  const double cov = sxy / n - (sx / n) * (sy / n);
  const double corr = cov / std::sqrt((sxx / n - sx * sx / n / n) * (syy / n - sy * sy / n / n));
  EXPECT_NEAR(corr, 0.0, 0.02);
}

TEST(Sampler, IsAPureFunctionOfItsInputs) {
  SampleStream a(123, 456, 7, 64), b(123, 456, 7, 64);
  for (int d = 0; d < 50; ++d) EXPECT_EQ(a.next1D(), b.next1D());
  const float base = SampleStream(123, 456, 7, 64).next1D();
  EXPECT_NE(SampleStream(124, 456, 7, 64).next1D(), base);
  EXPECT_NE(SampleStream(123, 457, 7, 64).next1D(), base);
  EXPECT_NE(SampleStream(123, 456, 8, 64).next1D(), base);
}

// The point of the sampler: a smooth 2D integral over 64 samples has far less error than with
// independent samples (whose mean squared error is Var / 64).
TEST(Sampler, IntegratesSmoothFunctionsBetterThanIndependentSampling) {
  const auto f = [](float u, float v) { return std::sin(3.0 * u) * std::exp(v); };
  const double exact = (1.0 - std::cos(3.0)) / 3.0 * (std::exp(1.0) - 1.0);
  const uint32_t spp = 64;
  const int pixels = 2000;
  double mseSobol = 0, mseIndependent = 0;
  for (int p = 0; p < pixels; ++p) {
    double sumSobol = 0, sumIndependent = 0;
    for (uint32_t s = 0; s < spp; ++s) {
      SampleStream stream(5, uint64_t(p), s, spp);
      float u, v;
      stream.next2D(&u, &v);
      sumSobol += f(u, v);
      const uint64_t h = mix64(uint64_t(p) * 1000003ull + s);
      sumIndependent += f(toUnitFloat(h), toUnitFloat(mix64(h)));
    }
    mseSobol += std::pow(sumSobol / spp - exact, 2);
    mseIndependent += std::pow(sumIndependent / spp - exact, 2);
  }
  EXPECT_LT(mseSobol, 0.05 * mseIndependent);
}

}  // namespace
}  // namespace candela

namespace candela {
namespace {

// The stream computes its points bit-reversed; they must be exactly the scrambled Sobol points.
TEST(Sampler, ReversedDomainEqualsScrambledSobol) {
  for (uint32_t i = 0; i < 5000; ++i) {
    const uint32_t seed = i * 2654435761u + 12345u;
    EXPECT_EQ(reverseBits32(sobolDimension1Reversed(i)), sobolDimension1(i));
    EXPECT_EQ(reverseBits32(laineKarrasHash(i, seed)), owenScramble(sobolDimension0(i), seed));
    EXPECT_EQ(reverseBits32(laineKarrasHash(sobolDimension1Reversed(i), seed)),
              owenScramble(sobolDimension1(i), seed));
  }
}

// The branch-free forms against their definitions, over indices with high bits set too: the
// bit reversal bit by bit, the second dimension by sobolDimension1's loop over the index bits.
TEST(Sampler, BranchFreeFormsMatchDefinitions) {
  for (uint32_t k = 0; k < 20000; ++k) {
    const uint32_t i = k < 10000 ? k : uint32_t(mix64(k));
    uint32_t reversed = 0;
    for (int b = 0; b < 32; ++b) reversed |= ((i >> b) & 1u) << (31 - b);
    EXPECT_EQ(reverseBits32(i), reversed);
    EXPECT_EQ(reverseBits32(sobolDimension1Reversed(i)), sobolDimension1(i));
  }
}

}  // namespace
}  // namespace candela
