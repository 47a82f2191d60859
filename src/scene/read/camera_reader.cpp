// Reading the camera; see camera_reader.h.
#include "scene/read/camera_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "core/constants.h"
#include "core/rotation.h"
#include "scene/along_up.h"
#include "scene/animation.h"
#include "scene/camera_crop.h"
#include "scene/camera_resolve.h"
#include "scene/read/gltf_camera.h"
#include "scene/read/resolve_path.h"
#include "scene/read/transform_reader.h"
#include "scene/scene_error.h"

namespace candela {
namespace {

constexpr uint64_t kMaxUint32 = UINT32_MAX;
constexpr double kRadiansPerDegree = 0.017453292519943295769;

// K from {"fx", "fy", "cx", "cy"} or a 3x3 matrix [[fx, s, cx], [0, fy, cy], [0, 0, 1]]. A skew s
// is kept: K^-1 handles it, and calibration tools do produce it.
Mat3 readIntrinsics(const JsonValue& value) {
  Mat3 k;
  if (value.json().is_object()) {
    JsonObject fields(value, {"fx", "fy", "cx", "cy"});
    k.m[0][0] = fields.require("fx").positiveNumber();
    k.m[1][1] = fields.require("fy").positiveNumber();
    k.m[0][2] = fields.require("cx").number();
    k.m[1][2] = fields.require("cy").number();
    fields.finish();
    return k;
  }
  if (!value.json().is_array())
    value.failExpected("intrinsics as {\"fx\", \"fy\", \"cx\", \"cy\"} or a 3x3 matrix");
  const std::vector<float> m = value.matrix(3, 3);
  const std::vector<JsonValue> rows = value.elements();
  if (!(m[0] > 0)) rows[0].elements()[0].failExpected("a positive number");
  if (!(m[4] > 0)) rows[1].elements()[1].failExpected("a positive number");
  if (m[3] != 0) rows[1].elements()[0].failExpected("0");
  if (m[6] != 0 || m[7] != 0 || m[8] != 1) rows[2].failExpected("[0, 0, 1]");
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) k.m[i][j] = m[3 * i + j];
  return k;
}

// E = [R t; 0 1], world-to-camera in OpenCV axes; R must be a rotation.
void readExtrinsics(const JsonValue& value, CameraDesc& camera) {
  const std::vector<float> e = value.matrix(4, 4);
  if (e[12] != 0 || e[13] != 0 || e[14] != 0 || e[15] != 1)
    value.elements()[3].failExpected("[0, 0, 0, 1]");
  Mat3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.m[i][j] = e[4 * i + j];
  // Tolerant enough for matrices printed with 4-5 significant digits.
  const Mat3 product = r.transposed() * r;
  double deviation = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      deviation = std::fmax(deviation, std::fabs(product.m[i][j] - (i == j ? 1.0 : 0.0)));
  const double determinant = dot(r.column(0), cross(r.column(1), r.column(2)));
  if (deviation > 1e-3 || determinant < 0)
    value.failExpected("a rotation (orthonormal, determinant +1) in the upper-left 3x3 block");
  camera.extrinsicsR = r;
  camera.extrinsicsT = Vec3(e[3], e[7], e[11]);
}

// OpenCV's distortion coefficients for the camera's projection: distCoeffs' [k1, k2, p1, p2]
// with k3, or k3 to k6, after them (the lengths cv::calibrateCamera gives for these models), or
// cv::fisheye's D = [k1, k2, k3, k4]. Whether the lens can be undone over the image is the
// camera's check (scene/camera_resolve.cpp).
LensDistortion readDistortion(const JsonValue& value, CameraProjection projection) {
  const bool fisheye = projection == CameraProjection::Fisheye;
  const std::string expected =
      fisheye ? "OpenCV's fisheye coefficients, an array [k1, k2, k3, k4]"
              : "OpenCV's distortion coefficients, an array [k1, k2, p1, p2], [k1, k2, p1, p2, "
                "k3] or [k1, k2, p1, p2, k3, k4, k5, k6]";
  const std::vector<JsonValue> elements = value.elements(expected);
  const size_t n = elements.size();
  if (fisheye ? n != 4 : (n != 4 && n != 5 && n != 8)) value.failExpected(expected);
  std::vector<float> coefficients;
  for (const JsonValue& element : elements) coefficients.push_back(element.number());
  return lensDistortion(coefficients, projection);
}

// "projection": a perspective camera's (the default), an equirectangular panorama's, which spans
// every direction and so has no K, lens or distortion, a fisheye's, which has no thin lens, or an
// orthographic camera's, whose K (or "view_width") maps pixels to its plane, with neither a field
// of view nor a lens.
void readProjection(JsonObject& fields, const JsonValue& value, CameraDesc& camera) {
  const size_t choice = value.choice({"perspective", "equirectangular", "fisheye", "orthographic"});
  if (choice == 1) {
    camera.projection = CameraProjection::Equirectangular;
    for (const char* key : {"fov", "intrinsics", "distortion", "aperture_radius", "focus_distance"})
      fields.reject(key, "not used by an equirectangular camera (its image spans every direction)");
  } else if (choice == 2) {
    camera.projection = CameraProjection::Fisheye;
    for (const char* key : {"aperture_radius", "focus_distance"})
      fields.reject(key, "not used by a fisheye camera (a pinhole's)");
  } else if (choice == 3) {
    camera.projection = CameraProjection::Orthographic;
    for (const char* key : {"fov", "distortion", "aperture_radius", "focus_distance"})
      fields.reject(key,
                    "not used by an orthographic camera (its rays are parallel: \"view_width\" or "
                    "\"intrinsics\" gives its scale)");
    fields.exclusive("view_width", "intrinsics");
    if (std::optional<JsonValue> width = fields.get("view_width"))
      camera.viewWidth = width->positiveNumber();
    else if (!fields.has("intrinsics") && !fields.has("gltf"))
      fields.fail(
          "missing required key \"view_width\" (an orthographic camera's width in world "
          "units) or \"intrinsics\"");
  }
}

// "gltf": the pose and vertical field of view of a camera that a glTF file places, the
// "gltf_camera"-th (from 0); the horizontal field of view follows from the image's width and
// height (an orthographic camera's width likewise from its height).
void readGltfCamera(JsonObject& fields, const std::string& baseDir, CameraDesc& camera) {
  const std::optional<JsonValue> gltf = fields.get("gltf");
  if (!gltf) {
    fields.reject("gltf_camera", "not used without \"gltf\"");
    fields.reject("gltf_animation", "not used without \"gltf\"");
    return;
  }
  for (const char* key : {"position", "rotation", "look_at", "up", "extrinsics", "transform", "fov",
                          "intrinsics", "projection"})
    fields.exclusive("gltf", key);
  const std::string written = gltf->string();
  if (written.empty()) gltf->failExpected("the path of a glTF file");
  uint32_t number = 0;
  if (std::optional<JsonValue> which = fields.get("gltf_camera"))
    number = uint32_t(which->integer(0, kMaxUint32, "a camera's number, from 0"));
  camera.gltfFile = resolvePath(written, baseDir);
  camera.gltfWritten = written;
  camera.gltfCamera = number;
  if (std::optional<JsonValue> animation = fields.get("gltf_animation")) {
    camera.gltfAnimated = true;
    if (animation->json().is_string()) {
      camera.gltfAnimationName = animation->string();
      if (camera.gltfAnimationName.empty())
        animation->failExpected("an animation's name or number, from 0");
    } else {
      camera.gltfAnimationNumber =
          int(animation->integer(0, 1u << 30, "an animation's name or number, from 0"));
    }
  }
  GltfCamera read;
  try {
    read = candela::readGltfCamera(camera.gltfFile, written, number);
  } catch (const SceneError& e) {
    gltf->fail(e.what());
  }
  camera.extrinsicsR = read.worldToCamera;
  camera.extrinsicsT = read.translation;
  if (read.ymag > 0) {  // orthographic: its height 2 ymag kept, as a perspective camera's yfov
    camera.projection = CameraProjection::Orthographic;
    camera.viewWidth = float(2.0 * read.ymag * camera.width / camera.height);
    if (!(std::isfinite(camera.viewWidth) && camera.viewWidth > 0.0f))
      gltf->fail("its ymag of " + formatNumber(float(read.ymag)) +
                 " spans no finite width across a " + std::to_string(camera.width) + " x " +
                 std::to_string(camera.height) + " image");
    return;
  }
  const double halfHeight = std::tan(read.yfovDegrees * kRadiansPerDegree / 2.0);
  camera.fov =
      float(2.0 * std::atan(halfHeight * camera.width / camera.height) / kRadiansPerDegree);
  if (!(camera.fov < 180.0f))
    gltf->fail("its vertical field of view of " + formatNumber(float(read.yfovDegrees)) +
               " degrees is wider than 180 across a " + std::to_string(camera.width) + " x " +
               std::to_string(camera.height) + " image");
}

// "transform": the camera-to-world matrix of Blender's, OpenGL's and candela's camera axes
// (looking down its -z, +y up), [R | t] with R a rotation: read as the position and rotation it
// gives.
void readCameraTransform(const JsonValue& value, CameraDesc& camera) {
  const Placement placement = readTransform(value);
  for (int k = 0; k < 3; ++k)
    if (!(std::fabs(placement.scale[k] - 1.0f) <= 1e-3f))
      value.failExpected(
          "a rotation (orthonormal, determinant +1) in the upper-left 3x3 block: a camera takes "
          "no scale or mirror");
  camera.position = placement.position;
  camera.rotation = placement.rotation;
}

void readPose(JsonObject& fields, CameraDesc& camera) {
  for (const char* key : {"position", "rotation", "look_at"}) fields.exclusive("extrinsics", key);
  for (const char* key : {"position", "rotation", "look_at", "extrinsics"})
    fields.exclusive("transform", key);
  fields.exclusive("rotation", "look_at");
  if (!fields.has("look_at")) fields.reject("up", "not used without \"look_at\"");

  if (std::optional<JsonValue> extrinsics = fields.get("extrinsics"))
    readExtrinsics(*extrinsics, camera);
  if (std::optional<JsonValue> transform = fields.get("transform"))
    readCameraTransform(*transform, camera);
  if (std::optional<JsonValue> position = fields.get("position"))
    camera.position = position->vec3();
  if (std::optional<JsonValue> rotation = fields.get("rotation"))
    camera.rotation = rotation->vec3();
  const std::optional<JsonValue> lookAt = fields.get("look_at");
  if (!lookAt) return;
  camera.lookAt = lookAt->vec3();
  const std::optional<JsonValue> up = fields.get("up");
  if (up) camera.up = up->vec3();

  const Vec3 forward = *camera.lookAt - camera.position;
  if (isBlack(forward)) lookAt->failExpected("a point other than the camera position");
  if (alongUp(forward, camera.up)) {
    if (up) up->failExpected("a direction that is not parallel to the viewing direction");
    fields.fail("missing required key \"up\" (the view is parallel to the default up [0, 1, 0])");
  }
}

// The image must fit in memory: at most kMaxPixels pixels, each of which the renderer keeps as
// three floats (and a PNG as three bytes more).
void checkImageSize(JsonObject& fields, const CameraDesc& camera) {
  const uint64_t pixels = uint64_t(camera.width) * camera.height;
  if (pixels <= kMaxPixels) return;
  const std::string key = camera.width >= camera.height ? "width" : "height";
  char gib[32];
  std::snprintf(gib, sizeof gib, "%.3g", double(pixels) * 12.0 / double(1ull << 30));
  fields.get(key)->fail("an image of " + std::to_string(camera.width) + " x " +
                          std::to_string(camera.height) + " pixels would need " + gib +
                          " GiB; expected at most " + std::to_string(kMaxPixels) +
                          " pixels (16384 x 16384)");
}

// "crop": [x, y, width, height], pixels of the camera's image.
CameraCrop readCrop(const JsonValue& value, const CameraDesc& camera) {
  const char* expected = "an array [x, y, width, height] of pixels";
  const std::vector<JsonValue> elements = value.elements(expected);
  if (elements.size() != 4) value.failExpected(expected);
  CameraCrop crop;
  crop.x = uint32_t(elements[0].integer(0, kMaxUint32, "a non-negative integer"));
  crop.y = uint32_t(elements[1].integer(0, kMaxUint32, "a non-negative integer"));
  crop.width = uint32_t(elements[2].integer(1, kMaxUint32, "a positive integer"));
  crop.height = uint32_t(elements[3].integer(1, kMaxUint32, "a positive integer"));
  if (const std::optional<std::string> problem = cropProblem(crop, camera.width, camera.height))
    value.fail(*problem);
  return crop;
}

}  // namespace

