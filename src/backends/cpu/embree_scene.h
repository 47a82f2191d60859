// EmbreeScene: a scene's geometry as Embree holds it, kept in step with the frames of an
// animation; tracer() is what the integrator traces with (backends/cpu/embree_tracer.h).
//
// Embree builds its own BVH (binned SAH at RTC_BUILD_QUALITY_MEDIUM: docs/performance.md) over
// a copy of the vertices and the scene's own triangle array, shared. A frame whose primitives
// moved (SceneChange::Motion) rewrites the vertices and refits that BVH; a new structure
// rebuilds it.
// Embree picks the widest SIMD the CPU has at run time (SSE2 up to AVX-512).
#pragma once

#include <embree3/rtcore.h>

#include <cstddef>

#include "backends/cpu/embree_tracer.h"
#include "render/scene_change.h"
#include "render/scene_data.h"

namespace candela {

class EmbreeScene {
 public:
  EmbreeScene();
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  // Makes Embree's scene match `scene`, which must stay alive and unchanged until the next call
  // (its triangles are shared, not copied). `change` is what may differ from the scene given
  // last; the first call takes everything. Throws BackendError when Embree fails (out of memory).
  void update(const SceneData& scene, SceneChange change);

  EmbreeTracer tracer() const { return EmbreeTracer{scene_, sphereCount_}; }
  // Seconds the last update spent building or refitting Embree's BVH.
  double buildSeconds() const { return buildSeconds_; }
  // Bytes Embree holds now for this process (BVH, vertex copy), from its memory monitor.
  static size_t bytesInUse();

 private:
  void build(const SceneData& scene);
  void refit(const SceneData& scene);
  void commit();

  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
  RTCGeometry triangles_ = nullptr;
  RTCGeometry spheres_ = nullptr;
  const Sphere* sphereArray_ = nullptr;  // the spheres' user data: the scene given last
  uint32_t sphereCount_ = 0;
  double buildSeconds_ = 0;
};

}  // namespace candela
