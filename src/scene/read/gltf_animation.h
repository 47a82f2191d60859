// A glTF animation's channels (a node's translation, rotation and scale, and its mesh's morph
// target weights), sampled at a time in seconds as glTF says: before its first key the first value,
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

  // The morph target weights of node `index`'s mesh at time t where this animation sets them
  // (*weights gets one per target), or false.
  bool weightsAt(int index, double t, std::vector<double>* weights) const;

  // The time of its last key (seconds): how long it lasts from time 0.
  double length() const { return length_; }

  // Whether a channel moves node `index` (its translation, rotation or scale).
  bool moves(int index) const { return nodes_.count(index) > 0; }
  // Whether a channel sets node `index`'s morph target weights.
  bool weighs(int index) const { return weights_.count(index) > 0; }

 private:
  struct Channel {
    enum class Mode { Step, Linear, Cubic } mode = Mode::Linear;
    std::vector<float> times, values;  // values: a key's components (CUBICSPLINE: in, value, out)
    int components = 3;
    bool rotation = false;                 // a unit quaternion: spherically interpolated
    void at(double t, double* out) const;  // `components` numbers
    std::array<double, 4> at(double t) const;
  };
  // node -> its translation's, rotation's and scale's channel in channels_ (-1: none)
  std::map<int, std::array<int, 3>> nodes_;
  std::map<int, int> weights_;  // node -> its weights' channel in channels_
  double length_ = 0;
  std::vector<Channel> channels_;
};

// The index of the animation that `name` names, or the `number`-th; throws SceneError "<label>:
// ..." where the file has none such.
size_t findGltfAnimation(const tinygltf::Model& model, const std::string& label,
                         const std::string& name, int number);
// The same among animations of these `names`, in the file's order.
size_t findGltfAnimation(const std::vector<std::string>& names, const std::string& label,
                         const std::string& name, int number);

}  // namespace candela