float readFov(const JsonValue& value, CameraProjection projection) {
  const bool fisheye = projection == CameraProjection::Fisheye;
  const std::string expectation =
      fisheye ? "a number above 0 and at most 360" : "a number between 0 and 180 (exclusive)";
  const float fov = value.number(expectation);
  if (!(fov > 0 && (fisheye ? fov <= 360 : fov < 180))) value.failExpected(expectation);
  return fov;
}

CameraDesc readCamera(const JsonValue& value, RenderSettings& render, const std::string& baseDir) {
  JsonObject fields(value, {"width",
                            "height",
                            "fov",
                            "intrinsics",
                            "position",
                            "rotation",
                            "look_at",
                            "up",
                            "extrinsics",
                            "transform",
                            "spp",
                            "rays",
                            "aperture_radius",
                            "focus_distance",
                            "distortion",
                            "projection",
                            "gltf",
                            "gltf_camera",
                            "view_width",
                            "gltf_animation",
                            "crop"});
  CameraDesc camera;
  if (std::optional<JsonValue> width = fields.get("width"))
    camera.width = static_cast<uint32_t>(width->integer(1, kMaxUint32, "a positive integer"));
  if (std::optional<JsonValue> height = fields.get("height"))
    camera.height = static_cast<uint32_t>(height->integer(1, kMaxUint32, "a positive integer"));

  checkImageSize(fields, camera);
  if (std::optional<JsonValue> crop = fields.get("crop")) camera.crop = readCrop(*crop, camera);

  if (std::optional<JsonValue> projection = fields.get("projection"))
    readProjection(fields, *projection, camera);
  if (camera.projection != CameraProjection::Orthographic) {
    const std::string name = projectionName(camera.projection);
    fields.reject("view_width", "not used by " + std::string(name[0] == 'e' ? "an " : "a ") + name +
                                    " camera (only orthographic cameras have a view width)");
  }
  fields.exclusive("fov", "intrinsics");
  if (std::optional<JsonValue> fov = fields.get("fov"))
    camera.fov = readFov(*fov, camera.projection);
  if (std::optional<JsonValue> intrinsics = fields.get("intrinsics"))
    camera.intrinsics = readIntrinsics(*intrinsics);
  if (std::optional<JsonValue> distortion = fields.get("distortion"))
    camera.distortion = readDistortion(*distortion, camera.projection);

  readPose(fields, camera);
  readGltfCamera(fields, baseDir, camera);

  fields.exclusive("spp", "rays");
  std::optional<JsonValue> spp = fields.get("spp");
  if (!spp) spp = fields.get("rays");
  if (spp) render.spp = static_cast<uint32_t>(spp->integer(1, kMaxUint32, "a positive integer"));

  if (std::optional<JsonValue> aperture = fields.get("aperture_radius"))
    camera.apertureRadius = aperture->nonNegativeNumber();
  if (std::optional<JsonValue> focus = fields.get("focus_distance"))
    camera.focusDistance = focus->positiveNumber();
  if (camera.apertureRadius > 0 && !camera.focusDistance && !camera.lookAt)
    fields.fail(
        "missing required key \"focus_distance\" (an open aperture without \"look_at\" "
        "has nothing else to focus on)");
  fields.finish();
  return camera;
}

