// How linear radiance becomes an 8-bit image: an exposure in stops, a tone map that brings values
// into [0, 1], then a display curve (power gamma or sRGB). Float formats (EXR, PFM) ignore it and
// keep the linear values.
#pragma once

namespace candela {

enum class GammaCurve { Power, Srgb };

// Clamp: values above 1 are 1. Reinhard: v / (1 + v). Aces: Narkowicz's 2015 fit of the ACES
// filmic curve, (v (2.51 v + 0.03)) / (v (2.43 v + 0.59) + 0.14), clamped to [0, 1]. Each channel
// alone, as Tungsten's tone maps.
enum class ToneMap { Clamp, Reinhard, Aces };

struct OutputDesc {
  GammaCurve curve = GammaCurve::Power;
  float gamma = 2.2f;
  float exposure = 0;  // stops
  ToneMap toneMap = ToneMap::Clamp;
};

}  // namespace candela
