// BackendError: a backend cannot run here or failed while rendering (no GPU, out of device
// memory, a kernel fault). The CLI reports it and exits 1; Python raises RuntimeError.
#pragma once

#include <stdexcept>

namespace candela {

class BackendError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace candela
