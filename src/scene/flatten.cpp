// flattenScene: SceneDesc -> SceneData (world-space arrays, resolved camera, BVH).
#include "scene/flatten.h"

#include <algorithm>
#include <map>
#include <tuple>

#include "core/rotation.h"
#include "geometry/bvh_build.h"
#include "geometry/motion.h"
#include "geometry/primitive_bounds.h"
#include "render/bsdf_sheen.h"
#include "render/material_prepare.h"
#include "render/scene_change.h"
#include "scene/camera_resolve.h"
#include "scene/content_hash.h"
#include "scene/flatten_environment.h"
#include "scene/light_emission_desc.h"
#include "scene/mesh_layout.h"
#include "scene/mesh_repeats.h"
#include "scene/model_box.h"
#include "scene/read/texture_reader.h"

namespace candela {

namespace {

uint32_t addMaterial(SceneData& s, const Material& m) {
  s.materials.push_back(m);
  return uint32_t(s.materials.size() - 1);
}

// Appends `count` materials from `first`, then `parts`, what their mixes mix, each mix's part
// indices moved to where the parts land (so that parts follow their mix: render/material_mix.h);
// returns the index of the first.
uint32_t addMaterials(SceneData& s, const Material* first, size_t count,
                      const std::vector<Material>& parts) {
  const uint32_t base = uint32_t(s.materials.size());
  s.materials.insert(s.materials.end(), first, first + count);
  const uint32_t partsBase = uint32_t(s.materials.size());
  s.materials.insert(s.materials.end(), parts.begin(), parts.end());
  for (size_t i = base; i < s.materials.size(); ++i)
    if (s.materials[i].type == MaterialType::Mix)
      for (uint32_t& p : s.materials[i].mixParts) p += partsBase;
  return base;
}

// The layouts of the meshes that a scene's objects place (scene/mesh_layout.h), one per mesh and
// use of its normals and uvs, made once however many objects place the mesh.
class MeshLayouts {
 public:
  const MeshLayout& of(const ObjectDesc& obj) {
    const MeshDesc& mesh = *obj.mesh;
    const Key key{&mesh, usesNormals(obj), usesUvs(obj)};
    auto it = layouts_.find(key);
    if (it == layouts_.end())
      it = layouts_.emplace(key, layOutMesh(mesh, key.normals, key.uvs)).first;
    return it->second;
  }

