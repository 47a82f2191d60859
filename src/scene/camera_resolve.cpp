#include "scene/camera_resolve.h"

#include <cmath>

#include "core/constants.h"
#include "core/rotation.h"
#include "scene/scene_error.h"

namespace candela {

Mat3 intrinsicMatrix(const CameraDesc& desc) {
  if (desc.intrinsics) return *desc.intrinsics;
  const float f = float(desc.width) / (2.0f * std::tan(desc.fov * (kPi / 360.0f)));
  Mat3 k;
  k.m[0][0] = f;
  k.m[1][1] = f;
  k.m[0][2] = float(desc.width) * 0.5f;
  k.m[1][2] = float(desc.height) * 0.5f;
  return k;
}

namespace {

// The contract's "rotation" camera looks along -z with +y up; OpenCV axes flip y and z.
const Mat3 kGlToOpenCv = Mat3::diagonal(Vec3(1.0f, -1.0f, -1.0f));

Mat3 lookAtBasis(const Vec3& eye, const Vec3& target, const Vec3& up) {
  const Vec3 forward = normalize(target - eye);
  const Vec3 right = normalize(cross(forward, up));
  const Vec3 down = cross(forward, right);
  return Mat3::fromColumns(right, down, forward);
}

}  // namespace

Camera resolveCamera(const CameraDesc& desc, const std::string& fileLabel) {
  Camera cam;
  cam.width = desc.width;
  cam.height = desc.height;
  if (!invert(intrinsicMatrix(desc), &cam.inverseK))
    throw SceneError(fileLabel + ": camera.intrinsics: expected an invertible matrix K");

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
  return cam;
}

bool projectToPixel(const Camera& camera, const Mat3& K, const Vec3& world, float* u, float* v) {
  const Vec3 pc = camera.cameraToWorld.transposed() * (world - camera.position);
  if (pc.z <= 0.0f) return false;
  const Vec3 h = K * (pc / pc.z);
  *u = h.x;
  *v = h.y;
  return true;
}

}  // namespace candela
