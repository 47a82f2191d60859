// Light-vertex connections: the second strategy by which paths reach point lights.
//
// Next-event estimation reaches a point light from the last surface y of a path whose earlier
// vertex x scattered towards y: y is found by x's BSDF sample, so where a light brightens a small
// patch of the scene (a wall beside a lamp) few of those samples find it, and indirect light
// is noisy. Each sample therefore also starts one light subpath: a point light picked by power
// emits a ray uniformly over the sphere, and its first hit y, found by the light, is connected by
// a shadow ray to every interaction x of the camera path that may scatter (as bidirectional path
// tracing's strategy s = 2 does). The two strategies are combined with the power heuristic over
// the density of y in area measure: the BSDF's at x, p(x -> y) = pdf(wi) |cos_y| / |x - y|^2,
// times the pick of the light at y; and the light's, pick(l) |cos_y'| / (4 pi r^2). Lights with
// a surface are reached by their own two strategies (render/integrator.h) and start no subpath.
#pragma once

#include <cmath>

#include "core/constants.h"
#include "core/float_error.h"
#include "core/sampling.h"
#include "core/sobol_sampler.h"
#include "geometry/surface.h"
#include "render/bsdf.h"
#include "render/light_selection.h"
#include "render/ray_counters.h"
#include "render/shadow_query.h"
#include "render/surface_color.h"

namespace candela {

// The first surface a light subpath reaches, where it can be connected: a surface with a smooth
// lobe that does not emit.
struct LightVertex {
  SurfacePoint sp;
  Vec3 color;    // the surface's colour there (textures included)
  Vec3 toLight;  // unit direction from sp.p to the light
  Vec3 power;    // the light's power over its pick probability
  uint32_t light = 0;
  float pdfArea = 0.0f;  // lightVertexPdf of the vertex
  bool valid = false;
};

// The chance that a light subpath starts from light `index`: by power, point lights alone
// (scene/flatten.cpp, setLightPathPicks).
CANDELA_HDI float lightPathPmf(const SceneView& scene, uint32_t index) {
  return scene.lights[index].pathPmf;
}

// The density, in area measure, with which a light subpath from light `index` reaches the point p
// of geometric normal ng as its first vertex: its pick, times its uniform emission 1 / (4 pi)
// carried to p's surface.
CANDELA_HDI float lightVertexPdf(const SceneView& scene, uint32_t index, const Vec3& p,
                                 const Vec3& ng) {
  const float pmf = lightPathPmf(scene, index);
  if (pmf == 0.0f) return 0.0f;
  const Vec3 d = scene.lights[index].position - p;
  const float r2 = dot(d, d);
  return pmf * (0.25f * kInvPi) * fabsf(dot(ng, d)) / (r2 * sqrtf(r2));
}

// The point light a subpath starts from, for u in [0, 1): the first whose cumulative pick
// exceeds u (lights without a pick have none to exceed it with).
CANDELA_HDI uint32_t pickLightPathLight(const SceneView& scene, float u) {
  uint32_t lo = 0, hi = scene.lightCount - 1;
  while (lo < hi) {
    const uint32_t mid = (lo + hi) / 2;
    if (scene.lights[mid].pathCdf > u)
      hi = mid;
    else
      lo = mid + 1;
  }
  return lo;
}

// Starts the sample's light subpath, from the stream's next dimensions (one for the pick where
// more than one light may start it, two for the direction), and records its first vertex in *lv
// (valid only where that surface may be connected to).
template <class Tracer>
CANDELA_HDI void traceLightVertex(const SceneView& scene, const Tracer& tracer, SampleStream& rng,
                                  RayCounters& counters, LightVertex* lv) {
  const float uPick = scene.lightPathLights > 1 ? rng.next1D() : 0.0f;
  float u1, u2;
  rng.next2D(&u1, &u2);
  const uint32_t index = pickLightPathLight(scene, uPick);
  const Light& light = scene.lights[index];
  Ray ray;
  ray.origin = light.position;
  ray.direction = sampleUniformCone(u1, u2, 2.0f);  // the whole sphere
  Hit hit;
  ++counters.bounce;
  if (!tracer.closest(ray, &hit)) return;
  const SurfacePoint sp = surfaceAt(scene, ray, hit);
  const Material& m = scene.materials[sp.material];
  if (isEmissive(m) || !hasSmoothLobe(m)) return;
  lv->sp = sp;
  lv->color = surfaceColor(scene, m, hit, sp);
  lv->toLight = -ray.direction;
  lv->light = index;
  lv->power = light.power / lightPathPmf(scene, index);
  lv->pdfArea = lightVertexPdf(scene, index, sp.p, sp.ng);
  lv->valid = lv->pdfArea > 0.0f;
}

// The connection of interaction `sp` (whose BSDF is `bsdf` and throughput `throughput`) to the
// light vertex `lv`, as a shadow query whose contribution is weighted against next-event
// estimation from lv (the power heuristic over the two densities of lv's point); no query where
// the connection carries nothing. The ray runs between the two points each offset off its
// surface, stopped short of the far one as shadow rays to area lights are.
CANDELA_HDI void connectLightVertex(const SceneView& scene, const LightVertex& lv, const Bsdf& bsdf,
                                    const SurfacePoint& sp, const Vec3& throughput,
                                    ShadowQuery* query) {
  const Vec3 d = lv.sp.p - sp.p;
  const float dist2 = dot(d, d);
  if (!(dist2 > 0.0f)) return;
  const Vec3 wi = d / sqrtf(dist2);
  float pdfHere;
  const Vec3 fHere = evalBsdf(bsdf, wi, &pdfHere);
  if (isBlack(fHere)) return;
  const Material& m = scene.materials[lv.sp.material];
  const Bsdf there = makeBsdf(m, lv.color, -wi, lv.sp.ng, lv.sp.ns);
  float pdfThere;
  const Vec3 fThere = evalBsdf(there, lv.toLight, &pdfThere);
  const float cosIn = fabsf(dot(lv.sp.ng, lv.toLight)), cosOut = fabsf(dot(lv.sp.ng, wi));
  if (isBlack(fThere) || !(cosIn > 0.0f)) return;
  // Next-event estimation at lv would have reached this path with the density of x's BSDF
  // sample towards lv times lv's pick of the light.
  const float pdfBsdf = pdfHere * cosOut / dist2 *
                        lightSelectPmf(scene, lv.light, lv.sp.p, reflectingHemisphere(there));
  const float weight = powerHeuristic(lv.pdfArea, pdfBsdf);
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
  query->active = true;
}

}  // namespace candela
