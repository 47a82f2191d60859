// Four floats operated on together: SSE on x86-64 hosts, plain loops elsewhere. Host code only
// (the BVH build); device code never includes it.
//
// Lane-wise min and max follow the SSE rule: min(a, b) = a < b ? a : b, so a NaN in `a` yields b.
#pragma once

#include <cstdint>

#if defined(__SSE2__) || defined(_M_X64)
#include <immintrin.h>
#define CANDELA_FLOAT4_SSE 1
#else
#define CANDELA_FLOAT4_SSE 0
#endif

namespace candela {

#if CANDELA_FLOAT4_SSE

struct Float4 {
  __m128 v;

  Float4() = default;
  explicit Float4(__m128 v_) : v(v_) {}
  explicit Float4(float s) : v(_mm_set1_ps(s)) {}
  Float4(float x, float y, float z, float w) : v(_mm_setr_ps(x, y, z, w)) {}

  static Float4 load(const float* p) { return Float4(_mm_loadu_ps(p)); }
  void store(float* p) const { _mm_storeu_ps(p, v); }
  float x() const { return _mm_cvtss_f32(v); }
  float y() const { return _mm_cvtss_f32(_mm_shuffle_ps(v, v, _MM_SHUFFLE(1, 1, 1, 1))); }
  float z() const { return _mm_cvtss_f32(_mm_shuffle_ps(v, v, _MM_SHUFFLE(2, 2, 2, 2))); }
  float operator[](int i) const {
    alignas(16) float f[4];
    _mm_store_ps(f, v);
    return f[i];
  }
};

inline Float4 operator+(Float4 a, Float4 b) { return Float4(_mm_add_ps(a.v, b.v)); }
inline Float4 operator-(Float4 a, Float4 b) { return Float4(_mm_sub_ps(a.v, b.v)); }
inline Float4 operator*(Float4 a, Float4 b) { return Float4(_mm_mul_ps(a.v, b.v)); }
inline Float4 min(Float4 a, Float4 b) { return Float4(_mm_min_ps(a.v, b.v)); }
inline Float4 max(Float4 a, Float4 b) { return Float4(_mm_max_ps(a.v, b.v)); }

// Truncates each lane towards zero into out[0..3]; lanes must lie in int range.
inline void truncateToInt(Float4 a, int32_t out[4]) {
  _mm_storeu_si128(reinterpret_cast<__m128i*>(out), _mm_cvttps_epi32(a.v));
}

// Whether a > b in any of lanes 0-2.
inline bool anyGreaterXyz(Float4 a, Float4 b) {
  return (_mm_movemask_ps(_mm_cmpgt_ps(a.v, b.v)) & 7) != 0;
}

#else

struct Float4 {
  float f[4];

  Float4() = default;
  explicit Float4(float s) : f{s, s, s, s} {}
  Float4(float x, float y, float z, float w) : f{x, y, z, w} {}

  static Float4 load(const float* p) { return Float4(p[0], p[1], p[2], p[3]); }
  void store(float* p) const {
    for (int i = 0; i < 4; ++i) p[i] = f[i];
  }
  float x() const { return f[0]; }
  float y() const { return f[1]; }
  float z() const { return f[2]; }
  float operator[](int i) const { return f[i]; }
};

#define CANDELA_FLOAT4_LANEWISE(name, expr)  \
  inline Float4 name(Float4 a, Float4 b) {   \
    Float4 r;                                \
    for (int i = 0; i < 4; ++i) r.f[i] = expr; \
    return r;                                \
  }
CANDELA_FLOAT4_LANEWISE(operator+, a.f[i] + b.f[i])
CANDELA_FLOAT4_LANEWISE(operator-, a.f[i] - b.f[i])
CANDELA_FLOAT4_LANEWISE(operator*, a.f[i] * b.f[i])
CANDELA_FLOAT4_LANEWISE(min, a.f[i] < b.f[i] ? a.f[i] : b.f[i])
CANDELA_FLOAT4_LANEWISE(max, a.f[i] > b.f[i] ? a.f[i] : b.f[i])
#undef CANDELA_FLOAT4_LANEWISE

inline void truncateToInt(Float4 a, int32_t out[4]) {
  for (int i = 0; i < 4; ++i) out[i] = static_cast<int32_t>(a.f[i]);
}

inline bool anyGreaterXyz(Float4 a, Float4 b) {
  return a.f[0] > b.f[0] || a.f[1] > b.f[1] || a.f[2] > b.f[2];
}

#endif

}  // namespace candela
