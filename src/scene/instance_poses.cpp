#include "scene/instance_poses.h"

#include <unordered_map>
#include <utility>

#include "core/frame.h"
#include "core/rotation.h"
#include "scene/flatten.h"
#include "scene/light_emission_desc.h"
#include "scene/model_box.h"

namespace candela {

Mat3 lightModel(const LightDesc& l) {
  if (l.type == LightType::Sphere) return Mat3::diagonal(Vec3(l.radius));
  if (l.rectangle) {
    const RectangleAxes axes = rectangleAxes(l);
    return Mat3::fromColumns(axes.width * l.rectangle->size.x, axes.height * l.rectangle->size.y,
                             axes.normal);
  }
  if (!l.spot && l.type != LightType::Directional) return Mat3();
  const Vec3 axis = l.spot ? spotCone(l).axis : unitVector(l.direction);
  const Frame frame(axis);
  return Mat3::fromColumns(frame.s, frame.t, frame.n);
}

std::vector<InstancePose> instancePoses(const SceneDesc& desc) {
  std::vector<InstancePose> poses;
  for (auto& [number, name] : instanceNames(desc)) {
    InstancePose pose;
    pose.number = number;
    pose.name = std::move(name);
    poses.push_back(std::move(pose));
  }
  size_t i = 0;
  for (const SphereDesc& s : desc.spheres) {
    poses[i].linear = Mat3::diagonal(Vec3(s.radius));
    poses[i].modelBox = sphereModelBox();
    poses[i++].position = s.position;
  }
  std::unordered_map<const MeshDesc*, Bounds3> meshBoxes;  // objects that name one file share it
  for (const ObjectDesc& o : desc.objects) {
    poses[i].linear = eulerRotation(o.rotation) * Mat3::diagonal(o.scale);
    const MeshDesc& model = modelMesh(o);
    const auto [box, fresh] = meshBoxes.try_emplace(&model);
    if (fresh) box->second = meshBox(model);
    poses[i].modelBox = box->second;
    poses[i++].position = o.position;
  }
  for (const LightDesc& l : desc.lights) {
    poses[i].linear = lightModel(l);
    poses[i].modelBox = lightModelBox(l);
    poses[i++].position = l.position;  // a directional light's: the origin
  }
  for (InstancePose& pose : poses) {  // -0 as 0, for the files
    for (auto& row : pose.linear.m)
      for (float& v : row) v += 0.0f;
    if (pose.modelBox)
      pose.modelBox = Bounds3(pose.modelBox->lo + Vec3(0.0f), pose.modelBox->hi + Vec3(0.0f));
  }
  return poses;
}

InstancePose poseInCamera(const InstancePose& pose, const CameraMatrices& camera) {
  InstancePose seen = pose;
  // R m and R p + t, each entry summed in double: one rounding, the result's.
  for (int i = 0; i < 3; ++i) {
    const float* r = camera.rotation.m[i];
    for (int j = 0; j < 3; ++j)
      seen.linear.m[i][j] =
          float(double(r[0]) * pose.linear.m[0][j] + double(r[1]) * pose.linear.m[1][j] +
                double(r[2]) * pose.linear.m[2][j]) +
          0.0f;  // -0 as 0, for the files
    seen.position[i] = float(double(r[0]) * pose.position.x + double(r[1]) * pose.position.y +
                             double(r[2]) * pose.position.z + double(camera.translation[i])) +
                       0.0f;
  }
  return seen;
}

}  // namespace candela
