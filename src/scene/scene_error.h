// SceneError: the one error type for a scene that cannot be rendered.
//
// Its message is complete and user-facing, e.g.
//   "scene.json: spheres[2].radius: expected a positive number, got -1"
// The CLI prints it and exits 2; Python raises it as a ValueError subclass.
#pragma once

#include <cstdio>
#include <stdexcept>
#include <string>

#include "core/vec3.h"

namespace candela {

class SceneError : public std::runtime_error {
 public:
  explicit SceneError(const std::string& message) : std::runtime_error(message) {}
};

// A number as messages show it: the shortest of %g, e.g. "1e-45", "0.5", "1e+300" (a float's
// value exactly as a double's).
inline std::string formatNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// Three numbers as messages show them: "[1, 0.5, 2]".
inline std::string formatVec3(const Vec3& v) {
  return "[" + formatNumber(v.x) + ", " + formatNumber(v.y) + ", " + formatNumber(v.z) + "]";
}

}  // namespace candela
