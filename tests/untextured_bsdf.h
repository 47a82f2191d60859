// The BSDF of a material at a point where nothing is textured: its own colour and roughness.
#pragma once

#include "render/bsdf.h"

namespace candela {

// The tangent orients an anisotropic material (zero: the frame core/frame.h builds about ns).
inline Bsdf untexturedBsdf(const Material& m, const Vec3& wo, const Vec3& ng, const Vec3& ns,
                           const Vec3& tangent = Vec3(0.0f)) {
  return makeBsdf(SceneView(), m, m.color, m.transmittance, m.roughness, tangent,
                  untexturedLayers(m), wo, ng, ns, kAllChannels);
}
// A Bsdf points at its material, so it must not be made of a temporary one.
Bsdf untexturedBsdf(Material&& m, const Vec3& wo, const Vec3& ng, const Vec3& ns,
                    const Vec3& tangent = Vec3(0.0f)) = delete;

}  // namespace candela
