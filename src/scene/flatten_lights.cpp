// addEmitterLights and takeLights (scene/flatten_lights.h).
#include "scene/flatten_lights.h"

#include <algorithm>
#include <cmath>

#include "core/constants.h"
#include "geometry/primitive_bounds.h"
#include "render/light_emission.h"
#include "scene/content_hash.h"
#include "scene/flatten_environment.h"
#include "scene/light_emission_desc.h"
#include "scene/light_tree_build.h"

namespace candela {

namespace {

// The radiance material `material` emits, its texture's mean where it has one (the power the light
// tree and the light subpaths' picks weigh, which need not be exact: a bound's error costs noise,
// not bias).
Vec3 emittedRadiance(const SceneData& s, uint32_t material) {
  const Material& m = s.materials[material];
  return m.emissionTexture.index < 0 ? m.radiance
                                     : m.radiance * s.textureMeans[m.emissionTexture.index];
}

// What the light tree knows of light l: its box, the cone of its emitting normals, and the power
// it weighs the light by, the sum of its RGB power (a surface of radiance L and area A emits
// pi A L, from one side of a triangle, from all of a sphere; a two-sided triangle twice that, its
// cone every direction). A light or shape that moves while the shutter is open is bounded over
// all it sweeps, its cone every direction (it may turn); its power is the frame's pose's. The
// lights at infinity, picked apart from the tree (SceneView::infiniteLightShare), have no power
// there.
LightBounds lightBounds(const SceneData& s, const SceneView& view, const Light& l) {
  LightBounds b;
  switch (l.type) {
    case LightType::Point:
      b.lo = b.hi = b.anchor = l.position;
      b.cosThetaO = -1.0;  // every direction
      if (hasCone(l.spot) && !l.moves) {  // the tree's cones widen by 90 degrees: a bound
        b.axis = l.spot.axis;
        b.cosThetaO = l.spot.cosCutoff;
      }
      if (l.moves)  // its poses, between which it moves on straight lines
        for (uint32_t k = 0; k < view.motionTimeCount; ++k) {
          b.lo = min(b.lo, s.lightPoses[l.shape + k].position);
          b.hi = max(b.hi, s.lightPoses[l.shape + k].position);
        }
      b.power = std::max(0.0, componentSum(l.power));
      break;
    case LightType::Sphere: {
      const Sphere& sphere = s.spheres[l.shape];
      const Bounds3 box = sweptBounds(view, l.shape);
      b.lo = box.lo;
      b.hi = box.hi;
      b.anchor = sphere.center;
      b.cosThetaO = -1.0;
      const double r = sphere.radius;
      b.power = 4.0 * kPi * kPi * r * r * componentSum(emittedRadiance(s, sphere.material));
      break;
    }
    case LightType::Triangle: {
      const Triangle& t = s.triangles[l.shape];
      const Bounds3 box = sweptBounds(view, view.sphereCount + l.shape);
      b.lo = box.lo;
      b.hi = box.hi;
      const Vec3& p0 = s.positions[t.v[0]];
      b.axis = cross(s.positions[t.v[1]] - p0, s.positions[t.v[2]] - p0);  // the emitting side
      b.anchor = (p0 + s.positions[t.v[1]] + s.positions[t.v[2]]) / 3.0f;
      const bool twoSided = s.materials[t.material].twoSided;
      b.cosThetaO = twoSided || triangleMoves(view, t) ? -1.0 : 1.0;
      const double sides = twoSided ? 2.0 : 1.0;
      b.power =
          kPi * 0.5 * sides * double(length(b.axis)) * componentSum(emittedRadiance(s, t.material));
      break;
    }
    case LightType::Environment:
    case LightType::Directional:
      break;
  }
  return b;
}

bool emits(const Material& m) { return hasEmission(m); }

// A hash of the lights' bounds, field by field (LightBounds has padding): equal hashes give equal
// trees, the build being a function of the bounds alone.
uint64_t lightTreeHash(const std::vector<LightBounds>& bounds) {
  static_assert(sizeof(Vec3) == 3 * sizeof(float), "Vec3 without padding");
  uint64_t h = bounds.size();
  for (const LightBounds& b : bounds) {
    h = hashBytes(&b.lo, sizeof b.lo, h);
    h = hashBytes(&b.hi, sizeof b.hi, h);
    h = hashBytes(&b.axis, sizeof b.axis, h);
    h = hashBytes(&b.cosThetaO, sizeof b.cosThetaO, h);
    h = hashBytes(&b.power, sizeof b.power, h);
    h = hashBytes(&b.anchor, sizeof b.anchor, h);
  }
  return h;
}

// Whether triangle a comes before b in the order of their vertices' places and then materials.
bool triangleBefore(const SceneData& s, const Triangle& a, const Triangle& b) {
  for (int k = 0; k < 3; ++k) {
    const Vec3 &p = s.positions[a.v[k]], &q = s.positions[b.v[k]];
    if (p.x != q.x) return p.x < q.x;
    if (p.y != q.y) return p.y < q.y;
    if (p.z != q.z) return p.z < q.z;
  }
  return a.material < b.material;
}

// The order in which the lights' subpath picks are laid out over [0, 1): the lights as listed,
// but the triangles' (the last lights, in triangle order) by their vertices' places, which do not
// depend on the order of the triangle array: an own BVH renumbers it in its leaf order, Embree's
// engine does not, and both must map a number to the same light.
std::vector<uint32_t> lightPathOrder(const SceneData& s) {
  std::vector<uint32_t> order(s.lights.size());
  for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin() + std::min<size_t>(s.firstTriangleLight, order.size()),
                   order.end(), [&s](uint32_t a, uint32_t b) {
                     return triangleBefore(s, s.triangles[s.lights[a].shape],
                                           s.triangles[s.lights[b].shape]);
                   });
  return order;
}

// The chances that a sample's light subpath starts from each light but those at infinity, by the
// sum of its RGB power (as the light tree weighs lights; a spot's, by what leaves its cone), and
// their running sums in lightPathOrder (render/light.h).
void setLightPathPicks(SceneData& s, const std::vector<LightBounds>& bounds) {
  std::vector<double> powers;
  for (uint32_t i = 0; i < s.lights.size(); ++i) {
    const Light& l = s.lights[i];
    double power = isInfiniteLight(l.type) ? 0.0 : bounds[i].power;
    if (hasCone(l.spot))  // what leaves the cone
      power *= coneFluxShare(std::acos(double(l.spot.cosBeam)), double(l.spot.cutoff));
    powers.push_back(power);
  }
  double total = 0;
  for (const double power : powers) total += power;
  s.lightsStartingPaths = 0;
  s.areaLightsStartPaths = false;
  s.lightPathOrder.clear();
  if (!(total > 0)) {
    for (Light& l : s.lights) l.pathPmf = l.pathCdf = l.pathAreaPdf = 0.0f;
    return;
  }
  s.lightPathOrder = lightPathOrder(s);
  const std::vector<uint32_t>& order = s.lightPathOrder;
  const SceneView view = s.view();
  double sum = 0;
  uint32_t last = 0;
  for (uint32_t k = 0; k < order.size(); ++k) {
    const uint32_t i = order[k];
    Light& l = s.lights[i];
    sum += powers[i];
    l.pathPmf = float(powers[i] / total);
    l.pathCdf = float(sum / total);
    const bool area = l.type == LightType::Sphere || l.type == LightType::Triangle;
    // (A light whose shape moves takes its own at each ray's time: lightPathAreaPdf.)
    l.pathAreaPdf = area ? l.pathPmf * emissionAreaPdf(view, l, 0.0f) : 0.0f;
    if (startsLightSubpaths(l)) {
      ++s.lightsStartingPaths;
      s.areaLightsStartPaths |= area;
      last = k;
    }
  }
  // The last pick must hold every u < 1, whatever the rounding of the sums.
  for (uint32_t k = last; k < order.size(); ++k) s.lights[order[k]].pathCdf = 1.0f;
}

// The lights at infinity that send light, each picked in an equal share, as the light tree as a
// whole is (pbrt-v4's BVHLightSampler does the same): a power estimated through the scene's
// bounding sphere grows with the square of the scene's size, and a ground sphere of radius 1000
// once made the environment's a million times a lamp's.
void setInfiniteLightPicks(SceneData& s) {
  for (uint32_t i = 0; i < s.firstTriangleLight; ++i) {  // none of the triangle lights after
    const Light& l = s.lights[i];
    const bool sends = l.type == LightType::Environment ? environmentMeanRadiance(s) > 0.0
                                                        : componentSum(l.power) > 0.0;
    if (!isInfiniteLight(l.type) || !sends) continue;
    s.infiniteLights.push_back(i);
    s.sunDiscs |= hasSunDisc(l);
  }
  if (s.infiniteLights.empty()) return;
  const size_t picks = s.infiniteLights.size() + (s.lightTree.empty() ? 0 : 1);
  s.infiniteLightShare = 1.0f / float(picks);
}

}  // namespace

