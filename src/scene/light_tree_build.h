// Builds the light tree (render/light_tree.h) over the scene's lights.
#pragma once

#include <cstdint>
#include <vector>

#include "core/vec3.h"
#include "render/light.h"
#include "render/light_tree.h"

namespace candela {

// What the tree knows of a light: its box, the cone of its emitting normals (axis and the
// cosine of its spread theta_o; a sphere or a point light: -1, the whole sphere) and its power
// (the sum of its RGB power; 0 leaves it out of the tree).
struct LightBounds {
  Vec3 lo, hi;
  Vec3 axis = Vec3(0.0f, 0.0f, 1.0f);
  double cosThetaO = 1.0;
  double power = 0.0;
  // A point of the light's own (a triangle's centroid, a sphere's or point light's centre): it
  // tells apart lights of equal bounds, such as the two halves of a rectangle, when the build
  // puts the lights in an order of their own.
  Vec3 anchor = Vec3(0.0f);
};

// The tree's nodes (the root first; none when no light has power) and, in *trails, one trail per
// light (kNotInLightTree for those without power). Splits minimise pbrt-v4's surface area and
// orientation heuristic. The tree depends on the lights, not on their order in `lights` (up to
// lights equal in every field): engines that number a scene's triangles, and so its emissive
// triangles' lights, differently get the same tree and pick the same light with the same numbers.
std::vector<LightTreeNode> buildLightTree(const std::vector<LightBounds>& lights,
                                          std::vector<uint64_t>* trails);

}  // namespace candela
