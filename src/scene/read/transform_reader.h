// An object's "transform": its object-to-world matrix, as tools that pose objects write it (a
// dataset's model-to-world pose [R | t], Mitsuba's to_world, Blender's matrix_world), read as the
// position, rotation and scale that place it.
#pragma once

#include <array>
#include <optional>
#include <string>

#include "core/vec3.h"
#include "scene/read/json_reader.h"

namespace candela {

struct Placement {
  Vec3 position;
  Vec3 rotation;  // degrees, R = Rz Ry Rx
  Vec3 scale;     // one negative where the matrix mirrors
};

// The placement of the affine object-to-world matrix whose first three rows are `rows` (row by
// row, 4 numbers each), or nullopt with `fault` saying what keeps it from being one: its upper-left
// 3 x 3 block singular, or not a rotation times a scale along the object's axes (its columns not
// at right angles to 1e-3, a shear).
std::optional<Placement> placementOf(const std::array<double, 12>& rows, std::string* fault);

// Reads `value`, rows [[a, b, c, tx], [d, e, f, ty], [g, h, i, tz]] with an optional fourth row
// [0, 0, 0, 1], whose upper-left 3 x 3 block must be a rotation times a scale along the object's
// axes (its columns at right angles, to 1e-3 as printed matrices allow; no shear, which objects
// cannot take) and not singular. Throws SceneError naming `value`'s path otherwise.
Placement readTransform(const JsonValue& value);

}  // namespace candela
