// Placing a glTF file's nodes; see gltf_nodes.h.
#include "scene/read/gltf_nodes.h"

#include <cmath>
#include <utility>
#include <vector>

#include "scene/read/did_you_mean.h"
#include "scene/scene_error.h"

namespace candela {
namespace {

GltfMatrix identity() { return {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}; }

}  // namespace

GltfMatrix gltfLocalTransform(const tinygltf::Node& node, const std::string& where) {
  auto finite = [&](const std::vector<double>& values, size_t count, const char* key) {
    if (!values.empty() && values.size() != count)
      throw SceneError(where + "." + key + ": expected " + std::to_string(count) + " numbers");
    for (double v : values)
      if (!std::isfinite(v)) throw SceneError(where + "." + key + ": expected finite numbers");
  };
  finite(node.matrix, 16, "matrix");
  finite(node.translation, 3, "translation");
  finite(node.rotation, 4, "rotation");
  finite(node.scale, 3, "scale");
  if (node.matrix.size() == 16) {
    GltfMatrix m;
    std::copy(node.matrix.begin(), node.matrix.end(), m.begin());
    return m;
  }
  std::array<double, 3> t{0, 0, 0}, scale{1, 1, 1};
  std::array<double, 4> q{0, 0, 0, 1};
  std::copy(node.translation.begin(), node.translation.end(), t.begin());
  std::copy(node.rotation.begin(), node.rotation.end(), q.begin());
  std::copy(node.scale.begin(), node.scale.end(), scale.begin());
  if (node.rotation.size() == 4 && !(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3] > 0))
    throw SceneError(where + ".rotation: expected a unit quaternion, got 0");
  return gltfTrs(t, q, scale);
}

GltfCofactors::GltfCofactors(const GltfMatrix& m) {
  const auto at = [&](int r, int k) { return m[size_t(4 * k + r)]; };
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k)
      c[r][k] = at((r + 1) % 3, (k + 1) % 3) * at((r + 2) % 3, (k + 2) % 3) -
                at((r + 1) % 3, (k + 2) % 3) * at((r + 2) % 3, (k + 1) % 3);
  det = at(0, 0) * c[0][0] + at(0, 1) * c[0][1] + at(0, 2) * c[0][2];
}

bool gltfInvert(const GltfMatrix& m, GltfMatrix* inverse) {
  const GltfCofactors cof(m);
  const double det = cof.det;
  if (!(std::abs(det) > 0) || !std::isfinite(det)) return false;
  GltfMatrix r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r[size_t(4 * j + i)] = cof.c[j][i] / det;  // the adjugate / det
  for (int i = 0; i < 3; ++i)
    r[size_t(12 + i)] =
        -(r[size_t(i)] * m[12] + r[size_t(4 + i)] * m[13] + r[size_t(8 + i)] * m[14]);
  r[15] = 1;
  *inverse = r;
  return true;
}

namespace {

// The nodes the file's scene places, outermost first.
std::vector<int> rootNodes(const tinygltf::Model& model, const std::string& label) {
  if (!model.scenes.empty()) {
    const int scene = model.defaultScene >= 0 ? model.defaultScene : 0;
    if (size_t(scene) >= model.scenes.size())
      throw SceneError(label + ": scene: scene " + std::to_string(scene) + " does not exist (" +
                       std::to_string(model.scenes.size()) + " scenes)");
    return model.scenes[size_t(scene)].nodes;
  }
  std::vector<bool> child(model.nodes.size(), false);
  for (const tinygltf::Node& node : model.nodes)
    for (int c : node.children)
      if (c >= 0 && size_t(c) < child.size()) child[size_t(c)] = true;
  std::vector<int> roots;
  for (size_t i = 0; i < child.size(); ++i)
    if (!child[i]) roots.push_back(int(i));
  return roots;
}

}  // namespace

