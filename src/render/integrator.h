// The path integrator, shared by every backend: a path is a loop over its interactions
// (`interact`), each of which leaves its shadow ray to the caller, so that a caller can trace
// the shadow rays of several paths together (render/render_pixel.h); traceRadiance runs one
// path alone.
//
// Depth follows the contract: interaction k is the k-th surface hit (the first hit is 1).
// Light reaching interaction k <= max_depth counts, by a shadow ray (next-event estimation) or
// by the ray scattered from k hitting an emitter or the environment; nothing beyond max_depth
// scatters. Emitting spheres and triangles are reached both ways and combined with the power
// heuristic, and so is the environment; point and directional lights are reached by shadow rays
// and by connections to the sample's light vertex (render/light_path.h), combined likewise.
#pragma once

#include <cmath>

#include "core/check.h"
#include "core/float_error.h"
#include "core/sobol_sampler.h"
#include "geometry/surface.h"
#include "render/aov.h"
#include "render/bsdf.h"
#include "render/index_matched.h"
#include "render/light_path.h"
#include "render/light_sample.h"
#include "render/light_selection.h"
#include "render/material_mix.h"
#include "render/medium.h"
#include "render/normal_map.h"
#include "render/object_coordinates.h"
#include "render/path_branch.h"
#include "render/phase_function.h"
#include "render/ray_counters.h"
#include "render/ray_kind.h"
#include "render/shadow_query.h"
#include "render/shadow_ray_origin.h"
#include "render/shadow_transmittance.h"
#include "render/surface_color.h"
#include "render/surface_tangent.h"

