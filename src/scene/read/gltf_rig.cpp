// Posing a glTF mesh by its nodes, morph targets and skins; see gltf_rig.h.
#include "scene/read/gltf_rig.h"

#include <cmath>

#include "scene/read/gltf_accessor.h"
#include "scene/scene_error.h"

namespace candela {
namespace {

const GltfMatrix kIdentity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

// Vertex v's own position or normal, moved by the morph targets' `weights`.
void morphed(const std::vector<float>& own, const std::vector<std::vector<float>>& targets,
             const std::vector<double>& weights, size_t v, double out[3]) {
  for (size_t c = 0; c < 3; ++c) out[c] = own[3 * v + c];
  for (size_t k = 0; k < targets.size() && k < weights.size(); ++k)
    if (!targets[k].empty() && weights[k] != 0)
      for (size_t c = 0; c < 3; ++c) out[c] += weights[k] * targets[k][3 * v + c];
}

}  // namespace

GltfRig::GltfRig(const tinygltf::Model& model, const std::string& label, int root)
    : label_(label), root_(root) {
  skeleton_.nodes = model.nodes;
  skeleton_.scenes = model.scenes;
  skeleton_.defaultScene = model.defaultScene;
  parents_.assign(model.nodes.size(), -1);
  for (size_t i = 0; i < model.nodes.size(); ++i)
    for (int c : model.nodes[i].children)
      if (c >= 0 && size_t(c) < parents_.size()) parents_[size_t(c)] = int(i);
  restWeights_.resize(model.nodes.size());
  for (size_t i = 0; i < model.nodes.size(); ++i) {
    const tinygltf::Node& node = model.nodes[i];
    if (node.mesh < 0 || size_t(node.mesh) >= model.meshes.size()) continue;
    const tinygltf::Mesh& mesh = model.meshes[size_t(node.mesh)];
    // glTF: the node's weights, else its mesh's, else zeros.
    restWeights_[i] = !node.weights.empty() ? node.weights : mesh.weights;
    const size_t targets = mesh.primitives.empty() ? 0 : mesh.primitives[0].targets.size();
    restWeights_[i].resize(targets, 0.0);
  }
  // A skin that no placed node uses may be broken: its fault is told where a node uses it.
  for (size_t s = 0; s < model.skins.size(); ++s) {
    Skin made;
    try {
      made = readSkin(model, label + ": skins[" + std::to_string(s) + "]", model.skins[s]);
    } catch (const SceneError& error) {
      made = Skin();
      made.fault = error.what();
    }
    skins_.push_back(std::move(made));
  }
}

GltfRig::Skin GltfRig::readSkin(const tinygltf::Model& model, const std::string& where,
                                const tinygltf::Skin& skin) {
  Skin made;
  for (size_t j = 0; j < skin.joints.size(); ++j) {
    const int joint = skin.joints[j];
    if (joint < 0 || size_t(joint) >= model.nodes.size())
      throw SceneError(where + ".joints[" + std::to_string(j) + "]: node " + std::to_string(joint) +
                       " does not exist (" + std::to_string(model.nodes.size()) + " nodes)");
    made.joints.push_back(joint);
  }
  if (made.joints.empty()) throw SceneError(where + ".joints: expected at least one joint");
  made.inverseBinds.assign(made.joints.size(), kIdentity);
  if (skin.inverseBindMatrices >= 0) {
    const std::vector<float> m = readFloatAccessor(model, skin.inverseBindMatrices, 16, kFloats,
                                                   where + ".inverseBindMatrices");
    if (m.size() != 16 * made.joints.size())
      throw SceneError(where + ".inverseBindMatrices: expected " +
                       std::to_string(made.joints.size()) + " matrices, one per joint, got " +
                       std::to_string(m.size() / 16));
    for (size_t j = 0; j < made.joints.size(); ++j)
      for (size_t k = 0; k < 16; ++k) made.inverseBinds[j][k] = m[16 * j + k];
  }
  return made;
}

GltfPose GltfRig::pose(const GltfAnimation* animation, double t) const {
  const size_t n = skeleton_.nodes.size();
  GltfPose pose;
  pose.worlds.assign(n, kIdentity);
  std::vector<bool> placed(n, false);
  GltfLocalOverride moved;
  if (animation)
    moved = [&](int index, const tinygltf::Node& node, GltfMatrix* local) {
      return animation->localAt(index, node, t, local);
    };
  forEachPlacedNode(
      skeleton_, label_,
      [&](int index, const tinygltf::Node&, const GltfMatrix& world) {
        pose.worlds[size_t(index)] = world;
        placed[size_t(index)] = true;
      },
      moved, root_);
  // A joint the walk did not reach (outside the object's node, or outside the file's scene)
  // stands where its parents put it in the file, seen from the object's node.
  const auto fileWorld = [&](int index) {
    GltfMatrix world = kIdentity;
    size_t steps = 0;
    for (int i = index; i >= 0; i = parents_[size_t(i)]) {
      if (++steps > n)
        throw SceneError(label_ + ": nodes[" + std::to_string(index) +
                         "]: its parents form a loop");
      const tinygltf::Node& node = skeleton_.nodes[size_t(i)];
      GltfMatrix local = gltfLocalTransform(node, label_ + ": nodes[" + std::to_string(i) + "]");
      if (moved) moved(i, node, &local);
      world = gltfMultiply(local, world);
    }
    return world;
  };
  std::optional<GltfMatrix> fromRoot;
  for (const Skin& skin : skins_)
    for (int joint : skin.joints) {
      if (placed[size_t(joint)]) continue;
      GltfMatrix world = fileWorld(joint);
      if (root_ >= 0) {
        if (!fromRoot) {
          fromRoot.emplace();
          if (!gltfInvert(fileWorld(root_), &*fromRoot))
            throw SceneError(label_ + ": nodes[" + std::to_string(root_) +
                             "]: its transform has no inverse, so its skins' joints cannot be "
                             "placed under it");
        }
        world = gltfMultiply(*fromRoot, world);
      }
      pose.worlds[size_t(joint)] = world;
      placed[size_t(joint)] = true;
    }
  pose.weights = restWeights_;
  if (animation)
    for (size_t i = 0; i < n; ++i) {
      std::vector<double> w;
      if (animation->weightsAt(int(i), t, &w)) {
        w.resize(pose.weights[i].size(), 0.0);
        pose.weights[i] = std::move(w);
      }
    }
  pose.skins.resize(skins_.size());
  for (size_t s = 0; s < skins_.size(); ++s)
    for (size_t j = 0; j < skins_[s].joints.size(); ++j)
      pose.skins[s].push_back(
          gltfMultiply(pose.worlds[size_t(skins_[s].joints[j])], skins_[s].inverseBinds[j]));
  return pose;
}

size_t GltfRig::readInfluences(const tinygltf::Model& model, const tinygltf::Primitive& source,
                               const std::string& where, GltfRigPrimitive* p) const {
  const size_t vertices = p->positions.size() / 3;
  const Skin& skin = skins_[size_t(p->skin)];
  if (!skin.fault.empty()) throw SceneError(skin.fault);
  const size_t jointCount = skin.joints.size();
  std::vector<std::vector<float>> joints, weights;
  for (int set = 0;; ++set) {
    const auto j = source.attributes.find("JOINTS_" + std::to_string(set));
    const auto w = source.attributes.find("WEIGHTS_" + std::to_string(set));
    if (j == source.attributes.end() && w == source.attributes.end()) break;
    const std::string at = where + ".attributes.";
    if (j == source.attributes.end() || w == source.attributes.end())
      throw SceneError(at + (j == source.attributes.end() ? "WEIGHTS_" : "JOINTS_") +
                       std::to_string(set) + ": expected " +
                       (j == source.attributes.end() ? "JOINTS_" : "WEIGHTS_") +
                       std::to_string(set) + " beside it");
    joints.push_back(readFloatAccessor(model, j->second, 4, kPlainIntegers,
                                       at + "JOINTS_" + std::to_string(set)));
    weights.push_back(readFloatAccessor(model, w->second, 4, kFloats | kUnsignedNormalized,
                                        at + "WEIGHTS_" + std::to_string(set)));
    if (joints.back().size() != 4 * vertices || weights.back().size() != 4 * vertices)
      throw SceneError(at + "JOINTS_" + std::to_string(set) + ": JOINTS_" + std::to_string(set) +
                       " and WEIGHTS_" + std::to_string(set) +
                       " must have as many elements as POSITION (" + std::to_string(vertices) +
                       ")");
  }
  if (joints.empty())
    throw SceneError(where +
                     ".attributes: the node has a skin, so expected JOINTS_0 and WEIGHTS_0");
  p->influences = int(4 * joints.size());
  p->joints.resize(vertices * size_t(p->influences));
  p->jointWeights.resize(p->joints.size());
  size_t unweighted = 0;
  for (size_t v = 0; v < vertices; ++v) {
    double sum = 0;
    for (size_t set = 0; set < joints.size(); ++set)
      for (size_t c = 0; c < 4; ++c) {
        const float joint = joints[set][4 * v + c], weight = weights[set][4 * v + c];
        if (!(weight >= 0))
          throw SceneError(where + ".attributes.WEIGHTS_" + std::to_string(set) + ": element " +
                           std::to_string(v) + ": expected weights of 0 or more, got " +
                           formatNumber(weight));
        if (weight > 0 && !(joint < float(jointCount)))
          throw SceneError(where + ".attributes.JOINTS_" + std::to_string(set) + ": element " +
                           std::to_string(v) + " names joint " + formatNumber(joint) +
                           ", past the skin's " + std::to_string(jointCount) + " joints");
        const size_t slot = v * size_t(p->influences) + 4 * set + c;
        p->joints[slot] = weight > 0 ? uint32_t(joint) : 0;
        p->jointWeights[slot] = weight;
        sum += weight;
      }
    if (!(sum > 0)) ++unweighted;  // placed by the node, as if it had no skin
    for (int i = 0; i < p->influences && sum > 0; ++i)
      p->jointWeights[v * size_t(p->influences) + size_t(i)] =
          float(p->jointWeights[v * size_t(p->influences) + size_t(i)] / sum);
  }
  return unweighted;
}

bool GltfRig::mirrored(const GltfRigPrimitive& p, const GltfPose& pose) const {
  if (p.skin >= 0) return false;  // glTF ignores the node's transform, and no joint decides
  const GltfMatrix world = p.instance ? gltfMultiply(pose.worlds[size_t(p.node)], *p.instance)
                                      : pose.worlds[size_t(p.node)];
  return GltfCofactors(world).det < 0;
}

void GltfRig::place(const GltfRigPrimitive& p, const GltfPose& pose, std::vector<Vec3>* positions,
                    std::vector<Vec3>* normals, std::vector<bool>* usable) const {
  const GltfMatrix nodeWorld = p.instance ? gltfMultiply(pose.worlds[size_t(p.node)], *p.instance)
                                          : pose.worlds[size_t(p.node)];
  const GltfCofactors nodeCofactors(nodeWorld);
  const std::vector<double>& weights = pose.weights[size_t(p.node)];
  const size_t vertices = p.positions.size() / 3;
  const bool withNormals = p.normalBase >= 0 && !p.normals.empty();
  if (usable) usable->clear();
  GltfMatrix skinned{};
  for (size_t v = 0; v < vertices; ++v) {
    const GltfMatrix* world = &nodeWorld;
    if (p.skin >= 0) {
      // The vertex's joints' transforms, weighted (none weighted: the node's).
      const size_t first = v * size_t(p.influences);
      bool any = false;
      skinned.fill(0.0);
      for (size_t i = first; i < first + size_t(p.influences); ++i) {
        const double w = p.jointWeights[i];
        if (!(w > 0)) continue;
        const GltfMatrix& joint = pose.skins[size_t(p.skin)][p.joints[i]];
        for (size_t k = 0; k < 16; ++k) skinned[k] += w * joint[k];
        any = true;
      }
      if (any) world = &skinned;
    }
    const GltfMatrix& m = *world;
    double x[3];
    morphed(p.positions, p.targetPositions, weights, v, x);
    Vec3 placed;
    for (size_t r = 0; r < 3; ++r)
      placed[int(r)] = float(m[r] * x[0] + m[4 + r] * x[1] + m[8 + r] * x[2] + m[12 + r]);
    (*positions)[p.base + v] = placed;
    if (!withNormals) continue;
    const GltfCofactors own = world == &nodeWorld ? nodeCofactors : GltfCofactors(m);
    double nx[3];
    morphed(p.normals, p.targetNormals, weights, v, nx);
    Vec3 n;
    for (int r = 0; r < 3; ++r)
      n[r] = float(own.c[r][0] * nx[0] + own.c[r][1] * nx[1] + own.c[r][2] * nx[2]);
    if (own.det < 0) n = -n;  // the cofactors of a mirroring transform turn the normal inside
    const float length = std::sqrt(dot(n, n));
    const bool fine = length > 0.0f && std::isfinite(length);
    if (usable) usable->push_back(fine);
    (*normals)[size_t(p.normalBase) + v] = fine ? n / length : Vec3(0.0f, 0.0f, 1.0f);
  }
}

bool GltfRig::movedBy(const GltfAnimation& animation) const {
  // Whether the animation moves node i or one of its parents (up to the object's node).
  const auto movesUnder = [&](int i, bool pastRoot) {
    for (size_t steps = 0; i >= 0 && steps <= parents_.size(); i = parents_[size_t(i)], ++steps) {
      if (i == root_ && !pastRoot) return false;
      if (animation.moves(i)) return true;
    }
    return false;
  };
  for (const GltfRigPrimitive& p : primitives) {
    if (animation.weighs(p.node)) return true;
    if (p.skin < 0 ? movesUnder(p.node, false) : false) return true;
    if (p.skin >= 0)
      for (int joint : skins_[size_t(p.skin)].joints)
        if (movesUnder(joint, true)) return true;
  }
  return false;
}

}  // namespace candela