void followGltfAnimation(SceneDesc& scene) {
  CameraDesc& camera = scene.camera;
  if (!camera.gltfAnimated) return;
  const std::string where = "camera.gltf_animation";
  if (!scene.animation)
    failAt(scene.file, where,
           "needs an \"animation\" block, whose frames and fps give the times at which the "
           "file's animation is played");
  AnimationDesc& animation = *scene.animation;
  std::vector<double> times(animation.frames);
  for (uint32_t k = 0; k < animation.frames; ++k) times[k] = double(k) / double(animation.fps);
  std::vector<GltfCamera> poses;
  try {
    poses = readGltfCameraPoses(camera.gltfFile, camera.gltfWritten, camera.gltfCamera,
                                camera.gltfAnimationName, camera.gltfAnimationNumber, times);
  } catch (const SceneError& e) {
    failAt(scene.file, where, e.what());
  }
  // The contract's camera looks down -z with +y up, as a glTF camera does, and OpenCV's axes
  // flip y and z: the node's rotation is cameraToWorld with y and z negated.
  AnimTrack position, rotation;
  position.property = AnimProperty::Position;
  rotation.property = AnimProperty::Rotation;
  position.where = rotation.where = where;
  for (uint32_t k = 0; k < animation.frames; ++k) {
    const Mat3 cameraToWorld = poses[k].worldToCamera.transposed();
    const Vec3 centre = -(cameraToWorld * poses[k].translation);
    const Mat3 node = cameraToWorld * Mat3::diagonal(Vec3(1.0f, -1.0f, -1.0f));
    position.keys.push_back({k, centre});
    rotation.keys.push_back(
        {k, k == 0 ? eulerDegrees(node) : eulerDegreesNear(node, rotation.keys.back().value)});
  }
  camera.extrinsicsR.reset();
  camera.extrinsicsT.reset();
  camera.position = position.keys[0].value;
  camera.rotation = rotation.keys[0].value;
  animation.tracks.push_back(std::move(position));
  animation.tracks.push_back(std::move(rotation));
  for (uint32_t k = 0; k < animation.frames; ++k)
    if (const std::optional<CameraProblem> problem = cameraProblem(
            cameraAtFrame(camera, animation, k), samplesBeyondEdge(scene.render.filter)))
      failAt(scene.file, where,
             "at frame " + std::to_string(k) + " " + problem->path + " " + problem->message);
}

}  // namespace candela
