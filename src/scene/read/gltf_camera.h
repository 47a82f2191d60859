// A camera of a glTF file (docs/scene-format.md, *A camera from a glTF file*): the `number`-th
// camera that the file's scene places (in the order its nodes are visited: a node before its
// children, siblings in order), posed by its node's transform (a glTF camera looks along its -z
// with +y up; any scale is dropped), with a perspective camera's vertical field of view or an
// orthographic camera's half height (ymag). Throws SceneError "<label>: <reason>" for a file that
// cannot be read, one that places fewer cameras, a field of view outside (0, 180) degrees or a
// ymag that is not positive.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/mat3.h"
#include "core/vec3.h"

namespace candela {

struct GltfCamera {
  Mat3 worldToCamera;  // OpenCV axes: x right, y down, z forward
  Vec3 translation;    // t of [R | t]
  double yfovDegrees = 0;  // a perspective camera's
  double ymag = 0;         // an orthographic camera's half height in world units (else 0)
};

GltfCamera readGltfCamera(const std::string& path, const std::string& label, uint32_t number);

// The same camera at each of `times` (seconds) of one of the file's animations (the one named
// `animationName`, or else the `animationNumber`-th; scene/read/gltf_animation.h), which moves
// its node or the node's parents; throws as readGltfCamera, and for an animation the file does
// not have or cannot play.
std::vector<GltfCamera> readGltfCameraPoses(const std::string& path, const std::string& label,
                                            uint32_t number, const std::string& animationName,
                                            int animationNumber, const std::vector<double>& times);

}  // namespace candela
