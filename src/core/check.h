// CANDELA_DCHECK: an invariant of the code, checked in debug builds and free in release ones
// (pbrt-v4's DCHECK). It states what must hold whatever the input is; input that can be wrong is
// validated where it is read, with a message for the user, never by a DCHECK.
//
// Shared by the CPU and CUDA backends: on the host a failure prints the condition and its place
// and aborts; on the device it prints the same and traps, so the kernel launch reports an error.
#pragma once

#include "core/device.h"

#if defined(NDEBUG) && !defined(CANDELA_FORCE_DCHECK)
#define CANDELA_DCHECK(condition) \
  do {                            \
  } while (false && (condition))
#else
#include <cstdio>
#if !CANDELA_DEVICE_CODE
#include <cstdlib>
#endif

namespace candela::detail {

[[noreturn]] CANDELA_HDI void dcheckFailed(const char* condition, const char* file, int line) {
#if defined(__CUDA_ARCH__)
  printf("%s:%d: CANDELA_DCHECK failed: %s\n", file, line, condition);
  __trap();
#else
  std::fprintf(stderr, "%s:%d: CANDELA_DCHECK failed: %s\n", file, line, condition);
  std::abort();
#endif
}

}  // namespace candela::detail

#define CANDELA_DCHECK(condition)                                                      \
  do {                                                                                 \
    if (!(condition)) ::candela::detail::dcheckFailed(#condition, __FILE__, __LINE__); \
  } while (false)
#endif
