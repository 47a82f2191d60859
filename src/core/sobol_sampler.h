// The sampler: padded, Owen-scrambled Sobol points (pbrt-v4's PaddedSobolSampler).
//
// Each 1D or 2D request of a sample takes the next "dimension" d. Within a pixel, the sample
// index is first shuffled by a permutation of [0, spp) seeded by (seed, pixel, d), then mapped to
// the first one or two Sobol dimensions (a (0,2)-sequence: every power-of-two prefix is
// stratified in 2D) and Owen-scrambled with seeds from the same hash. So:
// - every value is a pure function of (seed, pixel, sample index, dimension, spp): any thread,
//   tile order, backend or cluster slice draws the same numbers;
// - the spp samples of a pixel are stratified in each pair of dimensions, which lowers the error
//   of antialiasing, lens, light and first-bounce integrals well below independent sampling;
// - different dimension pairs and pixels are decorrelated by independent permutations and
//   scrambles ("padding").
#pragma once

#include <cstdint>

#include "core/device.h"
#include "core/rng.h"
#include "core/sample_table.h"

namespace candela {

// The bit-mixing steps below are templates over the word type U (uint32_t, or a SIMD vector
// of them, whose lanes the CPU's sample tables compute at once: core/sample_table.h), so that
// every lane computes what SampleStream does, from one source.

// Each byte's bits in reverse order.
template <class U>
CANDELA_HDI_ALWAYS U reverseBitsWithinBytes(U v) {
  v = ((v & 0x0f0f0f0fu) << 4) | ((v & 0xf0f0f0f0u) >> 4);
  v = ((v & 0x33333333u) << 2) | ((v & 0xccccccccu) >> 2);
  v = ((v & 0x55555555u) << 1) | ((v & 0xaaaaaaaau) >> 1);
  return v;
}

CANDELA_HDI uint32_t reverseBits32(uint32_t v) {
#if defined(__CUDA_ARCH__)  // the device compilation pass: one instruction
  return __brev(v);
#else
  return reverseBitsWithinBytes(__builtin_bswap32(v));  // bswap: one instruction on x86-64
#endif
}

// First Sobol dimension: the van der Corput sequence in base 2 (bit reversal of the index).
CANDELA_HDI uint32_t sobolDimension0(uint32_t index) { return reverseBits32(index); }

// Second Sobol dimension: direction numbers v_0 = 2^31, v_k = v_{k-1} ^ (v_{k-1} >> 1).
CANDELA_HDI uint32_t sobolDimension1(uint32_t index) {
  uint32_t result = 0, v = 0x80000000u;
  for (; index != 0; index >>= 1, v ^= v >> 1)
    if (index & 1u) result ^= v;
  return result;
}

// The second Sobol dimension computed bit-reversed (reverseBits32(sobolDimension1(i))). Its
// reversed direction numbers r_k = r_{k-1} ^ (r_{k-1} << 1), r_0 = 1, are the rows of Pascal's
// triangle mod 2: bit j of r_k is set iff j's bits are a subset of k's (Lucas). So bit j of the
// result is the XOR of the index bits k over all supersets k of j, which five shift-and-mask
// steps compute (the subset-sum transform over the five bits of a bit position), branch-free:
// a loop over the index bits mispredicted on every sample.
template <class U>
CANDELA_HDI_ALWAYS U sobolDimension1Reversed(U index) {
  index ^= (index >> 1) & 0x55555555u;
  index ^= (index >> 2) & 0x33333333u;
  index ^= (index >> 4) & 0x0f0f0f0fu;
  index ^= (index >> 8) & 0x00ff00ffu;
  index ^= (index >> 16) & 0x0000ffffu;
  return index;
}

// The Laine–Karras hash on a bit-reversed value: each bit is flipped depending only on the bits
// below it, i.e. on the more significant bits of the unreversed value.
template <class U>
CANDELA_HDI_ALWAYS U laineKarrasHash(U v, uint32_t seed) {
  v ^= v * 0x3d20adeau;
  v += seed;
  v *= (seed >> 16) | 1u;
  v ^= v * 0x05526c56u;
  v ^= v * 0x53a22864u;
  return v;
}

// Owen scrambling by hashing (Laine and Karras 2011, as in pbrt-v4's FastOwenScrambler): each
// bit is flipped depending on the bits above it, which keeps the stratification.
CANDELA_HDI uint32_t owenScramble(uint32_t v, uint32_t seed) {
  return reverseBits32(laineKarrasHash(reverseBits32(v), seed));
}

// The smallest mask of low bits that covers n - 1: the range permutationElement walks in.
CANDELA_HDI uint32_t permutationMask(uint32_t n) {
  uint32_t w = n - 1;
  w |= w >> 1;
  w |= w >> 2;
  w |= w >> 4;
  w |= w >> 8;
  w |= w >> 16;
  return w;
}

// One step of the cycle walk of permutationElement below, on words whose lanes are of type S.
// Every operation's low bits depend only on low bits (products, sums, and right shifts of values
// masked by w), so where w < 2^16 a vector of 16-bit lanes (S = uint16_t; not a scalar, which C++
// would promote to int) gives the same step as 32-bit words: the CPU's sample tables take one,
// whose multiplies then take half the time.
template <class U, class S = uint32_t>
CANDELA_HDI_ALWAYS U permutationStep(U i, uint32_t w, uint32_t seed) {
  i ^= S(seed);
  i *= S(0xe170893du);
  i ^= S(seed >> 16);
  i ^= (i & S(w)) >> 4;
  i ^= S(seed >> 8);
  i *= S(0x0929eb3fu);
  i ^= S(seed >> 23);
  i ^= (i & S(w)) >> 1;
  i *= S(1u | seed >> 27);
  i *= S(0x6935fa69u);
  i ^= (i & S(w)) >> 11;
  i *= S(0x74dcb303u);
  i ^= (i & S(w)) >> 2;
  i *= S(0x9e501cc3u);
  i ^= (i & S(w)) >> 2;
  i *= S(0xc860a3dfu);
  i &= S(w);
  i ^= i >> 5;
  return i;
}

// Element i of a pseudo-random permutation of [0, n) chosen by `seed` (Kensler 2013,
// "Correlated Multi-Jittered Sampling"), by cycle walking over the power-of-two range w + 1,
// w = permutationMask(n).
CANDELA_HDI_ALWAYS uint32_t permutationElement(uint32_t i, uint32_t n, uint32_t w, uint32_t seed) {
  do {
    i = permutationStep(i, w, seed);
  } while (i >= n);
  // A power-of-two n (the usual spp) needs no division.
  return n == w + 1 ? (i + seed) & w : (i + seed) % n;
}

CANDELA_HDI_ALWAYS uint32_t permutationElement(uint32_t i, uint32_t n, uint32_t seed) {
  return permutationElement(i, n, permutationMask(n), seed);
}

// 32 random bits as a float in [0, 1).
CANDELA_HDI float bitsToUnitFloat(uint32_t bits) {
  return static_cast<float>(bits >> 8) * 0x1p-24f;
}

// The hash that keys every stream of a pixel, and the one that keys its dimension d.
CANDELA_HDI uint64_t samplePixelKey(uint64_t seed, uint64_t pixelIndex) {
  return mix64(mix64(seed ^ 0x6a09e667f3bcc909ull) ^ pixelIndex);
}
CANDELA_HDI_ALWAYS uint64_t sampleDimensionHash(uint64_t pixelKey, uint32_t dimension) {
  return mix64(pixelKey + 0x9e3779b97f4a7c15ull * dimension);
}

// Dimension d's word as next1D draws it for the sample whose shuffled index is `index`
// (permutationElement under the low half of the dimension's hash h), still bit-reversed:
// owenScramble(sobolDimension0(index), h >> 32) computed in the bit-reversed domain, where
// dimension 0 is the index itself.
template <class U>
CANDELA_HDI_ALWAYS U scrambledWord1D(U index, uint64_t h) {
  return laineKarrasHash(index, uint32_t(h >> 32));
}

// Dimension d's pair of words as next2D draws it, still bit-reversed: the first two Sobol
// dimensions of `index`, Owen-scrambled by the two halves of `scramble` = mix64(h) (two bit
// reversals instead of six, the same bits).
template <class U>
CANDELA_HDI_ALWAYS void scrambledWords2D(U index, uint64_t scramble, U* u, U* v) {
  *u = laineKarrasHash(index, uint32_t(scramble));
  *v = laineKarrasHash(sobolDimension1Reversed(index), uint32_t(scramble >> 32));
}

// A pixel's key (samplePixelKey), from which each of its samples' streams starts: a caller with
// many samples of one pixel computes it once.
struct PixelKey {
  uint64_t value;
};

// The random numbers of one (seed, pixel, sample) among spp samples of that pixel; with a
// table, its first dimensions come from the table's lane `lane`, the same numbers.
class SampleStream {
 public:
  SampleStream() = default;
  CANDELA_HDI SampleStream(uint64_t seed, uint64_t pixelIndex, uint32_t sampleIndex, uint32_t spp,
                           SampleTable* table = nullptr, uint32_t lane = 0)
      : SampleStream(PixelKey{samplePixelKey(seed, pixelIndex)}, sampleIndex, spp, table, lane) {}
  CANDELA_HDI SampleStream(PixelKey pixel, uint32_t sampleIndex, uint32_t spp,
                           SampleTable* table = nullptr, uint32_t lane = 0)
      : pixelKey_(pixel.value),
        sampleIndex_(sampleIndex),
        spp_(spp > 0 ? spp : 1),
        sppMask_(permutationMask(spp_)),
        table_(table),
        lane_(lane) {}

