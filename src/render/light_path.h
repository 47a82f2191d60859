// Light-vertex connections: a further strategy by which paths reach the lights.
//
// Next-event estimation reaches a light from the last surface y of a path whose earlier vertex x
// scattered towards y: y is found by x's BSDF sample, so where a light brightens a small patch of
// the scene (a wall beside a lamp) few of those samples find it, and indirect light is noisy.
// Each sample therefore also starts one light subpath: a light picked by power emits a ray (a
// point light uniformly over the sphere; a light with a surface from a point uniform over its
// area, cosine-distributed about its normal), and its first hit y, found by the light, is
// connected by a shadow ray to every interaction x of the camera path that may scatter (as
// bidirectional path tracing's strategy s = 2 does).
//
// The strategies are combined by the balance heuristic (misWeight3) over the density of the whole
// of (y, light point) in area measure. For a point light there are two: x's BSDF sample finds y,
// whose next-event estimation picks the light, p(x -> y) pick(l at y), with p(x -> y) = pdf(wi)
// |cos_y| / |x - y|^2; and the light's, pathPick(l) |cos_y| / (4 pi r^2). A light with a surface
// is also reached by y's BSDF sample, so it has three: those two, each times the density of the
// light's point L from y (next-event estimation's, or the BSDF's, by area at L), and the light's,
// pathPick(l) / area(l) |cos_L| / pi |cos_y| / |y - L|^2.
#pragma once

#include <cmath>

#include "core/constants.h"
#include "core/float_error.h"
#include "core/frame.h"
#include "core/sampling.h"
#include "core/sobol_sampler.h"
#include "geometry/surface.h"
#include "render/bsdf.h"
#include "render/light_emission.h"
#include "render/light_sample.h"
#include "render/light_selection.h"
#include "render/material_mix.h"
#include "render/normal_map.h"
#include "render/ray_counters.h"
#include "render/ray_kind.h"
#include "render/shadow_query.h"
#include "render/surface_color.h"
#include "render/surface_tangent.h"

