// Plain description structs: what a scene file says, validated, before flattening.
//
// Parsing fills these; every value here is already checked (types, ranges, names resolved to
// materials). Raw camera fields are kept as written so that animation can change them per frame;
// scene/camera_resolve.h turns them into the renderer's Camera.
#pragma once

#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/mat3.h"
#include "core/texture.h"
#include "core/vec2.h"
#include "core/vec3.h"
#include "image/image.h"
#include "image/output_desc.h"
#include "render/camera.h"
#include "render/lens_distortion.h"
#include "render/light.h"
#include "render/material.h"
#include "render/render_settings.h"
#include "scene/mesh_motion.h"

namespace candela {

// A sphere's place at one time of a frame's exposure (SceneDesc::shutterTimes).
struct SpherePose {
  Vec3 position;
  float radius = 1;
};

struct SphereDesc {
  std::string id;     // may be empty
  std::string where;  // JSON path, e.g. "spheres[2]", for later messages
  Vec3 position;
  float radius = 1;
  Material material;
  // What its material mixes, where it is a mix (Material::mixParts index this; render/
  // material_mix.h).
  std::vector<Material> mixParts;
  // Empty, or where it is at each of SceneDesc::shutterTimes: it moves while the shutter is open.
  std::vector<SpherePose> shutterPoses;
};

// A triangle as the OBJ file indexes it: positions, normals and uvs separately.
struct MeshTriangle {
  uint32_t v[3];    // into MeshDesc::positions
  int32_t n[3];     // into MeshDesc::normals, or -1 on all three corners: use the face normal
  uint32_t material;  // into MeshDesc::materials
  int32_t t[3] = {-1, -1, -1};  // into MeshDesc::uvs, or -1 on all three corners: uv (0, 0)
};

// A triangle mesh in object space as read from an OBJ file (polygons already triangulated).
struct MeshDesc {
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;              // from the file's `vn`; may be empty
  std::vector<Vec2> uvs;                  // from the file's `vt` (u, v); may be empty
  // Linear RGB per position (a PLY's red/green/blue, an OBJ's `v x y z r g b`, a glTF's COLOR_0);
  // empty or parallel to positions. They multiply the colour of whatever material shades them.
  std::vector<Vec3> colors;
  std::vector<MeshTriangle> triangles;
  std::vector<Material> materials;  // from the MTL (obj_loader.h's mapping), else diffuse 0.8
  std::vector<Material> mixParts;   // what its mixes mix (Material::mixParts index this)
  std::vector<std::string> materialFiles;  // the MTL files read, beside the OBJ file
  std::vector<std::string> bufferFiles;    // a glTF file's buffers read from files of their own
  // A glTF file's animations, for `candela info`: each one's name and length in seconds (the time
  // of its last key; -1 where it cannot be played).
  std::vector<std::pair<std::string, double>> animations;
  bool holdsCameras = false;  // a glTF file with cameras (the scene's camera may take one)
  bool holdsLights = false;   // a glTF file with lights (the scene's lights may take them)
  // What the file leaves to a default that its author may not have meant, "<file>:<line>: ..."
  // (an MTL file that cannot be read, a material that no MTL file defines).
  std::vector<std::string> warnings;
};

// When an object plays a glTF animation: at s seconds of the scene it shows the animation's time
// start + speed s, wrapped into the animation's length where it loops (else held before its first
// key and after its last, as glTF says).
struct GltfClock {
  double start = 0, speed = 1;
  bool loop = false;
  double at(double seconds, double length) const {
    const double t = start + speed * seconds;
    if (!loop || !(length > 0)) return t;
    const double wrapped = std::fmod(t, length);
    return wrapped < 0 ? wrapped + length : wrapped;
  }
};

// An object's placement at one time of a frame's exposure (SceneDesc::shutterTimes).
struct ObjectPose {
  Vec3 position;
  Vec3 rotation;  // degrees, R = Rz * Ry * Rx
  Vec3 scale{1.0f};
  // Its mesh then, where the mesh moves (ObjectDesc::meshMotion); null: the object's.
  std::shared_ptr<const MeshDesc> mesh;
};

struct ObjectDesc {
  std::string id;
  std::string where;
  std::string file;   // as resolved against the scene file's folder; empty for a shape
  std::string shape;  // a built-in shape (scene/shape_meshes.h) in place of a file; else empty
  Vec3 position;
  Vec3 rotation;     // degrees, R = Rz * Ry * Rx
  Vec3 scale{1.0f};
  bool smooth = true;
  bool vertexColors = true;  // whether the mesh's vertex colours tint its materials
  // The uv pass is rendered: the mesh's uvs are kept though no material reads them
  // (layOutForPasses).
  bool uvPass = false;
  // Above 0 (degrees): the faces the file gives no normals get them computed, smoothed across
  // edges up to this angle (scene/vertex_normals.h); 0: such faces are flat.
  float creaseDegrees = 0;
  // A glTF file's KHR_materials_variants variant that picks its materials ("": the file's own).
  std::string gltfVariant;
  // The glTF file's node whose meshes (with its children's) the object holds ("": the file's
  // scene), in the node's own frame.
  std::string gltfNode;
  // "gltf_animation": the file's animation (by name, or else by number) that the object plays:
  // loading turns its motion of gltfNode into the object's position, rotation and scale tracks,
  // and gives what it moves below (nodes, morph weights, skins' joints) as meshMotion.
  bool gltfAnimated = false;
  std::string gltfAnimationName;
  int gltfAnimationNumber = 0;
  GltfClock gltfClock;
  // The OBJ file's group or object (the faces after a `g` or `o` of this name) the object holds
  // ("": all its faces).
  std::string objGroup;
  std::optional<Material> material;  // overrides the mesh's own materials when present
  std::vector<Material> mixParts;    // what `material` mixes, where it is a mix
  // Read once per file: the objects that name one file share it (and so do frames).
  std::shared_ptr<const MeshDesc> mesh = std::make_shared<const MeshDesc>();
  // Null, or what moves the mesh's vertices with time (sceneAtFrame puts each frame's in mesh).
  std::shared_ptr<const MeshMotion> meshMotion;
  // Null, or where a glTF animation poses `mesh`: the mesh as its file binds it, the frame of the
  // object_coordinates pass (docs/aovs.md), which stays on the surface however it is posed.
  std::shared_ptr<const MeshDesc> restMesh;
  // Empty, or its placement at each of SceneDesc::shutterTimes: it moves while the shutter is
  // open.
  std::vector<ObjectPose> shutterPoses;
};

// A spot light's cone (render/spot_cone.h), angles in degrees from its axis.
struct SpotDesc {
  float cutoffDegrees = 20;
  float beamDegrees = 15;
};

// A rectangle light's shape: flattening makes it two emissive triangles centred on its position,
// facing where it shines (scene/light_emission_desc.h, rectangleCorners).
struct RectangleDesc {
  Vec2 size{1.0f, 1.0f};   // along its width and its height
  std::optional<Vec3> up;  // which way its height runs; absent: y, or z where it shines along y
  bool twoSided = false;   // emits from its back too, half its power each way
  // A texture that its radiance tints (its "color" given as one), u across its width and v up
  // its height, seen upright from in front (-1: none).
  TextureRef texture;
};

// A point or spot light's profile (render/light_profile.h), from an IES file.
struct ProfileDesc {
  int32_t texture = -1;  // into SceneDesc::textures
  float scale = 1;       // 1 / the texture's mean over the sphere
  // The vertical angles (degrees) the file's values span, outside which the light sends nothing.
  float firstDegrees = 0, lastDegrees = 180;
  // Made perpendicular to the light's axis, the direction of the profile's C0 plane; without one
  // (or where an animated axis runs along it) +y, or +z where the axis runs along y.
  std::optional<Vec3> up;
};

struct LightDesc {
  std::string id;
  std::string where;
  // A spot light is a point light with a cone, a rectangle light two emissive triangles.
  LightType type = LightType::Point;
  Vec3 position;  // all but directional lights
  // Where a directional light's light travels, or where a spot or rectangle light points (unless
  // it has a look_at): a unit vector, but between an animation's keys.
  Vec3 direction;
  // The point a spot or rectangle light points at, from wherever it is at a frame.
  std::optional<Vec3> lookAt;
  float radius = 0;  // sphere lights
  // Directional lights: the apparent diameter of the disc they shine from, in degrees (0: a
  // delta light, of one direction).
  float angleDegrees = 0;
  // Total emitted power (a spot's: that of the point light it limits); a directional light's
  // irradiance on a surface facing it.
  float intensity = 0;
  Vec3 color{1.0f};
  std::optional<SpotDesc> spot;
  std::optional<RectangleDesc> rectangle;
  // A point or spot light's profile: where it points (`direction` or `lookAt`, straight down by
  // default for a point light) is the profile's axis.
  std::optional<ProfileDesc> profile;
  // A sphere or rectangle light, or a sun with a disc: whether the camera sees it (false: its
  // rays pass it by, while its light, its reflections and what is seen through glass stay).
  bool visible = true;
  // The glTF file the light came from ({"gltf": ...} in "lights", resolved), or empty.
  std::string gltfFile;
  // Empty, or the light at each of SceneDesc::shutterTimes where its tracks move it while the
  // shutter is open (sceneAtFrame fills it), each pose without poses of its own.
  std::vector<LightDesc> shutterPoses;
};

// Pixels [x, x + width) x [y, y + height) of a camera's image.
struct CameraCrop {
  uint32_t x = 0, y = 0, width = 0, height = 0;
};

struct CameraDesc {
  uint32_t width = 512, height = 512;
  // The part of the image rendered, each pixel as in the whole image's render ("crop"); none:
  // all of it.
  std::optional<CameraCrop> crop;
  float fov = 60;                  // horizontal, degrees; used when `intrinsics` is absent
  // An orthographic camera's: the world width its image spans (pixels square, the principal
  // point at the image's centre), when `intrinsics` is absent.
  float viewWidth = 0;
  std::optional<Mat3> intrinsics;  // K in pixel coordinates (pixel centres at +0.5)
  Vec3 position;
  Vec3 rotation;                   // degrees, camera-to-world, R = Rz * Ry * Rx
  std::optional<Vec3> lookAt;
  Vec3 up{0, 1, 0};
  std::optional<Mat3> extrinsicsR;  // world-to-camera, OpenCV axes
  std::optional<Vec3> extrinsicsT;
  float apertureRadius = 0;
  std::optional<float> focusDistance;
  LensDistortion distortion;  // OpenCV's distCoeffs (render/lens_distortion.h)
  CameraProjection projection = CameraProjection::Perspective;
  // The glTF file the pose and field of view came from ("gltf", resolved), or empty; its name as
  // written, and which of its cameras.
  std::string gltfFile, gltfWritten;
  uint32_t gltfCamera = 0;
  // "gltf_animation": the file's animation (by name, or else by number) whose motion of the
  // camera's node the frames follow (scene/read/camera_reader.h, followGltfAnimation).
  bool gltfAnimated = false;
  std::string gltfAnimationName;
  int gltfAnimationNumber = 0;
};

// What an animation track can change (docs/scene-format.md, *Animation*). Which properties a
// target accepts is the loader's check; see scene/read/animation_reader.h.
// The environment (docs/scene-format.md, *Environment*): a constant radiance, or an
// equirectangular map scaled by strength and tinted by color, turned by rotation.
struct EnvironmentDesc {
  Vec3 color{0.0f};  // the constant radiance; with a map its tint (default 1)
  std::string map;   // the map file as resolved against the scene's folder; empty: constant
  std::shared_ptr<const ImageRGB> image;  // the map, read and checked at load; shared by frames
  // Of the map's size and texels, set by the reader: frames whose maps have equal hashes share
  // the map's arrays, even when each frame's file read the map anew (scene/flatten_environment.h).
  // 0 where the map was made otherwise: flattening hashes it then.
  uint64_t mapHash = 0;
  float strength = 1;
  Vec3 rotation;     // degrees, map frame -> world, R = Rz * Ry * Rx
  bool visible = true;  // false: camera rays that leave the scene see black; it still lights
};

enum class AnimTarget { Camera, Sphere, Object, Light };
// The camera's, then the entities'.
enum class AnimProperty {
  // clang-format off
  Position, Rotation, LookAt, Up, Fov, ApertureRadius, FocusDistance,
  Radius, Color, Roughness, Anisotropy, Scattering, Scale, Intensity, Direction, Angle, Size
  // clang-format on
};

// One key: the value at `frame`. Scalars are stored in all three components, so that per-component
// interpolation serves every property alike.
struct AnimKey {
  uint32_t frame = 0;
  Vec3 value;
};

struct AnimTrack {
  AnimTarget target = AnimTarget::Camera;
  uint32_t index = 0;  // into spheres, objects or lights; unused for the camera
  AnimProperty property = AnimProperty::Position;
  std::vector<AnimKey> keys;  // non-empty, frames strictly increasing
  std::string where;          // JSON path, "animation.tracks[1]"
};

struct AnimationDesc {
  uint32_t frames = 1;  // frames 0 .. frames-1
  float fps = 24;       // playback rate, frames per second (used for videos)
  std::vector<AnimTrack> tracks;
  // Frame k's exposure: from k + shutterOpen to k + shutterClose, in frames (equal: an instant).
  float shutterOpen = 0, shutterClose = 0;
  // A rolling shutter's rows, read from the top: each row's share of the exposure (1: a global
  // shutter, every row open throughout).
  float rowExposure = 1;
  // Whether an object's mesh moves (ObjectDesc::meshMotion): the shutter blurs it too.
  bool meshesMove = false;
};

// The camera at one time of a frame's exposure, from 0 (the shutter opens) to 1 (it closes).
struct ShutterCamera {
  float time = 0;
  CameraDesc camera;
};

// An image texture as read (core/texture.h): RGBA texels from the top row, 8-bit for the 8-bit
// formats, float for TextureFormat::Float. Materials name it by its index in SceneDesc::textures.
struct TextureDesc {
  std::string file;  // as resolved, for messages
  TextureFormat format = TextureFormat::Srgb8;
  uint32_t width = 0, height = 0;
  std::vector<uint8_t> texels8;  // 4 * width * height, or empty
  std::vector<float> texelsF;    // 4 * width * height, or empty
  // Of format, size and texels, set by the reader: frames whose textures have equal hashes share
  // one texture pool (scene/frame_scene.cpp).
  uint64_t contentHash = 0;
};

// Sah: the tree the own engine and the GPU trace. Flat: one level, so every ray tests every
// primitive (`candela render --no-bvh`, benchmarks only: shows what the BVH buys). None: the CPU
// traces with Embree, which builds its own.
enum class OwnBvh : uint8_t { Sah, Flat, None };

struct SceneDesc {
  std::string file;  // the scene file as named by the user, prefix of every message
  CameraDesc camera;
  RenderSettings render;  // the file's camera.spp is render.spp
  // Which of candela's own BVHs flattening builds (images are the same with each).
  OwnBvh ownBvh = OwnBvh::Sah;
  // The object_coordinates pass is rendered: flattening lays out each vertex's place in its
  // object's frame (layOutForPasses).
  bool objectCoordinatesPass = false;
  OutputDesc output;
  std::vector<SphereDesc> spheres;
  std::vector<ObjectDesc> objects;
  std::vector<LightDesc> lights;
  EnvironmentDesc environment;
  // The images materials name by TextureRef::index, each file read once; shared by frames.
  std::vector<std::shared_ptr<const TextureDesc>> textures;
  std::optional<AnimationDesc> animation;  // absent: a still image
  // Empty, or the camera across the exposure where it moves while the shutter is open (at least
  // two times, from 0 to 1; sceneAtFrame fills it): the image is motion-blurred.
  std::vector<ShutterCamera> shutterCameras;
  // Empty, or the times (from 0, the shutter's opening, to 1, its closing; at least two) at which
  // the spheres, objects and lights that move while the shutter is open have shutterPoses
  // (sceneAtFrame fills them): the image is motion-blurred.
  std::vector<float> shutterTimes;
  // AnimationDesc::rowExposure, where shutterCameras or shutterTimes is not empty.
  float shutterRowExposure = 1;
  // Messages on what the scene's files leave to a default, each prefixed like an error's (the
  // scene file, the JSON path); the scene renders. The command line prints them, Python warns.
  std::vector<std::string> warnings;
};

// The scene's triangles: all its meshes', and each rectangle light's two.
inline uint64_t triangleCount(const SceneDesc& desc) {
  uint64_t count = 0;
  for (const ObjectDesc& object : desc.objects) count += object.mesh->triangles.size();
  for (const LightDesc& light : desc.lights) count += light.rectangle ? 2 : 0;
  return count;
}

// The scene's spheres, sphere lights included (each is an emissive sphere).
inline uint64_t sphereCount(const SceneDesc& desc) {
  uint64_t count = desc.spheres.size();
  for (const LightDesc& light : desc.lights) count += light.type == LightType::Sphere ? 1 : 0;
  return count;
}

}  // namespace candela
