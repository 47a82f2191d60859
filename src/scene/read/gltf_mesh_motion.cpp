// A mesh posed by a glTF animation at each time; see gltf_mesh_motion.h.
#include "scene/read/gltf_mesh_motion.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <mutex>
#include <utility>

#include "scene/dvec3.h"
#include "scene/read/gltf_animation.h"
#include "scene/vertex_normals.h"

namespace candela {
namespace {

// Gives the normals that `mesh` computed for its faces without normals of the file
// (withComputedNormals: those from `first` on) their values for the faces where they are now,
// each the angle-weighted sum of the unit normals of the faces whose corners share it, so that
// the faces smoothed together at rest stay smoothed together (and the mesh's indices, its
// layout, stay the same at every time).
void reshade(MeshDesc* mesh, size_t first) {
  if (mesh->normals.size() <= first) return;
  std::vector<DVec3> sums(mesh->normals.size() - first, DVec3{0, 0, 0});
  for (const MeshTriangle& t : mesh->triangles) {
    if (t.n[0] < int32_t(first)) continue;  // the file's normals, or flat
    const DVec3 p[3] = {dvec3(mesh->positions[t.v[0]]), dvec3(mesh->positions[t.v[1]]),
                        dvec3(mesh->positions[t.v[2]])};
    const DVec3 edge[3] = {p[1] - p[0], p[2] - p[1], p[0] - p[2]};  // edge k leaves corner k
    const DVec3 n = cross(edge[2], edge[0]);
    const double length = std::sqrt(dot(n, n));
    if (!(length > 0 && length <= 1e300)) continue;
    for (int k = 0; k < 3; ++k) {
      const int previous = (k + 2) % 3;
      const double c = -dot(edge[k], edge[previous]) /
                       std::sqrt(dot(edge[k], edge[k]) * dot(edge[previous], edge[previous]));
      const double weight = std::acos(std::clamp(c, -1.0, 1.0)) / length;
      DVec3& sum = sums[size_t(t.n[k]) - first];
      sum = {sum.x + weight * n.x, sum.y + weight * n.y, sum.z + weight * n.z};
    }
  }
  for (size_t j = 0; j < sums.size(); ++j) {
    const DVec3& sum = sums[j];
    const double length = std::sqrt(dot(sum, sum));
    if (length > 1e-12)  // else (its faces now of no area) it keeps its value at rest
      mesh->normals[first + j] =
          Vec3(float(sum.x / length), float(sum.y / length), float(sum.z / length));
  }
}

class GltfMeshMotion : public MeshMotion {
 public:
  // With `creaseDegrees`, the faces without normals of the file get them as at rest
  // (withComputedNormals).
  GltfMeshMotion(std::shared_ptr<const MeshDesc> mesh, std::shared_ptr<const GltfRig> rig,
                 GltfAnimation animation, const GltfClock& clock, float creaseDegrees)
      : rest_(creaseDegrees > 0 ? withComputedNormals(*mesh, creaseDegrees) : *mesh),
        fileNormals_(mesh->normals.size()),
        rig_(std::move(rig)),
        animation_(std::move(animation)),
        clock_(clock) {}

  std::shared_ptr<const MeshDesc> meshAt(double seconds) const override {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      for (const auto& [time, mesh] : recent_)
        if (time == seconds) return mesh;
    }
    MeshDesc posed = rest_;
    const GltfPose pose = rig_->pose(&animation_, clock_.at(seconds, animation_.length()));
    for (const GltfRigPrimitive& p : rig_->primitives)
      rig_->place(p, pose, &posed.positions, &posed.normals);
    reshade(&posed, fileNormals_);
    auto made = std::make_shared<const MeshDesc>(std::move(posed));
    const std::lock_guard<std::mutex> lock(mutex_);
    recent_.emplace_back(seconds, made);
    // A frame asks for its time, its shutter's and the next frame's (the flow pass): a few kept.
    if (recent_.size() > kKept) recent_.pop_front();
    return made;
  }

 private:
  static constexpr size_t kKept = 16;
  MeshDesc rest_;       // as loaded, with the normals computed for it
  size_t fileNormals_;  // how many of its normals are the file's
  std::shared_ptr<const GltfRig> rig_;
  GltfAnimation animation_;
  GltfClock clock_;
  mutable std::mutex mutex_;
  mutable std::deque<std::pair<double, std::shared_ptr<const MeshDesc>>> recent_;
};

}  // namespace

std::shared_ptr<const MeshMotion> gltfMeshMotion(const ObjectDesc& object, const std::string& label,
                                                 std::shared_ptr<const MeshDesc> mesh,
                                                 std::shared_ptr<const GltfRig> rig) {
  std::vector<std::string> names;
  for (const GltfRig::Animation& a : rig->animations) names.push_back(a.name);
  const GltfRig::Animation& picked = rig->animations[findGltfAnimation(
      names, label, object.gltfAnimationName, object.gltfAnimationNumber)];
  if (!picked.played) throw SceneError(picked.fault);
  const GltfAnimation& animation = *picked.played;
  if (!rig->movedBy(animation)) return nullptr;
  const bool computesNormals = object.smooth && object.creaseDegrees > 0 &&
                               std::any_of(mesh->triangles.begin(), mesh->triangles.end(),
                                           [](const MeshTriangle& t) { return t.n[0] < 0; });
  return std::make_shared<GltfMeshMotion>(std::move(mesh), std::move(rig), animation,
                                          object.gltfClock,
                                          computesNormals ? object.creaseDegrees : 0.0f);
}

}  // namespace candela
