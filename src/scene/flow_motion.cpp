#include "scene/flow_motion.h"

#include <cmath>
#include <string>

#include "core/rotation.h"
#include "scene/camera_resolve.h"
#include "scene/flatten.h"
#include "scene/instance_poses.h"
#include "scene/scene_error.h"

namespace candela {

namespace {

bool same(const Vec3& u, const Vec3& v) { return u.x == v.x && u.y == v.y && u.z == v.z; }

// p' = position' + (radius' / radius) (p - position).
InstanceMotion sphereMotion(const Vec3& position, float radius, const Vec3& nextPosition,
                            float nextRadius) {
  InstanceMotion m;
  if (same(position, nextPosition) && radius == nextRadius) return m;
  const float s = nextRadius / radius;
  m.linear = Mat3::diagonal(Vec3(s));
  m.offset = nextPosition - s * position;
  return m;
}

bool samePlacement(const ObjectDesc& a, const ObjectDesc& b) {
  return same(a.position, b.position) && same(a.rotation, b.rotation) && same(a.scale, b.scale);
}

// An object maps a mesh point q to position + R (scale * q); the motion takes a world point of
// it back to q and forward with the next frame's placement. A zero scale has no way back: its
// motion is NaN, which leaves its samples out of the pass.
InstanceMotion objectMotion(const ObjectDesc& now, const ObjectDesc& next) {
  InstanceMotion m;
  if (samePlacement(now, next)) return m;
  const Mat3 r = eulerRotation(now.rotation), rNext = eulerRotation(next.rotation);
  const Vec3 ratio(next.scale.x / now.scale.x, next.scale.y / now.scale.y,
                   next.scale.z / now.scale.z);
  m.linear = rNext * Mat3::diagonal(ratio) * r.transposed();
  m.offset = next.position - m.linear * now.position;
  return m;
}

// A rectangle light maps a point q of its model to position + A q (A its lightModel); the motion
// takes a world point of it back to q and forward with the next frame's placement.
InstanceMotion rectangleMotion(const LightDesc& now, const LightDesc& next) {
  InstanceMotion m;
  const Mat3 a = lightModel(now), aNext = lightModel(next);
  Mat3 inverse;
  if (!invert(a, &inverse)) return m;  // a rectangle's axes are never degenerate
  m.linear = aNext * inverse;
  m.offset = next.position - m.linear * now.position;
  return m;
}

FlowCamera flowCamera(const CameraDesc& desc, const std::string& label) {
  const Camera camera = resolveCamera(desc, label);
  FlowCamera f;
  f.K = intrinsicMatrix(desc);
  f.distortion = camera.distortion;
  f.projection = camera.projection;
  f.width = camera.width;
  f.height = camera.height;
  f.worldToCamera = camera.cameraToWorld.transposed();
  f.position = camera.position;
  return f;
}

}  // namespace

FlowMotion flowMotion(const SceneDesc& now, const SceneDesc& next) {
  if (now.spheres.size() != next.spheres.size() || now.objects.size() != next.objects.size() ||
      now.lights.size() != next.lights.size())
    throw SceneError(next.file + ": the flow pass needs the next frame to hold the same spheres, "
                     "objects and lights as " + now.file);
  FlowMotion f;
  f.instances.resize(1 + now.spheres.size() + now.objects.size() + now.lights.size());
  size_t i = 1;
  for (size_t k = 0; k < now.spheres.size(); ++k, ++i)
    f.instances[i] = sphereMotion(now.spheres[k].position, now.spheres[k].radius,
                                  next.spheres[k].position, next.spheres[k].radius);
  f.objectVertices.resize(now.objects.size());
  for (size_t k = 0; k < now.objects.size(); ++k, ++i) {
    f.instances[i] = objectMotion(now.objects[k], next.objects[k]);
    if (now.objects[k].meshMotion) {
      f.objectVertices[k] = placedVertices(next.objects[k], now.objects[k]);
      f.instances[i].perVertex = true;
    }
  }
  for (size_t k = 0; k < now.lights.size(); ++k, ++i)
    f.instances[i] = now.lights[k].rectangle
                         ? rectangleMotion(now.lights[k], next.lights[k])
                         : sphereMotion(now.lights[k].position, now.lights[k].radius,
                                        next.lights[k].position, next.lights[k].radius);
  f.frames.now = flowCamera(now.camera, now.file);
  f.frames.next = flowCamera(next.camera, next.file);
  f.frames.enabled = true;
  return f;
}

void applyFlowMotion(SceneData& scene, const FlowMotion& motion, FlowDirection direction) {
  const bool forward = direction == FlowDirection::Forward;
  std::vector<InstanceMotion>& motions = forward ? scene.materialMotions : scene.backwardMotions;
  auto& vertices = forward ? scene.flowVertices : scene.backwardFlowVertices;
  motions.assign(scene.materials.size(), InstanceMotion());
  for (size_t m = 0; m < scene.materials.size() && m < scene.materialInstances.size(); ++m) {
    const uint32_t instance = scene.materialInstances[m];
    if (instance < motion.instances.size()) motions[m] = motion.instances[instance];
  }
  vertices.clear();
  for (size_t k = 0; k < motion.objectVertices.size(); ++k) {
    const std::vector<Vec3>& next = motion.objectVertices[k];
    if (next.empty()) continue;
    // Flattened alike (the same mesh's layout): the object's vertices, as many in either frame.
    const uint32_t first = scene.objectFirstVertex[k];
    if (first + next.size() > scene.positions.size())
      throw SceneError(std::string("the flow pass's ") + (forward ? "next" : "previous") +
                       " frame places more vertices of objects[" + std::to_string(k) +
                       "] than this frame has");
    vertices.resize(scene.positions.size(), Vec3(0.0f));
    std::copy(next.begin(), next.end(), vertices.begin() + first);
  }
  (forward ? scene.flow : scene.backwardFlow) = motion.frames;
}

void clearFlowMotion(SceneData& scene) {
  scene.materialMotions.clear();
  scene.flowVertices.clear();
  scene.backwardMotions.clear();
  scene.backwardFlowVertices.clear();
  scene.flow = FlowFrames();
  scene.backwardFlow = FlowFrames();
}

}  // namespace candela
