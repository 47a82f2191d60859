// Triangulation of one OBJ face with more than four corners, in time that stays near linear.
//
// The polygon is projected on the plane its (Newell) normal is most aligned with. One without a
// reflex corner (convex, however many corners; a dent of less than 1e-5 of the polygon's size
// counts as rounding) is fanned from its first corner; a concave one is cut by ear clipping,
// which costs corners × reflex corners, so concave faces are limited to kMaxConcaveFaceCorners.
// A polygon that folds over itself still gets n - 2 triangles (where no ear is left, the next
// corner that is not reflex is cut), so no face is ever lost. Every triangle winds as the polygon
// does, so the outside stays the side the file says.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/vec3.h"

namespace candela {

// Ear clipping 10,000 corners takes a fraction of a second; far more than modelling tools write.
constexpr size_t kMaxConcaveFaceCorners = 10000;

using CornerTriangle = std::array<uint32_t, 3>;  // indices into the polygon's corners

// The n - 2 triangles of the polygon with these corners (n >= 3), or false for a concave polygon
// of more than kMaxConcaveFaceCorners corners.
bool triangulatePolygon(const std::vector<Vec3>& corners, std::vector<CornerTriangle>* triangles);

}  // namespace candela
