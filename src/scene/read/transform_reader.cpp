// Reading an object's transform matrix; see transform_reader.h.
#include "scene/read/transform_reader.h"

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "core/rotation.h"

namespace candela {

std::optional<Placement> placementOf(const std::array<double, 12>& m, std::string* fault) {
  // Column j of the block is the object's axis j, turned and scaled: its length is the scale.
  double column[3][3], length[3];
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) column[j][i] = m[4 * i + j];
    length[j] = std::sqrt(column[j][0] * column[j][0] + column[j][1] * column[j][1] +
                          column[j][2] * column[j][2]);
  }
  const auto dotColumns = [&](int a, int b) {
    return column[a][0] * column[b][0] + column[a][1] * column[b][1] + column[a][2] * column[b][2];
  };
  const double determinant =
      column[0][0] * (column[1][1] * column[2][2] - column[1][2] * column[2][1]) -
      column[1][0] * (column[0][1] * column[2][2] - column[0][2] * column[2][1]) +
      column[2][0] * (column[0][1] * column[1][2] - column[0][2] * column[1][1]);
  if (!(determinant != 0.0) || !std::isfinite(determinant)) {
    *fault =
        "a transform that keeps the object solid (the upper-left 3x3 block is singular, "
        "flattening it)";
    return std::nullopt;
  }
  for (const auto& [a, b] : {std::pair{0, 1}, std::pair{0, 2}, std::pair{1, 2}})
    if (std::fabs(dotColumns(a, b)) > 1e-3 * length[a] * length[b]) {
      *fault =
          "a rotation times a scale along the object's axes in the upper-left 3x3 block; its "
          "columns " +
          std::to_string(a + 1) + " and " + std::to_string(b + 1) +
          " are not at right angles (a shear, which an object cannot take)";
      return std::nullopt;
    }
  Placement p;
  p.position = Vec3(float(m[3]), float(m[7]), float(m[11]));
  // A mirroring matrix is a rotation times a scale with x negated.
  const double sign[3] = {determinant < 0 ? -1.0 : 1.0, 1.0, 1.0};
  Mat3 r;
  for (int j = 0; j < 3; ++j) {
    p.scale[j] = float(sign[j] * length[j]);
    for (int i = 0; i < 3; ++i) r.m[i][j] = float(column[j][i] / (sign[j] * length[j]));
  }
  p.rotation = eulerDegrees(r);
  return p;
}

Placement readTransform(const JsonValue& value) {
  const bool fourRows = value.json().is_array() && value.json().size() == 4;
  if (!value.json().is_array() || (value.json().size() != 3 && !fourRows))
    value.failExpected(
        "an object-to-world matrix: 3 rows of 4 numbers, [R S | t], and optionally [0, 0, 0, 1]");
  const std::vector<float> m = value.matrix(fourRows ? 4 : 3, 4);
  if (fourRows && (m[12] != 0 || m[13] != 0 || m[14] != 0 || m[15] != 1))
    value.elements()[3].failExpected("[0, 0, 0, 1] (an affine transform)");
  std::array<double, 12> rows;
  for (size_t i = 0; i < 12; ++i) rows[i] = m[i];
  std::string fault;
  const std::optional<Placement> placement = placementOf(rows, &fault);
  if (!placement) value.failExpected(fault);
  return *placement;
}

}  // namespace candela