namespace candela {

// Russian roulette starts after this many interactions (Mitsuba's default; docs/performance.md
// has what earlier starts cost).
constexpr uint32_t kRouletteDepth = 5;

// The ray leaving surface point `sp` towards `wi`, keyed `key` (SampleStream::rayKey).
CANDELA_HDI_ALWAYS Ray spawnRay(const SurfacePoint& sp, const Vec3& wi, uint32_t key) {
  Ray r;
  r.origin = offsetRayOrigin(sp.p, sp.error, sp.ng, wi);
  r.direction = wi;
  r.alphaKey = key;
  r.time = sp.time;
  return r;
}

// Direct light at a point with a smooth BSDF lobe from light `index`, as the shadow ray
// `*shadow` whose contribution is throughput times the light's share, weighted by the probability
// selectPmf of sampling that light; no query where the light shows the point nothing. `samples`
// is how many light samples the point takes (SceneView::firstHitLightSamples): each is weighed as
// one of that many (Veach's multi-sample MIS, the strategy's density times its count) and adds
// its share of their mean.
// `arrivalPdf` is the density in area measure with which the path's last BSDF sample found this
// point where a light vertex could have been connected to instead (0 where not): the light's
// share is then weighted against that connection too (render/light_path.h). The shadow ray is
// keyed `key`.
CANDELA_HDI void sampleOneLight(const SceneView& scene, uint32_t index, float selectPmf,
                                const Bsdf& bsdf, const SurfacePoint& sp, float u1, float u2,
                                const Vec3& throughput, float arrivalPdf, float samples,
                                uint32_t key, ShadowQuery* shadow) {
  const Light& light = scene.lights[index];
  LightSample ls;
  if (!sampleLight(scene, light, sp.p, sp.time, u1, u2, &ls)) return;
  const bool raised = raisesShadowRay(scene, sp, bsdf.frame.n, ls.wi);
  float bsdfPdf;
  const Vec3 f =
      raised ? evalBsdfAcrossFace(bsdf, ls.wi, &bsdfPdf) : evalBsdf(bsdf, ls.wi, &bsdfPdf);
  if (isBlack(f)) return;
  if (raised) {
    shadow->ray = raisedShadowRay(sp, ls.wi, ls.distance, key);
  } else {
    shadow->ray = spawnRay(sp, ls.wi, key);
    // The environment lies beyond everything: nothing short of infinity may block it.
    if (ls.distance < kInfinity) {
      const Vec3 target = sp.p + ls.wi * ls.distance;
      shadow->ray.tMax = length(target - shadow->ray.origin) * (1.0f - kShadowEpsilon);
    }
  }
  shadow->skipPrim = lightPrimitive(scene, light);
  const float lightPdf = samples * selectPmf * ls.pdf;
  // A light with a surface is also reached by the light subpath's connection (none: density 0).
  const float weight =
      !ls.isDelta
          ? misWeight3(lightPdf, bsdfPdf,
                       lightSubpathSolidAnglePdf(scene, index, sp.time, sp.ng, ls.wi, arrivalPdf),
                       connectsLightSubpaths(scene, light))
      : arrivalPdf > 0.0f ? misWeight3(samples * arrivalPdf * selectPmf,
                                       lightVertexPdf(scene, index, sp.time, sp.p, sp.ng), 0.0f,
                                       connectsLightSubpaths(scene, light))
                          : 1.0f;
  shadow->contribution = throughput * (f * ls.radiance * (weight / lightPdf));
  shadow->active = true;
}

// The two numbers a light sample of `light` uses, from the stream's next dimension. A delta
// light uses none: its dimension is passed over without computing them, so the stream's layout
// is the same whatever the lights are.
CANDELA_HDI void drawLightNumbers(SampleStream& rng, const Light& light, float* u1, float* u2) {
  rng.next2DIfUsed(!isDeltaLight(light), u1, u2);
}

// The light next-event estimation samples at p (hemisphere: as for selectLight), with its two
// numbers in (*u1, *u2) and its chance in *selectPmf: the scene's lone delta light, else one
// picked by its importance (render/light_selection.h); -1 for none. One dimension for the lone
// delta light, or two for a picked one (the pick with its light's sample, and one passed over
// unless the pick's place in its share is too coarse), whatever the geometry, so the stream's
// layout never depends on it (estimateDirectFromEach passes over the same two).
CANDELA_HDI int pickLightSample(const SceneView& scene, const Vec3& p, const Vec3& hemisphere,
                                SampleStream& rng, float* u1, float* u2, float* selectPmf) {
  *u1 = *u2 = 0.0f;
  *selectPmf = 1.0f;
  if (scene.loneDeltaLight) {
    drawLightNumbers(rng, scene.lights[0], u1, u2);
    return 0;
  }
  rng.next2D(u1, u2);
  return selectLightForSample(scene, p, hemisphere, rng, u1, selectPmf);
}

// Direct light at a point with a smooth BSDF lobe, whose reflecting hemisphere is around
// `hemisphere` (reflectingHemisphere: zero where the surface also transmits), as a shadow query
// (sampleOneLight, which `arrivalPdf` is passed to): from the scene's lone delta light
// (render/light.h, isLoneDeltaLight), else from one light picked by its importance here
// (render/light_selection.h); one of `samples` such samples the point takes.
CANDELA_HDI void estimateDirect(const SceneView& scene, const Bsdf& bsdf, const Vec3& hemisphere,
                                const SurfacePoint& sp, const Vec3& throughput, float arrivalPdf,
                                float samples, SampleStream& rng, ShadowQuery* shadow) {
  float u1, u2, selectPmf;  // as pickLightSample draws them
  const int index = pickLightSample(scene, sp.p, hemisphere, rng, &u1, &u2, &selectPmf);
  if (index < 0) return;
  sampleOneLight(scene, uint32_t(index), selectPmf, bsdf, sp, u1, u2, throughput, arrivalPdf,
                 samples, rayKeyFor(scene, rng, kShadowRay), shadow);
}

// Direct light at a path's first interaction in a scene of a few delta lights
// (SceneView::firstHitDeltaLights): every light sampled, light k as the shadow query
// lights->query[k]. The dimensions estimateDirect's pick draws are passed over, so the stream's
// layout is the same as with a pick.
CANDELA_HDI void estimateDirectFromEach(const SceneView& scene, const Bsdf& bsdf,
                                        const SurfacePoint& sp, const Vec3& throughput,
                                        SampleStream& rng, LightQueries* lights) {
  static_assert(kEachDeltaLightUpTo <= kMaxLightQueries, "a query for each light");
  static_assert(kMaxFirstHitLightSamples <= kMaxLightQueries, "a query for each light sample");
  rng.skip();  // the pick's pair of numbers (a delta light uses none)
  rng.skip();  // the stand-in for the pick's place
  for (uint32_t i = 0; i < scene.firstHitDeltaLights; ++i)
    sampleOneLight(scene, i, 1.0f, bsdf, sp, 0.0f, 0.0f, throughput, 0.0f, 1.0f,
                   rayKeyFor(scene, rng, RayKind(kEachLightRay + i)), &lights->query.emplace(i));
  lights->count = scene.firstHitDeltaLights;
}

// A path between its interactions: what it has gathered and what it carries to the next.
struct PathState {
  Vec3 radiance = Vec3(0.0f), throughput = Vec3(1.0f);
  Ray ray;             // towards the next interaction
  uint32_t depth = 1;  // of the next interaction
  uint32_t maxDepth = 0;
  bool specularBounce = true;  // the camera counts as specular: emitters seen directly count fully
  float bsdfPdf = 0.0f;        // pdf of the last non-delta bounce, for MIS on area lights
  // The product of eta^2 over the transmissions so far: Russian roulette judges the throughput
  // without the 1 / eta^2 radiance scaling, which says nothing about the path's worth.
  float etaScale = 1.0f;
  // The glass whose inside (its medium: hasMedium) the ray travels in, by material index, entered
  // and left by the transmissions through its surface; -1 outside (the camera and the lights are
  // outside every medium).
  int32_t medium = -1;
  HeroChannel hero;  // how the path draws its distances through scattering media
  // The one colour channel the path carries since it met dispersive glass (render/dispersion.h),
  // or kAllChannels.
  int32_t channel = kAllChannels;
  Vec3 bouncePoint = Vec3(0.0f), bounceHemisphere = Vec3(0.0f);  // the last bounce's
  // The last bounce's geometric normal, and the density by area with which the bounce before
  // found its point where a light vertex could have been connected to instead (0 where not):
  // an emitter the last bounce finds is then weighted against that connection.
  Vec3 bounceNormal = Vec3(0.0f);
  float bounceArrivalPdf = 0.0f;
  // How many light samples next-event estimation took at the last bounce (estimateDirect's
  // `samples`): what the bounce's BSDF sample finds is weighed against that many.
  float bounceLightSamples = 1.0f;
  // The sample's light vertex (render/light_path.h), and whether the last interaction may be
  // connected to one, so that the next weighs its next-event estimation against that.
  LightVertex lightVertex;
  bool connectable = false;
  PathBranches branches;  // split off at smooth glass, to run when this path ends (path_branch.h)

