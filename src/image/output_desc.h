// How linear radiance becomes an 8-bit image: a tone curve (power gamma or sRGB) after an
// exposure in stops. Float formats (EXR, PFM) ignore it and keep the linear values.
#pragma once

namespace candela {

enum class GammaCurve { Power, Srgb };

struct OutputDesc {
  GammaCurve curve = GammaCurve::Power;
  float gamma = 2.2f;
  float exposure = 0;  // stops
};

}  // namespace candela
