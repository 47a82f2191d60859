#include "backends/cpu/embree_scene.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <string>

#include "backends/backend_error.h"
#include "geometry/bvh_build.h"
#include "geometry/motion.h"
#include "geometry/primitive_bounds.h"

namespace candela {

namespace {

std::atomic<long long> embreeBytes{0};

bool countMemory(void*, ssize_t bytes, bool) {
  embreeBytes += bytes;
  return true;
}

// Embree reports errors through a callback; the last one is kept for the BackendError.
thread_local std::string lastError;

void keepError(void*, RTCError, const char* message) { lastError = message ? message : "unknown"; }

RTCDevice newDevice(const std::string& config) {
  RTCDevice device = rtcNewDevice(config.c_str());
  if (!device)
    throw BackendError("Embree could not start: " + std::to_string(rtcGetDeviceError(nullptr)));
  rtcSetDeviceErrorFunction(device, keepError, nullptr);
  rtcSetDeviceMemoryMonitorFunction(device, countMemory, nullptr);
  return device;
}

}  // namespace

void rejectMaskedHit(const RTCFilterFunctionNArguments* args) {
  const auto* geometry = static_cast<const GeometryView*>(args->geometryUserPtr);
  const auto* context = reinterpret_cast<const EmbreeQueryContext*>(args->context);
  const unsigned n = args->N;
  for (unsigned i = 0; i < n; ++i) {
    if (args->valid[i] != -1) continue;
    const uint32_t triangle =
        triangleOfHit(context->firstTriangleOf, RTCHitN_geomID(args->hit, n, i),
                      RTCHitN_instID(args->hit, n, i, 0), RTCHitN_primID(args->hit, n, i));
    // The world's ray, as candela's own traversal tests it (its key draws the alpha test).
    const Ray& ray = context->rays[RTCRayN_id(args->ray, n, i)];
    if (!alphaKeepsHit(*geometry, geometry->triangles[triangle], RTCHitN_u(args->hit, n, i),
                       RTCHitN_v(args->hit, n, i), ray))
      args->valid[i] = 0;
  }
}

namespace {

// Points a triangle geometry at `count` of the scene's vertices from `vertices` on (the array
// padded: render/scene_data.h), which Embree reads in place.
void shareVertices(RTCGeometry geometry, const Vec3* vertices, size_t count) {
  rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, vertices, 0,
                             sizeof(Vec3), count);
}

// Points a triangle geometry at `count` of the scene's triangles; the fourth word of each (the
// material) is passed over by the stride.
void shareTriangles(RTCGeometry geometry, const Triangle* triangles, size_t count) {
  rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, triangles, 0,
                             sizeof(Triangle), count);
}

// Installs rejectMaskedHit on a triangle geometry for both queries, or removes it.
void setMaskFilter(RTCGeometry geometry, bool masked) {
  rtcSetGeometryIntersectFilterFunction(geometry, masked ? rejectMaskedHit : nullptr);
  rtcSetGeometryOccludedFilterFunction(geometry, masked ? rejectMaskedHit : nullptr);
}

}  // namespace

void rejectSkippedTriangle(const RTCFilterFunctionNArguments* args) {
  const auto* context = reinterpret_cast<const EmbreeQueryContext*>(args->context);
  const unsigned n = args->N;
  for (unsigned i = 0; i < n; ++i) {
    if (args->valid[i] != -1) continue;
    const uint32_t skip = context->skipPrims[RTCRayN_id(args->ray, n, i)];
    const uint32_t triangle =
        triangleOfHit(context->firstTriangleOf, RTCHitN_geomID(args->hit, n, i),
                      RTCHitN_instID(args->hit, n, i, 0), RTCHitN_primID(args->hit, n, i));
    if (context->sphereCount + triangle == skip) args->valid[i] = 0;
  }
}

