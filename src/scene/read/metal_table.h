// Named metals for the conductor material: their complex index of refraction eta + i k per RGB
// channel, relative to air.
#pragma once

#include <string>
#include <vector>

#include "core/vec3.h"

namespace candela {

struct NamedMetal {
  const char* name;
  Vec3 eta, k;
};

const std::vector<NamedMetal>& namedMetals();

}  // namespace candela
