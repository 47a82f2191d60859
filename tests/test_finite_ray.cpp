// The CPU tracer's finiteness check (backends/cpu/finite_ray.h) answers as the portable
// isFiniteRay does, for a NaN or an infinity of either sign in each of the six components, and
// for the largest, smallest and subnormal finite values.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "backends/cpu/finite_ray.h"
#include "core/constants.h"
#include "geometry/bvh_traverse.h"

namespace candela {
namespace {

TEST(FiniteRay, CpuCheckAnswersAsThePortableOne) {
  Ray ray;
  ray.origin = Vec3(1.0f, -2.0f, 3.0f);
  ray.direction = Vec3(0.0f, -0.6f, 0.8f);
  ray.tMax = std::numeric_limits<float>::infinity();  // not part of the check
  EXPECT_TRUE(isFiniteRayCpu(ray));
  EXPECT_TRUE(isFiniteRay(ray));
  using Limits = std::numeric_limits<float>;
  // The non-finite values, and the finite ones at the edges of the exponent's range.
  const float odd[] = {std::nanf(""),         -std::nanf(""), Limits::infinity(),
                       -Limits::infinity(),   kInfinity,      -kInfinity,
                       Limits::max(),         -Limits::max(), Limits::denorm_min(),
                       -Limits::denorm_min(), Limits::min(),  -0.0f};
  for (int component = 0; component < 6; ++component) {
    for (const float value : odd) {
      Ray r = ray;
      Vec3& v = component < 3 ? r.origin : r.direction;
      (component % 3 == 0 ? v.x : component % 3 == 1 ? v.y : v.z) = value;
      EXPECT_EQ(isFiniteRayCpu(r), isFiniteRay(r)) << "component " << component << " = " << value;
      EXPECT_EQ(isFiniteRayCpu(r), std::isfinite(value)) << "component " << component;
    }
  }
}

}  // namespace
}  // namespace candela
