// Following a glTF node's animation with an object; see gltf_object_animation.h.
#include "scene/read/gltf_object_animation.h"

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/rotation.h"
#include "scene/read/gltf_animation.h"
#include "scene/read/gltf_file.h"
#include "scene/read/gltf_nodes.h"
#include "scene/read/json_reader.h"
#include "scene/read/transform_reader.h"
#include "scene/scene_error.h"

namespace candela {
namespace {

// The world matrix of node `node` of the file's scene at each of `times` (seconds) under the
// file's animation `name` (or number).
std::vector<GltfMatrix> nodeWorlds(const ObjectDesc& object, const std::vector<double>& times) {
  const std::string& label = object.file;
  const std::unique_ptr<GltfFile> file = readGltfFile(object.file, label);
  const int node = gltfNodeIndex(file->model, object.gltfNode);
  const size_t index =
      findGltfAnimation(file->model, label, object.gltfAnimationName, object.gltfAnimationNumber);
  const GltfAnimation animation(file->model, index, label);
  std::vector<GltfMatrix> worlds;
  for (double seconds : times) {
    const double t = object.gltfClock.at(seconds, animation.length());
    std::optional<GltfMatrix> world;
    forEachPlacedNode(
        file->model, label,
        [&](int visited, const tinygltf::Node&, const GltfMatrix& w) {
          if (visited == node && !world) world = w;
        },
        [&](int visited, const tinygltf::Node& n, GltfMatrix* local) {
          return animation.localAt(visited, n, t, local);
        });
    if (!world)
      throw SceneError(label + ": node \"" + object.gltfNode +
                       "\" is not in the file's scene, so no animation places it");
    worlds.push_back(*world);
  }
  return worlds;
}

// The object's own placement as a column-major matrix: position, then Rz Ry Rx, then scale.
GltfMatrix objectMatrix(const ObjectDesc& object) {
  const Mat3 r = eulerRotation(object.rotation);
  GltfMatrix m{};
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) m[4 * j + i] = double(r.m[i][j]) * object.scale[j];
  for (int i = 0; i < 3; ++i) m[12 + i] = object.position[i];
  m[15] = 1;
  return m;
}

AnimTrack trackOf(uint32_t index, AnimProperty property, const std::string& where) {
  AnimTrack track;
  track.target = AnimTarget::Object;
  track.index = index;
  track.property = property;
  track.where = where;
  return track;
}

void follow(SceneDesc& scene, uint32_t index) {
  ObjectDesc& object = scene.objects[index];
  const std::string where = memberPath(object.where, "gltf_animation");
  // Without an animation block the scene is a still: the node as the animation has it at time 0
  // of the object's clock (its start).
  const bool still = !scene.animation;
  const uint32_t frames = still ? 1 : scene.animation->frames;
  if (!still)
    for (const AnimTrack& t : scene.animation->tracks)
      if (t.target == AnimTarget::Object && t.index == index &&
          (t.property == AnimProperty::Position || t.property == AnimProperty::Rotation ||
           t.property == AnimProperty::Scale))
        failAt(scene.file, t.where,
               "the object follows its \"gltf_animation\", which places it at every frame");
  std::vector<double> times(frames, 0.0);
  for (uint32_t k = 0; k < frames; ++k)
    times[k] = still ? 0.0 : double(k) / double(scene.animation->fps);
  std::vector<GltfMatrix> worlds;
  try {
    worlds = nodeWorlds(object, times);
  } catch (const SceneError& e) {
    failAt(scene.file, where, e.what());
  }
  const GltfMatrix placed = objectMatrix(object);
  AnimTrack position = trackOf(index, AnimProperty::Position, where);
  AnimTrack rotation = trackOf(index, AnimProperty::Rotation, where);
  AnimTrack scale = trackOf(index, AnimProperty::Scale, where);
  for (uint32_t k = 0; k < frames; ++k) {
    const GltfMatrix m = gltfMultiply(placed, worlds[k]);
    std::array<double, 12> rows;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 4; ++j) rows[4 * i + j] = m[4 * j + i];
    std::string fault;
    const std::optional<Placement> p = placementOf(rows, &fault);
    const std::string at = "at frame " + std::to_string(k) + " the node's placement is not ";
    if (!p) failAt(scene.file, where, at + fault);
    if (k > 0 && (p->scale.x < 0) != (scale.keys[0].value.x < 0))
      failAt(scene.file, where,
             at + "mirrored as at frame 0's, so the mesh would pass through "
                  "zero size");
    position.keys.push_back({k, p->position});
    rotation.keys.push_back(
        {k, k == 0 ? p->rotation
                   : eulerDegreesNear(eulerRotation(p->rotation), rotation.keys.back().value)});
    scale.keys.push_back({k, p->scale});
  }
  object.position = position.keys[0].value;
  object.rotation = rotation.keys[0].value;
  object.scale = scale.keys[0].value;
  if (still) return;
  for (AnimTrack* track : {&position, &rotation, &scale})
    scene.animation->tracks.push_back(std::move(*track));
}

}  // namespace

void followGltfObjectAnimations(SceneDesc& scene) {
  for (uint32_t i = 0; i < scene.objects.size(); ++i)
    if (scene.objects[i].gltfAnimated && !scene.objects[i].gltfNode.empty()) follow(scene, i);
}

}  // namespace candela
