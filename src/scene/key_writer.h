// KeyWriter: a value's raw bytes appended to a key, for the "did this change since the last
// frame?" comparisons of scene/frame_scene.cpp and scene/flatten.cpp.
#pragma once

#include <string>
#include <type_traits>
#include <utility>

namespace candela {

class KeyWriter {
 public:
  template <typename T>
  void add(const T& value) {
    static_assert(std::is_trivially_copyable<T>::value, "raw bytes only");
    const char* bytes = reinterpret_cast<const char*>(&value);
    key_.append(bytes, sizeof(T));
  }
  std::string take() { return std::move(key_); }

 private:
  std::string key_;
};

}  // namespace candela
