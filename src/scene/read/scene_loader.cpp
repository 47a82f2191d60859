// The scene loader's top level; see scene_loader.h.
#include "scene/read/scene_loader.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <tuple>
#include <vector>

#include "scene/camera_resolve.h"
#include "scene/mesh_layout.h"
#include "scene/mesh_order.h"
#include "scene/read/animation_reader.h"
#include "scene/read/camera_reader.h"
#include "scene/read/entity_reader.h"
#include "scene/read/environment_reader.h"
#include "scene/read/gltf_loader.h"
#include "scene/read/gltf_mesh_motion.h"
#include "scene/read/gltf_nodes.h"
#include "scene/read/gltf_object_animation.h"
#include "scene/read/gltf_scene.h"
#include "scene/read/gltf_variants.h"
#include "scene/read/json_parse.h"
#include "scene/read/material_reader.h"
#include "scene/read/obj_loader.h"
#include "scene/read/ply_loader.h"
#include "scene/read/reflectance_check.h"
#include "scene/read/render_reader.h"
#include "scene/read/scene_limits.h"
#include "scene/read/text_file.h"
#include "scene/scene_error.h"
#include "scene/shape_meshes.h"
#include "scene/vertex_normals.h"

namespace candela {
namespace {

// Ids name spheres, objects and lights for animation and messages, so they must be unique.
class IdRegistry {
 public:
  void add(const std::string& id, const std::string& where, const std::string& file) {
    if (id.empty()) return;
    const auto inserted = places_.emplace(id, where);
    if (!inserted.second)
      failAt(file, memberPath(where, "id"),
             "duplicate id " + quoted(id) + ", already used by " + inserted.first->second);
  }

