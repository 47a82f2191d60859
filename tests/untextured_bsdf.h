// The BSDF of a material at a point where nothing is textured: its own colour and roughness.
#pragma once

#include "render/bsdf.h"

namespace candela {

inline Bsdf untexturedBsdf(const Material& m, const Vec3& wo, const Vec3& ng, const Vec3& ns) {
  return makeBsdf(SceneView(), m, m.color, m.roughness, wo, ng, ns, kAllChannels);
}

}  // namespace candela
