// Reading a glTF file's camera; see gltf_camera.h.
#include "scene/read/gltf_camera.h"

#include <cmath>
#include <memory>

#include "core/constants.h"
#include "scene/dvec3.h"
#include "scene/read/gltf_animation.h"
#include "scene/read/gltf_file.h"
#include "scene/read/gltf_nodes.h"
#include "scene/scene_error.h"

namespace candela {
namespace {

constexpr double kDegreesPerRadian = 180.0 / kPiDouble;

// The `number`-th camera that the file's scene places, its nodes moved by `animation` at time t
// where one is given.
GltfCamera cameraOf(const tinygltf::Model& model, const std::string& label, uint32_t number,
                    const GltfAnimation* animation, double t) {
  uint32_t seen = 0;
  bool found = false;
  GltfCamera camera;
  const GltfLocalOverride moved = [&](int index, const tinygltf::Node& node, GltfMatrix* local) {
    return animation && animation->localAt(index, node, t, local);
  };
  forEachPlacedNode(
      model, label,
      [&](int index, const tinygltf::Node& node, const GltfMatrix& w) {
        if (node.camera < 0 || found || seen++ != number) return;
        found = true;
        const std::string where = label + ": nodes[" + std::to_string(index) + "].camera";
        if (size_t(node.camera) >= model.cameras.size())
          throw SceneError(where + ": camera " + std::to_string(node.camera) + " does not exist (" +
                           std::to_string(model.cameras.size()) + " cameras)");
        const tinygltf::Camera& c = model.cameras[size_t(node.camera)];
        const std::string cameraWhere = label + ": cameras[" + std::to_string(node.camera) + "]";
        if (c.type == "orthographic") {
          camera.ymag = c.orthographic.ymag;
          if (!(camera.ymag > 0.0 && camera.ymag < 1e30))
            throw SceneError(cameraWhere + ".orthographic.ymag: expected a positive number, got " +
                             formatNumber(float(c.orthographic.ymag)));
        } else if (c.type == "perspective") {
          camera.yfovDegrees = c.perspective.yfov * kDegreesPerRadian;
          if (!(camera.yfovDegrees > 0.0 && camera.yfovDegrees < 180.0))
            throw SceneError(cameraWhere + ".perspective.yfov: expected an angle between 0 and " +
                             "pi (exclusive), got " + std::to_string(c.perspective.yfov));
        } else {
          throw SceneError(cameraWhere + ".type: expected \"perspective\" or \"orthographic\", " +
                           "got \"" + c.type + "\"");
        }
        // Right and up from the node's x and y axes, made orthonormal; the camera looks along
        // right x up's opposite, whatever the node's scale or mirroring.
        const DVec3 x{w[0], w[1], w[2]}, y{w[4], w[5], w[6]};
        const DVec3 right = unit(x), up = unit(y - dot(right, y) * right);
        if (!std::isfinite(dot(right, right) + dot(up, up)))
          throw SceneError(where + ": the node's transform flattens the camera");
        const DVec3 back = cross(right, up);
        // OpenCV's world-to-camera rows: x right, y down, z forward; t = -R position.
        const DVec3 rows[3] = {right, -1.0 * up, -1.0 * back};
        const DVec3 position{w[12], w[13], w[14]};
        for (int i = 0; i < 3; ++i) {
          const DVec3& r = rows[i];
          camera.worldToCamera.m[i][0] = float(r.x);
          camera.worldToCamera.m[i][1] = float(r.y);
          camera.worldToCamera.m[i][2] = float(r.z);
          const double tr = -dot(r, position);
          if (!(std::fabs(tr) < 1e30))
            throw SceneError(where + ": the camera's place is beyond reach");
          camera.translation[i] = float(tr);
        }
      },
      moved);
  if (!found)
    throw SceneError(label + ": camera " + std::to_string(number) + " is asked for, but " +
                     "the file's scene places " + std::to_string(seen) +
                     (seen == 1 ? " camera" : " cameras"));
  return camera;
}

}  // namespace

GltfCamera readGltfCamera(const std::string& path, const std::string& label, uint32_t number) {
  const std::unique_ptr<GltfFile> file = readGltfFile(path, label);
  return cameraOf(file->model, label, number, nullptr, 0.0);
}

std::vector<GltfCamera> readGltfCameraPoses(const std::string& path, const std::string& label,
                                            uint32_t number, const std::string& animationName,
                                            int animationNumber, const std::vector<double>& times) {
  const std::unique_ptr<GltfFile> file = readGltfFile(path, label);
  const size_t index = findGltfAnimation(file->model, label, animationName, animationNumber);
  const GltfAnimation animation(file->model, index, label);
  std::vector<GltfCamera> poses;
  poses.reserve(times.size());
  for (double t : times) poses.push_back(cameraOf(file->model, label, number, &animation, t));
  return poses;
}

}  // namespace candela
