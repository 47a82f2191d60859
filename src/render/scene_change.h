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

// Whether an array that `rewrittenBy` changes may differ after `change`.
constexpr bool mayRewrite(SceneChange change, SceneChange rewrittenBy) {
  return uint8_t(change) >= uint8_t(rewrittenBy);
}

}  // namespace candela
