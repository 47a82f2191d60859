// The lights of a flattened scene: every emitter becomes a light (render/light.h), with the
// light tree that next-event estimation picks from and the chances with which light subpaths
// start from each light.
#pragma once

#include <cstdint>
#include <vector>

#include "render/scene_data.h"

namespace candela {

// A frame's lights and light tree, kept for the next frame: when its lights have the same
// shapes, bounds and powers, it takes the tree rather than building the same one again.
struct PreviousLights {
  std::vector<uint64_t> trails;  // of each light, in order
  std::vector<LightTreeNode> tree;
  uint64_t hash = 0;  // SceneData::lightTreeHash
};

// Moves the lights' trails and the light tree out of `scene`, leaving it without lights.
PreviousLights takeLights(SceneData& scene);

// Appends a light for every emissive sphere that is not yet one, for the environment unless it
// is black, and for every emissive triangle (last, in triangle order, as lightOfPrimitive
// expects), and sets the light selection. Triangles must be in their final order. With
// `previous` (the last frame's) the light tree is taken from it when the lights are the same
// (a moving camera), else built: a frame's tree never depends on the frames before it.
void addEmitterLights(SceneData& scene, PreviousLights* previous = nullptr);

}  // namespace candela
