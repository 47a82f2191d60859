#include "backends/cpu/embree_scene.h"

#include <atomic>
#include <chrono>
#include <cstring>
#include <limits>
#include <string>

#include "backends/backend_error.h"
#include "geometry/primitive_bounds.h"
#include "geometry/sphere_intersect.h"

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

Ray toRay(const RTCRay& r) {
  Ray ray;
  ray.origin = Vec3(r.org_x, r.org_y, r.org_z);
  ray.direction = Vec3(r.dir_x, r.dir_y, r.dir_z);
  ray.tMax = r.tfar;
  return ray;
}

// The sphere geometry's user data is the EmbreeScene's pointer to the spheres of the scene given
// last, so a frame that moves spheres needs no new geometry. Only single-ray queries are made
// (rtcIntersect1, rtcOccluded1), so every callback sees N = 1.
const Sphere* spheresOf(void* userPtr) { return *static_cast<const Sphere* const*>(userPtr); }

void sphereBounds(const RTCBoundsFunctionArguments* args) {
  const Bounds3 b = sphereBounds(spheresOf(args->geometryUserPtr)[args->primID]);
  *args->bounds_o = RTCBounds{b.lo.x, b.lo.y, b.lo.z, 0.0f, b.hi.x, b.hi.y, b.hi.z, 0.0f};
}

void sphereIntersect(const RTCIntersectFunctionNArguments* args) {
  if (args->valid[0] == 0) return;
  RTCRayHit* rayHit = reinterpret_cast<RTCRayHit*>(args->rayhit);
  float t;
  const Sphere& sphere = spheresOf(args->geometryUserPtr)[args->primID];
  if (!intersectSphere(sphere, toRay(rayHit->ray), rayHit->ray.tfar, &t)) return;
  rayHit->ray.tfar = t;
  rayHit->hit.u = rayHit->hit.v = 0.0f;
  rayHit->hit.Ng_x = rayHit->hit.Ng_y = rayHit->hit.Ng_z = 0.0f;  // surfaceAt computes it
  rayHit->hit.primID = args->primID;
  rayHit->hit.geomID = args->geomID;
  rayHit->hit.instID[0] = args->context->instID[0];
}

void sphereOccluded(const RTCOccludedFunctionNArguments* args) {
  if (args->valid[0] == 0) return;
  const auto* context = reinterpret_cast<const EmbreeSkipContext*>(args->context);
  if (args->primID == context->skipPrim) return;
  RTCRay* ray = reinterpret_cast<RTCRay*>(args->ray);
  float t;
  const Sphere& sphere = spheresOf(args->geometryUserPtr)[args->primID];
  if (intersectSphere(sphere, toRay(*ray), ray->tfar, &t))
    ray->tfar = -std::numeric_limits<float>::infinity();
}

}  // namespace

void rejectSkippedTriangle(const RTCFilterFunctionNArguments* args) {
  const auto* context = reinterpret_cast<const EmbreeSkipContext*>(args->context);
  const RTCHit* hit = reinterpret_cast<const RTCHit*>(args->hit);
  if (hit->geomID == kEmbreeTriangles && context->sphereCount + hit->primID == context->skipPrim)
    args->valid[0] = 0;
}

EmbreeScene::EmbreeScene() {
  device_ = rtcNewDevice(nullptr);
  if (!device_)
    throw BackendError("Embree could not start: " + std::to_string(rtcGetDeviceError(nullptr)));
  rtcSetDeviceErrorFunction(device_, keepError, nullptr);
  rtcSetDeviceMemoryMonitorFunction(device_, countMemory, nullptr);
}

EmbreeScene::~EmbreeScene() {
  if (scene_) rtcReleaseScene(scene_);
  if (triangles_) rtcReleaseGeometry(triangles_);
  if (spheres_) rtcReleaseGeometry(spheres_);
  rtcReleaseDevice(device_);
}

size_t EmbreeScene::bytesInUse() { return size_t(std::max(0LL, embreeBytes.load())); }

void EmbreeScene::update(const SceneData& scene, SceneChange change) {
  if (!scene_ || change == SceneChange::Structure)
    build(scene);
  else if (change == SceneChange::Motion)
    refit(scene);
  sphereArray_ = scene.spheres.data();
}

void EmbreeScene::build(const SceneData& scene) {
  if (scene_) rtcReleaseScene(scene_);
  if (triangles_) rtcReleaseGeometry(triangles_);
  if (spheres_) rtcReleaseGeometry(spheres_);
  scene_ = nullptr;
  triangles_ = spheres_ = nullptr;
  lastError.clear();

  scene_ = rtcNewScene(device_);
  rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);
  rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_MEDIUM);
  sphereArray_ = scene.spheres.data();
  sphereCount_ = uint32_t(scene.spheres.size());

  if (!scene.triangles.empty()) {
    triangles_ = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    // Embree reads vertices with 16-byte loads, so it gets its own padded copy; the triangles'
    // fourth word (the material) is passed over by the stride.
    void* vertices =
        rtcSetNewGeometryBuffer(triangles_, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                sizeof(Vec3), scene.positions.size());
    if (vertices)
      std::memcpy(vertices, scene.positions.data(), scene.positions.size() * sizeof(Vec3));
    rtcSetSharedGeometryBuffer(triangles_, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                               scene.triangles.data(), 0, sizeof(Triangle), scene.triangles.size());
    rtcCommitGeometry(triangles_);
    rtcAttachGeometryByID(scene_, triangles_, kEmbreeTriangles);
  }
  if (!scene.spheres.empty()) {
    spheres_ = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(spheres_, unsigned(scene.spheres.size()));
    rtcSetGeometryUserData(spheres_, &sphereArray_);
    rtcSetGeometryBoundsFunction(spheres_, sphereBounds, nullptr);
    rtcSetGeometryIntersectFunction(spheres_, sphereIntersect);
    rtcSetGeometryOccludedFunction(spheres_, sphereOccluded);
    rtcCommitGeometry(spheres_);
    rtcAttachGeometryByID(scene_, spheres_, kEmbreeSpheres);
  }
  commit();
}

void EmbreeScene::refit(const SceneData& scene) {
  lastError.clear();
  sphereArray_ = scene.spheres.data();
  if (triangles_) {
    void* vertices = rtcGetGeometryBufferData(triangles_, RTC_BUFFER_TYPE_VERTEX, 0);
    std::memcpy(vertices, scene.positions.data(), scene.positions.size() * sizeof(Vec3));
    // The same triangles: only the array may have moved in memory.
    rtcSetSharedGeometryBuffer(triangles_, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                               scene.triangles.data(), 0, sizeof(Triangle), scene.triangles.size());
    rtcUpdateGeometryBuffer(triangles_, RTC_BUFFER_TYPE_VERTEX, 0);
    rtcSetGeometryBuildQuality(triangles_, RTC_BUILD_QUALITY_REFIT);
    rtcCommitGeometry(triangles_);
  }
  if (spheres_) rtcCommitGeometry(spheres_);
  commit();
}

void EmbreeScene::commit() {
  const auto start = std::chrono::steady_clock::now();
  rtcCommitScene(scene_);
  buildSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (rtcGetDeviceError(device_) != RTC_ERROR_NONE || !lastError.empty())
    throw BackendError("Embree could not build the scene's BVH: " +
                       (lastError.empty() ? std::string("unknown error") : lastError));
}

}  // namespace candela
