// Light profiles: how a point or spot light's intensity varies with direction, as an IES file
// (scene/read/ies_profile.h) gives it for a real fixture.
//
// A profile is a table of relative intensities over the light's type C angles, resampled on a
// regular grid and kept as a float texture of the scene's pool: row j holds vertical angle theta =
// j / (kProfileRows - 1) * 180 degrees from the light's axis (its nadir, where it points), column
// i the C-plane phi = i / columns * 360 degrees, counted from the light's C0 direction towards its
// C90 direction (counter-clockwise seen from behind the axis, as the IES convention has it seen
// from above a downlight). A profile of one column is the same in every C-plane. Between grid
// points the intensity is bilinear (wrapping around in phi); rows beyond the file's vertical
// angles repeat its last ones, and the lookup cuts there. `scale` makes its mean over the sphere
// 1, so that the light's power stays `intensity`.
#pragma once

#include <cmath>
#include <cstdint>

#include "core/constants.h"
#include "core/texture.h"
#include "core/vec3.h"

namespace candela {

constexpr uint32_t kProfileRows = 361;     // 0.5 degrees apart
constexpr uint32_t kProfileColumns = 144;  // 2.5 degrees apart, where the profile has C-planes

struct LightProfile {
  int32_t texture = -1;  // into the scene's textures; -1: none (the same in every direction)
  Vec3 axis{0.0f, -1.0f, 0.0f};  // theta 0
  Vec3 c0{0.0f, 0.0f, 1.0f};     // phi 0, perpendicular to the axis
  Vec3 c90{1.0f, 0.0f, 0.0f};    // phi 90 degrees
  float scale = 1.0f;            // 1 / the table's mean over the sphere
  // The cosines of the vertical angles the file's values begin and end at (0 or 90 degrees, 90
  // or 180): the light sends nothing outside them, with an edge as sharp as the file's.
  float cosFirst = 1.0f, cosLast = -1.0f;
};

// profileFactor of a light that has a profile. Out of line: most lights have none.
CANDELA_HD_NOINLINE inline float profileLookup(const TexturePool& pool, const LightProfile& p,
                                               const Vec3& d) {
  const Texture& t = pool.textures[p.texture];
  const float* texels = pool.texelsF + t.offset;
  const float cosTheta = fminf(fmaxf(dot(d, p.axis), -1.0f), 1.0f);
  if (cosTheta > p.cosFirst || cosTheta < p.cosLast) return 0.0f;
  const float y = acosf(cosTheta) * (float(t.height - 1) * kInvPi);
  const uint32_t y0 = uint32_t(fminf(y, float(t.height - 2)));
  const float fy = fminf(y - float(y0), 1.0f);
  float fx = 0.0f;
  uint32_t x0 = 0, x1 = 0;
  if (t.width > 1) {
    float phi = atan2f(dot(d, p.c90), dot(d, p.c0));
    if (phi < 0.0f) phi += 2.0f * kPi;
    const float x = phi * (float(t.width) * 0.5f * kInvPi);
    x0 = uint32_t(x) % t.width;
    fx = fminf(fmaxf(x - floorf(x), 0.0f), 1.0f);
    x1 = (x0 + 1) % t.width;
  }
  const float* row0 = texels + 4 * y0 * t.width;  // R of each texel
  const float* row1 = row0 + 4 * t.width;
  const float top = row0[4 * x0] + fx * (row0[4 * x1] - row0[4 * x0]);
  const float bottom = row1[4 * x0] + fx * (row1[4 * x1] - row1[4 * x0]);
  return (top + fy * (bottom - top)) * p.scale;
}

// The profile's relative intensity towards unit direction d (from the light), mean 1 over all
// directions; 1 without a profile.
CANDELA_HDI float profileFactor(const TexturePool& pool, const LightProfile& p, const Vec3& d) {
  return p.texture < 0 ? 1.0f : profileLookup(pool, p, d);
}

}  // namespace candela
