#include "render/scene_data.h"

#include <algorithm>
#include <limits>
#include <utility>

#include "core/check.h"
#include "render/index_matched.h"
#include "render/light_selection.h"
#include "render/path_branch.h"

namespace candela {

SceneView SceneData::view() const {
  SceneView v;
#define CANDELA_VIEW_OF(Type, name, count, rewrittenBy) \
  v.name = name.data();                                 \
  v.count = uint32_t(name.size());
  CANDELA_SCENE_ARRAYS(CANDELA_VIEW_OF)
#undef CANDELA_VIEW_OF
  v.firstTriangleLight = firstTriangleLight;
  v.loneDeltaLight = loneDeltaLight;
  v.firstHitDeltaLights = firstHitDeltaLights;
  v.firstHitLightSamples =
      takesFirstHitLightSamples(v) ? std::max(settings.firstHitLightSamples, 1u) : 1u;
  v.lightPathLights = settings.integrator == IntegratorType::Path && settings.maxDepth >= 2 &&
                              settings.lightPaths != LightPaths::Off
                          ? lightsStartingPaths
                          : 0;
  v.lightPathDepth = settings.lightPathDepth == 0 ? kEveryInteraction : settings.lightPathDepth;
  v.glassSplitDepth = kGlassSplitDepth;
  v.infiniteLightShare = infiniteLightShare;
  v.sunDiscs = sunDiscs;
  v.environment = environment;
  v.emissionReachable = !isBlack(environment.radiance) || sunDiscs;
  v.reflectorsEmit = false;
  for (const Material& m : materials) {
    v.emissionReachable |= hasEmission(m);
    v.reflectorsEmit |= hasEmission(m) && m.type != MaterialType::Emissive;
    v.indexMatchedMedia |= isIndexMatched(m);
  }
  // A light subpath would stop at an index-matched boundary that the camera's paths and shadow
  // rays cross, so the connections' weights would miss paths that cross one.
  if (v.indexMatchedMedia) v.lightPathLights = 0;
  v.areaLightPaths = v.lightPathLights > 0 && areaLightsStartPaths;
  v.camera = camera;
  v.settings = settings;
  v.flow = flow;
  v.backwardFlow = backwardFlow;
  return v;
}

void SceneData::takeGroup(SceneData& from, RewrittenBy group) {
#define CANDELA_TAKE_GROUP_ARRAY(Type, name, count, rewrittenBy) \
  if (RewrittenBy::rewrittenBy == group) name = std::move(from.name);
  CANDELA_SCENE_ARRAYS(CANDELA_TAKE_GROUP_ARRAY)
#undef CANDELA_TAKE_GROUP_ARRAY
  switch (group) {
    case RewrittenBy::EnvironmentMap:
      environmentMapHash = from.environmentMapHash;
      environmentMapMean = from.environmentMapMean;
      environment.grid = from.environment.grid;
      break;
    case RewrittenBy::TexturePool:
      texturePoolHash = from.texturePoolHash;
      textureMeans = std::move(from.textureMeans);
      break;
    default:
      CANDELA_DCHECK(!"takeGroup: not a group kept by content");
  }
  from.clearGroup(group);  // moved-from vectors are valid but unspecified: empty them
}

void SceneData::clearGroup(RewrittenBy group) {
#define CANDELA_CLEAR_GROUP_ARRAY(Type, name, count, rewrittenBy) \
  if (RewrittenBy::rewrittenBy == group) name.clear();
  CANDELA_SCENE_ARRAYS(CANDELA_CLEAR_GROUP_ARRAY)
#undef CANDELA_CLEAR_GROUP_ARRAY
  switch (group) {
    case RewrittenBy::EnvironmentMap:
      environmentMapHash = 0;
      environmentMapMean = Vec3(0.0f);
      environment.grid = EnvironmentGrid{};
      break;
    case RewrittenBy::TexturePool:
      texturePoolHash = 0;
      textureMeans.clear();
      break;
    default:
      CANDELA_DCHECK(!"clearGroup: not a group kept by content");
  }
}

void SceneData::bounds(Vec3* lo, Vec3* hi) const {
  Vec3 a(std::numeric_limits<float>::infinity()), b(-std::numeric_limits<float>::infinity());
  for (const Sphere& sp : spheres) {
    a = min(a, sp.center - Vec3(sp.radius));
    b = max(b, sp.center + Vec3(sp.radius));
  }
  for (const Triangle& t : triangles)
    for (uint32_t k : t.v) {
      a = min(a, positions[k]);
      b = max(b, positions[k]);
    }
  *lo = a;
  *hi = b;
}

}  // namespace candela
