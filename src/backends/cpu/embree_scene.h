// EmbreeScene: a scene's geometry as the Embree engine holds it, kept in step with the frames of
// an animation; tracer() is what the integrator traces with (backends/cpu/embree_tracer.h).
//
// Embree builds its own BVH over the triangles (binned SAH at RTC_BUILD_QUALITY_MEDIUM:
// docs/performance.md), from a copy of the vertices and the scene's own triangle array, shared.
// The spheres stay candela's: in blocks of 4 or 8 when they are few, else in a BVH of their own. A
// frame whose primitives moved (SceneChange::Motion) rewrites the vertices and refits Embree's
// BVH, and places the spheres anew (their blocks, or their BVH beyond 32 spheres); a new
// structure rebuilds both. Alpha-masked materials (geometry/alpha_mask.h) get intersection and
// occlusion filters on the triangles that apply the same test as candela's own traversal.
// Embree picks the widest SIMD the CPU has at run time (SSE2 up to
// AVX-512).
#pragma once

#include <embree3/rtcore.h>

#include <cstddef>
#include <vector>

#include "backends/cpu/embree_tracer.h"
#include "render/scene_change.h"
#include "render/scene_data.h"

namespace candela {

class EmbreeScene {
 public:
  // `deviceConfig`: Embree's device configuration (rtcNewDevice), e.g. "isa=avx2" to test an
  // instruction set below the CPU's; null: Embree's defaults.
  explicit EmbreeScene(const char* deviceConfig = nullptr);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  // Makes Embree's scene match `scene`, which must stay alive and unchanged until the next call
  // (its triangles are shared, not copied). `change` is what may differ from the scene given
  // last; the first call takes everything. Throws BackendError when Embree fails (out of memory).
  void update(const SceneData& scene, SceneChange change);

  EmbreeTracer tracer() const {
    return EmbreeTracer{scene_, sphereView_, sphereBlocks_.view(), sphereCount_};
  }
  // Seconds the last update spent building or refitting Embree's BVH.
  double buildSeconds() const { return buildSeconds_; }
  // Bytes the engine holds: what Embree has now for this process (its BVH, its vertex copy; from
  // its memory monitor) and the spheres' BVH.
  size_t bytes() const;

 private:
  void build(const SceneData& scene);
  void refit(const SceneData& scene);
  void placeSpheres(const SceneData& scene);
  void commit();
  void updateMasks(const SceneData& scene);

  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;  // the triangles; null when there are none
  RTCGeometry triangles_ = nullptr;
  std::vector<BvhNode> sphereNodes_;
  std::vector<uint32_t> spherePrims_;
  SphereBlocks sphereBlocks_;
  GeometryView sphereView_;  // the spheres of the scene given last, with sphereNodes_
  uint32_t sphereCount_ = 0;
  bool built_ = false;  // whether update() has built anything yet: the first frame builds
  double buildSeconds_ = 0;
  // What the alpha filter reads (the triangles, uvs, masks and textures of the scene given last),
  // and whether the filter is installed: only while some material is masked.
  GeometryView maskView_;
  bool filtered_ = false;
};

}  // namespace candela
