// A clear daylight sky without a map file: Preetham, Shirley and Smits's analytic model ("A
// Practical Analytic Model for Daylight", SIGGRAPH 1999), made into an equirectangular map of the
// environment's layout (docs/scene-format.md, Environment) when the scene loads, so that it is
// sampled and looked up as any map is.
#pragma once

#include <cstdint>
#include <optional>

#include "core/vec3.h"
#include "image/image.h"

namespace candela {

struct SkyParams {
  Vec3 sun{0.0f, 1.0f, 0.0f};  // unit, towards the sun, at or above the horizon (y >= 0)
  float turbidity = 3.0f;      // haze: 2 a very clear sky, 10 a hazy one (the model's fitted range)
  // The radiance below the horizon; absent: the horizon's at each azimuth, as haze would carry it
  // on to a distant ground.
  std::optional<Vec3> ground;
};

// The model's lowest and highest turbidity.
constexpr float kSkyTurbidityMin = 1.7f, kSkyTurbidityMax = 10.0f;

// The sky's linear sRGB radiance towards unit direction `d`: the Perez distribution of luminance
// and of chromaticity x and y about the zenith's, luminance in kcd/m^2, through CIE XYZ; each
// channel at least 0 (the model's colours near the sun can leave the sRGB gamut). Below the
// horizon, `ground` (or the horizon's).
Vec3 skyRadiance(const SkyParams& sky, const Vec3& d);

// skyRadiance at the centre of each texel of a width x height equirectangular map.
ImageRGB skyMap(const SkyParams& sky, uint32_t width, uint32_t height);

}  // namespace candela
