// A glTF animation's channels that move nodes (translation, rotation and scale; morph weights are
// not read), sampled at a time in seconds as glTF says: before its first key the first value,
// after its last the last; STEP holds each key, LINEAR interpolates (a rotation by spherical
// interpolation along the shorter arc), CUBICSPLINE follows the cubic Hermite spline of the keys'
// tangents (a rotation normalized after). Every accessor is checked as the mesh loader checks its
// own; errors throw SceneError "<label>: animations[i]...: <reason>".
#pragma once

#include <array>
#include <map>
#include <string>
#include <vector>

#include "scene/read/gltf_nodes.h"
#include "scene/read/tiny_gltf_config.h"

namespace candela {

class GltfAnimation {
 public:
  GltfAnimation(const tinygltf::Model& model, size_t index, const std::string& label);

  // The node's own transform at time t where this animation moves it (what it leaves, as the
  // node has it), or false.
  bool localAt(int index, const tinygltf::Node& node, double t, GltfMatrix* local) const;

 private:
  struct Channel {
    enum class Mode { Step, Linear, Cubic } mode = Mode::Linear;
    std::vector<float> times, values;  // values: a key's components (CUBICSPLINE: in, value, out)
    int components = 3;
    std::array<double, 4> at(double t) const;
  };
  // node -> its translation's, rotation's and scale's channel in channels_ (-1: none)
  std::map<int, std::array<int, 3>> nodes_;
  std::vector<Channel> channels_;
};

// The index of the animation that `name` names, or the `number`-th; throws SceneError "<label>:
// ..." where the file has none such.
size_t findGltfAnimation(const tinygltf::Model& model, const std::string& label,
                         const std::string& name, int number);

}  // namespace candela