namespace candela {

// Whether a light subpath's first hit on material m is a light vertex: a surface with a smooth
// lobe that does not emit, and not dispersive glass, whose lobe depends on the colour channel
// that the camera path chooses after the subpath is traced (render/dispersion.h).
CANDELA_HDI bool holdsLightVertex(const Material& m) {
  return !isEmissive(m) && hasSmoothLobe(m) && !isDispersive(m);
}

// The first surface a light subpath reaches, where it can be connected (holdsLightVertex).
struct LightVertex {
  SurfacePoint sp;
  Vec3 color;    // the surface's colour there (textures included)
  Vec3 transmittance = Vec3(0.0f);  // and a translucent surface's transmittance
  float roughness = 0.0f;  // and its roughness
  Vec3 tangent = Vec3(0.0f);  // and its tangent (render/surface_tangent.h)
  SurfaceLayers layers;       // and its layers (render/surface_layers.h)
  uint32_t material = 0;      // the material met there (a mix's part: render/material_mix.h)
  Vec3 toLight;  // unit direction from sp.p to the light (its point L where it has a surface)
  // What the light sends to the vertex over the density of the subpath up to it, less the
  // geometry term between the two: a point light's power over its pick; a surface's radiance at
  // L times pi over the pick and the density of L by area.
  Vec3 power;
  uint32_t light = 0;
  float pdfArea = 0.0f;  // the subpath's density of the vertex (with L's, for a surface)
  // A light with a surface: the cosine at L towards the vertex over their squared distance, and
  // that distance, for the densities with which the camera path's strategies reach L.
  float cosOverDist2 = 0.0f, distance = 0.0f;
  Vec3 lightNormal = Vec3(0.0f);
  // The density with which next-event estimation at the vertex reaches the light: its pick there
  // (times, for a light with a surface, the density of L). The same for every connection of the
  // sample, so the first that needs it computes it (-1 until then).
  float neePdf = -1.0f;
  bool area = false;
  bool valid = false;
};

// lv's neePdf, computed on first use. Every connection that reaches here has a camera vertex
// on the side of lv's surface that the light shines on (else lv's BSDF carried nothing), so the
// pick's hemisphere is that side's, as next-event estimation at lv would take it.
CANDELA_HDI float lightVertexNeePdf(const SceneView& scene, LightVertex* lv) {
  if (lv->neePdf >= 0.0f) return lv->neePdf;
  const Material& m = scene.materials[lv->material];
  const float pick =
      lightSelectPmf(scene, lv->light, lv->sp.p, reflectingHemisphere(m, lv->toLight, lv->sp.ng));
  lv->neePdf = !lv->area ? pick
                         : pick * emitterPdf(scene, scene.lights[lv->light], lv->sp.p, lv->sp.time,
                                             lv->toLight, lv->distance, lv->lightNormal);
  return lv->neePdf;
}

// The chance that a light subpath starts from light `index`: by power
// (scene/flatten_lights.cpp, setLightPathPicks); the lights at infinity start none.
CANDELA_HDI float lightPathPmf(const SceneView& scene, uint32_t index) {
  return scene.lights[index].pathPmf;
}

// The density, in area measure, with which a light subpath from point light `light` (picked with
// `pmf`, as it stands at the path's time) reaches the point p of geometric normal ng as its first
// vertex: its pick, times its uniform emission 1 / (4 pi) (a spot's: uniform within its cone, 0
// outside) carried to p's surface.
CANDELA_HDI float pointLightVertexPdf(const Light& light, float pmf, const Vec3& p,
                                      const Vec3& ng) {
  const Vec3 d = light.position - p;
  const float r2 = dot(d, d);
  float density = 0.25f * kInvPi;
  if (hasCone(light.spot)) {
    if (!(dot(-d, light.spot.axis) > light.spot.cosCutoff * sqrtf(r2))) return 0.0f;
    density = uniformConePdf(coneOneMinusCos(light.spot));
  }
  return pmf * density * fabsf(dot(ng, d)) / (r2 * sqrtf(r2));
}

// pointLightVertexPdf of point light `index` at `time`.
CANDELA_HDI float lightVertexPdf(const SceneView& scene, uint32_t index, float time, const Vec3& p,
                                 const Vec3& ng) {
  const float pmf = lightPathPmf(scene, index);
  if (pmf == 0.0f) return 0.0f;
  const Light& light = scene.lights[index];
  if (light.moves)
    return pointLightVertexPdf(posedLight(scene, scene.lightPoses, light, time), pmf, p, ng);
  return pointLightVertexPdf(light, pmf, p, ng);
}

// Light `index`'s pathAreaPdf at `time`: for a light whose shape moves (and may grow), its pick
// over its area then.
CANDELA_HDI_ALWAYS float lightPathAreaPdf(const SceneView& scene, uint32_t index, float time) {
  const Light& l = scene.lights[index];
  if (scene.motionTimeCount == 0) return l.pathAreaPdf;
  const bool area = l.type == LightType::Sphere || l.type == LightType::Triangle;
  if (!area || l.pathPmf == 0.0f || !areaLightMoves(scene, l)) return l.pathAreaPdf;
  return l.pathPmf * emissionAreaPdf(scene, l, time);
}

// Where next-event estimation at p (geometric normal ng, found by a BSDF sample of density
// `arrivalPdf` by area) reaches a point of area light `index` in direction wi, the density with
// which a light subpath would have made that path instead, in the measure of next-event
// estimation's own density (solid angle at p, the densities of p cancelled):
// pathPick / area |cos_p| / (pi arrivalPdf), the area at `time`. 0 for a light that starts no
// subpath.
CANDELA_HDI float lightSubpathSolidAnglePdf(const SceneView& scene, uint32_t index, float time,
                                            const Vec3& ng, const Vec3& wi, float arrivalPdf) {
  if (!(arrivalPdf > 0.0f)) return 0.0f;
  const float start = lightPathAreaPdf(scene, index, time);
  if (start == 0.0f) return 0.0f;
  return start * fabsf(dot(ng, wi)) * kInvPi / arrivalPdf;
}

// Whether this render connects its paths to light subpaths from light `l`: the light starts
// them, and the render traces them (SceneView::lightPathLights, 0 where the integrator, the
// depth, the scene's light_paths or the pilot leave them out).
CANDELA_HDI bool connectsLightSubpaths(const SceneView& scene, const Light& l) {
  return scene.lightPathLights > 0 && startsLightSubpaths(l);
}

// The weight of the strategy of density `a` among three (c = 0: between two): for a light whose
// light subpaths this render connects to (connectsLightSubpaths), whose connections are then
// among the strategies, the balance heuristic; for any other, the power heuristic (to the bit
// powerHeuristic(a, b) for c = 0). Where connections take part the balance heuristic leaves less
// noise (the bench scenes, up to 6%); between next-event estimation and a BSDF sample alone the
// power heuristic does, on glossy surfaces above all, and on lights that subtend a small cone
// (docs/performance.md). The choice is the light's and the render's, not the densities', so every
// site that weighs a path makes the same one.
CANDELA_HDI float misWeight3(float a, float b, float c, bool connectsSubpaths) {
  if (connectsSubpaths) return a / (a + b + c);
  const float a2 = a * a;
  return a2 / (a2 + b * b + c * c);
}

// The light a subpath starts from, for u in [0, 1): in lightPathOrder, the first whose
// cumulative pick exceeds u (lights without a pick have none to exceed it with).
CANDELA_HDI uint32_t pickLightPathLight(const SceneView& scene, float u) {
  uint32_t lo = 0, hi = scene.lightPathOrderCount - 1;
  while (lo < hi) {
    const uint32_t mid = (lo + hi) / 2;
    if (scene.lights[scene.lightPathOrder[mid]].pathCdf > u)
      hi = mid;
    else
      lo = mid + 1;
  }
  return scene.lightPathOrder[lo];
}

// Starts the sample's light subpath, from the stream's next dimensions (one for the pick where
// more than one light may start it, two for the direction, and where lights with a surface start
// subpaths two for the point, which a point light passes over), at the camera ray's `time`, and
// records its first vertex in *lv (valid only where that surface may be connected to).
template <class Tracer>
CANDELA_HDI void traceLightVertex(const SceneView& scene, const Tracer& tracer, SampleStream& rng,
                                  RayCounters& counters, float time, LightVertex* lv) {
  const float uPick = scene.lightPathLights > 1 ? rng.next1D() : 0.0f;
  float u1, u2;
  rng.next2D(&u1, &u2);
  const uint32_t index = pickLightPathLight(scene, uPick);
  PosedLightSlot posed;  // a moving point light, where it stands at `time`
  const Light& light =
      scene.lights[index].moves
          ? (posed.light = posedLight(scene, scene.lightPoses, scene.lights[index], time))
          : scene.lights[index];
  // A point light or a light with a surface: the lights at infinity start none (pathPmf 0).
  const bool area = light.type == LightType::Sphere || light.type == LightType::Triangle;
  float v1 = 0.0f, v2 = 0.0f;
  if (scene.areaLightPaths) rng.next2DIfUsed(area, &v1, &v2);
  Ray ray;
  EmissionPoint e;
  float emitCos = 0.0f;
  if (area) {
    e = sampleEmissionPoint(scene, light, time, v1, v2);
    const Vec3 local = sampleCosineHemisphere(u1, u2);
    emitCos = local.z;
    if (!(emitCos > 0.0f) || isBlack(e.radiance)) return;
    ray.direction = normalize(Frame(e.n).toWorld(local));
    ray.origin = offsetRayOrigin(e.p, e.error, e.n, ray.direction);
  } else {
    ray.origin = light.position;
    ray.direction = hasCone(light.spot) ? sampleConeDirection(light.spot, u1, u2)
                                        : sampleUniformCone(u1, u2, 2.0f);  // the whole sphere
  }
  ray.alphaKey = rayKeyFor(scene, rng, kLightRay);
  ray.time = time;
  Hit hit;
  ++counters.bounce;
  if (!tracer.closest(ray, &hit)) return;
  SurfacePoint sp = surfaceAt(scene, ray, hit);
  const uint32_t material = materialMet(scene, sp.material, hit, sp, rng);
  const Material& m = scene.materials[material];
  if (!holdsLightVertex(m)) return;
  const Vec3 coatNormal =
      hasMaps(m) ? applyNormalMaps(scene, m, hit, &sp, -ray.direction) : Vec3(0.0f);
  lv->sp = sp;
  lv->color = surfaceColor(scene, m, hit, sp);
  lv->transmittance = isTranslucent(m) ? surfaceTransmittance(scene, m, hit, sp) : Vec3(0.0f);
  lv->roughness = surfaceRoughness(scene, m, hit, sp);
  lv->tangent = surfaceTangent(scene, m, hit, sp);
  lv->layers = hasLayers(m) ? surfaceLayers(scene, m, hit, sp, coatNormal) : SurfaceLayers();
  lv->material = material;
  lv->toLight = -ray.direction;
  lv->light = index;
  lv->area = area;
  if (!area) {
    lv->power = light.power / lightPathPmf(scene, index);
    // A spot's directions are drawn within its cone, (1 - cos cutoff) / 2 of the sphere's, and
    // weighted by its falloff.
    if (hasCone(light.spot))
      lv->power *= coneFalloff(light.spot, ray.direction) * 0.5f * coneOneMinusCos(light.spot);
    // A profile's directions are drawn uniformly (within the cone) and weighted by it.
    if (light.profile.texture >= 0)
      lv->power *= profileLookup(scene.texturePool(), light.profile, ray.direction);
    lv->pdfArea = pointLightVertexPdf(light, lightPathPmf(scene, index), sp.p, sp.ng);
  } else {
    // The subpath's density: pick / area at L, cos_L / pi towards the vertex, carried to its
    // surface by |cos_y| / d^2. What the light sends over it, less the geometry term, is then
    // radiance pi / (pick / area).
    const float startPdf = lightPathAreaPdf(scene, index, time);
    const Vec3 span = e.p - sp.p;
    const float dist2 = dot(span, span);
    lv->distance = sqrtf(dist2);
    lv->cosOverDist2 = emitCos / dist2;
    lv->lightNormal = e.n;
    lv->power = e.radiance * (kPi / startPdf);
    lv->pdfArea = startPdf * emitCos * kInvPi * fabsf(dot(sp.ng, ray.direction)) / dist2;
  }
  lv->valid = lv->pdfArea > 0.0f;
}

// The connection of interaction `sp` (whose BSDF is `bsdf` and throughput `throughput`) to the
// light vertex `lv`, as a shadow query whose contribution is weighted against next-event
// estimation from lv (the balance heuristic over the two densities of lv's point); no query where
// the connection carries nothing. The ray runs between the two points each offset off its
// surface, stopped short of the far one as shadow rays to area lights are, and keyed `key`. lv
// keeps what every connection to it shares (lightVertexNeePdf).
CANDELA_HDI void connectLightVertex(const SceneView& scene, LightVertex* vertex, const Bsdf& bsdf,
                                    const SurfacePoint& sp, const Vec3& throughput, uint32_t key,
                                    ShadowQuery* query) {
  const LightVertex& lv = *vertex;
  const Vec3 d = lv.sp.p - sp.p;
  const float dist2 = dot(d, d);
  if (!(dist2 > 0.0f)) return;
  const Vec3 wi = d / sqrtf(dist2);
  float pdfHere;
  const Vec3 fHere = evalBsdf(bsdf, wi, &pdfHere);
  if (isBlack(fHere)) return;
  const Material& m = scene.materials[lv.material];
  const Bsdf there = makeBsdf(scene, m, lv.color, lv.transmittance, lv.roughness, lv.tangent,
                              lv.layers, -wi, lv.sp.ng, lv.sp.ns, kAllChannels);
  float pdfThere;
  const Vec3 fThere = evalBsdf(there, lv.toLight, &pdfThere);
  const float cosIn = fabsf(dot(lv.sp.ng, lv.toLight)), cosOut = fabsf(dot(lv.sp.ng, wi));
  if (isBlack(fThere) || !(cosIn > 0.0f)) return;
  // Next-event estimation at lv would have reached this path with the density of x's BSDF
  // sample towards lv times lv's pick of the light (and, for a light with a surface, the density
  // of its point L from lv; lv's BSDF sample too, by its density towards L).
  const float neePdf = lightVertexNeePdf(scene, vertex);
  float weight;
  if (!lv.area) {
    const float pdfBsdf = pdfHere * cosOut / dist2 * neePdf;
    weight = misWeight3(lv.pdfArea, pdfBsdf, 0.0f, true);
  } else {
    const float toVertex = pdfHere * cosOut / dist2;
    weight = misWeight3(lv.pdfArea, toVertex * neePdf * lv.cosOverDist2,
                        toVertex * pdfThere * lv.cosOverDist2, true);
  }
  // The light's 1 / (4 pi r^2) irradiance over its density of lv leaves power / (cos_in pick).
  query->contribution =
      throughput * fHere * fThere * lv.power * (weight * cosOut / (dist2 * cosIn));
  const Vec3 from = offsetRayOrigin(sp.p, sp.error, sp.ng, wi);
  const Vec3 to = offsetRayOrigin(lv.sp.p, lv.sp.error, lv.sp.ng, -wi);
  const Vec3 span = to - from;
  const float length = sqrtf(dot(span, span));
  if (!(length > 0.0f)) return;
  query->ray.origin = from;
  query->ray.direction = span / length;
  query->ray.tMax = length * (1.0f - kShadowEpsilon);
  query->ray.alphaKey = key;
  query->ray.time = sp.time;
  query->active = true;
}

}  // namespace candela
