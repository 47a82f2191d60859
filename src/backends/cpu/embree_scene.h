// EmbreeScene: a scene's geometry as the Embree engine holds it, kept in step with the frames of
// an animation; tracer() is what the integrator traces with (backends/cpu/embree_tracer.h).
//
// Embree builds its own BVH over the triangles (binned SAH at RTC_BUILD_QUALITY_MEDIUM:
// docs/performance.md) over the scene's own vertices, shared, not copied, and its triangles
// (shared too where their indices need no shift). Its leaves hold copies of their triangles'
// vertices, or in scenes of at least kIndexedLeavesFromTriangles triangles only their indices
// (Embree's Triangle4i leaves, which read the shared vertices as they trace).
// Objects that repeat a mesh of at least kInstanceFromTriangles triangles (render/mesh_instances.h)
// are instances of one BVH built over the mesh in object space, each with its object's transform;
// the other objects' triangles are geometries over the runs of the triangle array between them
// (with no repeats, one over all). The spheres stay candela's: in blocks of 4 or 8 when they are
// few, else in a BVH of their own. A scene of at most kTriangleBlocksUpTo triangles, none of them
// masked, has no Embree BVH: its triangles are tested in blocks too
// (backends/cpu/triangle_blocks.h). A frame whose primitives moved (SceneChange::Motion) shares
// its vertices and refits Embree's BVHs, moves the instances, and places the spheres (their
// blocks, or their BVH beyond 32 spheres) and the triangle blocks anew; a new structure rebuilds
// both. Spheres and objects that move while the shutter is open are in none of these but in the
// scene's motion BVH (geometry/motion.h), which the tracer traverses with candela's own code.
// Alpha-masked materials
// (geometry/alpha_mask.h) get intersection and occlusion filters on the triangles that apply the
// same test as candela's own traversal. Embree picks the widest SIMD the CPU has at run time (SSE2
// up to AVX-512).
#pragma once

#include <embree3/rtcore.h>

#include <cstddef>
#include <string>
#include <vector>

#include "backends/cpu/embree_tracer.h"
#include "render/scene_change.h"
#include "render/scene_data.h"

namespace candela {

// Repeated meshes of fewer triangles stay in the runs: docs/performance.md, "Instances".
constexpr uint32_t kInstanceFromTriangles = 64;

// Indexed leaves take 30 fewer bytes per triangle (62 in all on the 100k-triangle meshes, against
// 92 with leaves of vertex copies) and traced the bench's big meshes as fast, Sponza 2% slower;
// the Cornell box's 32 triangles, which nearly every ray tests, 6% slower, so small scenes keep
// the copies (docs/performance.md, "Memory").
constexpr uint32_t kIndexedLeavesFromTriangles = 10000;

class EmbreeScene {
 public:
  // `deviceConfig`: Embree's device configuration (rtcNewDevice), e.g. "isa=avx2" to test an
  // instruction set below the CPU's; null: Embree's defaults. Scenes of at least
  // `indexedLeavesFrom` triangles get indexed leaves.
  explicit EmbreeScene(const char* deviceConfig = nullptr,
                       uint32_t indexedLeavesFrom = kIndexedLeavesFromTriangles);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  // Makes Embree's scene match `scene`, which must stay alive and unchanged until the next call
  // (its vertices and triangles are shared, not copied; its vertex arrays are padded for that,
  // render/scene_data.h). `change` is what may differ from the scene given last; the first call
  // takes everything. Throws BackendError when Embree fails (out of memory).
  void update(const SceneData& scene, SceneChange change);

  EmbreeTracer tracer() const {
    return EmbreeTracer{scene_,
                        firstTriangleOf_.data(),
                        prototypes_.empty(),
                        sphereView_,
                        sphereBlocks_.view(),
                        sphereCount_,
                        triangleBlocks_.view(),
                        moving_};
  }
  // How many objects Embree traces as instances of a repeated mesh.
  uint32_t instanceCount() const;
  // Seconds the last update spent building or refitting Embree's BVH.
  double buildSeconds() const { return buildSeconds_; }
  // Bytes the engine holds: what Embree has now for this process (its BVH, from its memory
  // monitor), the spheres' BVH or blocks and the triangle blocks.
  size_t bytes() const;

