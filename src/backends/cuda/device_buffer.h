// DeviceBuffer<T>: an owning, typed cudaMalloc allocation with explicit copies. No managed
// memory: the host decides when data moves. Out-of-memory errors say how much was asked for
// and how much was free.
#pragma once

#include <cuda_runtime.h>

#include <cstddef>
#include <string>
#include <vector>

#include "backends/cuda/cuda_check.h"

namespace candela {

template <typename T>
class DeviceBuffer {
 public:
  DeviceBuffer() = default;
  explicit DeviceBuffer(size_t count) { allocate(count); }
  ~DeviceBuffer() { release(); }
  DeviceBuffer(const DeviceBuffer&) = delete;
  DeviceBuffer& operator=(const DeviceBuffer&) = delete;
  DeviceBuffer(DeviceBuffer&& o) noexcept : ptr_(o.ptr_), count_(o.count_) {
    o.ptr_ = nullptr;
    o.count_ = 0;
  }

  void allocate(size_t count) {
    release();
    if (count == 0) return;
    const size_t bytes = count * sizeof(T);
    const cudaError_t err = cudaMalloc(reinterpret_cast<void**>(&ptr_), bytes);
    if (err != cudaSuccess) {
      cudaGetLastError();  // clear the sticky allocation error
      size_t freeBytes = 0, totalBytes = 0;
      cudaMemGetInfo(&freeBytes, &totalBytes);
      throw CudaError("out of GPU memory: asked for " + formatBytes(bytes) + ", " +
                      formatBytes(freeBytes) + " free of " + formatBytes(totalBytes));
    }
    count_ = count;
  }

  template <class Allocator>
  void upload(const std::vector<T, Allocator>& host) {
    if (host.size() != count_) allocate(host.size());
    if (count_) CANDELA_CUDA_CHECK(cudaMemcpy(ptr_, host.data(), count_ * sizeof(T), cudaMemcpyHostToDevice));
  }

  void download(std::vector<T>* host) const {
    host->resize(count_);
    if (count_) CANDELA_CUDA_CHECK(cudaMemcpy(host->data(), ptr_, count_ * sizeof(T), cudaMemcpyDeviceToHost));
  }

  void zero() {
    if (count_) CANDELA_CUDA_CHECK(cudaMemset(ptr_, 0, count_ * sizeof(T)));
  }

  T* get() const { return ptr_; }
  size_t size() const { return count_; }

 private:
  void release() {
    if (ptr_) cudaFree(ptr_);
    ptr_ = nullptr;
    count_ = 0;
  }

  T* ptr_ = nullptr;
  size_t count_ = 0;
};

}  // namespace candela