 private:
  std::map<std::string, std::string> places_;  // id -> JSON path of its owner
};

// Each element of the array under `key`, read by `read`.
template <typename Read>
void forEachElement(JsonObject& top, const std::string& key, Read read) {
  if (std::optional<JsonValue> array = top.get(key))
    for (const JsonValue& element : array->elements()) read(element);
}

// An object that gives `smooth` a crease angle takes its mesh with normals computed for the faces
// its file gives none; objects that place one file at one angle share that mesh.
void shadeFacesWithoutNormals(SceneDesc& scene) {
  std::map<std::pair<const MeshDesc*, float>, std::shared_ptr<const MeshDesc>> shaded;
  for (ObjectDesc& object : scene.objects) {
    const MeshDesc& mesh = *object.mesh;
    if (!object.smooth || object.creaseDegrees <= 0 ||
        std::none_of(mesh.triangles.begin(), mesh.triangles.end(),
                     [](const MeshTriangle& t) { return t.n[0] < 0; }))
      continue;
    std::shared_ptr<const MeshDesc>& made = shaded[{&mesh, object.creaseDegrees}];
    if (!made)
      made = std::make_shared<const MeshDesc>(withComputedNormals(mesh, object.creaseDegrees));
    object.mesh = made;
  }
}

// Object `index` that plays a glTF animation gets the motion of its mesh, where the animation
// moves any vertex of it (its motion of the object's node is the object's tracks:
// gltf_object_animation.h); `rig` poses the mesh as loaded. In a scene without an animation
// block it takes the mesh as posed at its clock's start instead.
void playGltfAnimation(SceneDesc& scene, size_t index, const std::string& writtenName,
                       const std::shared_ptr<GltfRig>& rig) {
  ObjectDesc& object = scene.objects[index];
  if (!object.gltfAnimated) return;
  const std::string where = memberPath(object.where, "gltf_animation");
  try {
    object.meshMotion = gltfMeshMotion(object, writtenName, object.mesh, rig);
  } catch (const SceneError& error) {
    failAt(scene.file, where, error.what());
  }
  if (!object.meshMotion) return;
  object.restMesh = object.mesh;
  if (scene.animation) {
    scene.animation->meshesMove = true;
    return;
  }
  // A still scene: the mesh as the animation has it at time 0 of the object's clock (its start).
  object.mesh = object.meshMotion->meshAt(0.0);
  object.meshMotion.reset();
}

// Whether two paths name one file (as far as they exist; else as written).
bool sameFile(const std::string& a, const std::string& b) {
  if (a.empty() || b.empty()) return false;
  std::error_code error;
  const std::filesystem::path ca = std::filesystem::weakly_canonical(a, error);
  const std::filesystem::path cb = std::filesystem::weakly_canonical(b, error);
  return error ? a == b : ca == cb;
}

// The mesh files (OBJ, PLY or glTF) named by the scene's objects, each read once however many
// objects use it and its triangles put in spatial order (scene/mesh_order.h). A failure is reported
// at the object's "file" key, with the file as the scene wrote it.
void loadMeshes(SceneDesc& scene, const std::vector<std::string>& writtenNames,
                TextureLoader& textures) {
  // (resolved path, glTF variant, glTF node or OBJ group, shape, played) -> its mesh, and for one
  // that an object plays an animation of, what poses it
  struct Loaded {
    std::shared_ptr<const MeshDesc> mesh;
    std::shared_ptr<GltfRig> rig;
  };
  std::map<std::tuple<std::string, std::string, std::string, std::string, bool>, Loaded> loaded;
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    ObjectDesc& object = scene.objects[i];
    const auto key =
        std::make_tuple(object.file, object.gltfVariant, object.gltfNode + object.objGroup,
                        object.shape, object.gltfAnimated);
    const auto previous = loaded.find(key);
    if (previous != loaded.end()) {
      object.mesh = previous->second.mesh;
      playGltfAnimation(scene, i, writtenNames[i], previous->second.rig);
      continue;
    }
    std::shared_ptr<GltfRig> rig;
    try {
      MeshDesc mesh = !object.shape.empty()    ? shapeMesh(object.shape)
                      : isPlyPath(object.file) ? loadPlyFile(object.file, writtenNames[i])
                      : isGltfPath(object.file)
                          ? loadGltfFile(object.file, writtenNames[i], textures, object.gltfVariant,
                                         object.gltfNode, object.gltfAnimated ? &rig : nullptr)
                          : loadObjFile(object.file, writtenNames[i], textures, object.objGroup);
      orderTrianglesSpatially(&mesh);
      object.mesh = std::make_shared<const MeshDesc>(std::move(mesh));
    } catch (const GltfVariantError& error) {
      failAt(scene.file, memberPath(object.where, "gltf_variant"),
             writtenNames[i] + ": " + error.what());
    } catch (const ObjGroupError& error) {
      failAt(scene.file, memberPath(object.where, "obj_group"),
             writtenNames[i] + ": " + error.what());
    } catch (const GltfNodeError& error) {
      failAt(scene.file, memberPath(object.where, "gltf_node"),
             writtenNames[i] + ": " + error.what());
    } catch (const SceneError& error) {
      failAt(scene.file, memberPath(object.where, "file"), error.what());
    }
    loaded.emplace(key, Loaded{object.mesh, rig});
    playGltfAnimation(scene, i, writtenNames[i], rig);
  }
  // A mesh's warnings concern its own materials: each is given once, at the first object that
  // takes its materials from the file.
  std::set<const MeshDesc*> warned;
  for (const ObjectDesc& object : scene.objects) {
    if (object.material || !warned.insert(object.mesh.get()).second) continue;
    for (const std::string& warning : object.mesh->warnings)
      scene.warnings.push_back(scene.file + ": " + memberPath(object.where, "file") + ": " +
                               warning);
  }
  // A glTF file's cameras and lights, once per file, unless the scene's camera or lights take
  // them.
  std::set<const MeshDesc*> cameras, lights;
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const ObjectDesc& object = scene.objects[i];
    const std::string where = scene.file + ": " + memberPath(object.where, "file") + ": " +
                              writtenNames[i] + ": the file's ";
    if (object.mesh->holdsCameras && !sameFile(object.file, scene.camera.gltfFile) &&
        cameras.insert(object.mesh.get()).second)
      scene.warnings.push_back(where +
                               "cameras are not used (the scene's camera takes one with "
                               "\"gltf\")");
    const bool lightsTaken =
        std::any_of(scene.lights.begin(), scene.lights.end(),
                    [&](const LightDesc& light) { return sameFile(object.file, light.gltfFile); });
    if (object.mesh->holdsLights && !lightsTaken && lights.insert(object.mesh.get()).second)
      scene.warnings.push_back(where +
                               "lights (KHR_lights_punctual) are not used (the scene's "
                               "lights take them with {\"gltf\": file})");
  }
  // A texture on a mesh without texture coordinates reads one texel everywhere: a flat colour,
  // surely not what was meant (a file exported without `vt`); an anisotropic material has no
  // tangent to follow. Once per file for its own materials, as above, and per object for a
  // material the scene gives it.
  std::set<const MeshDesc*> flat;
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const ObjectDesc& object = scene.objects[i];
    const MeshDesc& mesh = *object.mesh;
    if (!mesh.uvs.empty()) continue;
    const bool textured = anyMaterialOf(object, readsTextures);
    if (!anyMaterialOf(object, readsUvs) || (!object.material && !flat.insert(&mesh).second))
      continue;
    scene.warnings.push_back(
        scene.file + ": " + object.where + ": " +
        (object.material ? "its material" : "a material of " + writtenNames[i]) +
        (textured ? " has a texture, but " : " is anisotropic, but ") + writtenNames[i] +
        " has no texture coordinates (\"vt\"): " +
        (textured ? "the texel at uv (0, 0) covers the whole surface"
                  : "its roughness follows a tangent that the normal alone gives"));
  }
  shadeFacesWithoutNormals(scene);
}

}  // namespace

