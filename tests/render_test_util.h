// Helpers for image tests: render a JSON scene given as text, and noise-aware statistics.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "backends/cpu/cpu_renderer.h"
#include "scene/flatten.h"
#include "scene/read/scene_loader.h"
#include "scene/scene_error.h"

namespace candela::test {

// A number as JSON text, to 9 significant digits: a float's value exactly.
inline std::string num(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

// The error that a 4 x 4 scene of the lights `lights` (JSON objects, comma-separated) and the
// top-level members `more` (",\"animation\": {...}") is refused with, or "(no error)".
inline std::string lightsError(const std::string& lights, const std::string& more = "") {
  try {
    parseSceneText(
        R"({"camera": {"width": 4, "height": 4}, "lights": [)" + lights + "]" + more + "}",
        "s.json", ".");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

// The top-level member lightsError takes for an animation of 3 frames with one track: `property`
// of `target` keyed by `keys` (JSON text).
inline std::string oneTrack(const std::string& target, const std::string& property,
                            const std::string& keys) {
  return R"(, "animation": {"frames": 3, "tracks": [{"target": ")" + target +
         R"(", "property": ")" + property + R"(", "keys": )" + keys + "}]}";
}

inline SceneData loadTestScene(const std::string& json, const std::string& baseDir = ".") {
  return flattenScene(parseSceneText(json, "test.json", baseDir));
}

// The error loading scene `json` from `baseDir` gives (as loadTestScene does), or "(no error)".
inline std::string loadError(const std::string& json, const std::string& baseDir) {
  try {
    loadTestScene(json, baseDir);
  } catch (const SceneError& e) {
    return std::string(e.what());
  }
  return std::string("(no error)");
}

// The unit direction, in double precision, of the ray through the centre of pixel (x, y) of a
// camera `width` x `height` pixels, `fovDegrees` across, looking along -z with +y up (the
// contract's camera without a rotation): the tests' own reference for where rays go.
inline std::array<double, 3> pixelCentreDirection(uint32_t width, uint32_t height,
                                                  double fovDegrees, uint32_t x, uint32_t y) {
  const double f = width / (2.0 * std::tan(fovDegrees * 3.14159265358979323846 / 360.0));
  const double d[3] = {(x + 0.5 - width / 2.0) / f, -(y + 0.5 - height / 2.0) / f, -1.0};
  const double n = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  return {d[0] / n, d[1] / n, d[2] / n};
}

// Where, as a unit direction from the sphere's centre, the ray through the centre of pixel (x, y)
// of a camera `width` x `height` pixels, `fovDegrees` across, at (distance, 0, 0) looking at the
// origin (up +y) meets a sphere of `radius` at the origin, in double precision. The camera looks
// along the world's -x with its right along -z: the pixel's direction (cx, cy, cz) in the
// camera's axes is (cz, cy, -cx) in the world's.
inline std::array<double, 3> sphereHitSeenFromPlusX(uint32_t width, uint32_t height,
                                                    double fovDegrees, double distance,
                                                    double radius, uint32_t x, uint32_t y) {
  const std::array<double, 3> c = pixelCentreDirection(width, height, fovDegrees, x, y);
  const double b = distance * c[2];
  const double t = -b - std::sqrt(b * b - (distance * distance - radius * radius));
  return {(distance + t * c[2]) / radius, t * c[1] / radius, -t * c[0] / radius};
}

// The length of the chord that the line from `origin` along the unit direction `d` cuts through
// the ball of `centre` and `radius` (0 where it misses), in double precision.
inline double chordThroughBall(const std::array<double, 3>& origin, const std::array<double, 3>& d,
                               const std::array<double, 3>& centre, double radius) {
  double b = 0.0, c = -radius * radius;
  for (int k = 0; k < 3; ++k) {
    b += (origin[k] - centre[k]) * d[k];
    c += (origin[k] - centre[k]) * (origin[k] - centre[k]);
  }
  return b * b > c ? 2.0 * std::sqrt(b * b - c) : 0.0;
}

