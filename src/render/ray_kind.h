// The kinds of ray a sample's path casts, which its keys (SampleStream::rayKey) tell apart where
// two are cast at the same point of its stream (the shadow ray and the light vertex's connection).
#pragma once

#include <cstdint>

#include "core/sobol_sampler.h"
#include "render/scene_view.h"

namespace candela {

enum RayKind : uint32_t {
  kCameraRay = 1,
  kShadowRay = 2,
  kConnectionRay = 3,
  kBounceRay = 4,
  kBranchRay = 5,
  kLightRay = 6,
  // The shadow rays towards each of a few point lights at a first interaction
  // (SceneView::firstHitDeltaLights): kEachLightRay + the light's index.
  kEachLightRay = 8,
};

// The key of a ray of kind `kind` cast here in `rng`'s stream (Ray::alphaKey). Only the alpha
// test reads keys, so in a scene without alpha masks every ray gets 0 and no hash is computed
// (2.5% of the Cornell box's instructions).
CANDELA_HDI_ALWAYS uint32_t rayKeyFor(const SceneView& scene, const SampleStream& rng,
                                      RayKind kind) {
  return scene.alphaMaskCount > 0 ? rng.rayKey(kind) : 0u;
}

}  // namespace candela
