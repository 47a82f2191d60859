// A camera of a glTF file (docs/scene-format.md, *A camera from a glTF file*): the `number`-th
// perspective camera that the file's scene places (in the order its nodes are visited: a node
// before its children, siblings in order), posed by its node's transform (a glTF camera looks
// along its -z with +y up; any scale is dropped) and its vertical field of view. Throws SceneError
// "<label>: <reason>" for a file that cannot be read, one that places fewer cameras, an
// orthographic camera or a field of view outside (0, 180) degrees.
#pragma once

#include <cstdint>
#include <string>

#include "core/mat3.h"
#include "core/vec3.h"

namespace candela {

struct GltfCamera {
  Mat3 worldToCamera;  // OpenCV axes: x right, y down, z forward
  Vec3 translation;    // t of [R | t]
  double yfovDegrees = 0;
};

GltfCamera readGltfCamera(const std::string& path, const std::string& label, uint32_t number);

}  // namespace candela
