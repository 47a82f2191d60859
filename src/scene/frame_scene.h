// FrameScene: the flattened scene of each frame of an animation, rebuilding only when needed.
//
// Frames usually differ in a few values. When a frame's geometry is the same as the previous
// frame's (every sphere's centre and radius, every sphere light's centre and radius, every
// object's mesh, transform and smoothing, and the structure of the materials), the previous
// SceneData is kept, with its world-space meshes and its BVH, and only the camera, settings,
// environment, materials and lights are replaced: a moving camera or a dimming light costs
// microseconds. Otherwise the frame is flattened afresh, BVH included.
#pragma once

#include <string>

#include "scene/scene_data.h"

namespace candela {

class FrameScene {
 public:
  // The renderable scene of `desc` (a still, e.g. from sceneAtFrame); valid until the next call.
  const SceneData& prepare(const SceneDesc& desc);

  // About the last prepare(): whether the geometry and BVH were reused, and how long it took.
  bool reused() const { return reused_; }
  double seconds() const { return seconds_; }

 private:
  SceneData data_;
  std::string geometryKey_;  // the bytes that must match for reuse; empty before the first frame
  bool reused_ = false;
  double seconds_ = 0;
};

// The geometry of `desc` as bytes: equal keys mean flattenScene would make the same vertices,
// triangles, spheres and BVH. Meshes enter as a hash of their contents.
std::string geometryKey(const SceneDesc& desc);

}  // namespace candela
