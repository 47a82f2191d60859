// CudaError: any failure of the CUDA backend (no device, out of memory, a kernel fault).
#pragma once

#include "backends/backend_error.h"

namespace candela {

class CudaError : public BackendError {
 public:
  using BackendError::BackendError;
};

}  // namespace candela
