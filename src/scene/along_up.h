// Whether a direction runs along an up vector, which then gives no way round it: a look-at
// camera's view and a rectangle light's axis each need an up that does not.
#pragma once

#include "core/vec3.h"

namespace candela {

// Whether the sine of the angle between `axis` and `up` is below a millionth (or either is zero);
// in double, so that large coordinates cannot overflow.
inline bool alongUp(const Vec3& axis, const Vec3& up) {
  const double a[3] = {axis.x, axis.y, axis.z}, u[3] = {up.x, up.y, up.z};
  const double c[3] = {a[1] * u[2] - a[2] * u[1], a[2] * u[0] - a[0] * u[2],
                       a[0] * u[1] - a[1] * u[0]};
  const double norm2 =
      (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]) * (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  return !((c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) > 1e-12 * norm2);
}

}  // namespace candela
