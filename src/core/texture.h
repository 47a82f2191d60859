// Image textures: a descriptor into a flat texel pool, and the bilinear lookup that both backends
// (and the geometry layer's alpha tests) use.
//
// Conventions:
// - Texels are RGBA, stored row by row from the image's TOP row. 8-bit textures live in a uint8
//   pool (4 bytes a texel), float ones in a float pool (4 floats a texel); `offset` is the index
//   of the texture's first element in its pool.
// - (u, v) = (0, 0) is the image's bottom-left corner, (1, 1) its top-right (OBJ's convention),
//   and texel (i, j) (j counted from the top) has its centre at u = (i + 0.5) / W,
//   v = 1 - (j + 0.5) / H. Lookups repeat in u and v unless the use says otherwise (TextureWrap),
//   and interpolate bilinearly between texel centres unless it asks for the nearest texel.
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

// How a lookup reads the image beyond its edges along one axis: the image repeated, its edge
// texels held (glTF's CLAMP_TO_EDGE, Mitsuba 3's "clamp"), or repeated with every other copy
// mirrored (MIRRORED_REPEAT, "mirror").
enum class TextureWrap : uint8_t { Repeat = 0, Clamp = 1, Mirror = 2 };

// How a lookup reads between texels: bilinear interpolation between the four centres around the
// point, or the one texel the point lies in (glTF's NEAREST: pixel art, voxel models, id maps).
enum class TextureFilter : uint8_t { Bilinear = 0, Nearest = 1 };

// A material's use of a texture: which one, how many times it repeats across uv's [0, 1), how
// far it is turned and where it starts (textureCoordinates), and how it is read beyond its edges
// and between its texels.
struct TextureRef {
  int32_t index = -1;  // into the scene's textures; -1: none
  float scaleU = 1, scaleV = 1;
  float offsetU = 0, offsetV = 0;
  // The cosine and sine of the angle by which the image is turned counter-clockwise on the
  // surface (u right, v up).
  float rotationCos = 1, rotationSin = 0;
  TextureWrap wrapS = TextureWrap::Repeat;  // along the image's x (s, from textureCoordinates)
  TextureWrap wrapT = TextureWrap::Repeat;  // along its y (t)
  TextureFilter filter = TextureFilter::Bilinear;
  uint8_t unused = 0;  // so that no byte of the struct is left undefined
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

// The two texels along one axis of n that a lookup blends, the fraction towards i1, and the sign
// with which the texel coordinate grows with the image coordinate (-1 in a mirrored copy).
struct TexelSpan {
  uint32_t i0, i1;
  float f;
  float sign;
};

// Along an axis of n texels, at image coordinate a (one copy of the image per unit): texel
// coordinates run along a, or against it where `fromTop` (rows are stored from the image's top).
CANDELA_HDI TexelSpan texelSpan(float a, uint32_t n, TextureWrap wrap, TextureFilter filter,
                                bool fromTop) {
  // c: where in [0, 1] of one copy the lookup reads; NaN and infinities read at 0.
  float c = 0.0f, sign = 1.0f;
  if (wrap == TextureWrap::Repeat) {
    c = wrapUnit(a);
  } else if (wrap == TextureWrap::Clamp) {
    c = a > 0.0f ? (a < 1.0f ? a : 1.0f) : 0.0f;
  } else {
    const float m = a - 2.0f * floorf(0.5f * a);  // in [0, 2): which copy, and where in it
    c = m >= 0.0f && m < 2.0f ? m : 0.0f;
    if (c > 1.0f) {
      c = 2.0f - c;
      sign = -1.0f;
    }
  }
  if (fromTop) c = 1.0f - c;
  const int32_t last = int32_t(n) - 1;
  const float x = c * float(n);  // in [0, n]
  if (filter == TextureFilter::Nearest) {
    const uint32_t i = x < float(n) ? uint32_t(x) : uint32_t(last);
    return {i, i, 0.0f, sign};
  }
  // Texel centres at integers: x - 0.5 in [-0.5, n - 0.5], so i0 in [-1, n - 1].
  const float xc = x - 0.5f, i0f = floorf(xc);
  int32_t i0 = int32_t(i0f), i1 = i0 + 1;
  if (wrap == TextureWrap::Repeat) {
    // Past an edge the next copy's first texel (c < 1 in a repeat: only i0 = -1 wraps, or i1 = n).
    if (i0 < 0) i0 += int32_t(n);
    if (i1 > last) i1 = 0;
  } else {
    // Clamped, and mirrored copies, meet their edge texel again past the edge.
    if (i0 < 0) i0 = 0;
    if (i1 > last) i1 = last;
  }
  return {uint32_t(i0), uint32_t(i1), xc - i0f, sign};
}

// The four texels around (u, v) that a lookup of `ref` blends, the weights' fractions (fx towards
// x1, fy towards y1; x right, y down the image), and the signs of x's and y's growth with the image
// coordinates s and t (TexelSpan::sign; y runs against t).
struct TexelQuad {
  uint32_t x0, y0, x1, y1;
  float fx, fy;
  float signX, signY;
};

CANDELA_HDI TexelQuad texelQuad(const Texture& t, const TextureRef& ref, float u, float v) {
  float s, tc;
  textureCoordinates(ref, u, v, &s, &tc);
  const TexelSpan x = texelSpan(s, t.width, ref.wrapS, ref.filter, false);
  const TexelSpan y = texelSpan(tc, t.height, ref.wrapT, ref.filter, true);
  return {x.i0, y.i0, x.i1, y.i1, x.f, y.f, x.sign, y.sign};
}

// Texel (x, y) of `t` as linear RGB's luminance (Rec. 709 weights, as Mitsuba 3's).
CANDELA_HDI float texelLuminance(const TexturePool& pool, const Texture& t, uint32_t x,
                                 uint32_t y) {
  float c[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  addTexel(pool, t, x, y, 1.0f, c);
  return textureLuminance(Vec3(c[0], c[1], c[2]));
}

}  // namespace detail

// The texture `ref` at texture coordinates (u, v) (textureCoordinates), filtered and wrapped as
// `ref` says.
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

// Whether the copy of the image that `ref` reads at (u, v) is mirrored along s and along t: -1
// for a mirrored axis, else 1 (TextureWrap::Mirror's every other copy).
CANDELA_HDI void textureMirrorSigns(const TextureRef& ref, float u, float v, float* signS,
                                    float* signT) {
  float s, t;
  textureCoordinates(ref, u, v, &s, &t);
  *signS = detail::texelSpan(s, 1, ref.wrapS, TextureFilter::Nearest, false).sign;
  *signT = detail::texelSpan(t, 1, ref.wrapT, TextureFilter::Nearest, false).sign;
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
  // x = s W and y = (1 - t) H within a copy (against s and t in a mirrored copy), (s, t) =
  // R(-rotation) (u su, v sv) + offset: the gradient in (s, t), turned back by the rotation and
  // scaled. (Clamped beyond an edge, or read from the nearest texel, the cell is flat.)
  const float ds = ddx * float(t.width) * q.signX, dt = -ddy * float(t.height) * q.signY;
  *ddu = (ref.rotationCos * ds - ref.rotationSin * dt) * ref.scaleU;
  *ddv = (ref.rotationSin * ds + ref.rotationCos * dt) * ref.scaleV;
}

// sRGB's decoding curve (IEC 61966-2-1), for the host to fill TexturePool::srgbToLinear.
inline float srgbToLinearValue(float s) {
  return s <= 0.04045f ? s / 12.92f : std::pow((s + 0.055f) / 1.055f, 2.4f);
}

}  // namespace candela
