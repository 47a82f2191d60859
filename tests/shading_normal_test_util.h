// What the normal- and bump-map tests share: a plane and a sphere whose shading normals the maps
// tilt, rendered with the normal pass, and the pixels whose centres see the sphere.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "render/aov_layers.h"
#include "render_test_util.h"
#include "scene/dvec3.h"
#include "scene/read/scene_loader.h"

namespace candela::test {

// A folder of the test's files.
inline std::filesystem::path mapTestFolder(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / name;
  std::filesystem::create_directories(dir);
  return dir;
}

// A square of half-side 100 in the plane y = 0 facing +y, u growing along +x and v along -z (as a
// texture seen from above, top up, with -z up), or along +z with `mirrored`: dp/du = (200, 0, 0),
// dp/dv = (0, 0, -200) or (0, 0, 200).
inline void writeMappedPlane(const std::filesystem::path& path, bool mirrored = false) {
  const double v0 = mirrored ? 0 : 1, v1 = 1 - v0;
  std::ofstream(path) << "v -100 0 -100\nv 100 0 -100\nv 100 0 100\nv -100 0 100\n"
                      << "vt 0 " << v0 << "\nvt 1 " << v0 << "\nvt 1 " << v1 << "\nvt 0 " << v1
                      << "\nf 1/1 4/4 3/3\nf 1/1 3/3 2/2\n";
}

struct RenderedWithNormals {
  SceneData data;
  RenderResult result;
  std::vector<ImageLayer> layers;  // the normal pass
};

inline RenderedWithNormals renderWithNormals(const std::string& json,
                                             const std::filesystem::path& dir) {
  RenderedWithNormals r{loadTestScene(json, dir.string()), {}, {}};
  RenderOptions options;
  options.aovs = true;
  r.result = renderCpu(r.data.view(), options);
  r.layers = makeAovLayers(r.data, parseAovList("normal"), r.result.aovs);
  return r;
}

// writeMappedPlane's plane.obj of `material` under a directional light, seen from above through
// the centres of 24 x 16 pixels (u and v within 0.015 of 0.5), one bounce.
inline std::string planeUnderSun(const std::string& material, const DVec3& sunDirection,
                                 double irradiance) {
  return R"({
    "camera": {"width": 24, "height": 16, "fov": 60, "position": [0, 5, 0],
               "look_at": [0, 0, 0.001], "up": [0, 0, -1], "spp": 2},
    "render": {"antialiasing": false, "max_depth": 1},
    "objects": [{"file": "plane.obj", "material": )" +
         material + R"(}],
    "lights": [{"type": "directional", "direction": [)" +
         num(sunDirection.x) + ", " + num(sunDirection.y) + ", " + num(sunDirection.z) +
         R"(], "intensity": )" + num(irradiance) + "}]}";
}

// The error of a scene "s.json" in `dir` whose one material, "m", is `material` (JSON text), or
// "(no error)" where it loads.
inline std::string materialError(const std::filesystem::path& dir, const std::string& material) {
  try {
    parseSceneText(R"({"camera": {"width": 4, "height": 4}, "materials": {"m": )" + material + "}}",
                   "s.json", dir.string());
  } catch (const SceneError& e) {
    return std::string(e.what());
  }
  return std::string("(no error)");
}

// Expects pixel (x, y) of r's normal pass to hold the unit normal n, or n's tilt mirrored about
// the unmapped normal ns where n turns its back on `toEye`, the direction to the camera (as
// render/normal_map.h mirrors it).
inline void expectMappedNormal(const RenderedWithNormals& r, uint32_t x, uint32_t y, DVec3 n,
                               const DVec3& ns, const DVec3& toEye, double tolerance) {
  if (dot(toEye, ns) * dot(toEye, n) <= 0) n = unit(2 * dot(n, ns) * ns - n);
  const float* normal = &r.layers[0].pixels[3 * (size_t(y) * r.data.camera.width + x)];
  EXPECT_NEAR(normal[0], n.x, tolerance) << x << "," << y;
  EXPECT_NEAR(normal[1], n.y, tolerance) << x << "," << y;
  EXPECT_NEAR(normal[2], n.z, tolerance) << x << "," << y;
}

// Expects every pixel of r, a render of planeUnderSun, to be `expected` in its first channel
// (within tolerance * expected) and to hold the unit normal n in its normal pass (within
// tolerance).
inline void expectUniformPlane(const RenderedWithNormals& r, double expected, const DVec3& n,
                               double tolerance) {
  ASSERT_EQ(r.layers.size(), 1u);
  for (uint32_t y = 0; y < 16; ++y)
    for (uint32_t x = 0; x < 24; ++x) {
      EXPECT_NEAR(r.result.image.at(x, y).x, expected, tolerance * expected) << x << "," << y;
      const float* normal = &r.layers[0].pixels[3 * (size_t(y) * 24 + x)];
      EXPECT_NEAR(normal[0], n.x, tolerance) << x << "," << y;
      EXPECT_NEAR(normal[1], n.y, tolerance) << x << "," << y;
      EXPECT_NEAR(normal[2], n.z, tolerance) << x << "," << y;
    }
}

// Calls visit(x, y, d) for each pixel of `camera` whose centre's ray meets the sphere of `radius`
// at the origin, with d the unit direction of the point it meets first, but for the pixels that
// graze its silhouette and those near its poles (where u has no direction); returns how many.
template <class Visit>
int forEachSphereHit(const Camera& camera, double radius, Visit visit) {
  const DVec3 o = dvec3(camera.position);
  int visited = 0;
  for (uint32_t y = 0; y < camera.height; ++y)
    for (uint32_t x = 0; x < camera.width; ++x) {
      const DVec3 ray =
          unit(dvec3(camera.cameraToWorld * (camera.inverseK * Vec3(x + 0.5f, y + 0.5f, 1.0f))));
      const double b = dot(o, ray), disc = b * b - (dot(o, o) - radius * radius);
      if (disc < 0.05 * radius * radius) continue;
      const DVec3 d = (1 / radius) * (o + (-b - std::sqrt(disc)) * ray);
      if (d.x * d.x + d.z * d.z < 0.01) continue;
      visit(x, y, d);
      ++visited;
    }
  return visited;
}

}  // namespace candela::test
