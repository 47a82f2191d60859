// Image textures: a descriptor into a flat texel pool, and the bilinear lookup that both backends
// (and the geometry layer's alpha tests) use.
//
// Conventions:
// - Texels are RGBA, stored row by row from the image's TOP row. 8-bit textures live in a uint8
//   pool (4 bytes a texel), float ones in a float pool (4 floats a texel); `offset` is the index
//   of the texture's first element in its pool.
// - (u, v) = (0, 0) is the image's bottom-left corner, (1, 1) its top-right (OBJ's convention),
//   and texel (i, j) (j counted from the top) has its centre at u = (i + 0.5) / W,
//   v = 1 - (j + 0.5) / H. Lookups repeat in both u and v and interpolate bilinearly.
// - Srgb8 decodes R, G and B through a 256-entry table (sRGB -> linear, made once on the host);
//   alpha is linear in every format.
#pragma once

#include <cmath>
#include <cstdint>

#include "core/device.h"
#include "core/vec3.h"

namespace candela {

enum class TextureFormat : uint32_t { Srgb8 = 0, Linear8 = 1, Float = 2 };

struct Texture {
  uint32_t offset = 0;  // first element in texels8 (8-bit formats) or texelsF (Float)
  uint32_t width = 0, height = 0;
  TextureFormat format = TextureFormat::Srgb8;
};

// A material's use of a texture: which one, how many times it repeats across uv's [0, 1), how
// far it is turned and where it starts (textureCoordinates).
struct TextureRef {
  int32_t index = -1;  // into the scene's textures; -1: none
  float scaleU = 1, scaleV = 1;
  float offsetU = 0, offsetV = 0;
  // The cosine and sine of the angle by which the image is turned counter-clockwise on the
  // surface (u right, v up).
  float rotationCos = 1, rotationSin = 0;
};

// The image coordinates that `ref` reads at texture coordinates (u, v): scaled, then turned by
// the rotation (the point by its opposite, so that the image turns by it), then moved by the
// offset.
CANDELA_HDI void textureCoordinates(const TextureRef& ref, float u, float v, float* s, float* t) {
  const float su = u * ref.scaleU, sv = v * ref.scaleV;
  *s = ref.rotationCos * su + ref.rotationSin * sv + ref.offsetU;
  *t = ref.rotationCos * sv - ref.rotationSin * su + ref.offsetV;
}

// The directions in (u, v) along which `ref`'s image coordinates s and t grow (the inverse of
// textureCoordinates' linear part, up to positive factors): a normal map's tangent and bitangent.
CANDELA_HDI void textureAxes(const TextureRef& ref, float* su, float* sv, float* tu, float* tv) {
  *su = ref.rotationCos / ref.scaleU;
  *sv = ref.rotationSin / ref.scaleV;
  *tu = -ref.rotationSin / ref.scaleU;
  *tv = ref.rotationCos / ref.scaleV;
}

// The scene's texture arrays, as the lookup reads them.
struct TexturePool {
  const Texture* textures = nullptr;
  const uint8_t* texels8 = nullptr;
  const float* texelsF = nullptr;
  const float* srgbToLinear = nullptr;  // 256 entries
};

struct TextureSample {
  Vec3 rgb;
  float alpha = 1;
};

// The luminance of a texture's colour (a grey image's value), with the bump map's weights.
CANDELA_HDI float textureLuminance(const Vec3& c) {
  return 0.212671f * c.x + 0.715160f * c.y + 0.072169f * c.z;
}

// A scalar read from a texture: channel 0 (R), 1 (G), 2 (B), 3 (A), or kLuminanceChannel.
constexpr uint32_t kLuminanceChannel = 4;

CANDELA_HDI float textureChannel(const TextureSample& s, uint32_t channel) {
  if (channel == kLuminanceChannel) return textureLuminance(s.rgb);
  return channel < 3 ? s.rgb[int(channel)] : s.alpha;
}

namespace detail {

// Texel (x, y) of `t` (x, y within the image) as linear RGBA, accumulated with weight w.
CANDELA_HDI void addTexel(const TexturePool& pool, const Texture& t, uint32_t x, uint32_t y,
                          float w, float out[4]) {
  const uint32_t i = t.offset + 4u * (y * t.width + x);
  if (t.format == TextureFormat::Float) {
    for (int c = 0; c < 4; ++c) out[c] += w * pool.texelsF[i + c];
    return;
  }
  const uint8_t* p = pool.texels8 + i;
  if (t.format == TextureFormat::Srgb8) {
    for (int c = 0; c < 3; ++c) out[c] += w * pool.srgbToLinear[p[c]];
  } else {
    for (int c = 0; c < 3; ++c) out[c] += w * (float(p[c]) * (1.0f / 255.0f));
  }
  out[3] += w * (float(p[3]) * (1.0f / 255.0f));
}

// The fractional part of a coordinate, in [0, 1); NaN and infinities give 0.
CANDELA_HDI float wrapUnit(float a) {
  const float f = a - floorf(a);
  return f >= 0.0f && f < 1.0f ? f : 0.0f;
}

// The four texels around (u, v) that a bilinear lookup of `ref` blends, and the weights' fractions
// (fx towards x1, fy towards y1; x right, y down the image).
struct TexelQuad {
  uint32_t x0, y0, x1, y1;
  float fx, fy;
};

CANDELA_HDI TexelQuad texelQuad(const Texture& t, const TextureRef& ref, float u, float v) {
  // Continuous texel coordinates with texel centres at integers, x right and y down.
  float s, tc;
  textureCoordinates(ref, u, v, &s, &tc);
  const float x = wrapUnit(s) * float(t.width) - 0.5f;
  const float y = (1.0f - wrapUnit(tc)) * float(t.height) - 0.5f;
  const float x0f = floorf(x), y0f = floorf(y);
  // x0f and y0f lie in [-1, W - 1] and [-1, H - 1]: one wrap suffices.
  const int32_t w = int32_t(t.width), h = int32_t(t.height);
  int32_t x0 = int32_t(x0f), y0 = int32_t(y0f);
  x0 = x0 < 0 ? x0 + w : (x0 >= w ? x0 - w : x0);
  y0 = y0 < 0 ? y0 + h : (y0 >= h ? y0 - h : y0);
  const int32_t x1 = x0 + 1 == w ? 0 : x0 + 1, y1 = y0 + 1 == h ? 0 : y0 + 1;
  return {uint32_t(x0), uint32_t(y0), uint32_t(x1), uint32_t(y1), x - x0f, y - y0f};
}

// Texel (x, y) of `t` as linear RGB's luminance (Rec. 709 weights, as Mitsuba 3's).
CANDELA_HDI float texelLuminance(const TexturePool& pool, const Texture& t, uint32_t x,
                                 uint32_t y) {
  float c[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  addTexel(pool, t, x, y, 1.0f, c);
  return textureLuminance(Vec3(c[0], c[1], c[2]));
}

}  // namespace detail

// The texture `ref` at texture coordinates (u, v) (textureCoordinates): bilinear, repeating.
CANDELA_HDI TextureSample lookupTexture(const TexturePool& pool, const TextureRef& ref, float u,
                                        float v) {
  const Texture& t = pool.textures[ref.index];
  const detail::TexelQuad q = detail::texelQuad(t, ref, u, v);
  const float fx = q.fx, fy = q.fy;
  float sum[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  detail::addTexel(pool, t, q.x0, q.y0, (1.0f - fx) * (1.0f - fy), sum);
  detail::addTexel(pool, t, q.x1, q.y0, fx * (1.0f - fy), sum);
  detail::addTexel(pool, t, q.x0, q.y1, (1.0f - fx) * fy, sum);
  detail::addTexel(pool, t, q.x1, q.y1, fx * fy, sum);
  return {Vec3(sum[0], sum[1], sum[2]), sum[3]};
}

// The derivatives with respect to u and v of the luminance of `ref`'s bilinear lookup at (u, v)
// (that of the cell of texels around it; Mitsuba 3's eval_1_grad): a height map's slopes.
CANDELA_HDI void textureLuminanceGradient(const TexturePool& pool, const TextureRef& ref, float u,
                                          float v, float* ddu, float* ddv) {
  const Texture& t = pool.textures[ref.index];
  const detail::TexelQuad q = detail::texelQuad(t, ref, u, v);
  const float f00 = detail::texelLuminance(pool, t, q.x0, q.y0);
  const float f10 = detail::texelLuminance(pool, t, q.x1, q.y0);
  const float f01 = detail::texelLuminance(pool, t, q.x0, q.y1);
  const float f11 = detail::texelLuminance(pool, t, q.x1, q.y1);
  const float ddx = (1.0f - q.fy) * (f10 - f00) + q.fy * (f11 - f01);
  const float ddy = (1.0f - q.fx) * (f01 - f00) + q.fx * (f11 - f10);
  // x = s W and y = (1 - t) H within a repeat, (s, t) = R(-rotation) (u su, v sv) + offset: the
  // gradient in (s, t), turned back by the rotation and scaled.
  const float ds = ddx * float(t.width), dt = -ddy * float(t.height);
  *ddu = (ref.rotationCos * ds - ref.rotationSin * dt) * ref.scaleU;
  *ddv = (ref.rotationSin * ds + ref.rotationCos * dt) * ref.scaleV;
}

// sRGB's decoding curve (IEC 61966-2-1), for the host to fill TexturePool::srgbToLinear.
inline float srgbToLinearValue(float s) {
  return s <= 0.04045f ? s / 12.92f : std::pow((s + 0.055f) / 1.055f, 2.4f);
}

}  // namespace candela
