// AlphaMask: how much of a material's surface is there, for the alpha test of traversal.
//
// A hit of alpha a is kept when a >= u, u a pseudo-random number hashed from the ray's origin and
// direction (pbrt-v4's GeometricPrimitive::Intersect): a = 0 is never a surface, a = 1 always, and
// in between the surface lets a fraction 1 - a of rays through, camera, bounce and shadow rays
// alike. Alpha is the product of `constant` and, when `texture` names one, the texture's channel
// `channel` (3: alpha; 0: red or the luminance, for masks without one), and for a thin dielectric
// sheet (the "thin_glass" material) of the sheet's reflectance at the ray's angle: a sheet sends
// straight on what it does not reflect, so passing the rays it transmits is exact, and shadow
// rays see through it as the light does. Only triangles are masked.
#pragma once

#include <cstdint>

#include "core/texture.h"

namespace candela {

struct AlphaMask {
  float constant = 1.0f;  // in [0, 1]
  TextureRef texture;     // index -1: none
  uint32_t channel = 3;   // of the texture (core/texture.h, textureChannel): R, A or luminance
  float thinSheetIor = 0.0f;  // above 0: a thin sheet of this relative index (the face reflects)
};

// Whether a material with this mask is ever anything but opaque.
inline bool isMasked(const AlphaMask& m) {
  return m.constant < 1.0f || m.texture.index >= 0 || m.thinSheetIor > 0.0f;
}

}  // namespace candela
