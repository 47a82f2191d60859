// The colour of a black body's light, for lights and emitters given by temperature (a 3200 K
// tungsten lamp, a 5600 K daylight panel), as Cycles' Blackbody node and lighting desks give them.
#pragma once

#include "core/vec3.h"

namespace candela {

constexpr double kBlackbodyMinKelvin = 1000.0, kBlackbodyMaxKelvin = 40000.0;

// Linear sRGB of Planck's spectrum at `kelvin` (kBlackbodyMin to MaxKelvin), scaled to luminance
// 1, so that a light's intensity or an emitter's strength keeps its meaning: the spectrum through
// the CIE 1931 2-degree observer (Wyman, Sloan and Shirley's multi-lobe fit, JCGT 2013) from 360
// to 830 nm, XYZ to sRGB's primaries, a channel below 0 (the reddest, outside sRGB's gamut) held
// at 0 before the scaling.
Vec3 blackbodyColour(double kelvin);

}  // namespace candela
