// Telling a tangent-space normal map from a map of heights by its texels: MTL has no standard
// statement for normal maps, and Blender's exporter (among others) writes them as `map_Bump`,
// which names heights everywhere else.
#pragma once

#include "scene/scene_desc.h"

namespace candela {

// Whether `texture`'s texels, read linearly, are the encoded unit normals of a tangent-space
// normal map: nearly all of them (2 c - 1) of length about 1 pointing out of the surface (blue
// above one half), and most of them not grey, which a height map's are.
bool holdsUnitNormals(const TextureDesc& texture);

}  // namespace candela
