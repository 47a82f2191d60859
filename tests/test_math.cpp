// Core math: vectors, orthonormal frames, the counter-based RNG and the sample warps.
//
// Statistical tests run on fixed seeds, so they are deterministic; their thresholds are set at a
// 1e-3 significance level (chi-square) or five standard deviations (means, correlations).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "core/constants.h"
#include "core/float_error.h"
#include "core/frame.h"
#include "core/oct_normal.h"
#include "core/rng.h"
#include "core/sampling.h"
#include "core/trig.h"
#include "core/vec3.h"
#include "test_random.h"

namespace candela {
namespace {

using test::randomUnitVector;

constexpr int kDraws = 100000;
constexpr int kBins = 64;

// Upper 1e-3 quantile of the chi-square distribution with `dof` degrees of freedom
// (Wilson–Hilferty approximation, accurate to a fraction of a percent for dof >= 30).
double chiSquareCritical(int dof) {
  const double z = 3.090232;  // standard normal quantile for 1 - 1e-3
  const double k = dof;
  const double h = 2.0 / (9.0 * k);
  return k * std::pow(1.0 - h + z * std::sqrt(h), 3.0);
}

// Chi-square statistic of values in [0, 1) against the uniform distribution over kBins bins.
double chiSquareUniform(const std::vector<float>& values) {
  std::vector<double> counts(kBins, 0.0);
  for (float v : values) counts[std::min(kBins - 1, static_cast<int>(v * kBins))] += 1.0;
  const double expected = static_cast<double>(values.size()) / kBins;
  double chi2 = 0.0;
  for (double c : counts) chi2 += (c - expected) * (c - expected) / expected;
  return chi2;
}

double mean(const std::vector<float>& v) {
  double sum = 0.0;
  for (float x : v) sum += x;
  return sum / v.size();
}

void expectUniform(const std::vector<float>& values, const char* what) {
  for (float v : values) {
    ASSERT_GE(v, 0.0f) << what;
    ASSERT_LT(v, 1.0f) << what;
  }
  EXPECT_LT(chiSquareUniform(values), chiSquareCritical(kBins - 1)) << what;
  // The mean of n uniform numbers has standard deviation sqrt(1 / (12 n)).
  EXPECT_NEAR(mean(values), 0.5, 5.0 * std::sqrt(1.0 / (12.0 * values.size()))) << what;
}

void expectNearVec(const Vec3& a, const Vec3& b, float tol) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

TEST(VecMath, DotCrossNormalize) {
  const Vec3 a(1, 2, 3), b(-4, 5, 0.5f);
  EXPECT_FLOAT_EQ(dot(a, b), -4 + 10 + 1.5f);
  expectNearVec(cross(Vec3(1, 0, 0), Vec3(0, 1, 0)), Vec3(0, 0, 1), 0.0f);
  expectNearVec(cross(Vec3(0, 1, 0), Vec3(0, 0, 1)), Vec3(1, 0, 0), 0.0f);
  expectNearVec(cross(a, b), -cross(b, a), 0.0f);
  const Vec3 c = cross(a, b);
  EXPECT_NEAR(dot(c, a), 0.0f, 1e-5f);
  EXPECT_NEAR(dot(c, b), 0.0f, 1e-5f);
  // |a x b|^2 = |a|^2 |b|^2 - (a.b)^2 (Lagrange's identity).
  EXPECT_NEAR(lengthSquared(c), lengthSquared(a) * lengthSquared(b) - dot(a, b) * dot(a, b), 1e-3f);
  EXPECT_FLOAT_EQ(length(Vec3(3, 4, 12)), 13.0f);
  EXPECT_NEAR(length(normalize(a)), 1.0f, 1e-6f);
  expectNearVec(normalize(Vec3(0, 0, -7)), Vec3(0, 0, -1), 0.0f);
  expectNearVec(faceForward(Vec3(0, 0, 1), Vec3(0, 0, -1)), Vec3(0, 0, -1), 0.0f);
  EXPECT_EQ(maxDimension(Vec3(1, -5, 3)), 2);
  EXPECT_EQ(maxDimension(abs(Vec3(1, -5, 3))), 1);
}

TEST(Frame, OrthonormalAndRightHandedForManyNormals) {
  std::vector<Vec3> normals = {{0, 0, 1},
                               {0, 0, -1},
                               {1, 0, 0},
                               {0, 1, 0},
                               {-1, 0, 0},
                               {0, -1, 0},
                               normalize(Vec3(1e-4f, 0, -1)),
                               normalize(Vec3(0, -1e-7f, -1)),
                               normalize(Vec3(1, 1, 1))};
  std::mt19937 gen(7);
  for (int i = 0; i < 10000; ++i) normals.push_back(randomUnitVector(gen));
  for (const Vec3& n : normals) {
    const Frame f(n);
    EXPECT_NEAR(length(f.s), 1.0f, 1e-5f);
    EXPECT_NEAR(length(f.t), 1.0f, 1e-5f);
    EXPECT_NEAR(dot(f.s, f.t), 0.0f, 1e-5f);
    EXPECT_NEAR(dot(f.s, f.n), 0.0f, 1e-5f);
    EXPECT_NEAR(dot(f.t, f.n), 0.0f, 1e-5f);
    expectNearVec(cross(f.s, f.t), n, 1e-5f);
  }
}

// A wall's normal whose z is 0 only up to rounding (exactly 0 from a cross product on the CPU,
// +-1e-9 where the GPU fuses a multiply-add) gets one frame, not two mirrored ones that would send
// a sample in different directions on the two backends.
TEST(Frame, NormalsWithZeroZUpToRoundingShareTheirFrame) {
  const Vec3 wall = normalize(Vec3(-0.99998f, 0.0058f, 0.0f));
  const Frame f(wall);
  for (const float z : {-0.0f, 1e-9f, -1e-9f, 3e-8f, -3e-8f}) {
    const Frame g(Vec3(wall.x, wall.y, z));
    expectNearVec(g.s, f.s, 1e-6f);
    expectNearVec(g.t, f.t, 1e-6f);
  }
}

TEST(OctNormal, RoundTripWithinSeventyMicroradians) {
  std::mt19937 gen(5);
  std::normal_distribution<float> g(0.0f, 1.0f);
  double worst = 0.0;
  std::vector<Vec3> normals = {Vec3(0, 0, -1), Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(-1, 0, 0),
                               Vec3(0, 1, 0), Vec3(0, -1, 0), normalize(Vec3(-1, -1, -1e-7f))};
  for (int i = 0; i < 200000; ++i) normals.push_back(normalize(Vec3(g(gen), g(gen), g(gen))));
  for (const Vec3& n : normals) {
    const OctNormal o = encodeOctNormal(n);
    ASSERT_FALSE(o.isNone());
    const Vec3 d = decodeOctNormal(o);
    EXPECT_NEAR(length(d), 1.0f, 1e-6f);
    // The chord between unit vectors is their angle to within its cube; acos of a float dot
    // product would drown 3e-5 in rounding.
    const double dx = double(d.x) - n.x, dy = double(d.y) - n.y, dz = double(d.z) - n.z;
    worst = std::max(worst, std::sqrt(dx * dx + dy * dy + dz * dz));
  }
  EXPECT_LT(worst, 7e-5);
  EXPECT_GT(worst, 1e-6);  // the encoding is lossy: a test of nothing would show 0
  // Length does not matter; zero and non-finite vectors mean "no normal".
  EXPECT_EQ(encodeOctNormal(Vec3(0, 3, 4)).bits, encodeOctNormal(Vec3(0, 0.6f, 0.8f)).bits);
  EXPECT_TRUE(encodeOctNormal(Vec3(0.0f)).isNone());
  EXPECT_TRUE(encodeOctNormal(Vec3(std::numeric_limits<float>::infinity(), 0, 0)).isNone());
  EXPECT_TRUE(encodeOctNormal(Vec3(std::nanf(""), 0, 1)).isNone());
  EXPECT_TRUE(OctNormal().isNone());
}

TEST(Frame, LocalWorldRoundTrip) {
  std::mt19937 gen(11);
  for (int i = 0; i < 10000; ++i) {
    const Vec3 n = i == 0 ? Vec3(0, 0, -1) : randomUnitVector(gen);
    const Frame f(n);
    expectNearVec(f.toLocal(n), Vec3(0, 0, 1), 1e-5f);
    const Vec3 v = randomUnitVector(gen) * 3.0f;
    expectNearVec(f.toWorld(f.toLocal(v)), v, 1e-5f);
    expectNearVec(f.toLocal(f.toWorld(v)), v, 1e-5f);
  }
}

// Independent uniform numbers from the counter-based hash, for the warping tests below.
struct HashUniform {
  uint64_t key;
  uint64_t counter = 0;
  HashUniform(uint64_t seed, uint64_t stream, uint64_t) : key(mix64(mix64(seed) ^ stream)) {}
  float next() { return toUnitFloat(mix64(key + 0x9e3779b97f4a7c15ull * ++counter)); }
};

TEST(Sampling, CosineHemisphereDensityIntegratesToOne) {
  // Monte Carlo integral of the pdf over the hemisphere with uniformly distributed directions
  // (cos theta uniform in [0, 1), density 1 / 2pi): the mean of pdf * 2pi estimates it.
  double sum = 0.0;
  for (int i = 0; i < kDraws; ++i) {
    HashUniform s(5, i, 0);
    sum += cosineHemispherePdf(s.next()) * 2.0 * kPi;
  }
  // The estimator 2 cos(theta) has variance 1/3.
  EXPECT_NEAR(sum / kDraws, 1.0, 5.0 * std::sqrt(1.0 / 3.0 / kDraws));
}

TEST(Sampling, CosineHemisphereDirectionsFollowTheirDensity) {
  std::vector<float> cos2, azimuth;
  for (int i = 0; i < kDraws; ++i) {
    HashUniform s(6, i, 0);
    const float u1 = s.next(), u2 = s.next();
    const Vec3 w = sampleCosineHemisphere(u1, u2);
    ASSERT_GE(w.z, 0.0f);
    ASSERT_NEAR(length(w), 1.0f, 1e-5f);
    // Under the density cos(theta) / pi, cos^2(theta) and the azimuth are uniform.
    cos2.push_back(std::min(w.z * w.z, kOneMinusEpsilon));
    float phi = std::atan2(w.y, w.x) / (2.0f * kPi);
    if (phi < 0.0f) phi += 1.0f;
    azimuth.push_back(std::min(phi, kOneMinusEpsilon));
  }
  expectUniform(cos2, "cos^2 theta");
  expectUniform(azimuth, "azimuth");
  // Corners of the unit square still give unit vectors in the upper hemisphere.
  for (float u1 : {0.0f, 0.5f, kOneMinusEpsilon})
    for (float u2 : {0.0f, 0.5f, kOneMinusEpsilon}) {
      const Vec3 w = sampleCosineHemisphere(u1, u2);
      EXPECT_GE(w.z, 0.0f);
      EXPECT_NEAR(length(w), 1.0f, 1e-5f);
    }
}

TEST(Sampling, ConeSamplesStayInsideTheCone) {
  for (float cosThetaMax : {-0.5f, 0.0f, 0.5f, 0.99f, 0.999999f}) {
    std::vector<float> heights;
    for (int i = 0; i < kDraws; ++i) {
      HashUniform s(8, i, 0);
      const float u1 = s.next(), u2 = s.next();
      const Vec3 w = sampleUniformCone(u1, u2, 1.0f - cosThetaMax);
      ASSERT_GE(w.z, cosThetaMax - 1e-6f);
      ASSERT_LE(w.z, 1.0f);
      ASSERT_NEAR(length(w), 1.0f, 1e-5f);
      // Uniform over the cap's solid angle: cos(theta) is uniform in [cosThetaMax, 1].
      if (cosThetaMax < 0.99f)
        heights.push_back(std::min((w.z - cosThetaMax) / (1.0f - cosThetaMax), kOneMinusEpsilon));
    }
    if (!heights.empty()) expectUniform(heights, "cone height");
    // The density times the cap's solid angle 2pi (1 - cosThetaMax) is 1.
    EXPECT_NEAR(uniformConePdf(1.0f - cosThetaMax) * 2.0f * kPi * (1.0f - cosThetaMax), 1.0f, 1e-5f);
  }
}

TEST(Sampling, ConcentricDiskStaysInsideTheUnitDisk) {
  std::vector<float> radius2, angle;
  for (int i = 0; i < kDraws; ++i) {
    HashUniform s(4, i, 0);
    const float u1 = s.next(), u2 = s.next();
    float x, y;
    sampleUniformDisk(u1, u2, &x, &y);
    ASSERT_LE(x * x + y * y, 1.0f + 1e-6f);
    // Uniform over the disk: r^2 and the angle are uniform.
    radius2.push_back(std::min(x * x + y * y, kOneMinusEpsilon));
    float phi = std::atan2(y, x) / (2.0f * kPi);
    if (phi < 0.0f) phi += 1.0f;
    angle.push_back(std::min(phi, kOneMinusEpsilon));
  }
  expectUniform(radius2, "disk r^2");
  expectUniform(angle, "disk angle");
  for (float u1 : {0.0f, 0.5f, kOneMinusEpsilon})
    for (float u2 : {0.0f, 0.5f, kOneMinusEpsilon}) {
      float x, y;
      sampleUniformDisk(u1, u2, &x, &y);
      EXPECT_LE(x * x + y * y, 1.0f + 1e-6f);
    }
}

// The polynomial sine and cosine the disk map uses, against the double-precision library over
// their whole range [-pi/4, pi/4], ends included: within 3e-7, a few float ulps.
TEST(Sampling, QuarterPiSineAndCosineMatchTheLibrary) {
  double worst = 0.0;
  for (int i = 0; i <= 200000; ++i) {
    const float x = -kPi / 4.0f + (kPi / 2.0f) * float(i) / 200000.0f;
    float s, c;
    sinCosQuarterPi(x, &s, &c);
    worst = std::max({worst, std::abs(double(s) - std::sin(double(x))),
                      std::abs(double(c) - std::cos(double(x)))});
  }
  EXPECT_LT(worst, 3e-7);
  float s, c;
  sinCosQuarterPi(0.0f, &s, &c);
  EXPECT_EQ(s, 0.0f);
  EXPECT_EQ(c, 1.0f);
}

}  // namespace
}  // namespace candela