SceneDesc parseSceneText(const std::string& text, const std::string& fileLabel,
                         const std::string& baseDir) {
  const Json document = parseJson(text, fileLabel);
  JsonObject top(
      JsonValue(document, fileLabel, ""),
      {"camera", "render", "materials", "spheres", "objects", "lights", "environment", "animation"},
      "an object at the top level");

  SceneDesc scene;
  scene.file = fileLabel;
  scene.camera = readCamera(top.require("camera"), scene.render, baseDir);
  if (std::optional<JsonValue> render = top.get("render"))
    readRender(*render, scene.render, scene.output);

  TextureLoader textures(scene.textures, baseDir);
  MaterialLibrary library;
  if (std::optional<JsonValue> materials = top.get("materials"))
    library = readMaterialLibrary(*materials, textures);

  IdRegistry ids;
  forEachElement(top, "spheres", [&](const JsonValue& element) {
    scene.spheres.push_back(readSphere(element, library, textures));
    ids.add(scene.spheres.back().id, scene.spheres.back().where, fileLabel);
  });
  std::vector<std::string> writtenNames;
  forEachElement(top, "objects", [&](const JsonValue& element) {
    scene.objects.push_back(readObject(element, library, baseDir, textures));
    ids.add(scene.objects.back().id, scene.objects.back().where, fileLabel);
    const ObjectDesc& object = scene.objects.back();
    writtenNames.push_back(object.shape.empty() ? element.json().at("file").get<std::string>()
                                                : "the " + object.shape);
  });
  forEachElement(top, "lights", [&](const JsonValue& element) {
    if (namesGltfLights(element)) {
      for (LightDesc& light : readGltfLightEntry(element, baseDir))
        scene.lights.push_back(std::move(light));
      return;
    }
    scene.lights.push_back(readLight(element, textures));
    ids.add(scene.lights.back().id, scene.lights.back().where, fileLabel);
  });

  if (std::optional<JsonValue> environment = top.get("environment"))
    scene.environment = readEnvironment(*environment, baseDir);
  // Last: tracks are checked against the camera and the entities they animate, and an animated
  // camera at every frame; a still camera is checked here.
  if (std::optional<JsonValue> animation = top.get("animation"))
    scene.animation = readAnimation(*animation, scene);
  followGltfAnimation(scene);
  followGltfObjectAnimations(scene);
  const bool cameraAnimated =
      scene.animation && std::any_of(scene.animation->tracks.begin(), scene.animation->tracks.end(),
                                     [](const AnimTrack& t) { return t.target == AnimTarget::Camera; });
  if (!cameraAnimated)
    if (const std::optional<CameraProblem> problem =
            cameraProblem(scene.camera, samplesBeyondEdge(scene.render.filter)))
      failAt(fileLabel, problem->path, problem->message);
  checkLightEmission(scene);
  top.finish();
  warnReflectanceAboveOne(scene);

  loadMeshes(scene, writtenNames, textures);
  checkWorldExtent(scene);
  return scene;
}

SceneDesc loadSceneFile(const std::string& path) {
  const std::string folder = std::filesystem::path(path).parent_path().string();
  if (isGltfPath(path)) return parseSceneText(gltfSceneText(path, path), path, folder);
  std::string text, reason;
  if (!readTextFile(path, &text, &reason))
    throw SceneError(path + ": cannot open scene file (" + reason + ")");
  return parseSceneText(text, path, folder);
}

}  // namespace candela