PreviousLights takeLights(SceneData& s) {
  PreviousLights previous;
  for (const Light& l : s.lights) previous.trails.push_back(l.trail);
  previous.tree = std::move(s.lightTree);
  previous.hash = s.lightTreeHash;
  s.lights.clear();
  s.lightTree.clear();  // moved-from: left valid but unspecified by the standard
  s.lightTreeHash = 0;
  return previous;
}

void addEmitterLights(SceneData& s, PreviousLights* previous) {
  for (uint32_t i = 0; i < s.spheres.size(); ++i) {
    Sphere& sphere = s.spheres[i];
    if (sphere.light >= 0 || !emits(s.materials[sphere.material])) continue;
    Light light;
    light.type = LightType::Sphere;
    light.shape = i;
    sphere.light = int32_t(s.lights.size());
    s.lights.push_back(light);
  }
  s.environment.light = -1;
  if (!isBlack(s.environment.radiance)) {
    Light light;
    light.type = LightType::Environment;
    s.environment.light = int32_t(s.lights.size());
    s.lights.push_back(light);
  }
  s.firstTriangleLight = uint32_t(s.lights.size());
  // Every frame that reuses the geometry comes here: a scene of millions of triangles and no
  // emissive material must not pay for a look at each triangle.
  if (std::any_of(s.materials.begin(), s.materials.end(), emits)) {
    for (uint32_t i = 0; i < s.triangles.size(); ++i) {
      if (!emits(s.materials[s.triangles[i].material])) continue;
      Light light;
      light.type = LightType::Triangle;
      light.shape = i;
      s.lights.push_back(light);
    }
  }
  s.loneDeltaLight = isLoneDeltaLight(s.lights.data(), s.lights.size());
  s.firstHitDeltaLights = firstHitDeltaLights(s.lights.data(), s.lights.size());
  std::vector<LightBounds> bounds;
  const SceneView view = s.view();
  for (const Light& l : s.lights) bounds.push_back(lightBounds(s, view, l));
  setLightPathPicks(s, bounds);
  s.lightTree.clear();
  s.lightTreeHash = 0;
  s.infiniteLights.clear();
  s.infiniteLightShare = 0.0f;
  s.sunDiscs = false;
  if (s.loneDeltaLight) return;
  s.lightTreeHash = lightTreeHash(bounds);
  if (previous && previous->hash == s.lightTreeHash) {
    s.lightTree = std::move(previous->tree);
    for (size_t i = 0; i < s.lights.size(); ++i) s.lights[i].trail = previous->trails[i];
  } else {
    std::vector<uint64_t> trails;
    s.lightTree = buildLightTree(bounds, &trails);
    for (size_t i = 0; i < s.lights.size(); ++i) s.lights[i].trail = trails[i];
  }
  setInfiniteLightPicks(s);
}

}  // namespace candela