namespace candela {
namespace {

// nextFloatUp/Down step the bit pattern; they must agree with the C library everywhere.
TEST(FloatError, NextFloatMatchesNextafter) {
  std::vector<float> values = {0.0f, -0.0f, 1.0f, -1.0f, 1e-40f, -1e-40f, 3.4e38f, -3.4e38f,
                               1e-3f, -1e4f, 0x1p-149f, -0x1p-149f};
  std::mt19937 gen(3);
  std::uniform_real_distribution<float> exponent(-40.0f, 38.0f);
  for (int i = 0; i < 10000; ++i)
    values.push_back((i % 2 ? -1.0f : 1.0f) * std::pow(10.0f, exponent(gen)));
  for (float v : values) {
    EXPECT_EQ(nextFloatUp(v), std::nextafter(v == 0.0f ? 0.0f : v, INFINITY)) << v;
    EXPECT_EQ(nextFloatDown(v), std::nextafter(v == 0.0f ? -0.0f : v, -INFINITY)) << v;
  }
  EXPECT_EQ(nextFloatUp(INFINITY), INFINITY);
  EXPECT_EQ(nextFloatDown(-INFINITY), -INFINITY);
}

// The rounding in offsetRayOrigin against its definition: each coordinate of p +
// offset moved one float further along the offset's sign, and left alone where the offset is 0.
TEST(FloatError, OffsetRayOriginRoundsAwayFromThePoint) {
  std::mt19937 gen(7);
  std::uniform_real_distribution<float> coordinate(-100.0f, 100.0f), unit(-1.0f, 1.0f);
  for (int i = 0; i < 20000; ++i) {
    const Vec3 p(coordinate(gen), i % 3 == 0 ? 0.0f : coordinate(gen), coordinate(gen));
    const Vec3 error(1e-4f * std::abs(unit(gen)), 1e-4f, 1e-5f);
    // Every fourth normal lies along an axis, so some offsets are exactly 0.
    const Vec3 n = i % 4 == 0 ? Vec3(0.0f, i % 8 == 0 ? 1.0f : -1.0f, 0.0f)
                              : normalize(Vec3(unit(gen), unit(gen), unit(gen)));
    const Vec3 w(unit(gen), unit(gen), unit(gen));
    Vec3 offset = n * dot(abs(n), error);
    if (dot(w, n) < 0.0f) offset = -offset;
    const Vec3 po = offsetRayOrigin(p, error, n, w);
    for (int a = 0; a < 3; ++a) {
      const float sum = p[a] + offset[a];
      const float expected = offset[a] > 0.0f   ? std::nextafter(sum, INFINITY)
                             : offset[a] < 0.0f ? std::nextafter(sum, -INFINITY)
                                                : sum;
      EXPECT_EQ(po[a], expected) << "axis " << a << " p " << p[a] << " offset " << offset[a];
    }
  }
}

// atan2Approx against the library's atan2 in double, over every octant, the axes, signed zeros
// and tiny and huge arguments.
TEST(Trig, Atan2ApproxIsWithinTwoUlpsOfPi) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> angle(-3.2f, 3.2f), scale(-30.0f, 30.0f);
  double worst = 0.0;
  for (int i = 0; i < 200000; ++i) {
    const float a = angle(rng), r = std::exp2(scale(rng));
    const float y = r * std::sin(a), x = r * std::cos(a);
    worst = std::max(worst, std::fabs(double(atan2Approx(y, x)) - std::atan2(double(y), double(x))));
  }
  EXPECT_LT(worst, 3.5e-7);
  for (float y : {0.0f, -0.0f, 1.0f, -1.0f, 1e-30f, -1e30f})
    for (float x : {0.0f, -0.0f, 1.0f, -1.0f, 1e-30f, 1e30f}) {
      if (y == 0.0f && x == 0.0f) continue;
      EXPECT_NEAR(atan2Approx(y, x), std::atan2(y, x), 3.5e-7) << y << ", " << x;
    }
  EXPECT_EQ(atan2Approx(0.0f, 0.0f), 0.0f);  // the poles of the map: any u will do
  EXPECT_EQ(std::signbit(atan2Approx(-0.0f, -1.0f)), std::signbit(std::atan2(-0.0f, -1.0f)));
}

}  // namespace
}  // namespace candela