 private:
  struct Key {
    const MeshDesc* mesh;
    bool normals, uvs;
    bool operator<(const Key& o) const {
      return std::tie(mesh, normals, uvs) < std::tie(o.mesh, o.normals, o.uvs);
    }
  };
  std::map<Key, MeshLayout> layouts_;
};

// Room in s's vertex and triangle arrays for the objects' meshes and the rectangle lights, so that
// each array is written once: grown object by object, the scale scene's 8.5 M triangles spent most
// of their flattening copying and paging in the arrays' earlier sizes (docs/performance.md).
void reserveMeshes(SceneData& s, const SceneDesc& desc, MeshLayouts& layouts) {
  size_t vertices = s.positions.size(), triangles = s.triangles.size();
  for (const LightDesc& light : desc.lights)
    if (light.rectangle) {
      vertices += 4;
      triangles += 2;
    }
  bool normals = false, uvs = false, colors = false;
  for (const ObjectDesc& obj : desc.objects) {
    const MeshLayout& layout = layouts.of(obj);
    vertices += layout.vertexCount(*obj.mesh);
    triangles += layout.triangles.size();
    normals = normals || layout.withNormals;
    uvs = uvs || layout.withUvs;
    colors = colors || usesVertexColors(obj);
  }
  s.positions.reserve(vertices);
  s.triangles.reserve(triangles);
  if (normals) s.normals.reserve(vertices);
  if (uvs) s.uvs.reserve(vertices);
  if (colors) s.vertexColors.reserve(vertices);
}

// The world-space positions of an object's vertices (the mesh's, then its splits) placed at
// `position`, rotation r and `scale`, appended to *out.
template <class Positions>
void placeVertices(const MeshDesc& mesh, const MeshLayout& layout, const Vec3& position,
                   const Mat3& r, const Vec3& scale, Positions* out) {
  const size_t base = out->size();
  for (const Vec3& p : mesh.positions) out->push_back(position + r * (scale * p));
  for (uint32_t v : layout.splitSources) out->push_back((*out)[base + v]);
}

// Where each vertex of `mesh` laid out by `layout` (its own, then its splits) lies in the mesh's
// box, from 0 to 1 along each axis (0.5 along an axis the box is flat in), appended to *out: the
// object_coordinates pass's (render/object_coordinates.h).
void addObjectCoordinates(const MeshDesc& mesh, const MeshLayout& layout, PaddedVector<Vec3>* out) {
  const Bounds3 box = meshBox(mesh);  // as the poses file gives it (scene/model_box.h)
  const Vec3 lo = box.lo, hi = box.hi;
  const size_t base = out->size();
  for (const Vec3& p : mesh.positions) {
    Vec3 c(0.5f);
    for (int axis = 0; axis < 3; ++axis)
      if (hi[axis] > lo[axis]) c[axis] = (p[axis] - lo[axis]) / (hi[axis] - lo[axis]);
    out->push_back(c);
  }
  for (uint32_t v : layout.splitSources) out->push_back((*out)[base + v]);
}

// The normal of an object's vertex of corner c (rotation r, `scale`): "none" without one.
OctNormal placedNormal(const MeshDesc& mesh, const MeshLayout::Corner& c, const Mat3& r,
                       const Vec3& scale) {
  return c.n >= 0 ? encodeOctNormal(r * (mesh.normals[uint32_t(c.n)] / scale)) : OctNormal();
}

// Room in the motion arrays (geometry/geometry_view.h) for `vertexCount` vertices from `base`
// that move while the shutter is open, at `poseCount` poses each, vertex by vertex: returns
// where the first vertex's poses begin (vertex v's pose k at first + v * poseCount + k).
uint32_t addVertexMotion(SceneData& s, uint32_t base, uint32_t vertexCount, uint32_t poseCount) {
  const uint32_t first = uint32_t(s.motionPositions.size());
  s.vertexMotions.resize(base, kStill);
  for (uint32_t v = 0; v < vertexCount; ++v) s.vertexMotions.push_back(first + v * poseCount);
  s.motionPositions.resize(first + size_t(vertexCount) * poseCount);
  s.motionNormals.resize(s.motionPositions.size(), OctNormal());
  return first;
}

// The last sphere of s, which moves while the shutter is open: its place and radius at each of
// `poses` (anything with a position and a radius).
template <class Pose>
void addSphereMotion(SceneData& s, const std::vector<Pose>& poses) {
  const Sphere& sphere = s.spheres.back();
  s.sphereMotions.resize(s.spheres.size() - 1, kStill);
  s.sphereMotions.push_back(uint32_t(s.motionSpheres.size()));
  for (const Pose& pose : poses)
    s.motionSpheres.push_back(Sphere{pose.position, pose.radius, sphere.material});
}

// An object that moves while the shutter is open (ObjectDesc::shutterPoses): its vertices from
// `base` at each pose.
void addObjectMotion(SceneData& s, const ObjectDesc& obj, const MeshLayout& layout, uint32_t base) {
  const MeshDesc& mesh = *obj.mesh;
  const uint32_t vertexCount = layout.vertexCount(mesh),
                 poseCount = uint32_t(obj.shutterPoses.size());
  const uint32_t first = addVertexMotion(s, base, vertexCount, poseCount);
  std::vector<Vec3> placed;
  for (uint32_t k = 0; k < poseCount; ++k) {
    const ObjectPose& pose = obj.shutterPoses[k];
    // A mesh that moves has its vertices where they are then; its triangles, and so its layout,
    // are the mesh's at every time.
    const MeshDesc& posed = pose.mesh ? *pose.mesh : mesh;
    const Mat3 r = eulerRotation(pose.rotation);
    placed.clear();
    placeVertices(posed, layout, pose.position, r, pose.scale, &placed);
    for (uint32_t v = 0; v < vertexCount; ++v) {
      s.motionPositions[first + v * poseCount + k] = placed[v];
      if (layout.withNormals)
        s.motionNormals[first + v * poseCount + k] =
            placedNormal(posed, layout.corners[v], r, pose.scale);
    }
  }
}

// Appends an object's mesh in world space: p' = position + R (scale * p). Normals transform by
// the inverse transpose, R * (n / scale). A mirroring scale reverses the winding, so the vertex
// order is swapped to keep each face's outside where it was.
//
// The vertices are the mesh's, then its splits (scene/mesh_layout.h); a vertex of a face without
// normals gets the encoding "none" (OctNormal()), meaning "use the face normal", and one without
// uvs the uv (0, 0); one without vertex colours (of a mesh without them, or of an object that
// leaves them) the colour 1. With `geometry` false only the object's materials are appended (see
// refreshSceneValues); with it, the object's place (s.meshInstances) too, and in *flattened its
// mesh and layout (which `layouts` keeps). With `objectCoordinates` (the pass is rendered), each
// vertex's place in its object's box too.
void addObject(SceneData& s, const ObjectDesc& obj, bool geometry, bool objectCoordinates,
               MeshLayouts& layouts, FlattenedObject* flattened) {
  const MeshDesc& mesh = *obj.mesh;
  const uint32_t materialBase =
      obj.material ? addMaterials(s, &*obj.material, 1, obj.mixParts)
                   : addMaterials(s, mesh.materials.data(), mesh.materials.size(), mesh.mixParts);
  if (!geometry) return;

  const MeshLayout& layout = layouts.of(obj);
  const Mat3 r = eulerRotation(obj.rotation);
  const uint32_t base = uint32_t(s.positions.size());
  placeVertices(mesh, layout, obj.position, r, obj.scale, &s.positions);
  s.objectFirstVertex.push_back(base);
  if (!obj.shutterPoses.empty()) addObjectMotion(s, obj, layout, base);
  MeshInstance placed;
  placed.firstTriangle = uint32_t(s.triangles.size());
  placed.triangleCount = uint32_t(mesh.triangles.size());
  placed.firstVertex = base;
  placed.vertexCount = layout.vertexCount(mesh);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) placed.linear.m[i][j] = r.m[i][j] * obj.scale[j];
  placed.translation = obj.position;
  placed.moves = !obj.shutterPoses.empty();
  s.meshInstances.objects.push_back(placed);
  flattened->mesh = &mesh;
  flattened->layout = &layout;

