// An allocator whose every block has 16 readable bytes past its end, and the vector that uses it.
//
// Embree reads vertices with 16-byte loads, so a float3 array it shares (instead of copying it)
// must stay readable 4 bytes past its last element (rtcSetSharedGeometryBuffer). A vector of
// this allocator is, at any size and after any copy or growth.
#pragma once

#include <cstddef>
#include <cstdint>
#include <new>
#include <vector>

namespace candela {

constexpr size_t kAllocationPadding = 16;

template <class T>
struct PaddedAllocator {
  using value_type = T;

  PaddedAllocator() = default;
  template <class U>
  PaddedAllocator(const PaddedAllocator<U>&) {}

  T* allocate(size_t n) {
    if (n > (SIZE_MAX - kAllocationPadding) / sizeof(T)) throw std::bad_array_new_length();
    return static_cast<T*>(::operator new(n * sizeof(T) + kAllocationPadding));
  }
  void deallocate(T* p, size_t) { ::operator delete(p); }

  template <class U>
  bool operator==(const PaddedAllocator<U>&) const {
    return true;
  }
  template <class U>
  bool operator!=(const PaddedAllocator<U>&) const {
    return false;
  }
};

template <class T>
using PaddedVector = std::vector<T, PaddedAllocator<T>>;

}  // namespace candela