EmbreeScene::EmbreeScene(const char* deviceConfig, uint32_t indexedLeavesFrom)
    : deviceConfig_(deviceConfig ? deviceConfig : ""),
      indexedLeavesFrom_(indexedLeavesFrom),
      device_(newDevice(deviceConfig_)) {
  // Eight-wide nodes where the instruction set Embree runs has them (AVX and up), as its default.
  indexedLeavesConfig_ =
      (deviceConfig_.empty() ? "" : deviceConfig_ + ",") +
      (rtcGetDeviceProperty(device_, RTC_DEVICE_PROPERTY_NATIVE_RAY8_SUPPORTED) != 0
           ? "tri_accel=bvh8.triangle4i"
           : "tri_accel=bvh4.triangle4i");
}

EmbreeScene::~EmbreeScene() {
  release();
  if (device_) rtcReleaseDevice(device_);
}

void EmbreeScene::useIndexedLeaves(bool indexed) {
  if (indexed == indexedLeaves_) return;
  rtcReleaseDevice(device_);
  device_ = nullptr;
  device_ = newDevice(indexed ? indexedLeavesConfig_ : deviceConfig_);
  indexedLeaves_ = indexed;
}

void EmbreeScene::release() {
  if (scene_) rtcReleaseScene(scene_);
  for (Part& part : parts_)
    if (part.geometry) rtcReleaseGeometry(part.geometry);
  for (Prototype& prototype : prototypes_) {
    if (prototype.scene) rtcReleaseScene(prototype.scene);
    if (prototype.geometry) rtcReleaseGeometry(prototype.geometry);
  }
  scene_ = nullptr;
  parts_.clear();
  prototypes_.clear();
  firstTriangleOf_.clear();
}

size_t EmbreeScene::bytes() const {
  return size_t(std::max(0LL, embreeBytes.load())) + sphereNodes_.size() * sizeof(BvhNode) +
         spherePrims_.size() * sizeof(uint32_t) + sphereBlocks_.bytes() +
         triangleBlocks_.bytes();
}

uint32_t EmbreeScene::instanceCount() const {
  return uint32_t(std::count_if(parts_.begin(), parts_.end(),
                                [](const Part& part) { return part.object >= 0; }));
}

void EmbreeScene::update(const SceneData& scene, SceneChange change) {
  // A material that became masked needs Embree's filters, which the blocks do not apply.
  const bool blocksNoLonger = triangleBlocks_.view().blockCount != 0 && !scene.alphaMasks.empty();
  if (change == SceneChange::Structure || !built_ || blocksNoLonger) {
    build(scene);
  } else if (change == SceneChange::Motion || verticesMoved(scene)) {
    // New values keep the geometry, but where its arrays moved Embree must read them anew.
    refit(scene);
  }
  // A frame of new values keeps the geometry, but its arrays may lie elsewhere.
  sphereView_.spheres = scene.spheres.data();
  motionView_ = scene.view();
  moving_ = scene.motionNodes.empty() ? nullptr : &motionView_;
  updateMasks(scene);
}

void EmbreeScene::setMaskFilters(bool masked) {
  const auto set = [masked](RTCGeometry geometry) {
    setMaskFilter(geometry, masked);
    rtcCommitGeometry(geometry);
  };
  for (const Prototype& prototype : prototypes_) {
    set(prototype.geometry);
    commit(prototype.scene);
  }
  for (const Part& part : parts_)
    if (part.object < 0) set(part.geometry);
  filtered_ = masked;
}

void EmbreeScene::updateMasks(const SceneData& scene) {
  const SceneView view = scene.view();
  maskView_ = view;  // the geometry part: triangles, uvs, masks and textures
  const bool masked = view.alphaMaskCount != 0;
  if (!scene_ || masked == filtered_) return;
  // Scenes without masks pay nothing: the filters are installed only when a material is masked.
  setMaskFilters(masked);
  commit(scene_);
}

