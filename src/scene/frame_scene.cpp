// Reuse or rebuild of a frame's flattened scene; see frame_scene.h.
#include "scene/frame_scene.h"

#include <chrono>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <vector>

namespace candela {
namespace {

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

// FNV-1a over a vector's bytes: equal meshes give equal hashes; a collision would need two
// different meshes with the same counts in one animation.
template <typename T>
uint64_t hashOf(const std::vector<T>& items) {
  uint64_t h = 1469598103934665603ull;
  const unsigned char* p = reinterpret_cast<const unsigned char*>(items.data());
  for (size_t i = 0, n = items.size() * sizeof(T); i < n; ++i) h = (h ^ p[i]) * 1099511628211ull;
  return h ^ items.size();
}

}  // namespace

std::string geometryKey(const SceneDesc& desc) {
  KeyWriter key;
  key.add(desc.spheres.size());
  for (const SphereDesc& s : desc.spheres) {
    key.add(s.position);
    key.add(s.radius);
  }
  key.add(desc.lights.size());
  for (const LightDesc& l : desc.lights) {
    key.add(l.type);
    if (l.type == LightType::Sphere) {  // sphere lights are spheres of the BVH
      key.add(l.position);
      key.add(l.radius);
    }
  }
  key.add(desc.objects.size());
  for (const ObjectDesc& o : desc.objects) {
    key.add(o.position);
    key.add(o.rotation);
    key.add(o.scale);
    key.add(o.smooth);
    key.add(o.material.has_value());  // decides how many materials the object appends
    key.add(o.mesh.materials.size());
    key.add(hashOf(o.mesh.positions));
    key.add(hashOf(o.mesh.normals));
    key.add(hashOf(o.mesh.triangles));
  }
  return key.take();
}

const SceneData& FrameScene::prepare(const SceneDesc& desc) {
  const auto start = std::chrono::steady_clock::now();
  std::string key = geometryKey(desc);
  reused_ = !geometryKey_.empty() && key == geometryKey_;
  if (reused_) {
    refreshSceneValues(data_, desc);
  } else {
    data_ = flattenScene(desc);
    geometryKey_ = std::move(key);
  }
  seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return data_;
}

}  // namespace candela