// The error a scene of one unit sphere whose material is `material` (JSON) is refused with, or
// "(no error)".
inline std::string sphereMaterialError(const std::string& material) {
  return loadError(
      R"({"camera": {}, "spheres": [{"position": [0, 0, 0], "radius": 1, "material": )" + material +
          "}]}",
      ".");
}

inline RenderResult renderTestScene(const std::string& json, int threads = 0,
                                    const std::string& baseDir = ".") {
  const SceneData data = loadTestScene(json, baseDir);
  RenderOptions options;
  options.threads = threads;
  return renderCpu(data.view(), options);
}

// Writes a square of half-side `half` in the plane y = 0 (two triangles facing +y) as an OBJ file
// `name` in the test's temporary folder; returns its path. Tests that share a name run in
// processes of their own at once (ctest -j): each writes its own file and renames it into place,
// so that none reads another's half written.
inline std::string writePlaneObj(const std::string& name, double half) {
  const std::string path = ::testing::TempDir() + name;
  const std::string own = path + "." + std::to_string(getpid()) + ".tmp";
  {
    std::ofstream f(own);
    f << "v " << -half << " 0 " << -half << "\nv " << half << " 0 " << -half << "\nv " << half
      << " 0 " << half << "\nv " << -half << " 0 " << half << "\nf 1 3 2\nf 1 4 3\n";
  }
  std::rename(own.c_str(), path.c_str());
  return path;
}

// Writes a torus about the y axis at `centre` (radii `major` and `minor`, rings x sides quads, two
// triangles each, wound counter-clockwise seen from outside) as an OBJ file `name` in the test's
// temporary folder, as writePlaneObj does; returns its path. A lamp of many small emitters, as
// the bench's lamp room's.
inline std::string writeTorusObj(const std::string& name, double cx, double cy, double cz,
                                 double major, double minor, int rings, int sides) {
  const std::string path = ::testing::TempDir() + name;
  const std::string own = path + "." + std::to_string(getpid()) + ".tmp";
  {
    std::ofstream f(own);
    const double tau = 6.283185307179586;
    for (int i = 0; i < rings; ++i)
      for (int j = 0; j < sides; ++j) {
        const double u = tau * i / rings, v = tau * j / sides, r = major + minor * std::cos(v);
        f << "v " << cx + r * std::cos(u) << " " << cy + minor * std::sin(v) << " "
          << cz + r * std::sin(u) << "\n";
      }
    const auto at = [&](int i, int j) { return (i % rings) * sides + (j % sides) + 1; };
    for (int i = 0; i < rings; ++i)
      for (int j = 0; j < sides; ++j)
        f << "f " << at(i, j) << " " << at(i, j + 1) << " " << at(i + 1, j + 1) << "\nf "
          << at(i, j) << " " << at(i + 1, j + 1) << " " << at(i + 1, j) << "\n";
  }
  std::rename(own.c_str(), path.c_str());
  return path;
}

// Mean and standard deviation of one channel over a pixel rectangle [x0,x1) x [y0,y1).
struct RegionStats {
  double mean = 0, stddev = 0;
  size_t count = 0;
  // Standard error of the mean, for pixels that are independent estimates of one value.
  double standardError() const { return stddev / std::sqrt(double(count)); }
};

inline RegionStats regionStats(const ImageRGB& img, uint32_t x0, uint32_t y0, uint32_t x1,
                               uint32_t y1, int channel) {
  RegionStats s;
  double sum = 0, sum2 = 0;
  for (uint32_t y = y0; y < y1; ++y)
    for (uint32_t x = x0; x < x1; ++x) {
      const double v = img.at(x, y)[channel];
      sum += v;
      sum2 += v * v;
      ++s.count;
    }
  s.mean = sum / double(s.count);
  s.stddev = std::sqrt(std::max(0.0, sum2 / double(s.count) - s.mean * s.mean));
  return s;
}

// The walls of a small room as JSON array elements: six diffuse spheres of radius 1000 whose near
// sides bound x in [-5, 5], z in [-5, 10] and y in [0, 6].
constexpr const char* kSmallRoomWalls =
    R"({"position": [-1005, 0, 0], "radius": 1000, "color": [0.7, 0.3, 0.2]},
       {"position": [1005, 0, 0], "radius": 1000, "color": [0.3, 0.4, 0.7]},
       {"position": [0, 0, -1005], "radius": 1000, "color": 0.7},
       {"position": [0, 0, 1010], "radius": 1000, "color": 0.7},
       {"position": [0, -1000, 0], "radius": 1000, "color": 0.6},
       {"position": [0, 1006, 0], "radius": 1000, "color": 0.8})";

