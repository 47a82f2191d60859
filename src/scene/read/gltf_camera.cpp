// Reading a glTF file's camera; see gltf_camera.h.
#include "scene/read/gltf_camera.h"

#include <cmath>
#include <memory>

#include "scene/read/gltf_file.h"
#include "scene/read/gltf_nodes.h"
#include "scene/scene_error.h"

namespace candela {
namespace {

constexpr double kDegreesPerRadian = 57.295779513082320876798;

// The unit vector along v in double precision, or none where v has no length.
bool normalized(const double v[3], double out[3]) {
  const double length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  if (!(length > 0.0 && std::isfinite(length))) return false;
  for (int i = 0; i < 3; ++i) out[i] = v[i] / length;
  return true;
}

}  // namespace

GltfCamera readGltfCamera(const std::string& path, const std::string& label, uint32_t number) {
  const std::unique_ptr<GltfFile> file = readGltfFile(path, label);
  const tinygltf::Model& model = file->model;
  uint32_t seen = 0;
  bool found = false;
  GltfCamera camera;
  forEachPlacedNode(model, label, [&](int index, const tinygltf::Node& node, const GltfMatrix& w) {
    if (node.camera < 0 || found || seen++ != number) return;
    found = true;
    const std::string where = label + ": nodes[" + std::to_string(index) + "].camera";
    if (size_t(node.camera) >= model.cameras.size())
      throw SceneError(where + ": camera " + std::to_string(node.camera) + " does not exist (" +
                       std::to_string(model.cameras.size()) + " cameras)");
    const tinygltf::Camera& c = model.cameras[size_t(node.camera)];
    const std::string cameraWhere = label + ": cameras[" + std::to_string(node.camera) + "]";
    if (c.type != "perspective")
      throw SceneError(cameraWhere + ": a \"" + c.type +
                       "\" camera; candela takes perspective cameras from glTF files");
    camera.yfovDegrees = c.perspective.yfov * kDegreesPerRadian;
    if (!(camera.yfovDegrees > 0.0 && camera.yfovDegrees < 180.0))
      throw SceneError(cameraWhere +
                       ".perspective.yfov: expected an angle between 0 and pi "
                       "(exclusive), got " +
                       std::to_string(c.perspective.yfov));
    // Right and up from the node's x and y axes, made orthonormal; the camera looks along
    // right x up's opposite, whatever the node's scale or mirroring.
    double right[3], up[3], back[3];
    const double x[3] = {w[0], w[1], w[2]}, y[3] = {w[4], w[5], w[6]};
    double yOff[3];
    bool ok = normalized(x, right);
    const double along = right[0] * y[0] + right[1] * y[1] + right[2] * y[2];
    for (int i = 0; i < 3; ++i) yOff[i] = y[i] - along * right[i];
    ok = ok && normalized(yOff, up);
    if (!ok) throw SceneError(where + ": the node's transform flattens the camera");
    back[0] = right[1] * up[2] - right[2] * up[1];
    back[1] = right[2] * up[0] - right[0] * up[2];
    back[2] = right[0] * up[1] - right[1] * up[0];
    // OpenCV's world-to-camera rows: x right, y down, z forward; t = -R position.
    const double rows[3][3] = {
        {right[0], right[1], right[2]}, {-up[0], -up[1], -up[2]}, {-back[0], -back[1], -back[2]}};
    for (int i = 0; i < 3; ++i) {
      double t = 0.0;
      for (int j = 0; j < 3; ++j) {
        camera.worldToCamera.m[i][j] = float(rows[i][j]);
        t -= rows[i][j] * w[size_t(12 + j)];
      }
      if (!(std::fabs(t) < 1e30)) throw SceneError(where + ": the camera's place is beyond reach");
      camera.translation[i] = float(t);
    }
  });
  if (!found)
    throw SceneError(label + ": camera " + std::to_string(number) +
                     " is asked for, but the file's "
                     "scene places " +
                     std::to_string(seen) + (seen == 1 ? " camera" : " cameras"));
  return camera;
}

}  // namespace candela
