#include "render/scene_data.h"

#include <limits>

namespace candela {

SceneView SceneData::view() const {
  SceneView v;
#define CANDELA_VIEW_OF(Type, name, count, rewrittenBy) \
  v.name = name.data();                                 \
  v.count = uint32_t(name.size());
  CANDELA_SCENE_ARRAYS(CANDELA_VIEW_OF)
#undef CANDELA_VIEW_OF
  v.firstTriangleLight = firstTriangleLight;
  v.sampleEveryLight = sampleEveryLight;
  v.environmentShare = environmentShare;
  v.environment = environment;
  v.emissionReachable = !isBlack(environment.radiance);
  for (const Material& m : materials) v.emissionReachable |= m.type == MaterialType::Emissive;
  v.camera = camera;
  v.settings = settings;
  v.flow = flow;
  return v;
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
