// FrameScene: the flattened scene of each frame of an animation, rebuilding only when needed.
//
// Frames usually differ in a few values. When a frame's geometry is the same as the previous
// frame's (every sphere's centre and radius, every sphere light's centre and radius, every
// object's mesh, transform and smoothing, and the structure of the materials), the previous
// SceneData is kept, with its world-space meshes and its BVH, and only the camera, settings,
// environment, materials and lights are replaced: a moving camera or a dimming light costs
// little (the light tree is kept while the lights' bounds and powers are, else built). When only
// transforms or poses changed (objects, spheres or sphere lights moved, turned, scaled or resized;
// a mesh's vertices and normals moved by its glTF animation, with the same triangles, texture
// coordinates and colours), the vertices are transformed again and the BVH is refitted in linear
// time, unless refitting has made the SAH cost of the tree, or of a large part of it, grow past
// kRefitCostLimit times that of its last build: then a new BVH is built over the contents the
// frame has just flattened, as for any other change. Textures enter the keys by their content
// hashes: a frame with other texels is a new structure. Whatever the change, a frame keeps the last
// frame's texture pool, environment map arrays and light tree where its textures, map and lights
// are the same. A frame where something moves while the shutter is open (motion blur) is
// flattened and built afresh, and so is the one after it.
#pragma once

#include <string>

#include "geometry/bvh_refit.h"
#include "render/scene_change.h"
#include "render/scene_data.h"
#include "scene/flow_motion.h"
#include "scene/scene_desc.h"

namespace candela {

// A refitted tree is rebuilt once its SAH cost, or a large part's (bvhCostProfile), exceeds this
// multiple of the cost at its build.
constexpr double kRefitCostLimit = 1.5;

class FrameScene {
 public:
  // The renderable scene of `desc` (a still, e.g. from sceneAtFrame); valid until the next call.
  // With `flow` (flowMotion of this frame and the next) it carries the flow pass's motions, with
  // `backwardFlow` (of this frame and the previous) the backward flow pass's.
  const SceneData& prepare(const SceneDesc& desc, const FlowMotion* flow = nullptr,
                           const FlowMotion* backwardFlow = nullptr);

  // About the last prepare(): what may differ from the frame before (Values: the geometry and
  // BVH were reused; Motion: refitted; Structure: flattened and built afresh), and how long it
  // took.
  SceneChange change() const { return change_; }
  double seconds() const { return seconds_; }

 private:
  SceneData data_;
  std::string geometryKey_;   // the bytes that must match for reuse; empty before the first frame
  std::string structureKey_;  // the bytes that must match for a refit
  BvhCostProfile builtCosts_;  // SAH costs of the BVH when it was last built
  SceneChange change_ = SceneChange::Structure;
  double seconds_ = 0;
};

}  // namespace candela
