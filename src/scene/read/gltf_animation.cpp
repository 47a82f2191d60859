// Sampling a glTF animation's node channels; see gltf_animation.h.
#include "scene/read/gltf_animation.h"

#include <algorithm>
#include <cmath>

#include "scene/read/did_you_mean.h"
#include "scene/read/gltf_accessor.h"
#include "scene/scene_error.h"

namespace candela {
namespace {

using Key = std::array<double, 4>;

Key lerp(const Key& a, const Key& b, double u, int n) {
  Key r{};
  for (int c = 0; c < n; ++c) r[size_t(c)] = a[size_t(c)] + u * (b[size_t(c)] - a[size_t(c)]);
  return r;
}

Key normalized(Key q) {
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (n > 0)
    for (double& c : q) c /= n;
  return q;
}

// Spherical interpolation of unit quaternions along the shorter arc.
Key slerp(const Key& a, Key b, double u) {
  double d = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
  if (d < 0) {
    for (double& c : b) c = -c;
    d = -d;
  }
  if (d > 0.9995) return normalized(lerp(a, b, u, 4));
  const double angle = std::acos(std::min(d, 1.0));
  const double wa = std::sin((1 - u) * angle) / std::sin(angle),
               wb = std::sin(u * angle) / std::sin(angle);
  Key r{};
  for (size_t c = 0; c < 4; ++c) r[c] = wa * a[c] + wb * b[c];
  return r;
}

// The morph targets of node `index`'s mesh (its first primitive's; glTF gives all of a mesh's
// primitives as many), 0 where it has none.
size_t morphTargetCount(const tinygltf::Model& model, int index) {
  const int mesh = model.nodes[size_t(index)].mesh;
  if (mesh < 0 || size_t(mesh) >= model.meshes.size() ||
      model.meshes[size_t(mesh)].primitives.empty())
    return 0;
  return model.meshes[size_t(mesh)].primitives[0].targets.size();
}

}  // namespace

void GltfAnimation::Channel::at(double t, double* out) const {
  const size_t n = times.size(), w = size_t(components);
  const size_t stride = w * (mode == Mode::Cubic ? 3 : 1);
  const size_t value = mode == Mode::Cubic ? 1 : 0;  // the key's value, past a cubic in-tangent
  // Part `part` of key k (CUBICSPLINE: 0 in-tangent, 1 value, 2 out-tangent). A rotation value is
  // made unit: normalized integers (and rounded floats) hold one only nearly; tangents are not
  // rotations.
  const auto key = [&](size_t k, size_t part) {
    Key v{};
    for (size_t c = 0; c < w && c < 4; ++c) v[c] = values[k * stride + part * w + c];
    return rotation && part == value ? normalized(v) : v;
  };
  const auto component = [&](size_t k, size_t part, size_t c) {
    return double(values[k * stride + part * w + c]);
  };
  const auto copy = [&](const Key& v) { std::copy(v.begin(), v.begin() + w, out); };
  size_t k = 0;
  double u = 0, d = 0;
  if (t <= times[0] || n == 1 || t >= times[n - 1]) {
    k = t >= times[n - 1] ? n - 1 : 0;
    if (rotation) return copy(key(k, value));
    for (size_t c = 0; c < w; ++c) out[c] = component(k, value, c);
    return;
  }
  // Compared in double: t just below the last key must not round onto it (and past the end).
  const auto after = std::upper_bound(times.begin(), times.end(), t,
                                      [](double v, float time) { return v < double(time); });
  k = size_t(after - times.begin()) - 1;
  d = double(times[k + 1]) - double(times[k]);
  u = (t - double(times[k])) / d;
  switch (mode) {
    case Mode::Step:
      if (rotation) return copy(key(k, 0));
      for (size_t c = 0; c < w; ++c) out[c] = component(k, 0, c);
      return;
    case Mode::Linear:
      if (rotation) return copy(slerp(key(k, 0), key(k + 1, 0), u));
      for (size_t c = 0; c < w; ++c)
        out[c] = component(k, 0, c) + u * (component(k + 1, 0, c) - component(k, 0, c));
      return;
    case Mode::Cubic: {
      const double u2 = u * u, u3 = u2 * u;
      const double h00 = 2 * u3 - 3 * u2 + 1, h10 = (u3 - 2 * u2 + u) * d, h01 = -2 * u3 + 3 * u2,
                   h11 = (u3 - u2) * d;
      if (rotation) {
        const Key p0 = key(k, 1), m0 = key(k, 2), p1 = key(k + 1, 1), m1 = key(k + 1, 0);
        Key r{};
        for (size_t c = 0; c < 4; ++c) r[c] = h00 * p0[c] + h10 * m0[c] + h01 * p1[c] + h11 * m1[c];
        return copy(normalized(r));
      }
      for (size_t c = 0; c < w; ++c)
        out[c] = h00 * component(k, 1, c) + h10 * component(k, 2, c) +
                 h01 * component(k + 1, 1, c) + h11 * component(k + 1, 0, c);
      return;
    }
  }
}

std::array<double, 4> GltfAnimation::Channel::at(double t) const {
  Key r{};
  at(t, r.data());
  return r;
}

GltfAnimation::GltfAnimation(const tinygltf::Model& model, size_t index, const std::string& label) {
  const tinygltf::Animation& animation = model.animations[index];
  const std::string at = label + ": animations[" + std::to_string(index) + "]";
  // (node, 0 translation | 1 rotation | 2 scale | 3 weights)
  std::vector<std::pair<int, int>> targets;
  for (size_t i = 0; i < animation.channels.size(); ++i) {
    const tinygltf::AnimationChannel& channel = animation.channels[i];
    const std::string where = at + ".channels[" + std::to_string(i) + "]";
    const int path = channel.target_path == "translation" ? 0
                     : channel.target_path == "rotation"  ? 1
                     : channel.target_path == "scale"     ? 2
                     : channel.target_path == "weights"   ? 3
                                                          : -1;
    if (path < 0) continue;  // KHR_animation_pointer and the like: not read
    if (channel.target_node < 0 || size_t(channel.target_node) >= model.nodes.size())
      throw SceneError(where + ".target.node: node " + std::to_string(channel.target_node) +
                       " does not exist (" + std::to_string(model.nodes.size()) + " nodes)");
    const size_t weightCount = path == 3 ? morphTargetCount(model, channel.target_node) : 0;
    if (path == 3 && weightCount == 0)
      throw SceneError(where + ".target: node " + std::to_string(channel.target_node) +
                       " has no mesh with morph targets, whose weights the channel could set");
    if (channel.sampler < 0 || size_t(channel.sampler) >= animation.samplers.size())
      throw SceneError(where + ".sampler: sampler " + std::to_string(channel.sampler) +
                       " does not exist (" + std::to_string(animation.samplers.size()) +
                       " samplers)");
    const tinygltf::AnimationSampler& sampler = animation.samplers[size_t(channel.sampler)];
    const std::string samplerAt = at + ".samplers[" + std::to_string(channel.sampler) + "]";
    Channel c;
    c.components = path == 1 ? 4 : path == 3 ? int(weightCount) : 3;
    c.rotation = path == 1;
    c.mode = sampler.interpolation == "STEP"          ? Channel::Mode::Step
             : sampler.interpolation == "CUBICSPLINE" ? Channel::Mode::Cubic
                                                      : Channel::Mode::Linear;
    if (sampler.interpolation != "STEP" && sampler.interpolation != "CUBICSPLINE" &&
        sampler.interpolation != "LINEAR")
      throw SceneError(samplerAt + ".interpolation: expected LINEAR, STEP or CUBICSPLINE, got \"" +
                       sampler.interpolation + "\"");
    c.times = readFloatAccessor(model, sampler.input, 1, kFloats, samplerAt + ".input");
    if (c.times.empty()) throw SceneError(samplerAt + ".input: expected at least one key time");
    for (size_t k = 1; k < c.times.size(); ++k)
      if (!(c.times[k] > c.times[k - 1]))
        throw SceneError(samplerAt + ".input: key times must increase, got " +
                         formatNumber(c.times[k]) + " after " + formatNumber(c.times[k - 1]));
    // glTF stores rotations and weights as floats or as normalized integers of either sign; a
    // weights sampler's output is scalars, one per target per key.
    const unsigned encodings = path == 1 || path == 3
                                   ? kFloats | kSignedNormalized | kUnsignedNormalized
                                   : unsigned(kFloats);
    c.values = readFloatAccessor(model, sampler.output, path == 3 ? 1 : c.components, encodings,
                                 samplerAt + ".output");
    const size_t expected =
        c.times.size() * size_t(c.components) * (c.mode == Channel::Mode::Cubic ? 3 : 1);
    const size_t element = path == 3 ? 1 : size_t(c.components);  // weights: one per target
    if (c.values.size() != expected)
      throw SceneError(samplerAt + ".output: expected " + std::to_string(expected / element) +
                       " elements for " + std::to_string(c.times.size()) + " key times" +
                       (path == 3 ? " of " + std::to_string(c.components) + " morph targets" : "") +
                       ", got " + std::to_string(c.values.size() / element));
    length_ = std::max(length_, double(c.times.back()));
    channels_.push_back(std::move(c));
    targets.push_back({channel.target_node, path});
  }
  for (size_t i = 0; i < channels_.size(); ++i) {
    if (targets[i].second == 3) {
      weights_[targets[i].first] = int(i);
      continue;
    }
    const auto [node, fresh] = nodes_.try_emplace(targets[i].first, std::array<int, 3>{-1, -1, -1});
    node->second[size_t(targets[i].second)] = int(i);
  }
}

bool GltfAnimation::weightsAt(int index, double t, std::vector<double>* weights) const {
  const auto found = weights_.find(index);
  if (found == weights_.end()) return false;
  const Channel& channel = channels_[size_t(found->second)];
  weights->resize(size_t(channel.components));
  channel.at(t, weights->data());
  return true;
}

bool GltfAnimation::localAt(int index, const tinygltf::Node& node, double t,
                            GltfMatrix* local) const {
  const auto found = nodes_.find(index);
  if (found == nodes_.end() || node.matrix.size() == 16) return false;  // glTF: TRS nodes only
  std::array<double, 3> translation{0, 0, 0}, scale{1, 1, 1};
  std::array<double, 4> rotation{0, 0, 0, 1};
  // The node's own parts, where they have their sizes (forEachPlacedNode refuses those that do
  // not before it asks).
  const auto own = [](const std::vector<double>& values, auto* part) {
    if (values.size() == part->size()) std::copy(values.begin(), values.end(), part->begin());
  };
  own(node.translation, &translation);
  own(node.rotation, &rotation);
  own(node.scale, &scale);
  const std::array<int, 3>& channels = found->second;
  if (channels[0] >= 0) {
    const Key v = channels_[size_t(channels[0])].at(t);
    std::copy(v.begin(), v.begin() + 3, translation.begin());
  }
  if (channels[1] >= 0) rotation = channels_[size_t(channels[1])].at(t);
  if (channels[2] >= 0) {
    const Key v = channels_[size_t(channels[2])].at(t);
    std::copy(v.begin(), v.begin() + 3, scale.begin());
  }
  *local = gltfTrs(translation, rotation, scale);
  return true;
}

size_t findGltfAnimation(const std::vector<std::string>& names, const std::string& label,
                         const std::string& name, int number) {
  if (!name.empty()) {
    std::vector<std::string> named;
    for (size_t i = 0; i < names.size(); ++i) {
      if (names[i] == name) return i;
      if (!names[i].empty()) named.push_back(names[i]);
    }
    if (named.empty())
      throw SceneError(label + ": no animation is named \"" + name + "\" (the file's " +
                       std::to_string(names.size()) + " have no names)");
    const std::string close = closestMatch(name, named);
    throw SceneError(label + ": no animation is named \"" + name + "\"" +
                     (close.empty() ? "" : " (did you mean \"" + close + "\"?)") +
                     "; its animations: " + quotedNames(named));
  }
  if (number < 0 || size_t(number) >= names.size())
    throw SceneError(label + ": animation " + std::to_string(number) +
                     " is asked for, but the file has " + std::to_string(names.size()) +
                     (names.size() == 1 ? " animation" : " animations"));
  return size_t(number);
}

size_t findGltfAnimation(const tinygltf::Model& model, const std::string& label,
                         const std::string& name, int number) {
  std::vector<std::string> names;
  for (const tinygltf::Animation& animation : model.animations) names.push_back(animation.name);
  return findGltfAnimation(names, label, name, number);
}

}  // namespace candela
