#include "scene/mesh_order.h"

#include <tbb/parallel_for.h>

#include <array>
#include <cstdint>
#include <vector>

#include "geometry/aabb.h"

namespace candela {

namespace {

// The 10 low bits of x spread to every third bit of 30.
uint32_t spreadBits10(uint32_t x) {
  x &= 0x3ffu;
  x = (x | (x << 16)) & 0x030000ffu;
  x = (x | (x << 8)) & 0x0300f00fu;
  x = (x | (x << 4)) & 0x030c30c3u;
  x = (x | (x << 2)) & 0x09249249u;
  return x;
}

// 30-bit Morton codes of the triangles' centroids over the centroids' box.
std::vector<uint32_t> mortonCodes(const MeshDesc& mesh) {
  const size_t count = mesh.triangles.size();
  std::vector<Vec3> centroids(count);
  tbb::parallel_for(size_t(0), count, [&](size_t i) {
    const uint32_t* v = mesh.triangles[i].v;
    centroids[i] = (mesh.positions[v[0]] + mesh.positions[v[1]] + mesh.positions[v[2]]) / 3.0f;
  });
  Bounds3 box;
  for (const Vec3& c : centroids) box.grow(c);
  const Vec3 extent = box.extent();
  Vec3 scale;
  for (int a = 0; a < 3; ++a) scale[a] = extent[a] > 0.0f ? 1023.0f / extent[a] : 0.0f;
  std::vector<uint32_t> codes(count);
  tbb::parallel_for(size_t(0), count, [&](size_t i) {
    uint32_t code = 0;
    for (int a = 0; a < 3; ++a) {
      const float cell = (centroids[i][a] - box.lo[a]) * scale[a];  // NaN (a non-finite point): 0
      code |= spreadBits10(cell > 0.0f ? uint32_t(cell < 1023.0f ? cell : 1023.0f) : 0u) << a;
    }
    codes[i] = code;
  });
  return codes;
}

}  // namespace

void orderTrianglesSpatially(MeshDesc* mesh) {
  const size_t count = mesh->triangles.size();
  if (count < 2) return;
  const std::vector<uint32_t> codes = mortonCodes(*mesh);
  // Least significant digit first, 10 bits a pass: a stable radix sort of the triangle numbers.
  std::vector<uint32_t> order(count), sorted(count);
  for (size_t i = 0; i < count; ++i) order[i] = uint32_t(i);
  for (int shift = 0; shift < 30; shift += 10) {
    std::array<uint32_t, 1025> start{};
    for (uint32_t i : order) ++start[((codes[i] >> shift) & 1023u) + 1];
    for (size_t d = 1; d < start.size(); ++d) start[d] += start[d - 1];
    for (uint32_t i : order) sorted[start[(codes[i] >> shift) & 1023u]++] = i;
    order.swap(sorted);
  }
  std::vector<MeshTriangle> triangles(count);
  tbb::parallel_for(size_t(0), count, [&](size_t i) { triangles[i] = mesh->triangles[order[i]]; });
  mesh->triangles = std::move(triangles);
}

}  // namespace candela
