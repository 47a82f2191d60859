#include "scene/camera_resolve.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string>

#include "core/constants.h"
#include "core/rotation.h"
#include "render/camera_ray.h"
#include "render/fisheye.h"
#include "scene/scene_error.h"

namespace candela {

Mat3 intrinsicMatrix(const CameraDesc& desc) {
  if (desc.intrinsics) return *desc.intrinsics;
  // An equidistant fisheye's image radius is f theta: half the fov at half the width. An
  // orthographic camera's f is pixels per world unit.
  const float f = desc.projection == CameraProjection::Fisheye
                      ? float(desc.width) / (desc.fov * (kPi / 180.0f))
                  : desc.projection == CameraProjection::Orthographic
                      ? float(desc.width) / desc.viewWidth
                      : float(desc.width) / (2.0f * std::tan(desc.fov * (kPi / 360.0f)));
  Mat3 k;
  k.m[0][0] = f;
  k.m[1][1] = f;
  k.m[0][2] = float(desc.width) * 0.5f;
  k.m[1][2] = float(desc.height) * 0.5f;
  return k;
}

namespace {

// Where K comes from: the intrinsics, or the field of view.
std::string intrinsicsPath(const CameraDesc& desc) {
  if (!desc.gltfFile.empty()) return "camera.gltf";
  if (desc.intrinsics) return "camera.intrinsics";
  return desc.projection == CameraProjection::Orthographic ? "camera.view_width" : "camera.fov";
}

// Where the camera's pose comes from.
std::string posePath(const CameraDesc& desc) {
  if (!desc.gltfFile.empty()) return "camera.gltf";
  if (desc.extrinsicsR) return "camera.extrinsics";
  return desc.lookAt ? "camera.look_at" : "camera.rotation";
}

// A ray the renderer can trace: a finite origin and a finite unit direction.
bool traceable(const Ray& ray) {
  return isFinite(ray.origin) && isFinite(ray.direction) &&
         std::fabs(length(ray.direction) - 1.0f) < 1e-3f;
}

// The corners and the centre of the image widened by `beyondEdge` pixels each way.
using RegionCorners = std::array<std::array<float, 2>, 5>;
RegionCorners regionCorners(const Camera& cam, float beyondEdge) {
  const float lo = 0.0f - beyondEdge, w = float(cam.width) + beyondEdge;  // 0 - 0 is +0
  const float h = float(cam.height) + beyondEdge;
  return {{{lo, lo}, {w, lo}, {lo, h}, {w, h}, {0.5f * (lo + w), 0.5f * (lo + h)}}};
}

// Every ray the camera can make must be traceable: a non-finite direction would send traversal
// into every box. The pose must be a rotation; the rays through the corners of the region samples
// can land in (K^-1 is affine in the pixel, so they bound the rest) and, with a lens, from the
// lens's rim must be finite. That region is the image widened by `beyondEdge` pixels each way.
std::optional<CameraProblem> rayProblem(const Camera& cam, const CameraDesc& desc,
                                        float beyondEdge) {
  bool pose = isFinite(cam.position);
  for (int c = 0; c < 3; ++c) {
    const Vec3 axis = cam.cameraToWorld.column(c);
    pose = pose && isFinite(axis) && std::fabs(length(axis) - 1.0f) < 1e-3f;
  }
  if (!pose)
    return CameraProblem{posePath(desc),
                         "gives the camera no valid orientation (its rays would not be finite)"};
  Camera pinhole = cam;
  pinhole.apertureRadius = 0.0f;
  const RegionCorners image = regionCorners(cam, 0.0f), reached = regionCorners(cam, beyondEdge);
  for (const RegionCorners* region : {&image, &reached})
    for (const auto& p : *region)
      if (!traceable(generateCameraRay(pinhole, p[0], p[1], 0.5f, 0.5f))) {
        const std::string at = "(" + formatNumber(p[0]) + ", " + formatNumber(p[1]) + ")";
        if (region == &reached)
          return CameraProblem{"render.filter",
                               "reaches pixel " + at + " beyond the image, where " +
                                   intrinsicsPath(desc) +
                                   " gives rays that are not finite; expected a narrower filter"};
        return CameraProblem{intrinsicsPath(desc),
                             "gives rays that are not finite (at pixel " + at +
                                 "); expected intrinsics whose inverse maps every pixel to a "
                                 "finite direction"};
      }
  if (cam.apertureRadius <= 0.0f) return std::nullopt;
  const float rim[5][2] = {{0, 0.5f}, {1, 0.5f}, {0.5f, 0}, {0.5f, 1}, {0.5f, 0.5f}};
  for (const auto& p : reached)
    for (const auto& lens : rim)
      if (!traceable(generateCameraRay(cam, p[0], p[1], lens[0], lens[1])))
        return CameraProblem{
            desc.focusDistance ? "camera.focus_distance" : "camera.aperture_radius",
            "with aperture_radius " + formatNumber(cam.apertureRadius) + " and focus distance " +
                formatNumber(cam.focusDistance) +
                " the lens gives rays that are not finite; expected a larger aperture or focus "
                "distance"};
  return std::nullopt;
}

// Whether r R(r), the radial part of `d`, grows on [0, rMax] (with a positive denominator): the
// lens keeps the order of radii out to rMax. Sampled finely in double; a fold between samples
// would have to be narrower than a thousandth of the radius.
bool radialGrows(const LensDistortion& d, double rMax) {
  double last = 0;
  for (int i = 1; i <= 1024; ++i) {
    const double r = rMax * i / 1024, r2 = r * r;
    const double num = 1 + r2 * (d.k1 + r2 * (d.k2 + r2 * d.k3));
    const double den = 1 + r2 * (d.k4 + r2 * (d.k5 + r2 * d.k6));
    const double radius = r * num / den;
    if (!(den > 0) || !(radius > last)) return false;
    last = radius;
  }
  return true;
}

// The first problem `check(px, py, n)` finds at the points (px, py) of a grid over the region
// samples reach (the image widened by `beyondEdge` pixels each way), n being the point's K^-1
// (px, py, 1) on the plane z = 1; none if it finds none.
template <class Check>
std::optional<CameraProblem> firstGridProblem(const Camera& cam, float beyondEdge, Check check) {
  constexpr int kSteps = 64;
  const float lo = 0.0f - beyondEdge;
  const float w = float(cam.width) + beyondEdge, h = float(cam.height) + beyondEdge;
  for (int j = 0; j <= kSteps; ++j)
    for (int i = 0; i <= kSteps; ++i) {
      const float px = lo + (w - lo) * float(i) / kSteps, py = lo + (h - lo) * float(j) / kSteps;
      const Vec3 n = cam.inverseK * Vec3(px, py, 1.0f);
      if (std::optional<CameraProblem> problem = check(px, py, Vec2(n.x / n.z, n.y / n.z)))
        return problem;
    }
  return std::nullopt;
}

std::string pixelText(float px, float py) {
  return "pixel (" + formatNumber(px) + ", " + formatNumber(py) + ")";
}

const char* const kSteadyLens =
    "expected coefficients whose distortion grows steadily out to the image's corners";

CameraProblem foldsAt(const std::string& path, float px, float py) {
  return CameraProblem{path, "folds the image over itself near " + pixelText(px, py) +
                                 ", where no direction or more than one would reach a pixel; " +
                                 kSteadyLens};
}

// A distorted camera's rays undo its lens by Newton's method (render/lens_distortion.h), which
// finds a pixel's one direction only where the lens maps directions onto the image one to one.
// Checked on firstGridProblem's grid: each point's direction must project back onto it (to a
// hundredth of a pixel), with the distortion's Jacobian positive there, and the radial part must
// grow out to the largest radius reached.
std::optional<CameraProblem> distortionProblem(const Camera& cam, float beyondEdge) {
  if (!cam.distortion.enabled) return std::nullopt;
  const LensDistortion& d = cam.distortion;
  Mat3 k;
  invert(cam.inverseK, &k);
  const std::string path = "camera.distortion";
  double largestR2 = 0;
  const auto check = [&](float px, float py, const Vec2& n) -> std::optional<CameraProblem> {
    const Vec2 straight = undistortNormalized(d, n);
    float jacobian[4];
    const Vec2 bent = distortNormalized(d, straight.x, straight.y, jacobian);
    const Vec3 back = k * Vec3(bent.x, bent.y, 1.0f);
    const float miss = std::fabs(back.x - px) + std::fabs(back.y - py);
    const float det = jacobian[0] * jacobian[3] - jacobian[1] * jacobian[2];
    if (!(miss < 0.01f) || !(det > 0.0f)) return foldsAt(path, px, py);
    largestR2 =
        std::max(largestR2, double(straight.x) * straight.x + double(straight.y) * straight.y);
    return std::nullopt;
  };
  if (std::optional<CameraProblem> problem = firstGridProblem(cam, beyondEdge, check))
    return problem;
  const double rMax = std::sqrt(largestR2);
  if (!radialGrows(d, rMax * 1.01))
    return CameraProblem{path,
                         "folds back within the image (its radial distortion stops growing "
                         "before the corners' radius " +
                             formatNumber(float(rMax)) + " of the focal length); " + kSteadyLens};
  return std::nullopt;
}

// A fisheye camera's rays find each pixel's angle from the axis by Newton's method
// (render/fisheye.h), which needs the image radius to grow with the angle, and every pixel's
// angle must stay short of straight behind (180 degrees), past which directions would repeat.
// Checked on firstGridProblem's grid as distortionProblem checks a perspective lens.
std::optional<CameraProblem> fisheyeProblem(const Camera& cam, const CameraDesc& desc,
                                            float beyondEdge) {
  const LensDistortion& d = cam.distortion;
  const std::string path = d.enabled ? "camera.distortion" : intrinsicsPath(desc);
  Mat3 k;
  invert(cam.inverseK, &k);
  float widest = 0.0f;
  const auto check = [&](float px, float py, const Vec2& n) -> std::optional<CameraProblem> {
    const float theta = fisheyeAngle(d, std::sqrt(n.x * n.x + n.y * n.y));
    if (!(theta < 0.999f * kPi))
      return CameraProblem{path, "sees past straight behind the camera at " + pixelText(px, py) +
                                     " (180 degrees from its axis, where directions would "
                                     "repeat); expected a narrower view"};
    const Vec2 back = fisheyePoint(d, fisheyeDirection(d, n));
    const Vec3 pixel = k * Vec3(back.x, back.y, 1.0f);
    if (!(std::fabs(pixel.x - px) + std::fabs(pixel.y - py) < 0.01f)) return foldsAt(path, px, py);
    widest = std::max(widest, theta);
    return std::nullopt;
  };
  if (std::optional<CameraProblem> problem = firstGridProblem(cam, beyondEdge, check))
    return problem;
  for (int i = 1; i <= 1024; ++i) {
    float slope;
    fisheyeRadius(d, std::min(widest * 1.01f, kPi) * float(i) / 1024.0f, &slope);
    if (!(slope > 0.0f))
      return CameraProblem{path, std::string("folds back within the image (its image radius stops "
                                             "growing before the corners' angle from the axis); ") +
                                     kSteadyLens};
  }
  return std::nullopt;
}

// The contract's "rotation" camera looks along -z with +y up; OpenCV axes flip y and z.
const Mat3 kGlToOpenCv = Mat3::diagonal(Vec3(1.0f, -1.0f, -1.0f));

Mat3 lookAtBasis(const Vec3& eye, const Vec3& target, const Vec3& up) {
  const Vec3 forward = normalize(target - eye);
  const Vec3 right = normalize(cross(forward, up));
  const Vec3 down = cross(forward, right);
  return Mat3::fromColumns(right, down, forward);
}

}  // namespace

namespace {

std::optional<CameraProblem> makeCamera(const CameraDesc& desc, float beyondEdge, Camera* out) {
  Camera& cam = *out;
  cam.width = cam.panoramaWidth = desc.width;
  cam.height = cam.panoramaHeight = desc.height;
  cam.projection = desc.projection;
  if (!invert(intrinsicMatrix(desc), &cam.inverseK))
    return CameraProblem{intrinsicsPath(desc),
                         std::string("expected an invertible matrix K") +
                             (desc.intrinsics ? "" : " (the field of view gives none)")};
  if (desc.extrinsicsR && desc.extrinsicsT) {
    // E maps world to camera: x_c = R x_w + t, so the centre is -R^T t.
    cam.cameraToWorld = desc.extrinsicsR->transposed();
    cam.position = -(cam.cameraToWorld * *desc.extrinsicsT);
  } else if (desc.lookAt) {
    cam.position = desc.position;
    cam.cameraToWorld = lookAtBasis(desc.position, *desc.lookAt, desc.up);
  } else {
    cam.position = desc.position;
    cam.cameraToWorld = eulerRotation(desc.rotation) * kGlToOpenCv;
  }
  cam.apertureRadius = desc.apertureRadius;
  if (desc.focusDistance) {
    cam.focusDistance = *desc.focusDistance;
  } else if (desc.lookAt) {
    // Distance to look_at measured along the viewing axis (the focus plane is perpendicular).
    cam.focusDistance = dot(*desc.lookAt - cam.position, cam.cameraToWorld.column(2));
  }
  // The pinhole's rays first: the lens is undone on top of them, where it can be.
  if (std::optional<CameraProblem> problem = rayProblem(cam, desc, beyondEdge)) return problem;
  cam.distortion = desc.distortion;
  if (cam.projection == CameraProjection::Fisheye) return fisheyeProblem(cam, desc, beyondEdge);
  return distortionProblem(cam, beyondEdge);
}

}  // namespace

float samplesBeyondEdge(const PixelFilter& filter) { return filterRadius(filter) - 0.5f; }

std::optional<CameraProblem> cameraProblem(const CameraDesc& desc, float beyondEdge) {
  Camera unused;
  return makeCamera(desc, beyondEdge, &unused);
}

Camera resolveCamera(const CameraDesc& desc, const std::string& fileLabel) {
  Camera cam;
  if (const std::optional<CameraProblem> problem = makeCamera(desc, 0.0f, &cam))
    throw SceneError(fileLabel + ": " + problem->path + ": " + problem->message);
  return cam;
}

std::vector<CameraPose> shutterPoses(const SceneDesc& desc) {
  std::vector<CameraPose> poses;
  bool moves = false;
  for (const ShutterCamera& shutter : desc.shutterCameras) {
    const Camera cam = resolveCamera(shutter.camera, desc.file);
    CameraPose pose;
    pose.rotation = quaternionOf(cam.cameraToWorld);
    pose.position = cam.position;
    pose.time = shutter.time;
    if (!poses.empty())
      moves = moves || std::memcmp(&pose.position, &poses.front().position, sizeof(Vec3)) != 0 ||
              std::memcmp(&pose.rotation, &poses.front().rotation, sizeof(Quaternion)) != 0;
    poses.push_back(pose);
  }
  // A camera that holds still while the shutter is open draws no time for its samples.
  if (!moves) poses.clear();
  return poses;
}

namespace {

// LensDistortion's fields in the order OpenCV lists a projection's coefficients.
std::vector<float LensDistortion::*> coefficientOrder(CameraProjection projection) {
  using L = LensDistortion;
  if (projection == CameraProjection::Fisheye) return {&L::k1, &L::k2, &L::k3, &L::k4};
  return {&L::k1, &L::k2, &L::p1, &L::p2, &L::k3, &L::k4, &L::k5, &L::k6};
}

}  // namespace

std::vector<float> distortionCoefficients(const LensDistortion& d, CameraProjection projection) {
  if (!d.enabled) return {};
  std::vector<float> list;
  for (float LensDistortion::*k : coefficientOrder(projection)) list.push_back(d.*k);
  // The rational model's denominator only where it is there; five is the usual list.
  if (projection != CameraProjection::Fisheye && d.k4 == 0.0f && d.k5 == 0.0f && d.k6 == 0.0f)
    list.resize(5);
  return list;
}

LensDistortion lensDistortion(const std::vector<float>& coefficients, CameraProjection projection) {
  LensDistortion d;
  const std::vector<float LensDistortion::*> order = coefficientOrder(projection);
  for (size_t i = 0; i < coefficients.size() && i < order.size(); ++i) {
    d.*order[i] = coefficients[i];
    d.enabled = d.enabled || coefficients[i] != 0.0f;
  }
  return d;
}

const char* projectionName(CameraProjection projection) {
  switch (projection) {
    case CameraProjection::Equirectangular:
      return "equirectangular";
    case CameraProjection::Fisheye:
      return "fisheye";
    case CameraProjection::Orthographic:
      return "orthographic";
    case CameraProjection::Perspective:
      break;
  }
  return "perspective";
}

AffineRows affineRows(const Mat3& m, const Vec3& p) {
  AffineRows rows{};
  for (int i = 0; i < 3; ++i) rows[i] = {m.m[i][0], m.m[i][1], m.m[i][2], p[i]};
  rows[3] = {0.0f, 0.0f, 0.0f, 1.0f};
  return rows;
}

CameraMatrices cameraMatrices(const CameraDesc& desc, const std::string& fileLabel) {
  const Camera cam = resolveCamera(desc, fileLabel);
  CameraMatrices out;
  out.width = cam.width;
  out.height = cam.height;
  out.intrinsics = intrinsicMatrix(desc);
  out.rotation = cam.cameraToWorld.transposed();
  float t[3];
  for (int i = 0; i < 3; ++i) {
    float* row = out.rotation.m[i];
    // t = -R C, summed in double: the one rounding is the result's.
    t[i] = float(-(double(row[0]) * cam.position.x + double(row[1]) * cam.position.y +
                   double(row[2]) * cam.position.z)) +
           0.0f;  // + 0 turns -0 into 0, here and below, for the files' sake
    for (int j = 0; j < 3; ++j) row[j] += 0.0f;
  }
  out.translation = Vec3(t[0], t[1], t[2]);
  if (cam.apertureRadius > 0.0f) {
    out.apertureRadius = cam.apertureRadius;
    out.focusDistance = cam.focusDistance;
  }
  out.projection = cam.projection;
  out.distortion = distortionCoefficients(cam.distortion, cam.projection);
  return out;
}

}  // namespace candela
