// Limits of single precision that a scene must keep, checked once it is read, at every frame
// where the animation moves what they bound, so that no frame of a sequence is written before a
// bad one is found. Each throws SceneError naming the file and the entity's JSON path.
#pragma once

#include "scene/scene_desc.h"

namespace candela {

// Geometry placed further than this from the origin along any axis is refused: beyond about
// 1e19 a triangle's edge products, or a sphere's squared radius, overflow single precision and
// rays pass through it.
constexpr double kMaxWorldCoordinate = 1e18;

// Every light's power and a sphere light's surface radiance finite (light_emission_desc.h).
void checkLightEmission(const SceneDesc& scene);

// Every sphere (position and radius) and every object (its mesh's farthest vertex, scaled, and
// its position) within kMaxWorldCoordinate of the origin. Needs the objects' meshes loaded.
void checkWorldExtent(const SceneDesc& scene);

}  // namespace candela
