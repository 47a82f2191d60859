// Built-in shapes an object may take instead of a mesh file ("shape": "cube"): made as triangle
// meshes when the scene loads, so that they render, emit, take textures and animate as any mesh
// does, on every backend.
//
// Each fills the unit box [-0.5, 0.5]^3 centred on the origin, so that an object's `scale` is its
// extent along each axis. Fronts face outwards; uvs run over [0, 1]^2 and show a texture upright
// from outside (scene-format.md, Shapes, has the layout).
#pragma once

#include <string>
#include <vector>

#include "scene/scene_desc.h"

namespace candela {

// The sides of the polygon that approximates a disk's or a cylinder's circle: its area is 0.01%
// under the circle's, its rim within 0.008% of the radius of the circle's.
constexpr int kShapeCircleSegments = 256;

// The names a scene may give, in the order the documentation lists them.
const std::vector<std::string>& shapeNames();

// The mesh of the shape named `name` (one of shapeNames()), with one diffuse material of
// Material's default colour.
MeshDesc shapeMesh(const std::string& name);

}  // namespace candela
