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
// A table's lanes in 16-bit words, all in one vector.
typedef uint16_t Halves __attribute__((vector_size(2 * SampleTable::kLanes)));
constexpr uint32_t kVectors = SampleTable::kLanes / kWidth;

Words reverseBits(Words v) {
  v = (v << 24) | ((v << 8) & 0x00ff0000u) | ((v >> 8) & 0x0000ff00u) | (v >> 24);
  return reverseBitsWithinBytes(v);
}

template <class V>
bool anyLane(V m) {
  uint32_t any = 0;
  for (uint32_t k = 0; k < sizeof(V) / sizeof(m[0]); ++k) any |= m[k];
  return any != 0;
}

// permutationElement's cycle walk for every lane, in lanes of S: each walks until it lands in
// [0, n).
template <class V, class S>
V walkedIndices(V i, uint32_t n, uint32_t w, uint32_t seed) {
  V walking = ~V{};
  do {
    const V next = permutationStep<V, S>(i, w, seed);
    i = (next & walking) | (i & ~walking);
    walking &= (V)(i > S(n - 1));
  } while (anyLane(walking));
  return i;
}

// The lanes' samples under permutationElement, vector by vector. Lanes past the packet's
// samples take its first: a cycle walk ends only from an index in [0, n), whose cycle holds one
// there. Where every index of the walk fits 16 bits (w < 2^16: any spp up to 65,536), all the
// lanes walk at once in 16-bit words, the same steps in half the multiplies' time.
void permutationElements(const SampleTable& table, uint32_t n, uint32_t w, uint32_t seed,
                         Words* index) {
  const auto sampleOf = [&](uint32_t lane) {
    return table.firstSample + (lane < table.lanes ? lane : 0);
  };
  if (w <= 0xffffu) {
    Halves i;
    for (uint32_t k = 0; k < SampleTable::kLanes; ++k) i[k] = uint16_t(sampleOf(k));
    i = walkedIndices<Halves, uint16_t>(i, n, w, seed);
    for (uint32_t v = 0; v < kVectors; ++v)
      for (uint32_t k = 0; k < kWidth; ++k) index[v][k] = i[v * kWidth + k];
  } else {
    for (uint32_t v = 0; v * kWidth < table.lanes; ++v) {
      for (uint32_t k = 0; k < kWidth; ++k) index[v][k] = sampleOf(v * kWidth + k);
      index[v] = walkedIndices<Words, uint32_t>(index[v], n, w, seed);
    }
  }
  for (uint32_t v = 0; v * kWidth < table.lanes; ++v)
    index[v] = n == w + 1 ? (index[v] + seed) & w : (index[v] + seed) % n;
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
  Words indices[kVectors];
  permutationElements(*table, n, w, uint32_t(h), indices);
  for (uint32_t first = 0; first < table->lanes; first += kWidth) {
    const Words index = indices[first / kWidth];
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
