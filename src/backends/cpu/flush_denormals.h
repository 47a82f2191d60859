// FlushDenormals: while one lives, its thread's SSE arithmetic reads denormal inputs as zero and
// flushes denormal results to zero (MXCSR's DAZ and FTZ), as Embree's documentation asks of the
// threads that trace with it; it puts back the mode it found, so a caller's thread (Python's, a
// TBB worker shared with other work) keeps its own.
//
// Denormals cost the CPU a microcode assist on every operation that meets one. The light tree
// once held one in every point light's cluster (now 0 at its source), which made the first
// denormal-flushing renders of the dragon 1.15x faster; with the tree mended, flushing still
// gains a few percent (docs/performance.md, optimisation log). Images stay byte-identical on the
// bench scenes. The GPU handles denormals at full speed and keeps IEEE behaviour.
#pragma once

#if defined(__SSE2__) || defined(_M_X64)
#include <immintrin.h>
#define CANDELA_FLUSH_DENORMALS 1
#else
#define CANDELA_FLUSH_DENORMALS 0
#endif

namespace candela {

class FlushDenormals {
 public:
#if CANDELA_FLUSH_DENORMALS
  FlushDenormals() : saved_(_mm_getcsr()) { _mm_setcsr(saved_ | kDazFtz); }
  ~FlushDenormals() { _mm_setcsr(saved_); }
#else
  FlushDenormals() = default;
#endif
  FlushDenormals(const FlushDenormals&) = delete;
  FlushDenormals& operator=(const FlushDenormals&) = delete;

 private:
#if CANDELA_FLUSH_DENORMALS
  static constexpr unsigned kDazFtz = 0x0040u | 0x8000u;  // MXCSR bits 6 (DAZ) and 15 (FTZ)
  unsigned saved_;
#endif
};

}  // namespace candela
