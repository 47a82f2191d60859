// Unpolarised Fresnel reflectance of a smooth dielectric (fresnelDielectric, render/fresnel.h):
// known closed-form values (normal and grazing incidence, Brewster's angle, total internal
// reflection), a table against the full Fresnel equations, and reciprocity between the two sides
// of an interface.
//
// References are computed in double precision from the same float inputs the function gets, in
// the angle form of the Fresnel equations (sine and tangent laws), not the cosine form the
// function uses.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "render/fresnel.h"

namespace candela {
namespace {

constexpr double kPi = 3.14159265358979323846;

double radians(double degrees) { return degrees * kPi / 180.0; }

// Unpolarised reflectance at incidence angle thetaI (radians, in (0, pi/2)) from a medium of
// index 1 into one of index eta, from Fresnel's sine and tangent laws: Rs = sin^2(i - t) /
// sin^2(i + t), Rp = tan^2(i - t) / tan^2(i + t), with Snell's law sin t = sin i / eta. 1 under
// total internal reflection.
double referenceReflectance(double thetaI, double eta) {
  const double sinT = std::sin(thetaI) / eta;
  if (sinT >= 1.0) return 1.0;
  const double thetaT = std::asin(sinT);
  const double rs = std::sin(thetaI - thetaT) / std::sin(thetaI + thetaT);
  const double rp = std::tan(thetaI - thetaT) / std::tan(thetaI + thetaT);
  return 0.5 * (rs * rs + rp * rp);
}

// Cosine of the refraction angle for incidence cosine cosI into relative index eta (no total
// internal reflection).
double refractedCos(double cosI, double eta) {
  return std::sqrt(1.0 - (1.0 - cosI * cosI) / (eta * eta));
}

TEST(FresnelDielectric, NormalIncidenceIsSquaredIndexRatio) {
  EXPECT_NEAR(fresnelDielectric(1.0f, 1.5f), 0.04, 1e-7);
  // The same from the dense side: ((1/eta - 1) / (1/eta + 1))^2 = ((eta - 1) / (eta + 1))^2.
  EXPECT_NEAR(fresnelDielectric(1.0f, 1.0f / 1.5f), 0.04, 1e-7);
  for (const float eta : {1.33f, 1.0f / 1.33f, 2.4f}) {
    SCOPED_TRACE(eta);
    const double r = (double(eta) - 1.0) / (double(eta) + 1.0);
    EXPECT_NEAR(fresnelDielectric(1.0f, eta), r * r, 1e-7);
  }
}

TEST(FresnelDielectric, MatchedIndicesReflectNothing) {
  // Not exactly 0: cos t = sqrt(1 - (1 - cos^2 i)) rounds away from cos i.
  for (const float cosI : {1.0f, 0.7f, 0.2f}) EXPECT_NEAR(fresnelDielectric(cosI, 1.0f), 0.0, 1e-7);
}

TEST(FresnelDielectric, GrazingIncidenceReflectsEverything) {
  for (const float eta : {1.5f, 1.33f}) {
    SCOPED_TRACE(eta);
    EXPECT_FLOAT_EQ(fresnelDielectric(0.0f, eta), 1.0f);
    // And it approaches 1 continuously.
    EXPECT_NEAR(fresnelDielectric(1e-4f, eta), 1.0f, 1e-3);
  }
}

TEST(FresnelDielectric, TotalInternalReflectionBeyondTheCriticalAngleIsExactlyOne) {
  const float eta = 1.0f / 1.5f;
  const double critical = std::asin(double(eta));  // about 41.8 degrees
  for (const double beyond : {0.5, 5.0, 20.0, 40.0, 48.0}) {
    const float cosI = static_cast<float>(std::cos(critical + radians(beyond)));
    SCOPED_TRACE(cosI);
    EXPECT_EQ(fresnelDielectric(cosI, eta), 1.0f);
  }
  EXPECT_EQ(fresnelDielectric(0.0f, eta), 1.0f);
}

TEST(FresnelDielectric, AtBrewstersAngleOnlySPolarisationIsReflected) {
  // At Brewster's angle atan(eta) the refracted and reflected rays are perpendicular, so Rp = 0
  // and cos t = sin i, which makes rs = (1 - eta^2) / (1 + eta^2).
  for (const float eta : {1.5f, 1.33f, 1.0f / 1.5f, 1.0f / 1.33f}) {
    SCOPED_TRACE(eta);
    const double e2 = double(eta) * double(eta);
    const double rs = (1.0 - e2) / (1.0 + e2);
    const float cosBrewster = static_cast<float>(std::cos(std::atan(double(eta))));
    EXPECT_NEAR(fresnelDielectric(cosBrewster, eta), 0.5 * rs * rs, 1e-6);
  }
}

TEST(FresnelDielectric, MatchesTheFresnelEquationsAtTabulatedAngles) {
  struct Case {
    float eta;
    double degrees[6];
  };
  // From the dense side only angles below the critical one (41.8 and 48.8 degrees), and not so
  // close to it that float cancellation in cos t dominates.
  const Case cases[] = {
      {1.5f, {10, 30, 45, 60, 75, 85}},
      {1.33f, {10, 30, 45, 60, 75, 85}},
      {1.0f / 1.5f, {5, 10, 20, 30, 35, 40}},
      {1.0f / 1.33f, {5, 10, 20, 30, 40, 45}},
  };
  for (const Case& c : cases) {
    for (const double degrees : c.degrees) {
      SCOPED_TRACE(testing::Message() << "eta " << c.eta << ", " << degrees << " degrees");
      const float cosI = static_cast<float>(std::cos(radians(degrees)));
      const double expected = referenceReflectance(std::acos(double(cosI)), double(c.eta));
      EXPECT_NEAR(fresnelDielectric(cosI, c.eta), expected, 1e-5);
    }
  }
}

TEST(FresnelDielectric, ReferenceMatchesTextbookGlassValues) {
  // The reference itself, against the usual four-digit values for glass (eta 1.5): at 45 degrees
  // Rs = 0.0920 and Rp = 0.0085, so F = 0.0502; at 60 degrees Rs = 0.1766 and Rp = 0.0018, so
  // F = 0.0892.
  EXPECT_NEAR(referenceReflectance(radians(45.0), 1.5), 0.0502, 1e-4);
  EXPECT_NEAR(referenceReflectance(radians(60.0), 1.5), 0.0892, 1e-4);
}

TEST(FresnelDielectric, ReflectanceIsTheSameFromBothSidesOfTheInterface) {
  // Light refracted from cos i into cos t meets the same reflectance when it comes back along
  // the refracted direction: F(cos i, eta) = F(cos t, 1 / eta).
  for (const float eta : {1.5f, 1.33f}) {
    for (int k = 1; k <= 20; ++k) {
      const float cosI = 0.05f * static_cast<float>(k);
      SCOPED_TRACE(testing::Message() << "eta " << eta << ", cos i " << cosI);
      const float cosT = static_cast<float>(refractedCos(double(cosI), double(eta)));
      EXPECT_NEAR(fresnelDielectric(cosI, eta), fresnelDielectric(cosT, 1.0f / eta), 1e-5);
    }
  }
}

// A conductor's reflectance (fresnelConductor) against the Fresnel equations in complex
// arithmetic: r_s = (cos i - n cos t) / (cos i + n cos t), r_p = (n cos i - cos t) /
// (n cos i + cos t), n = eta + i k, cos t = sqrt(1 - sin^2 i / n^2).
double referenceConductor(double cosI, double eta, double k) {
  const std::complex<double> n(eta, k);
  const std::complex<double> cosT = std::sqrt(1.0 - (1.0 - cosI * cosI) / (n * n));
  const std::complex<double> rs = (cosI - n * cosT) / (cosI + n * cosT);
  const std::complex<double> rp = (n * cosI - cosT) / (n * cosI + cosT);
  return 0.5 * (std::norm(rs) + std::norm(rp));
}

TEST(FresnelConductor, MatchesTheComplexFresnelEquations) {
  const double metals[][2] = {{0.143, 3.983}, {1.6575, 9.2238}, {4.3697, 5.2066}, {0.2, 0.0},
                              {1.5, 0.0}};
  for (const auto& m : metals)
    for (double cosI : {1.0, 0.9, 0.6, 0.3, 0.1, 0.01}) {
      const double expected = referenceConductor(cosI, m[0], m[1]);
      EXPECT_NEAR(fresnelConductor(float(cosI), float(m[0]), float(m[1])), expected,
                  2e-5 + 1e-4 * expected)
          << "eta " << m[0] << " k " << m[1] << " cos " << cosI;
    }
  // Normal incidence: ((eta - 1)^2 + k^2) / ((eta + 1)^2 + k^2); grazing: 1.
  EXPECT_NEAR(fresnelConductor(1.0f, 0.143f, 3.983f),
              ((0.143 - 1) * (0.143 - 1) + 3.983 * 3.983) / (1.143 * 1.143 + 3.983 * 3.983), 1e-5);
  EXPECT_NEAR(fresnelConductor(0.0f, 0.143f, 3.983f), 1.0f, 1e-5f);
  // With k = 0 it is the dielectric's reflectance.
  EXPECT_NEAR(fresnelConductor(0.5f, 1.5f, 0.0f), fresnelDielectric(0.5f, 1.5f), 1e-6f);
}

}  // namespace
}  // namespace candela
