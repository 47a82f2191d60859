// An object that follows a glTF file's animation of its node ("gltf_animation" beside
// "gltf_node"): at frame k of the scene's animation it is placed as the node is in the file at
// k / fps seconds (its parents' motion included), after the object's own position, rotation and
// scale, which place the file in the scene.
#pragma once

#include "scene/scene_desc.h"

namespace candela {

// Turns each such object's animation into its position, rotation and scale tracks, keyed at every
// frame, its static placement that of frame 0; in a scene without an animation block (a still),
// into its placement at time 0 of its clock alone. Throws SceneError "<scene>: <path>: ..." where
// a track of the scene animates what the file's does, the file has no such animation or node, or
// the node's placement at some frame is no rotation times a scale (a shear) or mirrors where frame
// 0's does not.
void followGltfObjectAnimations(SceneDesc& scene);

}  // namespace candela