void EmbreeScene::placeSpheres(const SceneData& scene) {
  sphereCount_ = uint32_t(scene.spheres.size());
  sphereNodes_.clear();
  spherePrims_.clear();
  if (sphereCount_ <= kSphereBlocksUpTo) {
    sphereBlocks_.assign(scene.spheres.data(), sphereCount_, widestSphereBlock(),
                         scene.sphereMotions.empty() ? nullptr : scene.sphereMotions.data());
  } else {  // a BVH over those that stand still: those that move are the motion BVH's
    sphereBlocks_.assign(nullptr, 0);
    GeometryView spheres = scene.view();
    spheres.triangleCount = 0;
    std::vector<Bounds3> boxes;
    std::vector<uint32_t> still;
    partBoxes(spheres, false, 0, &boxes, &still);
    BvhBuildResult bvh = buildBvhOfBoxes(boxes.data(), still.data(), uint32_t(still.size()));
    sphereNodes_ = std::move(bvh.wideNodes);
    spherePrims_ = std::move(bvh.primIndices);
  }
  sphereView_ = GeometryView();
  sphereView_.spheres = scene.spheres.data();
  sphereView_.sphereCount = sphereCount_;
  sphereView_.nodes = sphereNodes_.data();
  sphereView_.nodeCount = uint32_t(sphereNodes_.size());
  sphereView_.primIndices = spherePrims_.data();
  sphereView_.primIndexCount = uint32_t(spherePrims_.size());
}

bool EmbreeScene::placeTriangleBlocks(const SceneData& scene) {
  if (scene.triangles.size() <= kTriangleBlocksUpTo && scene.alphaMasks.empty() &&
      scene.vertexMotions.empty())
    triangleBlocks_.assign(scene.positions.data(), scene.triangles.data(),
                           uint32_t(scene.triangles.size()));
  else
    triangleBlocks_.assign(nullptr, nullptr, 0);
  return triangleBlocks_.view().blockCount != 0;
}

EmbreeScene::Plan EmbreeScene::planParts(const SceneData& scene) {
  Plan plan;
  const MeshInstances& instances = scene.meshInstances;
  // Of each of the scene's prototypes, its place in plan.prototypes (-1: not traced as one).
  std::vector<int32_t> traced(instances.prototypes.size(), -1);
  for (uint32_t p = 0; p < instances.prototypes.size(); ++p) {
    const MeshInstance& first = instances.objects[instances.prototypes[p].firstInstance];
    if (first.triangleCount < kInstanceFromTriangles) continue;
    traced[p] = int32_t(plan.prototypes.size());
    plan.prototypes.push_back(Prototype{int32_t(p)});
  }
  // Without instances one run takes every triangle, as flattening left them (also where no
  // object's place is known: after an own BVH reordered them).
  Part run;  // the run being gathered, from the first triangle and vertex not in a part yet
  const auto endRun = [&](uint32_t triangleEnd, uint32_t vertexEnd) {
    run.triangleCount = triangleEnd - run.firstTriangle;
    run.vertexCount = vertexEnd - run.firstVertex;
    if (run.triangleCount != 0) plan.parts.push_back(run);
  };
  for (uint32_t i = 0; i < instances.objects.size(); ++i) {
    const MeshInstance& object = instances.objects[i];
    if (object.moves) {  // the motion BVH's (geometry/motion.h): in no part
      endRun(object.firstTriangle, object.firstVertex);
      run = Part();
      run.firstTriangle = object.firstTriangle + object.triangleCount;
      run.firstVertex = object.firstVertex + object.vertexCount;
      continue;
    }
    if (object.prototype < 0 || traced[uint32_t(object.prototype)] < 0) continue;
    endRun(object.firstTriangle, object.firstVertex);
    Part part;
    part.firstTriangle = object.firstTriangle;
    part.triangleCount = object.triangleCount;
    part.firstVertex = object.firstVertex;
    part.vertexCount = object.vertexCount;
    part.object = int32_t(i);
    part.prototype = traced[uint32_t(object.prototype)];
    plan.parts.push_back(part);
    run = Part();
    run.firstTriangle = object.firstTriangle + object.triangleCount;
    run.firstVertex = object.firstVertex + object.vertexCount;
  }
  // After the objects, the rectangle lights' quads, those that move left to the motion BVH.
  if (!scene.vertexMotions.empty())
    for (uint32_t t = run.firstTriangle; t < scene.triangles.size(); ++t) {
      const uint32_t* v = scene.triangles[t].v;
      if (scene.vertexMotions[v[0]] == kStill) continue;
      endRun(t, std::min({v[0], v[1], v[2]}));
      run = Part();
      run.firstTriangle = t + 1;
      run.firstVertex = std::max({v[0], v[1], v[2]}) + 1;
    }
  endRun(uint32_t(scene.triangles.size()), uint32_t(scene.positions.size()));
  return plan;
}

