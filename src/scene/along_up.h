// Whether a direction runs along an up vector, which then gives no way round it: a look-at
// camera's view and a rectangle light's axis each need an up that does not.
#pragma once

#include "core/vec3.h"
#include "scene/dvec3.h"

namespace candela {

// Whether the sine of the angle between `axis` and `up` is below a millionth (or either is zero);
// in double, so that large coordinates cannot overflow.
inline bool alongUp(const Vec3& axis, const Vec3& up) {
  const DVec3 a = dvec3(axis), u = dvec3(up), c = cross(a, u);
  return !(dot(c, c) > 1e-12 * (dot(a, a) * dot(u, u)));
}

}  // namespace candela
