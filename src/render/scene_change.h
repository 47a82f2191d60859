// What may differ between two consecutive scenes given to a renderer, from least to most: a
// backend that keeps a scene resident (the GPU) moves only the arrays the change may rewrite.
#pragma once

#include <cstdint>

namespace candela {

enum class SceneChange : uint8_t {
  Values = 0,     // camera, settings, environment, materials, lights; geometry identical
  Motion = 1,     // also spheres, vertices, normals and BVH boxes: primitives moved (a refit)
  Structure = 2,  // everything: triangles and the BVH's layout too (a rebuild, or a new scene)
};

// "values", "motion" or "structure".
constexpr const char* sceneChangeName(SceneChange change) {
  return change == SceneChange::Values ? "values"
                                       : (change == SceneChange::Motion ? "motion" : "structure");
}

// What rewrites an array of the kernel's scene (the last column of CANDELA_SCENE_ARRAYS). The
// first three are the frame changes above, each of which rewrites what those below it do. The
// others are groups that change with their own content only, whatever the frame's change: the
// environment map's arrays with the map (SceneData::environmentMapHash), the light tree with the
// lights' bounds and powers (SceneData::lightTreeHash), the texture pool with the textures
// (SceneData::texturePoolHash). A camera animation under a large map, or among many emissive
// triangles, moves neither to the GPU again, nor does a rebuild move textures that stayed.
enum class RewrittenBy : uint8_t {
  Values,
  Motion,
  Structure,
  EnvironmentMap,
  LightTree,
  TexturePool
};
static_assert(uint8_t(RewrittenBy::Values) == uint8_t(SceneChange::Values) &&
                  uint8_t(RewrittenBy::Motion) == uint8_t(SceneChange::Motion) &&
                  uint8_t(RewrittenBy::Structure) == uint8_t(SceneChange::Structure),
              "mayRewrite compares the frame changes by number");

// What a renderer holding the last scene must take of the next: the frame's change, and whether
// each keyed group differs from the one it holds (true where it holds none).
struct SceneUpdate {
  SceneChange change = SceneChange::Structure;
  bool environmentMap = true;
  bool lightTree = true;
  bool texturePool = true;
};

// Whether an array that `rewrittenBy` changes may differ after `update`.
constexpr bool mayRewrite(const SceneUpdate& update, RewrittenBy rewrittenBy) {
  switch (rewrittenBy) {
    case RewrittenBy::EnvironmentMap:
      return update.environmentMap;
    case RewrittenBy::LightTree:
      return update.lightTree;
    case RewrittenBy::TexturePool:
      return update.texturePool;
    default:
      return uint8_t(update.change) >= uint8_t(rewrittenBy);
  }
}

}  // namespace candela
