// PacketSlots: room for up to N values of T, one for each sample of a packet (a pixel's samples
// in step: render/render_pixel.h), each constructed when its sample takes it, so that a packet
// of n samples initialises n values and not N (and likewise an interaction's shadow queries,
// render/shadow_query.h). As an array T[N] of a type with default member
// initialisers (a path's state is 440 bytes), every packet initialised all 16 and copied each
// sample's in: 3% of the Cornell box's time at 16 spp, 7% at one (docs/performance.md).
#pragma once

#include <cstdint>
#include <new>
#include <type_traits>

#include "core/device.h"

namespace candela {

template <class T, uint32_t N>
class PacketSlots {
  static_assert(std::is_trivially_destructible<T>::value, "slots are never destroyed");

 public:
  // Constructs slot i from `args` and returns it.
  template <class... Args>
  CANDELA_HDI T& emplace(uint32_t i, const Args&... args) {
    return *new (bytes_ + i * sizeof(T)) T(args...);
  }
  // Slot i, which emplace has constructed.
  CANDELA_HDI T& operator[](uint32_t i) {
    return *std::launder(reinterpret_cast<T*>(bytes_ + i * sizeof(T)));
  }

 private:
  alignas(T) unsigned char bytes_[N * sizeof(T)];
};

}  // namespace candela
