// Skips a test that needs a GPU, saying why, where the CUDA backend cannot run (no GPU, or a
// build without it); scripts/gpu-check runs these tests on a GPU, where a skip fails the check.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "backends/renderer.h"

#define REQUIRE_GPU()                                                                  \
  do {                                                                                 \
    std::string gpuReason_;                                                            \
    if (!::candela::cudaUsable(&gpuReason_)) GTEST_SKIP() << "no GPU: " << gpuReason_; \
  } while (0)