  const bool mirrored = obj.scale.x * obj.scale.y * obj.scale.z < 0.0f;
  for (const Triangle& t : layout.triangles) {
    Triangle w;
    for (int k = 0; k < 3; ++k) w.v[k] = base + t.v[k];
    if (mirrored) std::swap(w.v[1], w.v[2]);
    w.material = obj.material ? materialBase : materialBase + t.material;
    s.triangles.push_back(w);
  }

  if (layout.withNormals) {
    s.normals.resize(base, OctNormal());  // earlier vertices without normals
    for (const MeshLayout::Corner& c : layout.corners)
      s.normals.push_back(placedNormal(mesh, c, r, obj.scale));
  }
  if (layout.withUvs) {
    s.uvs.resize(base, Vec2());  // earlier vertices without uvs
    for (const MeshLayout::Corner& c : layout.corners)
      s.uvs.push_back(c.t >= 0 ? mesh.uvs[uint32_t(c.t)] : Vec2());
  }
  if (objectCoordinates) {  // in the mesh as its file binds it, however an animation poses it
    s.objectCoordinates.resize(base, Vec3(0.0f));
    addObjectCoordinates(modelMesh(obj), layout, &s.objectCoordinates);
  }
  if (usesVertexColors(obj)) {
    s.vertexColors.resize(base, Vec3(1.0f));  // earlier vertices without colours
    s.vertexColors.insert(s.vertexColors.end(), mesh.colors.begin(), mesh.colors.end());
    for (uint32_t v : layout.splitSources) s.vertexColors.push_back(mesh.colors[v]);
  }
}

Material emitterOf(const Vec3& radiance) {
  Material emitter;
  emitter.type = MaterialType::Emissive;
  emitter.color = Vec3(0.0f);
  emitter.radiance = radiance;
  return emitter;
}

// A point or directional light that moves while the shutter is open (LightDesc::shutterPoses): its
// poses, from light->shape on in s.lightPoses (render/light_motion.h).
void addLightMotion(SceneData& s, const LightDesc& d, Light* light) {
  light->moves = true;
  light->shape = uint32_t(s.lightPoses.size());
  for (const LightDesc& pose : d.shutterPoses) {
    if (d.type == LightType::Directional) {
      s.lightPoses.push_back(LightPose{Vec3(0.0f), directionalLight(pose).direction, Vec3(0.0f),
                                       Vec3(0.0f), Vec3(0.0f)});
      continue;
    }
    const LightProfile profile = lightProfile(pose);
    s.lightPoses.push_back(
        LightPose{pose.position, spotCone(pose).axis, profile.axis, profile.c0, profile.c90});
  }
}

// A point light (a spot light: with a cone), a directional light, or a sphere light: an
// emissive sphere (of sphereLightRadiance) that names the light, which in turn names the sphere.
// A rectangle light appends only its material here: its triangles are geometry
// (addRectangleLight), made lights with every emissive triangle (addEmitterLights).
void addLight(SceneData& s, const LightDesc& d, bool geometry) {
  if (d.rectangle) {
    Material emitter = emitterOf(rectangleLightRadiance(d));
    emitter.twoSided = d.rectangle->twoSided;
    emitter.emissionTexture = d.rectangle->texture;
    emitter.hiddenFromCamera = !d.visible;
    addMaterial(s, emitter);
    return;
  }
  Light light;
  light.type = d.type;
  if (d.type == LightType::Point) {
    light.position = d.position;
    light.power = lightPower(d);
    light.spot = spotCone(d);
    light.profile = lightProfile(d);
    if (!d.shutterPoses.empty()) addLightMotion(s, d, &light);
  } else if (d.type == LightType::Directional) {
    light = directionalLight(d);
    if (!d.shutterPoses.empty()) addLightMotion(s, d, &light);
  } else {
    light.shape = uint32_t(s.spheres.size());
    Material emitter = emitterOf(sphereLightRadiance(d));
    emitter.hiddenFromCamera = !d.visible;
    s.spheres.push_back(
        Sphere{d.position, d.radius, addMaterial(s, emitter), int32_t(s.lights.size())});
    if (geometry && !d.shutterPoses.empty()) addSphereMotion(s, d.shutterPoses);
  }
  s.lights.push_back(light);
}

// A rectangle light's two triangles, of its material (`material`, as addLight appended it); with
// `objectCoordinates`, its corners' places in its square (0.5 across it).
void addRectangleLight(SceneData& s, const LightDesc& d, uint32_t material,
                       bool objectCoordinates) {
  const uint32_t base = uint32_t(s.positions.size());
  Vec3 corners[4];
  rectangleCorners(d, corners);
  s.positions.insert(s.positions.end(), corners, corners + 4);
  // Corners from the bottom left of its front, counter-clockwise (rectangleCorners).
  if (d.rectangle->texture.index >= 0 || !s.uvs.empty()) {
    s.uvs.resize(base, Vec2());  // earlier vertices without uvs
    s.uvs.insert(s.uvs.end(),
                 {Vec2(0.0f, 0.0f), Vec2(1.0f, 0.0f), Vec2(1.0f, 1.0f), Vec2(0.0f, 1.0f)});
  }
  if (objectCoordinates) {
    s.objectCoordinates.resize(base, Vec3(0.0f));
    s.objectCoordinates.insert(s.objectCoordinates.end(),
                               {Vec3(0.0f, 0.0f, 0.5f), Vec3(1.0f, 0.0f, 0.5f),
                                Vec3(1.0f, 1.0f, 0.5f), Vec3(0.0f, 1.0f, 0.5f)});
  }
  s.triangles.push_back(Triangle{{base, base + 1, base + 2}, material});
  s.triangles.push_back(Triangle{{base, base + 2, base + 3}, material});
  if (d.shutterPoses.empty()) return;
  // One that moves while the shutter is open: its corners at each pose.
  const uint32_t poseCount = uint32_t(d.shutterPoses.size());
  const uint32_t first = addVertexMotion(s, base, 4, poseCount);
  for (uint32_t k = 0; k < poseCount; ++k) {
    rectangleCorners(d.shutterPoses[k], corners);
    for (uint32_t v = 0; v < 4; ++v) s.motionPositions[first + v * poseCount + k] = corners[v];
  }
}

// The texture pool and its sRGB table (only when used).
void addTexturePool(SceneData& s, const SceneDesc& desc) {
  for (const std::shared_ptr<const TextureDesc>& t : desc.textures) {
    Texture texture;
    texture.width = t->width;
    texture.height = t->height;
    texture.format = t->format;
    std::vector<float>& floats = s.texelsF;
    std::vector<uint8_t>& bytes = s.texels8;
    const bool isFloat = t->format == TextureFormat::Float;
    texture.offset = uint32_t(isFloat ? floats.size() : bytes.size());
    if (isFloat)
      floats.insert(floats.end(), t->texelsF.begin(), t->texelsF.end());
    else
      bytes.insert(bytes.end(), t->texels8.begin(), t->texels8.end());
    s.textures.push_back(texture);
  }
  if (!s.textures.empty())
    for (int i = 0; i < 256; ++i) s.srgbToLinear.push_back(srgbToLinearValue(float(i) / 255.0f));
}

// What the materials make of the pool: the means of emission textures, and the alpha masks
// (only when some material has one).
void addTextureUses(SceneData& s) {
  // Only emission textures weigh light selection: colour textures, the usual and the large ones,
  // are never walked. A mean, once taken, stays with the pool. Each texel's centre looks that
  // texel up exactly.
  s.textureMeans.resize(s.textures.size(), Vec3(-1.0f));  // -1: not taken
  const TexturePool pool = s.view().texturePool();
  for (const Material& m : s.materials) {
    const int32_t i = m.emissionTexture.index;
    if (i < 0 || s.textureMeans[i].x >= 0.0f) continue;
    const Texture& t = s.textures[i];
    TextureRef ref;
    ref.index = i;
    double sum[3] = {0.0, 0.0, 0.0};
    for (uint32_t y = 0; y < t.height; ++y)
      for (uint32_t x = 0; x < t.width; ++x) {
        const Vec3 c = lookupTexture(pool, ref, (x + 0.5f) / float(t.width),
                                     1.0f - (y + 0.5f) / float(t.height))
                           .rgb;
        for (int k = 0; k < 3; ++k) sum[k] += c[k];
      }
    const double n = double(t.width) * t.height;
    s.textureMeans[i] = Vec3(float(sum[0] / n), float(sum[1] / n), float(sum[2] / n));
  }
  const auto masked = [](const Material& m) { return isMasked(m.alpha); };
  if (std::any_of(s.materials.begin(), s.materials.end(), masked))
    for (const Material& m : s.materials) s.alphaMasks.push_back(m.alpha);
}

// The motion arrays' last touches where something moves while the shutter is open: the times,
// and the vertices and spheres after the last moving one marked still.
void addMotionTimes(SceneData& s, const SceneDesc& desc) {
  if (s.vertexMotions.empty() && s.sphereMotions.empty() && s.lightPoses.empty()) return;
  s.motionTimes.assign(desc.shutterTimes.begin(), desc.shutterTimes.end());
  if (!s.vertexMotions.empty()) s.vertexMotions.resize(s.positions.size(), kStill);
  if (!s.sphereMotions.empty()) s.sphereMotions.resize(s.spheres.size(), kStill);
  if (s.normals.empty()) s.motionNormals.clear();
}

// The materials appended since the last call belong to instance `instance` (docs/aovs.md).
void tagInstance(SceneData& s, uint32_t instance) {
  s.materialInstances.resize(s.materials.size(), instance);
}

// The primitives and their materials, each material tagged with its instance; mesh vertices and
// triangles only with `geometry`. The order of materials depends only on the scene's structure,
// so triangles keep valid material indices when a refresh re-appends the materials.
void addInstances(SceneData& s, const SceneDesc& desc, bool geometry) {
  const InstanceNumbering number = instanceNumbering(desc);
  for (uint32_t i = 0; i < desc.spheres.size(); ++i) {
    const SphereDesc& sd = desc.spheres[i];
    s.spheres.push_back(
        Sphere{sd.position, sd.radius, addMaterials(s, &sd.material, 1, sd.mixParts)});
    tagInstance(s, number.firstSphere + i);
    if (geometry && !sd.shutterPoses.empty()) addSphereMotion(s, sd.shutterPoses);
  }
  // Lights after plain spheres: sphere lights append their own emissive spheres.
  std::vector<uint32_t> lightMaterials;  // of each light, where it has one
  for (uint32_t i = 0; i < desc.lights.size(); ++i) {
    lightMaterials.push_back(uint32_t(s.materials.size()));
    addLight(s, desc.lights[i], geometry);
    tagInstance(s, number.firstLight + i);
  }
  std::vector<FlattenedObject> flattened(desc.objects.size());
  MeshLayouts layouts;  // kept until the repeats are found: `flattened` points into it
  if (geometry) reserveMeshes(s, desc, layouts);
  for (uint32_t i = 0; i < desc.objects.size(); ++i) {
    addObject(s, desc.objects[i], geometry, desc.objectCoordinatesPass, layouts, &flattened[i]);
    tagInstance(s, number.firstObject + i);
  }
  if (geometry)  // after the objects', which the objects' places (s.meshInstances) count from
    for (uint32_t i = 0; i < desc.lights.size(); ++i)
      if (desc.lights[i].rectangle)
        addRectangleLight(s, desc.lights[i], lightMaterials[i], desc.objectCoordinatesPass);
  // Only where no own BVH will reorder the triangles (which voids the objects' places): an
  // engine of its own traces the scene.
  if (geometry) {
    if (desc.ownBvh == OwnBvh::None)
      findRepeatedMeshes(s, flattened);
    else
      s.meshInstances = MeshInstances();
  }
  // Vertices after the last smooth (or textured) mesh have no normals (or uvs) either.
  if (geometry && !s.normals.empty()) s.normals.resize(s.positions.size(), OctNormal());
  if (geometry && !s.uvs.empty()) s.uvs.resize(s.positions.size(), Vec2());
  if (geometry && !s.vertexColors.empty()) s.vertexColors.resize(s.positions.size(), Vec3(1.0f));
  if (geometry && desc.objectCoordinatesPass)
    s.objectCoordinates.resize(s.positions.size(), Vec3(0.0f));
  if (geometry) addMotionTimes(s, desc);
}

// The coat tables by roughness level, one per index of refraction, of the plastics whose
// roughness is textured and of the clear coats whose roughness is.
void addPlasticCoats(SceneData& s) {
  std::map<float, int32_t> offsets;
  const auto tableOf = [&](float ior) {
    auto found = offsets.find(ior);
    if (found == offsets.end()) {
      found = offsets.emplace(ior, int32_t(s.plasticCoats.size())).first;
      const std::vector<float> table = plasticCoatTable(ior);
      s.plasticCoats.insert(s.plasticCoats.end(), table.begin(), table.end());
    }
    return found->second;
  };
  for (Material& m : s.materials) {
    if (m.type == MaterialType::Plastic && m.roughnessTexture.index >= 0)
      m.plasticCoatTable = tableOf(m.ior);
    if (m.coatWeight > 0.0f && m.coatRoughnessTexture.index >= 0) m.coatTable = tableOf(m.coatIor);
  }
}

// The range of the values of `channel` (core/texture.h's textureChannel) over texture t's texels,
// at most 1: all that a lookup of it, which blends neighbouring texels, can return.
std::pair<float, float> channelRange(const TextureDesc& t, uint32_t channel) {
  float lo = 1.0f, hi = 0.0f;
  for (size_t i = 0; i < size_t(t.width) * t.height; ++i) {
    const float v =
        channel == kLuminanceChannel
            ? textureLuminance(Vec3(texelValue(t, i, 0), texelValue(t, i, 1), texelValue(t, i, 2)))
            : texelValue(t, i, channel);
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  return {std::min(lo, 1.0f), std::min(hi, 1.0f)};
}

// The sheen's tables by roughness level where some sheen's roughness is textured: the levels its
// textures' values reach, and the next (render/surface_layers.h reads a level and the one after).
void addSheenTables(SceneData& s, const SceneDesc& desc) {
  uint32_t first = kSheenLevels, last = 0;
  for (const Material& m : s.materials) {
    if (!hasSheen(m) || m.sheenRoughnessTexture.index < 0) continue;
    const auto [lo, hi] = channelRange(*desc.textures[size_t(m.sheenRoughnessTexture.index)],
                                       m.sheenRoughnessChannel);
    first = std::min(first, uint32_t(sheenLevelAt(lo)));
    last = std::max(last, uint32_t(sheenLevelAt(hi)) + 1);
  }
  if (first < kSheenLevels) s.sheenTables = sheenLevelTables(first, last);
}

// The render's pixels are the crop's, each drawing the samples it has in the whole image.
void cropCamera(const std::optional<CameraCrop>& crop, Camera& camera) {
  if (!crop) return;
  camera.imageWidth = camera.width;
  camera.windowX = crop->x;
  camera.windowY = crop->y;
  camera.width = crop->width;
  camera.height = crop->height;
}

// Everything but the BVH; mesh vertices and triangles only with `geometry`, the texture pool
// only with `texturePool`.
void addContents(SceneData& s, const SceneDesc& desc, bool geometry, bool texturePool) {
  addInstances(s, desc, geometry);
  addPlasticCoats(s);
  addSheenTables(s, desc);
  if (texturePool) addTexturePool(s, desc);
  addTextureUses(s);

  flattenEnvironment(desc.environment, s);
  s.camera = resolveCamera(desc.camera, desc.file);
  s.cameraPoses = shutterPoses(desc);
  if (!s.cameraPoses.empty() || !s.motionTimes.empty()) {
    s.camera.shutterRowShare = desc.shutterRowExposure;
    s.camera.shutterRowSlope = (1.0f - desc.shutterRowExposure) / float(s.camera.height);
  }
  cropCamera(desc.camera.crop, s.camera);
  s.settings = desc.render;
}

}  // namespace

InstanceNumbering instanceNumbering(const SceneDesc& desc) {
  InstanceNumbering n;
  n.firstObject = n.firstSphere + uint32_t(desc.spheres.size());
  n.firstLight = n.firstObject + uint32_t(desc.objects.size());
  return n;
}

std::vector<std::pair<uint32_t, std::string>> instanceNames(const SceneDesc& desc) {
  std::vector<std::pair<uint32_t, std::string>> names;
  const auto add = [&names](uint32_t first, const char* list, size_t i, const std::string& id) {
    names.emplace_back(first + uint32_t(i),
                       !id.empty() ? id : std::string(list) + "[" + std::to_string(i) + "]");
  };
  const InstanceNumbering number = instanceNumbering(desc);
  for (size_t i = 0; i < desc.spheres.size(); ++i)
    add(number.firstSphere, "spheres", i, desc.spheres[i].id);
  for (size_t i = 0; i < desc.objects.size(); ++i)
    add(number.firstObject, "objects", i, desc.objects[i].id);
  for (size_t i = 0; i < desc.lights.size(); ++i)
    add(number.firstLight, "lights", i, desc.lights[i].id);
  return names;
}

SceneData flattenPassContext(const SceneDesc& desc) {
  SceneData s;
  addInstances(s, desc, false);
  s.camera = resolveCamera(desc.camera, desc.file);
  cropCamera(desc.camera.crop, s.camera);
  s.settings = desc.render;
  return s;
}

void refreshSceneValues(SceneData& s, const SceneDesc& desc) {
  PreviousLights previous = takeLights(s);
  s.materials.clear();
  s.materialInstances.clear();
  s.plasticCoats.clear();
  s.sheenTables.clear();
  s.spheres.clear();
  s.alphaMasks.clear();
  addContents(s, desc, false, false);  // the frame's textures are the last frame's (equal keys)
  addEmitterLights(s, &previous);
}

namespace {

// Of the content hashes of the description's textures, in order.
uint64_t texturePoolHash(const SceneDesc& desc) {
  std::vector<uint64_t> hashes;
  for (const std::shared_ptr<const TextureDesc>& t : desc.textures)
    hashes.push_back(textureHash(*t));
  return hashVector(hashes);
}

}  // namespace

SceneData flattenSceneContents(const SceneDesc& desc, SceneData* previous) {
  SceneData s;
  const uint64_t poolHash = texturePoolHash(desc);
  const bool keepPool = previous && previous->texturePoolHash == poolHash;
  if (keepPool) s.takeGroup(*previous, RewrittenBy::TexturePool);
  s.texturePoolHash = poolHash;
  // flattenEnvironment keeps them when the map is the same.
  if (previous) s.takeGroup(*previous, RewrittenBy::EnvironmentMap);
  addContents(s, desc, true, !keepPool);
  return s;
}

// Renumbers the triangles in the order the BVH's leaves list them (primIndices, depth first), so
// that a leaf's triangles share cache lines and leaves visited together lie together: the load of
// a leaf's triangle was the hottest cache miss in traversal. Triangles that move, which the BVH
// leaves to the motion BVH, follow in their order.
void orderTrianglesByLeaf(SceneData& s) {
  const uint32_t sphereCount = uint32_t(s.spheres.size());
  std::vector<Triangle> ordered;
  ordered.reserve(s.triangles.size());
  for (uint32_t& prim : s.primIndices) {
    if (prim < sphereCount) continue;
    ordered.push_back(s.triangles[prim - sphereCount]);
    prim = sphereCount + uint32_t(ordered.size() - 1);
  }
  if (!s.vertexMotions.empty()) {
    const GeometryView view = s.view();
    for (const Triangle& t : s.triangles)
      if (triangleMoves(view, t)) ordered.push_back(t);
  }
  s.triangles = std::move(ordered);
}

namespace {

// The BVH `kind` over a flattened scene's contents (those that stand still, where some move),
// then the triangles in its leaf order.
void addBvh(SceneData& s, OwnBvh kind) {
  if (kind == OwnBvh::None) return;
  BvhBuildResult bvh;
  if (s.motionTimes.empty()) {
    bvh = (kind == OwnBvh::Flat ? buildFlatBvh : buildBvh)(
        s.spheres.data(), uint32_t(s.spheres.size()), s.positions.data(), s.triangles.data(),
        uint32_t(s.triangles.size()));
  } else {  // the SAH build, whatever `kind` (a flat tree serves benchmarks of still scenes)
    std::vector<Bounds3> boxes;
    std::vector<uint32_t> prims;
    partBoxes(s.view(), false, 0, &boxes, &prims);
    bvh = buildBvhOfBoxes(boxes.data(), prims.data(), uint32_t(prims.size()));
  }
  s.nodes = std::move(bvh.wideNodes);
  s.primIndices = std::move(bvh.primIndices);
  orderTrianglesByLeaf(s);
  s.bvh.nodeCount = uint32_t(s.nodes.size());
  s.bvh.leafCount = bvh.leafCount;
  s.bvh.maxDepth = bvh.maxDepth;
  s.bvh.buildSeconds = bvh.buildSeconds;
}

// The motion BVHs over the primitives that move while the shutter is open (geometry/motion.h),
// one for each step between two poses, whatever engine traces the rest: a box over the whole
// exposure would hold a turning mesh's whole arc.
void addMotionBvh(SceneData& s) {
  s.motionNodes.clear();
  s.motionRoots.clear();
  s.motionPrimIndices.clear();
  // (Where only point and directional lights move, no primitive does.)
  if (s.motionTimes.empty() || (s.vertexMotions.empty() && s.sphereMotions.empty())) return;
  for (uint32_t k = 0; k + 1 < s.motionTimes.size(); ++k) {
    std::vector<Bounds3> boxes;
    std::vector<uint32_t> prims;
    partBoxes(s.view(), true, k, &boxes, &prims);
    const BvhBuildResult bvh = buildBvhOfBoxes(boxes.data(), prims.data(), uint32_t(prims.size()));
    const uint32_t nodeBase = uint32_t(s.motionNodes.size());
    const uint32_t primBase = uint32_t(s.motionPrimIndices.size());
    s.motionRoots.push_back(nodeBase);
    for (BvhNode node : bvh.wideNodes) {
      for (int c = 0; c < 4; ++c) {
        if (node.count[c] != 0)
          node.child[c] += primBase;
        else if (node.child[c] != kNoBvhChild)
          node.child[c] += nodeBase;
      }
      s.motionNodes.push_back(node);
    }
    s.motionPrimIndices.insert(s.motionPrimIndices.end(), bvh.primIndices.begin(),
                               bvh.primIndices.end());
  }
}

}  // namespace

SceneData flattenScene(const SceneDesc& desc) { return flattenScene(desc, nullptr, nullptr); }

void addBvhAndLights(SceneData& s, OwnBvh kind, PreviousLights* lights) {
  addBvh(s, kind);
  addMotionBvh(s);
  addEmitterLights(s, lights);
}

SceneData flattenScene(const SceneDesc& desc, SceneData* previous, PreviousLights* lights) {
  SceneData s = flattenSceneContents(desc, previous);
  addBvhAndLights(s, desc.ownBvh, lights);
  return s;
}

SceneData flattenScene(SceneDesc&& desc) {
  SceneData s = flattenSceneContents(desc);
  for (ObjectDesc& object : desc.objects) object.mesh = std::make_shared<const MeshDesc>();
  addBvhAndLights(s, desc.ownBvh, nullptr);
  return s;
}

std::vector<Vec3> placedVertices(const ObjectDesc& obj, const ObjectDesc& laidOutAs) {
  const MeshLayout layout = layOutMesh(*obj.mesh, usesNormals(laidOutAs), usesUvs(laidOutAs));
  std::vector<Vec3> placed;
  placeVertices(*obj.mesh, layout, obj.position, eulerRotation(obj.rotation), obj.scale, &placed);
  return placed;
}

}  // namespace candela