bool EmbreeScene::verticesMoved(const SceneData& scene) const {
  const std::vector<MeshPrototype>& meshes = scene.meshInstances.prototypes;
  for (const Prototype& prototype : prototypes_)
    if (uint32_t(prototype.index) >= meshes.size() ||
        meshes[uint32_t(prototype.index)].positions.data() != prototype.vertices)
      return true;
  for (const Part& part : parts_)
    if (part.object < 0 && scene.positions.data() + part.firstVertex != part.vertices) return true;
  return false;
}

bool EmbreeScene::sameParts(const Plan& plan) const {
  const auto samePart = [](const Part& a, const Part& b) {
    return a.firstTriangle == b.firstTriangle && a.triangleCount == b.triangleCount &&
           a.firstVertex == b.firstVertex && a.vertexCount == b.vertexCount &&
           a.object == b.object && a.prototype == b.prototype;
  };
  if (plan.parts.size() != parts_.size() || plan.prototypes.size() != prototypes_.size())
    return false;
  for (size_t i = 0; i < parts_.size(); ++i)
    if (!samePart(plan.parts[i], parts_[i])) return false;
  for (size_t i = 0; i < prototypes_.size(); ++i)
    if (plan.prototypes[i].index != prototypes_[i].index) return false;
  return true;
}

RTCGeometry EmbreeScene::newTriangles(const Vec3* positions, uint32_t vertexCount,
                                      const Triangle* triangles, uint32_t triangleCount,
                                      uint32_t firstVertex, bool shareIndices) {
  RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
  rtcSetGeometryUserData(geometry, &maskView_);
  setMaskFilter(geometry, filtered_);
  shareVertices(geometry, positions, vertexCount);
  if (shareIndices) {
    shareTriangles(geometry, triangles, triangleCount);
  } else if (auto* indices = static_cast<uint32_t*>(
                 rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                         3 * sizeof(uint32_t), triangleCount))) {
    for (uint32_t t = 0; t < triangleCount; ++t)
      for (int k = 0; k < 3; ++k) indices[3 * t + k] = triangles[t].v[k] - firstVertex;
  }
  rtcCommitGeometry(geometry);
  return geometry;
}

void EmbreeScene::placeInstance(const SceneData& scene, const Part& part) {
  const MeshInstance& object = scene.meshInstances.objects[uint32_t(part.object)];
  float rows[12];
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) rows[4 * i + j] = object.linear.m[i][j];
    rows[4 * i + 3] = object.translation[i];
  }
  rtcSetGeometryTransform(part.geometry, 0, RTC_FORMAT_FLOAT3X4_ROW_MAJOR, rows);
  rtcCommitGeometry(part.geometry);
}

