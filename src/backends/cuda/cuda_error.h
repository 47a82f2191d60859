// CudaError: any failure of the CUDA backend (no device, out of memory, a kernel fault).
// The CLI reports it and exits 1.
#pragma once

#include <stdexcept>

namespace candela {

class CudaError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace candela
