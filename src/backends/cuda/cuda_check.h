// Every CUDA call is checked; a failure becomes a CudaError naming the call and the reason.
#pragma once

#include <cuda_runtime.h>

#include <cstdio>
#include <string>

#include "backends/cuda/cuda_error.h"

namespace candela {

std::string formatBytes(size_t bytes);
[[noreturn]] void throwCudaError(cudaError_t err, const char* call, const char* file, int line);

}  // namespace candela

#define CANDELA_CUDA_CHECK(call)                                                 \
  do {                                                                           \
    const cudaError_t candelaErr_ = (call);                                      \
    if (candelaErr_ != cudaSuccess)                                              \
      ::candela::throwCudaError(candelaErr_, #call, __FILE__, __LINE__);         \
  } while (0)
