// The Preetham sky; see sky_model.h.
#include "scene/sky_model.h"

#include <algorithm>
#include <cmath>

#include "core/constants.h"

namespace candela {
namespace {

// The Perez function's five coefficients, each a + b T in turbidity T.
struct Perez {
  double a, b, c, d, e;
};

Perez perez(const double (&coefficients)[5][2], double t) {
  double v[5];
  for (int i = 0; i < 5; ++i) v[i] = coefficients[i][0] * t + coefficients[i][1];
  return {v[0], v[1], v[2], v[3], v[4]};
}

// Preetham et al.'s Table (Appendix A.2): luminance Y and chromaticities x, y.
constexpr double kLuminance[5][2] = {
    {0.1787, -1.4630}, {-0.3554, 0.4275}, {-0.0227, 5.3251}, {0.1206, -2.5771}, {-0.0670, 0.3703}};
constexpr double kChromaX[5][2] = {{-0.0193, -0.2592},
                                   {-0.0665, 0.0008},
                                   {-0.0004, 0.2125},
                                   {-0.0641, -0.8989},
                                   {-0.0033, 0.0452}};
constexpr double kChromaY[5][2] = {{-0.0167, -0.2608},
                                   {-0.0950, 0.0092},
                                   {-0.0079, 0.2102},
                                   {-0.0441, -1.6537},
                                   {-0.0109, 0.0529}};

// F(theta, gamma) = (1 + A e^(B / cos theta)) (1 + C e^(D gamma) + E cos^2 gamma), for a view
// theta from the zenith and gamma from the sun.
double distribution(const Perez& p, double cosTheta, double gamma) {
  const double cosGamma = std::cos(gamma);
  return (1.0 + p.a * std::exp(p.b / std::max(cosTheta, 1e-6))) *
         (1.0 + p.c * std::exp(p.d * gamma) + p.e * cosGamma * cosGamma);
}

// The zenith's chromaticity: T^2, T and 1 times cubics in the sun's zenith angle.
double zenithChroma(const double (&m)[3][4], double t, double s) {
  const double sun[4] = {s * s * s, s * s, s, 1.0};
  const double turbidity[3] = {t * t, t, 1.0};
  double sum = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) sum += turbidity[i] * m[i][j] * sun[j];
  return sum;
}

constexpr double kZenithX[3][4] = {{0.00166, -0.00375, 0.00209, 0.0},
                                   {-0.02903, 0.06377, -0.03202, 0.00394},
                                   {0.11693, -0.21196, 0.06052, 0.25886}};
constexpr double kZenithY[3][4] = {{0.00275, -0.00610, 0.00317, 0.0},
                                   {-0.04214, 0.08970, -0.04153, 0.00516},
                                   {0.15346, -0.26756, 0.06670, 0.26688}};

}  // namespace

Vec3 skyRadiance(const SkyParams& sky, const Vec3& d) {
  if (d.y < 0.0f) {
    if (sky.ground) return *sky.ground;
    const float across = std::sqrt(d.x * d.x + d.z * d.z);
    return skyRadiance(
        sky, across > 0.0f ? Vec3(d.x / across, 0.0f, d.z / across) : Vec3(0.0f, 0.0f, -1.0f));
  }
  const double t = sky.turbidity;
  const double thetaSun = std::acos(std::clamp(double(sky.sun.y), -1.0, 1.0));
  const double cosGamma = std::clamp(
      double(d.x) * sky.sun.x + double(d.y) * sky.sun.y + double(d.z) * sky.sun.z, -1.0, 1.0);
  const double gamma = std::acos(cosGamma);
  const double chi = (4.0 / 9.0 - t / 120.0) * (kPiDouble - 2.0 * thetaSun);
  const double zenith[3] = {(4.0453 * t - 4.9710) * std::tan(chi) - 0.2155 * t + 2.4192,
                            zenithChroma(kZenithX, t, thetaSun),
                            zenithChroma(kZenithY, t, thetaSun)};
  const Perez models[3] = {perez(kLuminance, t), perez(kChromaX, t), perez(kChromaY, t)};
  double yxy[3];
  for (int i = 0; i < 3; ++i)
    yxy[i] =
        zenith[i] * distribution(models[i], d.y, gamma) / distribution(models[i], 1.0, thetaSun);
  // xyY -> XYZ -> linear sRGB (D65).
  const double luminance = yxy[0], x = yxy[1], y = yxy[2];
  const double bigX = x / y * luminance, bigZ = (1.0 - x - y) / y * luminance;
  const double r = 3.2404542 * bigX - 1.5371385 * luminance - 0.4985314 * bigZ;
  const double g = -0.9692660 * bigX + 1.8760108 * luminance + 0.0415560 * bigZ;
  const double b = 0.0556434 * bigX - 0.2040259 * luminance + 1.0572252 * bigZ;
  return Vec3(float(std::max(r, 0.0)), float(std::max(g, 0.0)), float(std::max(b, 0.0)));
}

ImageRGB skyMap(const SkyParams& sky, uint32_t width, uint32_t height) {
  ImageRGB map(width, height);
  for (uint32_t j = 0; j < height; ++j) {
    const double theta = kPiDouble * (j + 0.5) / height;
    for (uint32_t i = 0; i < width; ++i) {
      // The environment's mapping: u = 0.5 + atan2(d.x, -d.z) / 2 pi, v = acos(d.y) / pi.
      const double phi = 2.0 * kPiDouble * ((i + 0.5) / width - 0.5);
      const Vec3 d(float(std::sin(theta) * std::sin(phi)), float(std::cos(theta)),
                   float(-std::sin(theta) * std::cos(phi)));
      map.set(i, j, skyRadiance(sky, d));
    }
  }
  return map;
}

}  // namespace candela
