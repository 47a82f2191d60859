// A unit vector in 32 bits: the octahedral map with 16 bits per coordinate (Cigolle et al.,
// "A Survey of Efficient Representations for Independent Unit Vectors", JCGT 2014; pbrt-v4's
// OctahedralVector). A third of a Vec3's size, with an angular error under 7e-5 radians (0.004
// degrees), far below anything a shading normal can show.
//
// The bits 0 mean "no normal": every real direction encodes to something else (the corners of the
// map, where 0 would fall, all decode to -z, which the encoder writes as all ones).
#pragma once

#include <cmath>
#include <cstdint>

#include "core/device.h"
#include "core/vec3.h"

namespace candela {

struct OctNormal {
  uint32_t bits = 0;

  OctNormal() = default;  // "no normal"
  CANDELA_HDI explicit OctNormal(uint32_t bits_) : bits(bits_) {}

  CANDELA_HDI bool isNone() const { return bits == 0; }
};

namespace detail {

CANDELA_HDI float signNotZero(float v) { return v < 0.0f ? -1.0f : 1.0f; }

CANDELA_HDI uint32_t quantizeOct(float v) {
  const float q = rintf((fminf(fmaxf(v, -1.0f), 1.0f) * 0.5f + 0.5f) * 65535.0f);
  return static_cast<uint32_t>(q);
}

}  // namespace detail

// Encodes `n` (it need not be normalised); a zero or non-finite vector gives "none". Host code.
inline OctNormal encodeOctNormal(const Vec3& n) {
  const float l1 = std::fabs(n.x) + std::fabs(n.y) + std::fabs(n.z);
  if (!(l1 > 0.0f) || !std::isfinite(l1)) return OctNormal();
  float u = n.x / l1, v = n.y / l1;
  if (n.z < 0.0f) {
    const float fu = (1.0f - std::fabs(v)) * detail::signNotZero(u);
    const float fv = (1.0f - std::fabs(u)) * detail::signNotZero(v);
    u = fu;
    v = fv;
  }
  const uint32_t bits = detail::quantizeOct(u) | detail::quantizeOct(v) << 16;
  return OctNormal(bits == 0 ? 0xffffffffu : bits);
}

// The unit vector `o` encodes; `o` must not be "none".
CANDELA_HDI Vec3 decodeOctNormal(OctNormal o) {
  const float u = static_cast<float>(o.bits & 0xffffu) * (2.0f / 65535.0f) - 1.0f;
  const float v = static_cast<float>(o.bits >> 16) * (2.0f / 65535.0f) - 1.0f;
  Vec3 n(u, v, 1.0f - fabsf(u) - fabsf(v));
  if (n.z < 0.0f) {
    const float x = n.x;
    n.x = (1.0f - fabsf(n.y)) * detail::signNotZero(x);
    n.y = (1.0f - fabsf(x)) * detail::signNotZero(n.y);
  }
  return normalize(n);
}

}  // namespace candela