  CANDELA_HDI_ALWAYS float next1D() {
    if (tableHolds(false)) return table_->a[dimension_++][lane_];
    const uint64_t h = dimensionHash();
    const uint32_t index = permutationElement(sampleIndex_, spp_, sppMask_, uint32_t(h));
    return bitsToUnitFloat(reverseBits32(scrambledWord1D(index, h)));
  }

  // Passes over one dimension unused (a point light's position needs no random numbers), so
  // the dimensions after it are the same whether or not it was drawn.
  CANDELA_HDI void skip() { ++dimension_; }

  // next2D when `used`, else skip(): for a dimension that only some lights or cameras need.
  CANDELA_HDI_ALWAYS void next2DIfUsed(bool used, float* u, float* v) {
    if (used) {
      next2D(u, v);
    } else {
      skip();
    }
  }

  CANDELA_HDI_ALWAYS void next2D(float* u, float* v) {
    if (tableHolds(true)) {
      *u = table_->a[dimension_][lane_];
      *v = table_->b[dimension_++][lane_];
      return;
    }
    const uint64_t h = dimensionHash();
    uint32_t wordU, wordV;
    scrambledWords2D(permutationElement(sampleIndex_, spp_, sppMask_, uint32_t(h)), mix64(h),
                     &wordU, &wordV);
    *u = bitsToUnitFloat(reverseBits32(wordU));
    *v = bitsToUnitFloat(reverseBits32(wordV));
  }

