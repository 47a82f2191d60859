// Splitting at smooth glass: where a camera path meets smooth glass within its first
// SceneView::glassSplitDepth interactions, it follows both lobes instead of choosing one by the
// Fresnel reflectance. The refraction goes on at once, weighted (1 - F) as a transmission is;
// the reflection, weighted F, waits as one of the path's branches and runs when the path ends
// (the last split off first), adding to the same radiance with random numbers of its own
// (SampleStream::branch). The two weights sum to what the choice gives on average, so the
// estimate is the same, without the noise of the choice: through a glass ball it decided,
// sample by sample, between two different views, and was nine tenths of the noise there
// (docs/performance.md, "Splitting at smooth glass").
#pragma once

#include <cstdint>

#include "core/sobol_sampler.h"
#include "core/vec3.h"
#include "geometry/ray.h"
#include "render/medium.h"

namespace candela {

// Interactions up to this depth split at smooth glass: a camera ray's way into a glass object
// and out of it again (or its first reflection inside).
constexpr uint32_t kGlassSplitDepth = 2;

// A path splits at most once an interaction, so at most kGlassSplitDepth branches wait at once;
// a view that asks for deeper splits chooses where this many already wait.
constexpr uint32_t kMaxWaitingBranches = kGlassSplitDepth;

// A waiting branch: the path's state after the split, for the reflection. Written by the split
// before anything reads it, so a new path's slots are left as they are (every sample starts one).
struct PathBranch {
  Ray ray;
  Vec3 throughput;
  uint32_t depth;  // of its next interaction
  uint32_t maxDepth;
  float etaScale;
  int32_t medium;    // the medium it starts in (PathState::medium)
  HeroChannel hero;  // PathState::hero
  int32_t channel;  // the colour channel it carries (PathState::channel)
  SampleStream rng;
};

// A path's waiting branches, the last split off on top.
struct PathBranches {
  PathBranch branch[kMaxWaitingBranches];
  uint32_t waiting = 0;
};

}  // namespace candela
