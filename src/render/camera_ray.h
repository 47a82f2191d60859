// Camera rays: pixel position -> K^-1 -> the lens's distortion undone -> camera space (OpenCV
// axes) -> world; optional thin lens. Panoramas and orthographic cameras apart.
#pragma once

#include "core/sampling.h"
#include "geometry/ray.h"
#include "render/camera.h"
#include "render/fisheye.h"
#include "render/panorama.h"

namespace candela {

// The ray of an equirectangular camera through (px, py). Out of line: most cameras are
// perspective.
CANDELA_HD_NOINLINE inline Ray panoramaRay(const Camera& cam, float px, float py) {
  Ray ray;
  ray.origin = cam.position;
  ray.direction = normalize(cam.cameraToWorld *
                            panoramaDirection(px, py, cam.panoramaWidth, cam.panoramaHeight));
  return ray;
}

// The ray of an orthographic camera through (px, py): from its point of the camera's plane, along
// the camera's +z. Out of line, as panoramaRay.
CANDELA_HD_NOINLINE inline Ray orthographicRay(const Camera& cam, float px, float py) {
  const Vec3 onPlane = cam.inverseK * Vec3(px, py, 1.0f);
  Ray ray;
  ray.origin = cam.position + cam.cameraToWorld * Vec3(onPlane.x, onPlane.y, 0.0f);
  ray.direction = normalize(cam.cameraToWorld * Vec3(0.0f, 0.0f, 1.0f));
  return ray;
}

// (px, py) in pixel coordinates (pixel (i, j) covers [i, i+1) x [j, j+1)); (lensU, lensV)
// uniform in [0,1)^2, used only when the aperture is open. Returns a unit-direction ray.
CANDELA_HDI Ray generateCameraRay(const Camera& cam, float px, float py, float lensU, float lensV) {
  if (cam.projection == CameraProjection::Equirectangular) return panoramaRay(cam, px, py);
  if (cam.projection == CameraProjection::Orthographic) return orthographicRay(cam, px, py);
  Vec3 dir = cam.inverseK * Vec3(px, py, 1.0f);
  dir = dir / dir.z;  // a point on the plane z = 1 in front of the camera
  if (cam.projection == CameraProjection::Fisheye) {
    dir = fisheyeDirection(cam.distortion, Vec2(dir.x, dir.y));
  } else if (cam.distortion.enabled) {
    const Vec2 straight = undistortNormalized(cam.distortion, Vec2(dir.x, dir.y));
    dir = Vec3(straight.x, straight.y, 1.0f);
  }
  Vec3 origin(0.0f);
  if (cam.apertureRadius > 0.0f) {
    // Thin lens: every ray through the lens point converges on the plane z = focusDistance.
    float lx, ly;
    sampleUniformDisk(lensU, lensV, &lx, &ly);
    origin = Vec3(lx * cam.apertureRadius, ly * cam.apertureRadius, 0.0f);
    dir = dir * cam.focusDistance - origin;
  }
  Ray ray;
  ray.origin = cam.position + cam.cameraToWorld * origin;
  ray.direction = normalize(cam.cameraToWorld * dir);
  return ray;
}

}  // namespace candela