  PathState() = default;
  CANDELA_HDI PathState(const SceneView& scene, const Ray& cameraRay)
      : ray(cameraRay), maxDepth(scene.settings.maxDepth) {}
};

// The radiance of directional light l's disc that a ray leaving the scene along `st.ray` sees (0
// where l has none or the ray misses it), weighted against next-event estimation's sample of it
// as the environment is; a camera ray (`fromCamera`) does not see a disc hidden from the camera.
CANDELA_HDI Vec3 sunDiscSeen(const SceneView& scene, const Light& l, const PathState& st,
                             bool fromCamera) {
  if (!hasSunDisc(l) || !inSunDisc(l, st.ray.direction)) return Vec3(0.0f);
  if (fromCamera && l.hiddenFromCamera) return Vec3(0.0f);
  const float weight =
      st.specularBounce
          ? 1.0f
          : powerHeuristic(st.bsdfPdf, st.bounceLightSamples * scene.infiniteLightShare *
                                           uniformConePdf(l.sunOneMinusCos));
  return sunRadiance(l) * weight;
}

// What the suns' discs send along `st.ray` (sunDiscSeen), each where it stands at the ray's time.
CANDELA_HDI Vec3 sunDiscsSeen(const SceneView& scene, const PathState& st, bool fromCamera) {
  Vec3 sum(0.0f);
  for (uint32_t k = 0; k < scene.infiniteLightCount; ++k) {
    const Light& l = scene.lights[scene.infiniteLights[k]];
    sum += l.moves ? sunDiscSeen(scene, posedLight(scene, scene.lightPoses, l, st.ray.time), st,
                                 fromCamera)
                   : sunDiscSeen(scene, l, st, fromCamera);
  }
  return sum;
}

// Russian roulette after interaction `depth` (from kRouletteDepth on): false where the path ends,
// else its throughput is divided by its chance to go on.
CANDELA_HDI_ALWAYS bool survivesRoulette(uint32_t depth, SampleStream& rng, PathState* path) {
  if (depth < kRouletteDepth) return true;
  const float survive = minf(0.95f, maxComponent(path->throughput) * path->etaScale);
  if (rng.next1D() >= survive) return false;
  path->throughput /= survive;
  return true;
}

// Direct light at point p in the medium of index-matched glass `inside`, where a path travelling
// along `travel` at `time` scatters by its phase function, as the shadow query *shadow, which
// crosses the glass (render/shadow_transmittance.h); its numbers drawn as estimateDirect draws
// them.
CANDELA_HDI void estimateDirectInMedium(const SceneView& scene, const Material& inside,
                                        const Vec3& p, const Vec3& travel, float time,
                                        const Vec3& throughput, SampleStream& rng,
                                        ShadowQuery* shadow) {
  float u1, u2, selectPmf;
  const int index = pickLightSample(scene, p, Vec3(0.0f), rng, &u1, &u2, &selectPmf);
  if (index < 0) return;
  const uint32_t key = rayKeyFor(scene, rng, kShadowRay);
  const Light& light = scene.lights[index];
  LightSample ls;
  if (!sampleLight(scene, light, p, time, u1, u2, &ls)) return;
  const float phase = henyeyGreenstein(dot(travel, ls.wi), inside.scatteringAnisotropy);
  const float lightPdf = selectPmf * ls.pdf;
  const float weight = ls.isDelta ? 1.0f : powerHeuristic(lightPdf, phase);
  shadow->ray.origin = p;
  shadow->ray.direction = ls.wi;
  shadow->ray.tMax = ls.distance < kInfinity ? ls.distance * (1.0f - kShadowEpsilon) : kInfinity;
  shadow->ray.alphaKey = key;
  shadow->skipPrim = lightPrimitive(scene, light);
  shadow->contribution = throughput * ls.radiance * (phase * weight / lightPdf);
  shadow->active = true;
}

// Interaction `depth` of a path inside the medium of glass `inside`, where it scatters at point p
// (render/medium.h): a new direction by the phase function. Inside index-matched glass light is
// sampled from here too (estimateDirectInMedium) and weighed against what the scattered ray finds;
// inside any other the glass around blocks every shadow ray, so that whatever the scattered ray
// finds counts fully, as after a mirror. False when the path ends here.
template <bool kAovs>
CANDELA_HDI bool scatterInMedium(const SceneView& scene, const Material& inside, const Vec3& p,
                                 uint32_t depth, PathState* path, SampleStream& rng,
                                 RayCounters& counters, FirstHit* first, LightQueries* lights) {
  PathState& st = *path;
  if constexpr (kAovs) {
    if (!first->albedoDone) {
      first->albedoDone = true;
      first->albedo = singleScatteringAlbedo(inside.absorption, inside.scattering);
    }
  }
  if (depth > st.maxDepth || (depth == st.maxDepth && !scene.emissionReachable)) return false;
  const bool sampled = isIndexMatched(inside);
  if (sampled) {
    ShadowQuery& shadow = lights->query.emplace(0);
    lights->count = 1;
    estimateDirectInMedium(scene, inside, p, st.ray.direction, st.ray.time, st.throughput, rng,
                           &shadow);
    shadow.ray.time = st.ray.time;
    shadow.medium = st.medium;
    counters.shadow += shadow.active;
    if constexpr (kAovs) shadow.direct = depth == 1;
  }
  // "direct": the scattered ray only gathers emission, as after a diffuse surface.
  if (scene.settings.integrator == IntegratorType::Direct) st.maxDepth = depth;
  float u1, u2;
  rng.next2D(&u1, &u2);
  const float g = inside.scatteringAnisotropy;
  const Vec3 wi = sampleHenyeyGreenstein(st.ray.direction, g, u1, u2);
  st.specularBounce = !sampled;
  st.bsdfPdf = sampled ? henyeyGreenstein(dot(st.ray.direction, wi), g) : 0.0f;
  st.bouncePoint = p;
  st.bounceHemisphere = Vec3(0.0f);  // light comes from every side
  st.bounceNormal = Vec3(0.0f);
  st.bounceArrivalPdf = 0.0f;
  st.bounceLightSamples = 1.0f;
  st.connectable = false;
  if (!survivesRoulette(depth, rng, &st)) return false;
  st.ray.origin = p;
  st.ray.direction = wi;
  st.ray.tMax = kInfinity;
  st.ray.alphaKey = rayKeyFor(scene, rng, kBounceRay);
  ++counters.bounce;
  return true;
}

// Interaction path->depth, where path->ray found `hit` (`found` false: it left the scene): adds
// what it sees there to path->radiance, leaves next-event estimation's shadow rays in *lights
// (one, or at a first interaction one for each of a few delta lights) and the connection to the
// sample's light vertex in *connect (inactive when there is none) for the caller to trace, and
// scatters path->ray onwards (at smooth glass within scene.glassSplitDepth, leaving the reflection
// as a waiting branch: render/path_branch.h). False when the path ends here (its shadow queries
// still count; a waiting branch is the caller's to resume). With kAovs, `first` (zeroed by the
// caller) also receives the sample's first hit, albedo, direct light and emission (render/aov.h);
// that work is compiled only into the kAovs instance, and it draws no random numbers, so the
// radiance is the same.
template <bool kAovs>
CANDELA_HDI_ALWAYS bool interact(const SceneView& scene, PathState* path, bool found,
                                 const Hit& hit, SampleStream& rng, RayCounters& counters,
                                 FirstHit* first, LightQueries* lights, ShadowQuery* connect) {
  lights->count = 0;  // the slots may hold the last interaction's queries
  PathState& st = *path;
  const uint32_t depth = st.depth++;
  const bool fromCamera = depth == 1;  // a camera ray, which emitters hidden from it do not show
  // Rays are unit length, so the hit's t is the distance travelled through the medium.
  if (st.medium >= 0) {
    const Material& inside = scene.materials[st.medium];
    const float tMax = found ? hit.t : kInfinity;
    if (isBlack(inside.scattering)) {
      st.throughput *= beerTransmittance(inside.absorption, tMax);
    } else {
      float uHero, uDistance;
      rng.next2D(&uHero, &uDistance);
      if (st.hero.channel < 0) st.hero.pick(st.channel, uHero);
      const MediumStep step =
          sampleMediumStep(inside.absorption, inside.scattering, st.hero.channel, tMax, uDistance);
      st.throughput *= st.hero.take(step);
      if (step.scattered)
        return scatterInMedium<kAovs>(scene, inside, st.ray.origin + st.ray.direction * step.t,
                                      depth, path, rng, counters, first, lights);
    }
  }
  if (!found) {
    const int32_t light = st.specularBounce ? -1 : scene.environment.light;
    const float weight =
        light < 0
            ? 1.0f
            : powerHeuristic(st.bsdfPdf, st.bounceLightSamples *
                                             lightSelectPmf(scene, uint32_t(light), st.bouncePoint,
                                                            st.bounceHemisphere) *
                                             environmentPdf(scene, st.ray.direction));
    Vec3 background = fromCamera && scene.environment.hiddenFromCamera
                          ? Vec3(0.0f)
                          : environmentRadiance(scene, st.ray.direction);
    Vec3 seen = st.throughput * background * weight;
    Vec3 suns(0.0f);
    if (scene.sunDiscs) {
      suns = sunDiscsSeen(scene, st, fromCamera);
      background += suns;
      seen += st.throughput * suns;
    }
    if constexpr (kAovs) {
      // A black environment is none; a black texel of a visible map is still a backdrop.
      if (fromCamera)
        first->seesNothing =
            (scene.environment.light < 0 || scene.environment.hiddenFromCamera) && isBlack(suns);
      if (!first->albedoDone) {
        first->albedoDone = true;
        first->albedo = clampUnit(background);
      }
      if (depth <= 2) first->direct += seen;
    }
    st.radiance += seen;
    return false;
  }
  SurfacePoint sp = surfaceAt(scene, st.ray, hit);
  CANDELA_DCHECK(sp.material < scene.materialCount);
  // sp.material stays the surface's (the material pass shows a mix as itself), and so does what
  // it emits: a mix's emission is its own, whichever part the path meets.
  const Material& surface = scene.materials[sp.material];
  const uint32_t met = materialMet(scene, sp.material, hit, sp, rng);
  const Material& m = scene.materials[met];
  if (fromCamera && m.hiddenFromCamera) {  // the camera ray goes on as if it were not there
    st.depth = depth;
    st.ray = spawnRay(sp, st.ray.direction, rayKeyFor(scene, rng, kCameraRay));
    ++counters.camera;
    return true;
  }
  // Glass of index 1 bounds its medium and nothing more: the path crosses it as it is, tinted by
  // its colour, with the last scattering's weights for what it finds (as the shadow rays that
  // cross it too, render/shadow_transmittance.h), and the crossing is not an interaction.
  if (isIndexMatched(m)) {
    st.throughput *= surfaceColor(scene, m, hit, sp);
    st.medium = mediumAlong(m, met, st.ray.direction, sp.ng);
    st.depth = depth;
    st.ray =
        spawnRay(sp, st.ray.direction, rayKeyFor(scene, rng, fromCamera ? kCameraRay : kBounceRay));
    return true;
  }
  const Vec3 wo = -st.ray.direction;
  const Vec3 coatNormal = hasMaps(m) ? applyNormalMaps(scene, m, hit, &sp, wo) : Vec3(0.0f);
  [[maybe_unused]] bool albedoHere = false;  // the albedo pass takes this surface's colour
  if constexpr (kAovs) {
    if (depth == 1) {
      first->hit = true;
      first->position = sp.p;
      first->normal = facingNormal(wo, sp.ng, sp.ns);
      first->uv = surfaceUv(scene, hit, sp);
      first->objectCoordinates = objectCoordinatesAt(scene, hit, sp);
      first->material = sp.material;
      first->prim = hit.prim;
      first->b1 = hit.b1;
      first->b2 = hit.b2;
    }
    if (!first->albedoDone && (isEmissive(m) || hasSmoothLobe(m))) {
      first->albedoDone = true;
      if (isEmissive(m))
        first->albedo = emitsTowards(m, wo, sp.ng) ? clampUnit(m.radiance) : Vec3(0.0f);
      else
        albedoHere = true;  // from the surface colour below, looked up once
    }
  }

  // An emissive m is its surface's own material (no mix has one).
  if ((isEmissive(m) || (scene.reflectorsEmit && hasEmission(surface))) &&
      emitsTowards(surface, wo, sp.ng)) {
    float weight = 1.0f;
    const int32_t light = st.specularBounce ? -1 : lightOfPrimitive(scene, hit.prim);
    if (light >= 0) {
      const float selectPmf =
          lightSelectPmf(scene, uint32_t(light), st.bouncePoint, st.bounceHemisphere);
      // The ray may have left from an index-matched crossing after the bounce point.
      const float distance = scene.indexMatchedMedia ? length(sp.p - st.bouncePoint) : hit.t;
      const float neePdf = st.bounceLightSamples * selectPmf *
                           emitterPdf(scene, scene.lights[light], st.bouncePoint, sp.time,
                                      st.ray.direction, distance, sp.ng);
      const float subpathPdf = lightSubpathSolidAnglePdf(
          scene, uint32_t(light), sp.time, st.bounceNormal, st.ray.direction, st.bounceArrivalPdf);
      weight = misWeight3(st.bsdfPdf, neePdf, subpathPdf,
                          connectsLightSubpaths(scene, scene.lights[light]));
    }
    const Vec3 seen = st.throughput * surfaceRadiance(scene, surface, hit, sp) * weight;
    if constexpr (kAovs) {
      if (depth <= 2) first->direct += seen;
      if (depth == 1) first->emission = seen;
    }
    st.radiance += seen;
  }
  if (isEmissive(m)) return false;
  if (depth > st.maxDepth) {
    if constexpr (kAovs)
      if (albedoHere)
        first->albedo =
            aovAlbedo(m, surfaceColor(scene, m, hit, sp), surfaceTransmittance(scene, m, hit, sp));
    return false;
  }

  const Vec3 color = surfaceColor(scene, m, hit, sp);
  const Vec3 transmittance =
      isTranslucent(m) ? surfaceTransmittance(scene, m, hit, sp) : Vec3(0.0f);
  if constexpr (kAovs)
    if (albedoHere) first->albedo = aovAlbedo(m, color, transmittance);
  if (isDispersive(m) && st.channel == kAllChannels) {
    st.channel = int32_t(minf(rng.next1D() * 3.0f, 2.0f));
    Vec3 kept(0.0f);
    kept[st.channel] = 3.0f;
    st.throughput *= kept;
  }
  const Bsdf bsdf =
      makeBsdf(scene, m, color, transmittance, surfaceRoughness(scene, m, hit, sp),
               surfaceTangent(scene, m, hit, sp),
               hasLayers(m) ? surfaceLayers(scene, m, hit, sp, coatNormal) : SurfaceLayers(), wo,
               sp.ng, sp.ns, st.channel);
  const Vec3 hemisphere = reflectingHemisphere(bsdf);
  const bool smooth = hasSmoothLobe(m);
  float arrivalPdf = 0.0f;
  float lightSamples = 1.0f;  // taken here by next-event estimation
  if (smooth) {
    if (st.connectable && !st.specularBounce && holdsLightVertex(m)) {
      const Vec3 back = st.bouncePoint - sp.p;
      const float dist2 = dot(back, back);
      arrivalPdf = st.bsdfPdf * fabsf(dot(sp.ng, back)) / (dist2 * sqrtf(dist2));
    }
    if (depth == 1 && scene.firstHitDeltaLights > 0) {
      estimateDirectFromEach(scene, bsdf, sp, st.throughput, rng, lights);
      for (uint32_t k = 0; k < lights->count; ++k) {
        counters.shadow += lights->query[k].active;
        if constexpr (kAovs) lights->query[k].direct = true;
      }
    } else {
      // Several light samples at the first interaction where the scene asks for them, one
      // elsewhere.
      lights->count = depth == 1 ? scene.firstHitLightSamples : 1;
      lightSamples = float(lights->count);
      for (uint32_t k = 0; k < lights->count; ++k) {
        ShadowQuery& shadow = lights->query.emplace(k);
        estimateDirect(scene, bsdf, hemisphere, sp, st.throughput, arrivalPdf, lightSamples, rng,
                       &shadow);
        counters.shadow += shadow.active;
        if constexpr (kAovs) shadow.direct = depth == 1;
      }
    }
    // Each shadow ray starts in the medium on its side of the surface (glass's, or past any other
    // surface the path's); only shadow rays that cross index-matched glass read it.
    if (scene.indexMatchedMedia)
      for (uint32_t k = 0; k < lights->count; ++k) {
        ShadowQuery& q = lights->query[k];
        q.medium = boundsAnInside(m) ? mediumAlong(m, met, q.ray.direction, sp.ng) : st.medium;
      }
    // "direct": the scattered ray below only gathers emission; nothing scatters after it.
    if (scene.settings.integrator == IntegratorType::Direct) st.maxDepth = depth;
  }
  // A light vertex connected to here is the path's interaction depth + 1.
  st.connectable =
      smooth && scene.lightPathLights > 0 && depth < st.maxDepth && depth <= scene.lightPathDepth;
  if (st.connectable && st.lightVertex.valid) {
    connectLightVertex(scene, &st.lightVertex, bsdf, sp, st.throughput,
                       rayKeyFor(scene, rng, kConnectionRay), connect);
    if (connect->active) ++counters.shadow;
  }

  if (depth == st.maxDepth && !scene.emissionReachable) return false;

  const float uc = usesLobeChoice(m) ? rng.next1D() : 0.0f;
  float u1, u2;
  rng.next2D(&u1, &u2);
  BsdfSample bs, reflected;
  if (depth <= scene.glassSplitDepth && st.branches.waiting < kMaxWaitingBranches &&
      hasTwoDeltaLobes(m) && sampleBothDeltaLobes(bsdf, &bs, &reflected)) {
    PathBranch& b = st.branches.branch[st.branches.waiting++];
    b.ray = spawnRay(sp, reflected.wi, rayKeyFor(scene, rng, kBranchRay));
    b.throughput = st.throughput * reflected.weight;
    b.depth = st.depth;
    b.maxDepth = st.maxDepth;
    b.etaScale = st.etaScale * reflected.eta * reflected.eta;
    b.medium = st.medium;
    b.hero = st.hero;
    b.channel = st.channel;
    b.rng = rng.branch();
    ++counters.bounce;
  } else if (!sampleBsdf(bsdf, uc, u1, u2, &bs)) {
    return false;
  }
  st.throughput *= bs.weight;
  st.etaScale *= bs.eta * bs.eta;
  // A transmission enters the surface's inside, against its outward normal, or leaves it.
  const float outward = dot(bs.wi, sp.ng);
  if (boundsAnInside(m) && outward * dot(wo, sp.ng) < 0.0f)
    st.medium = mediumAlong(m, met, bs.wi, sp.ng);
  st.specularBounce = bs.delta;
  st.bsdfPdf = bs.pdf;
  st.bouncePoint = sp.p;
  st.bounceHemisphere = hemisphere;
  st.bounceNormal = sp.ng;
  st.bounceArrivalPdf = arrivalPdf;
  st.bounceLightSamples = lightSamples;

  if (!survivesRoulette(depth, rng, &st)) return false;
  st.ray = spawnRay(sp, bs.wi, rayKeyFor(scene, rng, kBounceRay));
  ++counters.bounce;
  return true;
}

// Starts the path's waiting branch (path_branch.h) where it ended, with the branch's random
// numbers in *rng; false when none waits.
CANDELA_HDI bool resumeBranch(PathState* path, SampleStream* rng) {
  if (path->branches.waiting == 0) return false;
  const PathBranch& b = path->branches.branch[--path->branches.waiting];
  path->ray = b.ray;
  path->throughput = b.throughput;
  path->depth = b.depth;
  path->maxDepth = b.maxDepth;
  path->etaScale = b.etaScale;
  path->medium = b.medium;
  path->hero = b.hero;
  path->channel = b.channel;
  path->specularBounce = true;  // a delta lobe: what it finds counts fully
  path->bsdfPdf = 0.0f;
  path->bounceArrivalPdf = 0.0f;
  path->bounceLightSamples = 1.0f;
  path->connectable = false;
  *rng = b.rng;
  return true;
}

// Adds what of an active shadow query's contribution reaches its point, `kept` of it
// (shadowTransmittance), to the path (with kAovs, next-event estimation's at the first hit also to
// first->direct).
template <bool kAovs>
CANDELA_HDI_ALWAYS void resolveShadow(const ShadowQuery& shadow, const Vec3& kept, PathState* path,
                                      FirstHit* first) {
  CANDELA_DCHECK(shadow.active);
  if (isBlack(kept)) return;
  const Vec3 contribution = shadow.contribution * kept;
  path->radiance += contribution;
  if constexpr (kAovs)
    if (shadow.direct) first->direct += contribution;
}

// Runs a path from its next interaction to its end, and then its branch, if one waits, one ray at
// a time; returns the radiance of both.
template <bool kAovs, class Tracer>
CANDELA_HDI Vec3 finishPath(const SceneView& scene, const Tracer& tracer, PathState* path,
                            SampleStream& rng, RayCounters& counters, FirstHit* first) {
  LightQueries lights;  // reused: each interaction sets the queries it leaves
  for (;;) {
    Hit hit;
    const bool found = tracer.closest(path->ray, &hit);
    ShadowQuery connect;
    const bool goesOn =
        interact<kAovs>(scene, path, found, hit, rng, counters, first, &lights, &connect);
    for (uint32_t k = 0; k < lights.count; ++k) {
      const ShadowQuery& shadow = lights.query[k];
      if (shadow.active)
        resolveShadow<kAovs>(shadow, shadowTransmittance(scene, tracer, shadow), path, first);
    }
    if (connect.active)
      resolveShadow<kAovs>(connect, shadowTransmittance(scene, tracer, connect), path, first);
    if (!goesOn && !resumeBranch(path, &rng)) return path->radiance;
  }
}

// Radiance arriving at the camera along `ray` (one sample), one ray at a time. With kAovs,
// `first` (zeroed by the caller) also receives the sample's first hit, albedo, direct light and
// emission (interact).
template <bool kAovs = false, class Tracer>
CANDELA_HDI Vec3 traceRadiance(const SceneView& scene, const Tracer& tracer, const Ray& ray,
                               SampleStream& rng, RayCounters& counters,
                               FirstHit* first = nullptr) {
  PathState path(scene, ray);
  if (scene.lightPathLights > 0)
    traceLightVertex(scene, tracer, rng, counters, ray.time, &path.lightVertex);
  return finishPath<kAovs>(scene, tracer, &path, rng, counters, first);
}

}  // namespace candela
