// The sample table's fill, 8 lanes to a vector (GCC's vector extensions), compiled for AVX2 and
// called only where the CPU has it (sampleTableFill). Every lane runs the sampler's own steps
// (core/sobol_sampler.h's templates), integer operations that give SampleStream's bits exactly.
#if defined(__x86_64__)
#include "backends/cpu/sample_table_fill.h"
#include "core/sobol_sampler.h"

namespace candela {

namespace {

constexpr uint32_t kWidth = 8;
typedef uint32_t Words __attribute__((vector_size(4 * kWidth)));
typedef int32_t SignedWords __attribute__((vector_size(4 * kWidth)));
typedef float Floats __attribute__((vector_size(4 * kWidth)));
static_assert(SampleTable::kLanes % kWidth == 0, "a table's lanes are whole vectors");

Words reverseBits(Words v) {
  v = (v << 24) | ((v << 8) & 0x00ff0000u) | ((v >> 8) & 0x0000ff00u) | (v >> 24);
  return reverseBitsWithinBytes(v);
}

bool anyLane(Words m) {
  uint32_t any = 0;
  for (uint32_t k = 0; k < kWidth; ++k) any |= m[k];
  return any != 0;
}

// permutationElement for every lane: each walks its cycle until it lands in [0, n).
Words permutationElements(Words i, uint32_t n, uint32_t w, uint32_t seed) {
  Words walking = ~Words{};
  do {
    const Words next = permutationStep(i, w, seed);
    i = (next & walking) | (i & ~walking);
    walking &= (Words)(i >= n);
  } while (anyLane(walking));
  return n == w + 1 ? (i + seed) & w : (i + seed) % n;
}

// bitsToUnitFloat: the top 24 bits, exactly representable, times 2^-24.
void store(Words bits, float* out) {
  const Floats f = __builtin_convertvector((SignedWords)(bits >> 8), Floats) * 0x1p-24f;
  __builtin_memcpy(out, &f, sizeof f);
}

}  // namespace

void fillSampleTableAvx2(SampleTable* table, uint32_t entry, bool twoD) {
  const uint32_t n = table->spp, w = permutationMask(n);
  const uint64_t h = sampleDimensionHash(table->pixelKey, entry + 1);
  const uint64_t scramble = mix64(h);
  for (uint32_t first = 0; first < table->lanes; first += kWidth) {
    // Lanes past the packet's samples take its first: a cycle walk ends only from an index in
    // [0, n), whose cycle holds one there.
    Words sample;
    for (uint32_t k = 0; k < kWidth; ++k)
      sample[k] = table->firstSample + (first + k < table->lanes ? first + k : 0);
    const Words index = permutationElements(sample, n, w, uint32_t(h));
    if (twoD) {
      Words u, v;
      scrambledWords2D(index, scramble, &u, &v);
      store(reverseBits(u), &table->a[entry][first]);
      store(reverseBits(v), &table->b[entry][first]);
    } else {
      store(reverseBits(scrambledWord1D(index, h)), &table->a[entry][first]);
    }
  }
  table->kind[entry] = twoD ? SampleTable::kTwoD : SampleTable::kOneD;
}

}  // namespace candela
#endif
