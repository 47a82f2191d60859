// The kinds of ray a sample's path casts, which its keys (SampleStream::rayKey) tell apart where
// two are cast at the same point of its stream (the shadow ray and the light vertex's connection).
#pragma once

#include <cstdint>

namespace candela {

enum RayKind : uint32_t {
  kCameraRay = 1,
  kShadowRay = 2,
  kConnectionRay = 3,
  kBounceRay = 4,
  kBranchRay = 5,
  kLightRay = 6,
};

}  // namespace candela
