#include "backends/cpu/embree_scene.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstring>
#include <string>

#include "backends/backend_error.h"
#include "geometry/bvh_build.h"

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

}  // namespace

void rejectMaskedHit(const RTCFilterFunctionNArguments* args) {
  const auto* geometry = static_cast<const GeometryView*>(args->geometryUserPtr);
  const unsigned n = args->N;
  for (unsigned i = 0; i < n; ++i) {
    if (args->valid[i] != -1) continue;
    Ray ray;
    ray.origin = Vec3(RTCRayN_org_x(args->ray, n, i), RTCRayN_org_y(args->ray, n, i),
                      RTCRayN_org_z(args->ray, n, i));
    ray.direction = Vec3(RTCRayN_dir_x(args->ray, n, i), RTCRayN_dir_y(args->ray, n, i),
                         RTCRayN_dir_z(args->ray, n, i));
    const Triangle& tri = geometry->triangles[RTCHitN_primID(args->hit, n, i)];
    if (!alphaKeepsHit(*geometry, tri, RTCHitN_u(args->hit, n, i), RTCHitN_v(args->hit, n, i),
                       ray))
      args->valid[i] = 0;
  }
}

void rejectSkippedTriangle(const RTCFilterFunctionNArguments* args) {
  const auto* context = reinterpret_cast<const EmbreeSkipContext*>(args->context);
  const unsigned n = args->N;
  for (unsigned i = 0; i < n; ++i) {
    if (args->valid[i] != -1) continue;
    const uint32_t skip = context->skipPrims[RTCRayN_id(args->ray, n, i)];
    if (context->sphereCount + RTCHitN_primID(args->hit, n, i) == skip) args->valid[i] = 0;
  }
}

EmbreeScene::EmbreeScene(const char* deviceConfig) {
  device_ = rtcNewDevice(deviceConfig);
  if (!device_)
    throw BackendError("Embree could not start: " + std::to_string(rtcGetDeviceError(nullptr)));
  rtcSetDeviceErrorFunction(device_, keepError, nullptr);
  rtcSetDeviceMemoryMonitorFunction(device_, countMemory, nullptr);
}

EmbreeScene::~EmbreeScene() {
  if (scene_) rtcReleaseScene(scene_);
  if (triangles_) rtcReleaseGeometry(triangles_);
  rtcReleaseDevice(device_);
}

size_t EmbreeScene::bytes() const {
  return size_t(std::max(0LL, embreeBytes.load())) + sphereNodes_.size() * sizeof(BvhNode) +
         spherePrims_.size() * sizeof(uint32_t) + sphereBlocks_.bytes();
}

void EmbreeScene::update(const SceneData& scene, SceneChange change) {
  if (change == SceneChange::Structure || !built_) {
    build(scene);
  } else if (change == SceneChange::Motion) {
    refit(scene);
  }
  // A frame of new values keeps the geometry, but its arrays may lie elsewhere.
  sphereView_.spheres = scene.spheres.data();
  updateMasks(scene);
}

void EmbreeScene::updateMasks(const SceneData& scene) {
  const SceneView view = scene.view();
  maskView_ = view;  // the geometry part: triangles, uvs, masks and textures
  const bool masked = view.alphaMaskCount != 0;
  if (!triangles_ || masked == filtered_) return;
  // Scenes without masks pay nothing: the filters are installed only when a material is masked.
  rtcSetGeometryIntersectFilterFunction(triangles_, masked ? rejectMaskedHit : nullptr);
  rtcSetGeometryOccludedFilterFunction(triangles_, masked ? rejectMaskedHit : nullptr);
  rtcCommitGeometry(triangles_);
  commit();
  filtered_ = masked;
}

void EmbreeScene::placeSpheres(const SceneData& scene) {
  sphereCount_ = uint32_t(scene.spheres.size());
  sphereNodes_.clear();
  spherePrims_.clear();
  if (sphereCount_ <= kSphereBlocksUpTo) {
    sphereBlocks_.assign(scene.spheres.data(), sphereCount_);
  } else {
    sphereBlocks_.assign(nullptr, 0);
    BvhBuildResult bvh = buildBvh(scene.spheres.data(), sphereCount_, nullptr, nullptr, 0);
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

void EmbreeScene::build(const SceneData& scene) {
  built_ = true;
  if (scene_) rtcReleaseScene(scene_);
  if (triangles_) rtcReleaseGeometry(triangles_);
  scene_ = nullptr;
  triangles_ = nullptr;
  lastError.clear();
  const auto start = std::chrono::steady_clock::now();
  placeSpheres(scene);
  buildSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (scene.triangles.empty()) return;

  scene_ = rtcNewScene(device_);
  rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);
  rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_MEDIUM);
  triangles_ = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
  rtcSetGeometryUserData(triangles_, &maskView_);
  filtered_ = !scene.alphaMasks.empty();
  if (filtered_) {
    rtcSetGeometryIntersectFilterFunction(triangles_, rejectMaskedHit);
    rtcSetGeometryOccludedFilterFunction(triangles_, rejectMaskedHit);
  }
  // Embree reads vertices with 16-byte loads, so it gets its own padded copy; the triangles'
  // fourth word (the material) is passed over by the stride.
  void* vertices = rtcSetNewGeometryBuffer(triangles_, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                           sizeof(Vec3), scene.positions.size());
  if (vertices)
    std::memcpy(vertices, scene.positions.data(), scene.positions.size() * sizeof(Vec3));
  rtcSetSharedGeometryBuffer(triangles_, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                             scene.triangles.data(), 0, sizeof(Triangle), scene.triangles.size());
  rtcCommitGeometry(triangles_);
  rtcAttachGeometry(scene_, triangles_);
  commit();
}

void EmbreeScene::refit(const SceneData& scene) {
  lastError.clear();
  const auto start = std::chrono::steady_clock::now();
  placeSpheres(scene);
  buildSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!triangles_) return;
  void* vertices = rtcGetGeometryBufferData(triangles_, RTC_BUFFER_TYPE_VERTEX, 0);
  std::memcpy(vertices, scene.positions.data(), scene.positions.size() * sizeof(Vec3));
  // The same triangles: only the array may have moved in memory.
  rtcSetSharedGeometryBuffer(triangles_, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                             scene.triangles.data(), 0, sizeof(Triangle), scene.triangles.size());
  rtcUpdateGeometryBuffer(triangles_, RTC_BUFFER_TYPE_VERTEX, 0);
  rtcSetGeometryBuildQuality(triangles_, RTC_BUILD_QUALITY_REFIT);
  rtcCommitGeometry(triangles_);
  commit();
}

void EmbreeScene::commit() {
  const auto start = std::chrono::steady_clock::now();
  rtcCommitScene(scene_);
  buildSeconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (rtcGetDeviceError(device_) != RTC_ERROR_NONE || !lastError.empty())
    throw BackendError("Embree could not build the scene's BVH: " +
                       (lastError.empty() ? std::string("unknown error") : lastError));
}

}  // namespace candela