  // The key of a ray that the sample's path casts here (geometry/ray.h, Ray::alphaKey), of the
  // kind `kind` (RayKind): a pure function of (seed, pixel, sample index, dimension) like the
  // numbers, drawing none of them.
  CANDELA_HDI uint32_t rayKey(uint32_t kind) const {
    return uint32_t(mix64(pixelKey_ ^ ((uint64_t(sampleIndex_) << 32) | dimension_)) >> 32) ^ kind;
  }

  // The stream of a branch split off the sample's path here (render/path_branch.h): the same
  // sample's numbers from kBranchDimensions dimensions further on, where no path reaches from
  // the dimension it left.
  static constexpr uint32_t kBranchDimensions = 1u << 16;
  CANDELA_HDI SampleStream branch() const {
    SampleStream s = *this;
    s.dimension_ += kBranchDimensions;
    return s;
  }

 private:
  CANDELA_HDI_ALWAYS uint64_t dimensionHash() {
    return sampleDimensionHash(pixelKey_, ++dimension_);
  }

  // Whether the table holds the next dimension drawn as asked (twoD: as a pair), after filling
  // it where no sample of the packet has drawn it yet. Host code only: the GPU has no table.
  CANDELA_HDI_ALWAYS bool tableHolds(bool twoD) {
#if defined(__CUDA_ARCH__)
    return false;
#else
    if (!table_ || dimension_ >= SampleTable::kMaxDimensions) return false;
    if (table_->kind[dimension_] == SampleTable::kEmpty) table_->fill(table_, dimension_, twoD);
    return table_->kind[dimension_] == (twoD ? SampleTable::kTwoD : SampleTable::kOneD);
#endif
  }

  uint64_t pixelKey_;
  uint32_t sampleIndex_;
  uint32_t spp_;
  uint32_t sppMask_;
  uint32_t dimension_ = 0;
  SampleTable* table_ = nullptr;
  uint32_t lane_ = 0;
};

}  // namespace candela