// The small room of kSmallRoomWalls with a ball on its floor, seen from its open side, lit by
// `lighting` (a "lights" or "objects" member); `camera` and `render` are the JSON objects' inner
// fields.
inline std::string smallRoomLitBy(const std::string& camera, const std::string& render,
                                  const std::string& lighting) {
  return R"({
    "camera": {"fov": 70, "position": [0, 2, 9], "look_at": [0, 2, 0], )" +
         camera + R"(},
    "render": {)" +
         render + R"(},
    "spheres": [)" +
         kSmallRoomWalls + R"(,
                {"position": [1, 1, -1], "radius": 1, "color": 0.5}],
    )" + lighting +
         "}";
}

// The small room lit by a point light half a unit below its ceiling, whose bright patch there
// lights the rest (the case light-vertex connections are for); `camera` and `render` as for
// smallRoomLitBy.
inline std::string lampUnderTheCeiling(const std::string& camera, const std::string& render) {
  return smallRoomLitBy(camera, render,
                        R"("lights": [{"position": [-3, 5.5, -3], "intensity": 400}])");
}

// The same room lit instead by a torus of 3,072 emitting triangles under its ceiling (the bench's
// lamp room in small), where two light samples at the first interaction pay
// (render.first_hit_light_samples); `camera` and `render` as for smallRoomLitBy.
inline std::string torusUnderTheCeiling(const std::string& camera, const std::string& render) {
  const std::string torus = writeTorusObj("torus_lamp.obj", 0, 3, -1, 2, 0.5, 64, 24);
  return smallRoomLitBy(camera, render,
                        R"("objects": [{"file": ")" + torus +
                            R"(", "material": {"type": "emissive", "radiance": 20}}])");
}

// One estimator's renders of an image with two seeds.
struct SeedPair {
  RenderResult a, b;
};

// Expects two estimators of one image (its sides multiples of `block`) to agree: each
// block x block block's mean within 5 standard errors of their difference, each pixel's variance
// estimated from its two seeds. Returns each estimator's noise: the summed variance, over pixels
// and channels, of a pixel's two-seed mean, (a - b)^2 / 4.
inline std::pair<double, double> expectSameImage(const SeedPair& first, const SeedPair& second,
                                                 uint32_t block = 8) {
  const auto meanAndVariance = [](const SeedPair& p, uint32_t x, uint32_t y, double* mean,
                                  double* variance) {
    *mean = *variance = 0;
    for (int c = 0; c < 3; ++c) {
      const double a = p.a.image.at(x, y)[c], b = p.b.image.at(x, y)[c];
      *mean += (a + b) / 2;
      *variance += (a - b) * (a - b) / 4;
    }
  };
  double noiseFirst = 0, noiseSecond = 0;
  const uint32_t width = first.a.image.width, height = first.a.image.height;
  for (uint32_t by = 0; by < height / block; ++by)
    for (uint32_t bx = 0; bx < width / block; ++bx) {
      double meanFirst = 0, meanSecond = 0, varianceOfMeans = 0;
      for (uint32_t y = by * block; y < (by + 1) * block; ++y)
        for (uint32_t x = bx * block; x < (bx + 1) * block; ++x) {
          double m, v;
          meanAndVariance(first, x, y, &m, &v);
          meanFirst += m;
          varianceOfMeans += v;
          noiseFirst += v;
          meanAndVariance(second, x, y, &m, &v);
          meanSecond += m;
          varianceOfMeans += v;
          noiseSecond += v;
        }
      const double n = double(block) * block;
      EXPECT_NEAR(meanFirst / n, meanSecond / n, 5 * std::sqrt(varianceOfMeans) / n)
          << "block " << bx << ", " << by;
    }
  return {noiseFirst, noiseSecond};
}

}  // namespace candela::test
