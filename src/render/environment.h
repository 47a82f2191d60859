// The environment: the radiance of every ray that leaves the scene, constant or from an
// equirectangular (latitude-longitude) map, and a light that next-event estimation samples.
//
// Mapping (docs/scene-format.md, *Environment*): a direction d in the map's frame (+y up) looks
// up u = 0.5 + atan2(d.x, -d.z) / (2 pi) wrapped into [0, 1), v = acos(d.y) / pi, where (0, 0) is
// the image's top-left corner and texel (i, j) covers [i/W, (i+1)/W) x [j/H, (j+1)/H): the
// image's centre lies along -z, +x right of it, the top row straight up. The map's frame is the
// world turned by the environment's rotation. Lookups are bilinear (wrapping in u); sampling
// follows a distribution over cells of the map (texels split into up to 4 x 4), bilinear within
// each as the lookup is, weighted by sin(theta), so a sun in the map is found by shadow rays
// rather than by chance, and each shadow ray carries nearly the same radiance / pdf. That
// distribution is MIS-compensated (scene/flatten_environment.cpp): it leaves out what is dimmer
// than the map's mean, which only BSDF sampling then finds, so the environment light is valid
// only beside BSDF sampling.
#pragma once

#include <cmath>
#include <cstdint>

#include "core/constants.h"
#include "core/distribution2d.h"
#include "core/mat3.h"
#include "core/trig.h"
#include "core/vec3.h"

namespace candela {

// The map's sampling grid (below): columns x rows cells, shifted by half a cell where texels are
// not split.
struct EnvironmentGrid {
  uint32_t columns = 0, rows = 0;
  bool shifted = false;
};

struct Environment {
  Vec3 radiance{0.0f};  // the constant radiance; with a map, the factor of every texel
  Mat3 toWorld;         // map frame -> world (the rotation); fromWorld is its transpose
  Mat3 fromWorld;
  uint32_t width = 0, height = 0;  // of the map; 0: a constant environment
  EnvironmentGrid grid;            // of its sampling distribution
  int32_t light = -1;              // its index among the lights; -1: black, not a light
  bool hiddenFromCamera = false;   // camera rays that leave the scene see black ("visible")
};

// The map coordinates of a unit direction in the map's frame. theta comes from atan2, not acos,
// which loses the precision near the poles that the sampling pdf's 1/sin(theta) needs; both
// angles by core/trig.h's polynomial, accurate to a millionth of a texel of any map.
CANDELA_HDI_ALWAYS void directionToMap(const Vec3& d, float* u, float* v) {
  float x = 0.5f + atan2Approx(d.x, -d.z) * (0.5f * kInvPi);
  x -= floorf(x);
  *u = x < 1.0f ? x : 0.0f;
  const float y = atan2Approx(sqrtf(d.x * d.x + d.z * d.z), d.y) * kInvPi;
  *v = y < 1.0f ? y : 0.99999994f;
}

// The unit direction in the map's frame of map point (u, v), and sin(theta) there.
CANDELA_HDI Vec3 mapToDirection(float u, float v, float* sinTheta) {
  const float theta = kPi * v, phi = 2.0f * kPi * (u - 0.5f);
  *sinTheta = sinf(theta);
  return {*sinTheta * sinf(phi), cosf(theta), -*sinTheta * cosf(phi)};
}

// Bilinear lookup of map point (u, v) in texels (width x height, rows from the top).
CANDELA_HDI_ALWAYS Vec3 lookupMap(const Vec3* texels, uint32_t width, uint32_t height, float u, float v) {
  const float x = u * float(width) - 0.5f, y = v * float(height) - 0.5f;
  const float x0f = floorf(x), y0f = floorf(y);
  const float fx = x - x0f, fy = y - y0f;
  const int32_t w = int32_t(width), h = int32_t(height);
  int32_t x0 = int32_t(x0f) % w;
  if (x0 < 0) x0 += w;
  const int32_t x1 = x0 + 1 < w ? x0 + 1 : 0;
  const int32_t y0 = y0f < 0.0f ? 0 : (int32_t(y0f) < h ? int32_t(y0f) : h - 1);
  const int32_t y1 = y0 + 1 < h ? (y0f < 0.0f ? 0 : y0 + 1) : h - 1;
  const Vec3 top =
      (1.0f - fx) * texels[size_t(y0) * width + x0] + fx * texels[size_t(y0) * width + x1];
  const Vec3 bottom =
      (1.0f - fx) * texels[size_t(y1) * width + x0] + fx * texels[size_t(y1) * width + x1];
  return (1.0f - fy) * top + fy * bottom;
}

// The map's sampling grid (scene/flatten_environment.cpp) has the texel centres among its cells'
// corners, so that each cell lies within one of the lookup's bilinear patches. Texels split into
// k x k cells (k even) give that as they are; unsplit texels need the grid shifted by half a cell,
// its first and last rows half as tall: they reach the poles from the first and last rows of
// texel centres.

// The density over the map of a point of row `row` per unit of the grid's density, whose rows
// are all of one height: 1 unless the grid is shifted.
CANDELA_HDI_ALWAYS float mapDensityPerGridDensity(const Environment& e, uint32_t row) {
  if (!e.grid.shifted) return 1.0f;
  const bool half = row == 0 || row == e.grid.rows - 1;
  return float(e.grid.rows - 1) / float(e.grid.rows) * (half ? 2.0f : 1.0f);
}

// The map point (u, v) of point (s, t) of cell (column, row).
CANDELA_HDI_ALWAYS void cellToMap(const Environment& e, uint32_t column, uint32_t row, float s,
                                  float t, float* u, float* v) {
  const bool shifted = e.grid.shifted;
  float x = (float(column) + (shifted ? 0.5f + s : s)) / float(e.grid.columns);
  x = x < 1.0f ? x : x - 1.0f;
  *u = x < 1.0f ? x : 0.0f;
  // In units of full rows: a shifted grid's first and last rows are halves.
  float y = float(row) + t;
  if (shifted)
    y = row == 0 ? 0.5f * t : (row == e.grid.rows - 1 ? y - 0.5f * (1.0f + t) : y - 0.5f);
  y /= float(shifted ? e.grid.rows - 1 : e.grid.rows);
  *v = y < 1.0f ? y : 0.99999994f;
}

// The cell (column, row) that holds map point (u, v) and the point (s, t) within it: cellToMap's
// inverse.
CANDELA_HDI_ALWAYS void mapToCell(const Environment& e, float u, float v, uint32_t* column,
                                  uint32_t* row, float* s, float* t) {
  const bool shifted = e.grid.shifted;
  float x = u * float(e.grid.columns) - (shifted ? 0.5f : 0.0f);
  x = x < 0.0f ? x + float(e.grid.columns) : x;
  *column = uint32_t(x) < e.grid.columns ? uint32_t(x) : e.grid.columns - 1;
  *s = minf(maxf(x - float(*column), 0.0f), 1.0f);
  const float y = shifted ? v * float(e.grid.rows - 1) + 0.5f : v * float(e.grid.rows);
  *row = uint32_t(y) < e.grid.rows ? uint32_t(y) : e.grid.rows - 1;
  float within = y - float(*row);
  if (shifted && *row == 0) within = 2.0f * within - 1.0f;
  if (shifted && *row == e.grid.rows - 1) within = 2.0f * within;
  *t = minf(maxf(within, 0.0f), 1.0f);
}

}  // namespace candela
