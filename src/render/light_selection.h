// Which light next-event estimation samples at a shading point, and with what probability: each
// light at infinity (the environment, directional lights) in a fixed share of the picks of its
// own (SceneView::infiniteLightShare), every other light through the light tree by its importance
// at the point (render/light_tree.h). A scene whose only light is a point or directional light
// samples it without a pick instead (render/light.h, isLoneDeltaLight).
#pragma once

#include "core/sobol_sampler.h"
#include "render/scene_view.h"

namespace candela {

// Whether next-event estimation picks a light at a path's first interaction, so that more than
// one light sample there (SceneView::firstHitLightSamples) may draw different lights: not in a
// scene without lights, nor where its lone point light, or each of its few delta lights, is
// sampled without a pick (render/light.h).
CANDELA_HDI bool takesFirstHitLightSamples(const SceneView& scene) {
  return scene.lightCount > 0 && !scene.loneDeltaLight && scene.firstHitDeltaLights == 0;
}

// The light picked at p, whose reflecting hemisphere is around n (zero where the surface also
// transmits), for uniform u in [0, 1), and in *pmf the probability of that pick, in *remapped
// u's place within the picked light's share of [0, 1), again uniform in [0, 1); -1 when no
// light can reach p.
CANDELA_HDI int selectLight(const SceneView& scene, const Vec3& p, const Vec3& n, float u,
                            float* pmf, float* remapped) {
  const float share = scene.infiniteLightShare;
  const float infinite = share * float(scene.infiniteLightCount);
  // Without a tree the infinite lights take every pick, whatever share * count rounds to.
  if (scene.infiniteLightCount > 0 && (u < infinite || scene.lightTreeNodeCount == 0)) {
    const float place = u / share;
    const uint32_t last = scene.infiniteLightCount - 1;
    const uint32_t k = uint32_t(place) < last ? uint32_t(place) : last;
    *pmf = share;
    *remapped = minf(place - float(k), kOneMinusEpsilon);
    return int(scene.infiniteLights[k]);
  }
  if (scene.lightTreeNodeCount == 0) return -1;
  const float rest = 1.0f - infinite;
  const int light = pickTreeLight(scene.lightTree, p, n,
                                  minf((u - infinite) / rest, kOneMinusEpsilon), pmf, remapped);
  *pmf *= rest;
  return light;
}

// Picks at least this likely hand on their place within their share as the first number of
// their light's sample (selectLightForSample): it keeps 14 of the number's 24 bits or more.
constexpr float kPickPlaceReusedFrom = 0x1p-10f;

// selectLight for a light sample whose two numbers are (*u1, u2): the pick takes *u1 and hands
// on its place within the picked light's share in its stead, so that picks and points together
// keep the pair's stratification over the lights' surfaces (Mitsuba 3's emitter sampling does
// the same). That place has only the share's resolution, a few bits for a light among
// thousands, so there a number of the stream's next dimension stands in; that dimension is
// passed over otherwise, so the stream's layout is the same either way.
CANDELA_HDI int selectLightForSample(const SceneView& scene, const Vec3& p, const Vec3& n,
                                     SampleStream& rng, float* u1, float* pmf) {
  float place = 0.0f;
  const int light = selectLight(scene, p, n, *u1, pmf, &place);
  // No light (nothing to sample) or a likely one: the stand-in's dimension is not computed.
  if (light < 0 || *pmf >= kPickPlaceReusedFrom) {
    *u1 = place;
    rng.skip();
  } else {
    *u1 = rng.next1D();
  }
  return light;
}

// The probability with which selectLight picks light `index` at p with hemisphere normal n.
CANDELA_HDI float lightSelectPmf(const SceneView& scene, uint32_t index, const Vec3& p,
                                 const Vec3& n) {
  if (scene.loneDeltaLight) return 1.0f;
  const Light& l = scene.lights[index];
  if (isInfiniteLight(l.type)) {  // a few at most: the environment and the directional lights
    for (uint32_t k = 0; k < scene.infiniteLightCount; ++k)
      if (scene.infiniteLights[k] == index) return scene.infiniteLightShare;
    return 0.0f;
  }
  if (l.trail == kNotInLightTree) return 0.0f;
  const float rest = 1.0f - scene.infiniteLightShare * float(scene.infiniteLightCount);
  return rest * treeLightPmf(scene.lightTree, l.trail, p, n);
}

}  // namespace candela
