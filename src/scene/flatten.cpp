// flattenScene: SceneDesc -> SceneData (world-space arrays, resolved camera, BVH).
#include <algorithm>
#include <limits>

#include "core/constants.h"
#include "core/rotation.h"
#include "geometry/bvh_build.h"
#include "scene/camera_resolve.h"
#include "scene/scene_data.h"

namespace candela {

namespace {

Material toMaterial(const MaterialDesc& d) {
  Material m;
  m.type = d.type;
  m.color = d.color;
  m.ior = d.ior;
  m.radiance = d.radiance;
  return m;
}

uint32_t addMaterial(SceneData& s, const Material& m) {
  s.materials.push_back(m);
  return uint32_t(s.materials.size() - 1);
}

// Appends an object's mesh in world space: p' = position + R (scale * p). Normals transform by
// the inverse transpose, R * (n / scale). A mirroring scale reverses the winding, so the vertex
// order is swapped to keep each face's outside where it was.
// With `geometry` false only the object's materials are appended (see refreshSceneValues).
void addObject(SceneData& s, const ObjectDesc& obj, bool geometry) {
  const MeshDesc& mesh = obj.mesh;
  uint32_t materialBase = 0;
  if (obj.material) {
    materialBase = addMaterial(s, toMaterial(*obj.material));
  } else {
    materialBase = uint32_t(s.materials.size());
    for (const MaterialDesc& m : mesh.materials) s.materials.push_back(toMaterial(m));
  }
  if (!geometry) return;

  const Mat3 r = eulerRotation(obj.rotation);
  const uint32_t positionBase = uint32_t(s.positions.size());
  const uint32_t normalBase = uint32_t(s.normals.size());
  for (const Vec3& p : mesh.positions) s.positions.push_back(obj.position + r * (obj.scale * p));
  if (obj.smooth)
    for (const Vec3& n : mesh.normals) s.normals.push_back(normalize(r * (n / obj.scale)));

  const bool mirrored = obj.scale.x * obj.scale.y * obj.scale.z < 0.0f;
  for (const Triangle& t : mesh.triangles) {
    Triangle w;
    for (int k = 0; k < 3; ++k) {
      w.v[k] = positionBase + t.v[k];
      w.n[k] = (obj.smooth && t.n[k] >= 0) ? int32_t(normalBase + uint32_t(t.n[k])) : -1;
    }
    if (mirrored) {
      std::swap(w.v[1], w.v[2]);
      std::swap(w.n[1], w.n[2]);
    }
    w.material = obj.material ? materialBase : materialBase + t.material;
    s.triangles.push_back(w);
  }
}

void addLight(SceneData& s, const LightDesc& d) {
  Light light;
  light.type = d.type;
  light.position = d.position;
  light.radius = d.radius;
  light.power = d.color * d.intensity;
  if (d.type == LightType::Sphere) {
    light.radiance = light.power / (4.0f * kPi * kPi * d.radius * d.radius);
    Material emitter;
    emitter.type = MaterialType::Emissive;
    emitter.color = Vec3(0.0f);
    emitter.radiance = light.radiance;
    emitter.lightIndex = int32_t(s.lights.size());
    light.sphere = uint32_t(s.spheres.size());
    s.spheres.push_back(Sphere{d.position, d.radius, addMaterial(s, emitter)});
  }
  s.lights.push_back(light);
}

// Everything but the BVH; mesh vertices and triangles only with `geometry`. The order of
// materials depends only on the scene's structure, so triangles keep valid material indices
// when a refresh re-appends the materials.
void addContents(SceneData& s, const SceneDesc& desc, bool geometry) {
  for (const SphereDesc& sd : desc.spheres)
    s.spheres.push_back(Sphere{sd.position, sd.radius, addMaterial(s, toMaterial(sd.material))});
  // Lights after plain spheres: sphere lights append their own emissive spheres.
  for (const LightDesc& ld : desc.lights) addLight(s, ld);
  for (const ObjectDesc& od : desc.objects) addObject(s, od, geometry);

  s.environment = desc.environment;
  s.camera = resolveCamera(desc.camera, desc.file);
  s.settings = desc.render;
}

}  // namespace

void refreshSceneValues(SceneData& s, const SceneDesc& desc) {
  s.materials.clear();
  s.spheres.clear();
  s.lights.clear();
  addContents(s, desc, false);
}

SceneData flattenScene(const SceneDesc& desc) {
  SceneData s;
  addContents(s, desc, true);

  BvhBuildResult bvh = buildBvh(s.spheres.data(), uint32_t(s.spheres.size()), s.positions.data(),
                                s.triangles.data(), uint32_t(s.triangles.size()));
  s.nodes = std::move(bvh.nodes);
  s.primIndices = std::move(bvh.primIndices);
  s.bvh.nodeCount = uint32_t(s.nodes.size());
  s.bvh.leafCount = bvh.leafCount;
  s.bvh.maxDepth = bvh.maxDepth;
  s.bvh.buildSeconds = bvh.buildSeconds;
  return s;
}

SceneView SceneData::view() const {
  SceneView v;
  v.materials = materials.data();
  v.spheres = spheres.data();
  v.positions = positions.data();
  v.normals = normals.data();
  v.triangles = triangles.data();
  v.lights = lights.data();
  v.nodes = nodes.data();
  v.primIndices = primIndices.data();
  v.materialCount = uint32_t(materials.size());
  v.sphereCount = uint32_t(spheres.size());
  v.positionCount = uint32_t(positions.size());
  v.normalCount = uint32_t(normals.size());
  v.triangleCount = uint32_t(triangles.size());
  v.lightCount = uint32_t(lights.size());
  v.nodeCount = uint32_t(nodes.size());
  v.environment = environment;
  v.camera = camera;
  v.settings = settings;
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