 private:
  // A run of the scene's triangles (and the vertices they use) that Embree holds as one
  // geometry, or one object that is an instance of a prototype.
  struct Part {
    uint32_t firstTriangle = 0, triangleCount = 0, firstVertex = 0, vertexCount = 0;
    int32_t object = -1;     // the instance's object; -1 for a run
    int32_t prototype = -1;  // the instance's, into prototypes_
    RTCGeometry geometry = nullptr;
    const Vec3* vertices = nullptr;  // a run's, as shared with Embree

    // Whether Embree reads the scene's own triangle array: a run whose vertices start at the
    // scene's first, so the indices need no shift (else Embree holds shifted copies).
    bool sharesIndices() const { return object < 0 && firstVertex == 0; }
  };
  // A prototype traced as instances: its own Embree scene of one triangle geometry.
  struct Prototype {
    int32_t index = -1;  // into SceneData::meshInstances.prototypes
    RTCScene scene = nullptr;
    RTCGeometry geometry = nullptr;
    const Vec3* vertices = nullptr;  // as shared with Embree
  };

  struct Plan {
    std::vector<Part> parts;
    std::vector<Prototype> prototypes;
  };

  void build(const SceneData& scene);
  void refit(const SceneData& scene);
  // Whether a part or prototype's vertices now lie elsewhere than Embree reads them.
  bool verticesMoved(const SceneData& scene) const;
  void release();
  // Makes device_ one whose triangle leaves are indexed or not (a new device where that changes;
  // release() first).
  void useIndexedLeaves(bool indexed);
  // The parts and prototypes of `scene`, before Embree has any of them.
  static Plan planParts(const SceneData& scene);
  // Whether `plan` has the parts and prototypes of the scene built last: what a refit needs.
  bool sameParts(const Plan& plan) const;
  // A triangle geometry over shared vertices, whose triangles index them from firstVertex on;
  // the triangles are shared where `shareIndices` (firstVertex must then be 0), else copied less
  // firstVertex. Both must stay until the next update.
  RTCGeometry newTriangles(const Vec3* positions, uint32_t vertexCount, const Triangle* triangles,
                           uint32_t triangleCount, uint32_t firstVertex, bool shareIndices);
  void placeInstance(const SceneData& scene, const Part& part);
  void placeSpheres(const SceneData& scene);
  // Puts the scene's triangles in blocks where it qualifies, else empties them; returns whether
  // the blocks hold the triangles.
  bool placeTriangleBlocks(const SceneData& scene);
  // Commits `scene` (scene_, or a prototype's), adding the seconds to buildSeconds_.
  void commit(RTCScene scene);
  void updateMasks(const SceneData& scene);
  void setMaskFilters(bool masked);

  std::string deviceConfig_, indexedLeavesConfig_;  // the latter with Embree's indexed leaves
  uint32_t indexedLeavesFrom_;
  RTCDevice device_ = nullptr;
  bool indexedLeaves_ = false;  // device_'s
  RTCScene scene_ = nullptr;  // the triangles; null when there are none
  std::vector<Part> parts_;   // in the order of the triangles, whose geometry IDs they have
  std::vector<Prototype> prototypes_;
  std::vector<uint32_t> firstTriangleOf_;  // of each part, by geometry ID
  std::vector<BvhNode> sphereNodes_;
  std::vector<uint32_t> spherePrims_;
  SphereBlocks sphereBlocks_;
  TriangleBlocks triangleBlocks_;
  GeometryView sphereView_;  // the spheres of the scene given last, with sphereNodes_
  uint32_t sphereCount_ = 0;
  bool built_ = false;  // whether update() has built anything yet: the first frame builds
  double buildSeconds_ = 0;
  // What the alpha filter reads (the triangles, uvs, masks and textures of the scene given last),
  // and whether the filter is installed: only while some material is masked.
  GeometryView maskView_;
  bool filtered_ = false;
  // The scene given last, whose motion BVH the tracer traverses itself (null where nothing moves).
  GeometryView motionView_;
  const GeometryView* moving_ = nullptr;
};

}  // namespace candela
