// The optical flow pass's view of the next frame (render/motion.h), from the scene at this frame
// and at the next one: each instance's motion and both cameras.
#pragma once

#include <vector>

#include "render/motion.h"
#include "render/scene_data.h"
#include "scene/scene_desc.h"

namespace candela {

struct FlowMotion {
  std::vector<InstanceMotion> instances;  // by instance number (docs/aovs.md); [0] unused
  // By object: where the vertices of one whose mesh moves (ObjectDesc::meshMotion) stand in the
  // next frame, flattened as this frame's are; empty for the others.
  std::vector<std::vector<Vec3>> objectVertices;
  FlowFrames frames;
};

// How the entities of `now` move to where `next` (the same scene a frame later: sceneAtFrame of
// the next frame) has them. An entity whose placement is unchanged gets exactly the identity, so
// a still scene's flow is exactly 0. Throws SceneError when the two do not list the same
// entities.
FlowMotion flowMotion(const SceneDesc& now, const SceneDesc& next);

// Which flow pass a FlowMotion serves: towards the next frame (flow), or the previous
// (backward_flow, from flowMotion(now, previous)).
enum class FlowDirection { Forward, Backward };

// Gives `scene` (flattened from `now`) the flow pass's motions and cameras.
void applyFlowMotion(SceneData& scene, const FlowMotion& motion,
                     FlowDirection direction = FlowDirection::Forward);

// Takes them away again (both directions): a render without the flow passes.
void clearFlowMotion(SceneData& scene);

}  // namespace candela
