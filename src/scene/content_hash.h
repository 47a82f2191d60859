// hashBytes: a 64-bit hash of a block of memory, for telling whether a mesh, texture,
// environment map or set of lights is the one a previous frame had (scene/frame_scene.cpp,
// scene/flatten.cpp, scene/flatten_lights.cpp).
// Equal contents give equal hashes; a collision would need two different inputs of one scene.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <vector>

#include "image/image.h"
#include "scene/scene_desc.h"

namespace candela {

// Eight bytes a step, mixed by a multiply and rotate (as xxHash's), so that hashing costs little
// beside decoding or transforming the same bytes. `seed` chains hashes: hashBytes(b, n,
// hashBytes(a, m)) hashes a then b.
inline uint64_t hashBytes(const void* data, size_t size, uint64_t seed = 0) {
  constexpr uint64_t kPrime1 = 0x9e3779b185ebca87ull, kPrime2 = 0xc2b2ae3d27d4eb4full;
  uint64_t h = seed ^ kPrime1;
  const auto mix = [&h](uint64_t word) {
    h ^= word * kPrime2;
    h = ((h << 31) | (h >> 33)) * kPrime1;
  };
  const unsigned char* p = static_cast<const unsigned char*>(data);
  size_t i = 0;
  for (; i + 8 <= size; i += 8) {
    uint64_t word;
    std::memcpy(&word, p + i, 8);
    mix(word);
  }
  uint64_t tail = size;  // the length too, so that ranges differing only in trailing zeros differ
  for (; i < size; ++i) tail = (tail << 8) | p[i];
  mix(tail);
  return h ^ (h >> 29);
}

// The hash of a vector's elements (trivially copyable, without padding bytes).
template <typename T>
uint64_t hashVector(const std::vector<T>& items, uint64_t seed = 0) {
  static_assert(std::is_trivially_copyable<T>::value, "raw bytes only");
  return hashBytes(items.data(), items.size() * sizeof(T), seed);
}

// The hash of a texture's format, size and texels (TextureDesc::contentHash).
inline uint64_t hashTexture(const TextureDesc& t) {
  const uint64_t shape = (uint64_t(t.format) << 56) ^ (uint64_t(t.width) << 28) ^ t.height;
  return hashVector(t.texelsF, hashVector(t.texels8, shape));
}

// A texture's hash: the reader's, or for one made in memory (contentHash 0) its texels'.
inline uint64_t textureHash(const TextureDesc& t) {
  return t.contentHash != 0 ? t.contentHash : hashTexture(t);
}

// The hash of an image's size and pixels (EnvironmentDesc::mapHash).
inline uint64_t hashImage(const ImageRGB& image) {
  return hashVector(image.pixels, (uint64_t(image.width) << 32) | image.height);
}

}  // namespace candela