void EmbreeScene::build(const SceneData& scene) {
  built_ = true;
  release();
  useIndexedLeaves(scene.triangles.size() >= indexedLeavesFrom_);
  lastError.clear();
  const auto start = std::chrono::steady_clock::now();
  placeSpheres(scene);
  const bool inBlocks = placeTriangleBlocks(scene);
  buildSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (scene.triangles.empty() || inBlocks) return;

  Plan plan = planParts(scene);
  parts_ = std::move(plan.parts);
  prototypes_ = std::move(plan.prototypes);
  for (const Part& part : parts_) firstTriangleOf_.push_back(part.firstTriangle);
  filtered_ = !scene.alphaMasks.empty();
  for (Prototype& prototype : prototypes_) {
    const MeshPrototype& mesh = scene.meshInstances.prototypes[uint32_t(prototype.index)];
    const MeshInstance& first = scene.meshInstances.objects[mesh.firstInstance];
    prototype.scene = rtcNewScene(device_);
    rtcSetSceneFlags(prototype.scene, RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);
    rtcSetSceneBuildQuality(prototype.scene, RTC_BUILD_QUALITY_MEDIUM);
    // Its own indices: the instance whose triangles they are may be gone when a later frame
    // refits, and the prototype's vertices start at that instance's first.
    prototype.vertices = mesh.positions.data();
    prototype.geometry = newTriangles(prototype.vertices, uint32_t(mesh.positions.size()),
                                      scene.triangles.data() + first.firstTriangle,
                                      first.triangleCount, first.firstVertex, false);
    rtcAttachGeometryByID(prototype.scene, prototype.geometry, 0);
  }
  scene_ = rtcNewScene(device_);
  rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);
  rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_MEDIUM);
  for (uint32_t id = 0; id < parts_.size(); ++id) {
    Part& part = parts_[id];
    if (part.object < 0) {
      part.vertices = scene.positions.data() + part.firstVertex;
      part.geometry =
          newTriangles(part.vertices, part.vertexCount, scene.triangles.data() + part.firstTriangle,
                       part.triangleCount, part.firstVertex, part.sharesIndices());
    } else {
      part.geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_INSTANCE);
      rtcSetGeometryInstancedScene(part.geometry, prototypes_[uint32_t(part.prototype)].scene);
      placeInstance(scene, part);
    }
    rtcAttachGeometryByID(scene_, part.geometry, id);
  }
  for (const Prototype& prototype : prototypes_) commit(prototype.scene);
  commit(scene_);
}

void EmbreeScene::refit(const SceneData& scene) {
  lastError.clear();
  const auto start = std::chrono::steady_clock::now();
  placeSpheres(scene);
  placeTriangleBlocks(scene);
  buildSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!scene_) return;
  // A motion keeps the meshes (FrameScene's structure key covers them) and so the repeats; a
  // caller's Motion that repeats them otherwise gets a new build.
  if (!sameParts(planParts(scene))) {
    build(scene);
    return;
  }
  // The prototypes, in object space, stay (they are shared anew where their arrays moved): the
  // objects move, the runs' vertices and the instances' transforms.
  for (Prototype& prototype : prototypes_) {
    const PaddedVector<Vec3>& positions =
        scene.meshInstances.prototypes[uint32_t(prototype.index)].positions;
    if (positions.data() == prototype.vertices) continue;
    prototype.vertices = positions.data();
    shareVertices(prototype.geometry, prototype.vertices, positions.size());
    rtcSetGeometryBuildQuality(prototype.geometry, RTC_BUILD_QUALITY_REFIT);
    rtcCommitGeometry(prototype.geometry);
    commit(prototype.scene);
  }
  for (Part& part : parts_) {
    if (part.object >= 0) {
      placeInstance(scene, part);
      continue;
    }
    part.vertices = scene.positions.data() + part.firstVertex;
    shareVertices(part.geometry, part.vertices, part.vertexCount);
    rtcSetGeometryBuildQuality(part.geometry, RTC_BUILD_QUALITY_REFIT);
    // The same triangles: only the array may have moved in memory.
    if (part.sharesIndices())
      shareTriangles(part.geometry, scene.triangles.data() + part.firstTriangle,
                     part.triangleCount);
    rtcCommitGeometry(part.geometry);
  }
  commit(scene_);
}

void EmbreeScene::commit(RTCScene scene) {
  const auto start = std::chrono::steady_clock::now();
  rtcCommitScene(scene);
  buildSeconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (rtcGetDeviceError(device_) != RTC_ERROR_NONE || !lastError.empty())
    throw BackendError("Embree could not build the scene's BVH: " +
                       (lastError.empty() ? std::string("unknown error") : lastError));
}

}  // namespace candela