GltfMatrix gltfMultiply(const GltfMatrix& a, const GltfMatrix& b) {
  GltfMatrix m{};
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      for (int k = 0; k < 4; ++k) m[4 * c + r] += a[4 * k + r] * b[4 * c + k];
  return m;
}

GltfMatrix gltfTrs(const std::array<double, 3>& t, std::array<double, 4> q,
                   const std::array<double, 3>& s) {
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (n > 0)
    for (double& c : q) c /= n;
  const double x = q[0], y = q[1], z = q[2], w = q[3];
  GltfMatrix m = {1 - 2 * (y * y + z * z),
                  2 * (x * y + z * w),
                  2 * (x * z - y * w),
                  0,
                  2 * (x * y - z * w),
                  1 - 2 * (x * x + z * z),
                  2 * (y * z + x * w),
                  0,
                  2 * (x * z + y * w),
                  2 * (y * z - x * w),
                  1 - 2 * (x * x + y * y),
                  0,
                  t[0],
                  t[1],
                  t[2],
                  1};
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) m[size_t(4 * c + r)] *= s[size_t(c)];
  return m;
}

void forEachPlacedNode(const tinygltf::Model& model, const std::string& label,
                       const std::function<void(int index, const tinygltf::Node& node,
                                                const GltfMatrix& world)>& visit,
                       const GltfLocalOverride& moved, int root) {
  const std::vector<int> roots = root >= 0 ? std::vector<int>{root} : rootNodes(model, label);
  std::vector<bool> reached(model.nodes.size(), false);
  std::vector<std::pair<int, GltfMatrix>> pending;
  for (auto it = roots.rbegin(); it != roots.rend(); ++it) pending.push_back({*it, identity()});
  while (!pending.empty()) {
    const auto [index, parent] = pending.back();
    pending.pop_back();
    if (index < 0 || size_t(index) >= model.nodes.size())
      throw SceneError(label + ": node " + std::to_string(index) + " does not exist (" +
                       std::to_string(model.nodes.size()) + " nodes)");
    const std::string where = "nodes[" + std::to_string(index) + "]";
    if (reached[size_t(index)])
      throw SceneError(label + ": " + where +
                       " is reached twice (a node may have one parent and appear once)");
    reached[size_t(index)] = true;
    const tinygltf::Node& node = model.nodes[size_t(index)];
    // The node's own transform is checked (its arrays' sizes, finite numbers) even where an
    // animation moves it: the override copies the parts it leaves from the node.
    GltfMatrix local = gltfLocalTransform(node, label + ": " + where);
    if (moved) moved(index, node, &local);
    if (index == root) local = identity();
    const GltfMatrix world = gltfMultiply(parent, local);
    visit(index, node, world);
    for (auto c = node.children.rbegin(); c != node.children.rend(); ++c)
      pending.push_back({*c, world});
  }
}

int gltfNodeIndex(const tinygltf::Model& model, const std::string& name) {
  std::vector<int> found;
  std::vector<std::string> names;
  for (size_t i = 0; i < model.nodes.size(); ++i) {
    if (model.nodes[i].name == name) found.push_back(int(i));
    if (!model.nodes[i].name.empty()) names.push_back(model.nodes[i].name);
  }
  if (found.size() == 1) return found[0];
  if (found.size() > 1)
    throw GltfNodeError("the file names " + std::to_string(found.size()) + " nodes \"" + name +
                        "\" (nodes[" + std::to_string(found[0]) + "] and nodes[" +
                        std::to_string(found[1]) + "]); expected a name that one node has");
  if (names.empty())
    throw GltfNodeError("the file's nodes have no names, so none is \"" + name + "\"");
  const std::string close = closestMatch(name, names);
  throw GltfNodeError("the file has no node \"" + name + "\"" +
                      (close.empty() ? "" : " (did you mean \"" + close + "\"?)") +
                      "; its nodes: " + quotedNames(names));
}

}  // namespace candela
