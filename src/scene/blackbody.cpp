// Black-body colours; see blackbody.h.
#include "scene/blackbody.h"

#include <algorithm>
#include <cmath>

namespace candela {
namespace {

// A lobe of the fit: a Gaussian of mean mu with the reciprocal widths below and above it.
double lobe(double lambda, double mu, double below, double above) {
  const double t = (lambda - mu) * (lambda < mu ? below : above);
  return std::exp(-0.5 * t * t);
}

double cieX(double l) {
  return 0.362 * lobe(l, 442.0, 0.0624, 0.0374) + 1.056 * lobe(l, 599.8, 0.0264, 0.0323) -
         0.065 * lobe(l, 501.1, 0.0490, 0.0382);
}
double cieY(double l) {
  return 0.821 * lobe(l, 568.8, 0.0213, 0.0247) + 0.286 * lobe(l, 530.9, 0.0613, 0.0322);
}
double cieZ(double l) {
  return 1.217 * lobe(l, 437.0, 0.0845, 0.0278) + 0.681 * lobe(l, 459.0, 0.0385, 0.0725);
}

// Planck's spectral radiance at `nanometres`, up to a constant factor.
double planck(double nanometres, double kelvin) {
  const double c2 = 1.4387769e7;  // h c / k_B, in nm K
  const double l = nanometres;
  return 1.0 / (l * l * l * l * l * std::expm1(c2 / (l * kelvin)));
}

}  // namespace

Vec3 blackbodyColour(double kelvin) {
  double xyz[3] = {0.0, 0.0, 0.0};
  for (double l = 360.0; l <= 830.0; l += 1.0) {
    const double p = planck(l, kelvin);
    xyz[0] += p * cieX(l);
    xyz[1] += p * cieY(l);
    xyz[2] += p * cieZ(l);
  }
  const double rgb[3] = {
      std::max(0.0, 3.2404542 * xyz[0] - 1.5371385 * xyz[1] - 0.4985314 * xyz[2]),
      std::max(0.0, -0.9692660 * xyz[0] + 1.8760108 * xyz[1] + 0.0415560 * xyz[2]),
      std::max(0.0, 0.0556434 * xyz[0] - 0.2040259 * xyz[1] + 1.0572252 * xyz[2])};
  const double luminance = 0.2126729 * rgb[0] + 0.7151522 * rgb[1] + 0.0721750 * rgb[2];
  return Vec3(float(rgb[0] / luminance), float(rgb[1] / luminance), float(rgb[2] / luminance));
}

}  // namespace candela
