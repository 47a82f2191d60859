// candela_make_sky OUT.(exr|pfm): writes the procedural sky of scenes/examples/sky.json, an
// equirectangular map (docs/scene-format.md, *Environment*) of 256 x 128 texels.
// candela_make_sky --check FILE: exit 0 when FILE's pixels are exactly this sky's, else 1.
//
// A clear sky, brighter and whiter towards the horizon, over a darker ground, with a sun of
// angular radius 1.5 degrees at 30 degrees elevation to the right of the map's centre (-z).
// Radiance is in the same units as candela's emitters; each texel averages 4 x 4 directions, so
// the sun's edge is antialiased. The committed scenes/skies/sky.exr is this program's output; a
// test (--check) regenerates it and compares the pixels.
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>

#include "core/constants.h"
#include "core/vec3.h"
#include "image/image.h"
#include "image/image_io.h"

namespace {

using candela::Vec3;

constexpr float kSunElevation = 30.0f, kSunAzimuth = 35.0f, kSunRadius = 1.5f;  // degrees
constexpr float kSunRadiance = 2500.0f;

float radians(float degrees) { return degrees * candela::kPi / 180.0f; }

// The sun's direction: azimuth measured from -z towards +x, as the map's u is.
Vec3 sunDirection() {
  const float e = radians(kSunElevation), a = radians(kSunAzimuth);
  return {std::cos(e) * std::sin(a), std::sin(e), -std::cos(e) * std::cos(a)};
}

Vec3 skyRadiance(const Vec3& d) {
  const Vec3 sun = sunDirection();
  const float cosSun = d.x * sun.x + d.y * sun.y + d.z * sun.z;
  if (cosSun >= std::cos(radians(kSunRadius)))
    return Vec3(kSunRadiance, kSunRadiance * 0.95f, kSunRadiance * 0.85f);
  if (d.y < 0.0f) {
    const float fade = std::exp(d.y * 12.0f);  // the haze of the horizon over the ground
    return Vec3(0.10f, 0.09f, 0.07f) * (1.0f - fade) + Vec3(0.6f, 0.65f, 0.7f) * fade;
  }
  const float towardsHorizon = std::pow(1.0f - d.y, 4.0f);
  const Vec3 zenith(0.12f, 0.25f, 0.6f), horizon(0.6f, 0.65f, 0.7f);
  const Vec3 glow = Vec3(1.0f, 0.9f, 0.7f) * (0.8f * std::exp((cosSun - 1.0f) * 20.0f));
  return zenith * (1.0f - towardsHorizon) + horizon * towardsHorizon + glow;
}

}  // namespace

candela::ImageRGB makeSky() {
  constexpr uint32_t kWidth = 256, kHeight = 128, kSub = 4;
  candela::ImageRGB image(kWidth, kHeight);
  for (uint32_t j = 0; j < kHeight; ++j)
    for (uint32_t i = 0; i < kWidth; ++i) {
      Vec3 sum(0.0f);
      for (uint32_t sj = 0; sj < kSub; ++sj)
        for (uint32_t si = 0; si < kSub; ++si) {
          // The mapping's inverse: u = 0.5 + phi / (2 pi), v = theta / pi.
          const float u = (i + (si + 0.5f) / kSub) / kWidth, v = (j + (sj + 0.5f) / kSub) / kHeight;
          const float theta = candela::kPi * v, phi = 2.0f * candela::kPi * (u - 0.5f);
          sum += skyRadiance(
              {std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi)});
        }
      image.set(i, j, sum / float(kSub * kSub));
    }
  return image;
}

int main(int argc, char** argv) {
  const bool check = argc == 3 && std::string(argv[1]) == "--check";
  if (argc != 2 && !check) {
    std::fprintf(stderr, "usage: candela_make_sky OUT.(exr|pfm) | --check FILE\n");
    return 2;
  }
  const char* path = argv[argc - 1];
  const candela::ImageRGB sky = makeSky();
  try {
    if (!check) {
      candela::writeImage(path, sky, candela::OutputDesc{});
      return 0;
    }
    const candela::ImageRGB file = candela::readImage(path);
    if (file.width == sky.width && file.height == sky.height && file.pixels == sky.pixels) return 0;
    std::fprintf(stderr, "candela_make_sky: %s differs from the generated sky\n", path);
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "candela_make_sky: %s\n", e.what());
    return 1;
  }
}
