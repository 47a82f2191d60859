// The index of refraction of a glass in each colour channel, from its index at the helium d line
// and its Abbe number, by Cauchy's two-term law n(lambda) = A + B / lambda^2 (render/dispersion.h
// bends light by them).
#pragma once

namespace candela {

// The wavelengths, in micrometres, at which the Abbe number is defined (Fraunhofer's F and C
// lines, helium's d line), and those taken for the channels: the dominant wavelengths of the sRGB
// primaries.
constexpr double kLambdaF = 0.4861327, kLambdaD = 0.5875618, kLambdaC = 0.6562725;
constexpr double kChannelLambda[3] = {0.611, 0.549, 0.464};

// Cauchy's index at `lambda` for a glass of index nd at the d line and Abbe number
// abbe = (nd - 1) / (nF - nC).
inline double cauchyIndex(double nd, double abbe, double lambda) {
  const double b =
      (nd - 1.0) / (abbe * (1.0 / (kLambdaF * kLambdaF) - 1.0 / (kLambdaC * kLambdaC)));
  return nd + b * (1.0 / (lambda * lambda) - 1.0 / (kLambdaD * kLambdaD));
}

}  // namespace candela
