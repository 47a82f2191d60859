#include "scene/vertex_normals.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "core/constants.h"
#include "scene/dvec3.h"

namespace candela {
namespace {

bool sameValue(const Vec3& a, const Vec3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

// A float's bits as a hash key, -0 as +0 (they compare equal).
uint32_t keyBits(float f) {
  f += 0.0f;
  uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  return u;
}

// For each position, the index of the first position of equal value (open addressing: a
// std::unordered_map took 6-10 ms for the dragon's 50,000 positions).
std::vector<uint32_t> weldPositions(const std::vector<Vec3>& positions) {
  size_t capacity = 16;
  while (capacity < 2 * positions.size()) capacity *= 2;
  constexpr uint32_t kEmpty = ~0u;
  std::vector<uint32_t> slots(capacity, kEmpty), weld(positions.size());
  for (uint32_t i = 0; i < positions.size(); ++i) {
    const Vec3& p = positions[i];
    const uint64_t hash = (keyBits(p.x) * 0x9e3779b97f4a7c15ull) ^
                          (keyBits(p.y) * 0xc2b2ae3d27d4eb4full) ^
                          (keyBits(p.z) * 0x165667b19e3779f9ull);
    size_t slot = (hash >> 32) & (capacity - 1);
    while (slots[slot] != kEmpty && !sameValue(positions[slots[slot]], p))
      slot = (slot + 1) & (capacity - 1);
    if (slots[slot] == kEmpty) slots[slot] = i;
    weld[i] = slots[slot];
  }
  return weld;
}

// A triangle's unit normal and its angle at each corner (computed in double, so that tiny and
// huge triangles alike keep their directions); hasArea is false for a triangle of no area.
struct FaceShape {
  Vec3 normal;
  float angle[3] = {0, 0, 0};
  bool hasArea = false;
};

FaceShape faceShape(const MeshDesc& mesh, const MeshTriangle& t) {
  FaceShape s;
  const Vec3 &p0 = mesh.positions[t.v[0]], &p1 = mesh.positions[t.v[1]],
             &p2 = mesh.positions[t.v[2]];
  // Edge k leaves corner k.
  const DVec3 edge[3] = {dvec3(p1) - dvec3(p0), dvec3(p2) - dvec3(p1), dvec3(p0) - dvec3(p2)};
  const DVec3 n = cross(edge[2], edge[0]);  // edge 0 x -edge 2
  const double length = std::sqrt(dot(n, n));
  if (!(length > 0 && length <= 1e300)) return s;
  s.normal = Vec3(float(n.x / length), float(n.y / length), float(n.z / length));
  s.hasArea = true;
  double edgeLength[3];
  for (int k = 0; k < 3; ++k) edgeLength[k] = std::sqrt(dot(edge[k], edge[k]));
  // The angle at corner k lies between edge k and the reversed edge k - 1.
  for (int k = 0; k < 3; ++k) {
    const int previous = (k + 2) % 3;
    const double c = -dot(edge[k], edge[previous]) / (edgeLength[k] * edgeLength[previous]);
    s.angle[k] = std::acos(float(std::clamp(c, -1.0, 1.0)));
  }
  return s;
}

// The most faces at one position whose corners are each weighed against all the others there.
constexpr uint32_t kMostFacesCreasedAtAVertex = 4096;

}  // namespace

MeshDesc withComputedNormals(const MeshDesc& mesh, float creaseDegrees) {
  const size_t triangleCount = mesh.triangles.size(), positionCount = mesh.positions.size();
  std::vector<FaceShape> shapes(triangleCount);
  tbb::parallel_for(size_t(0), triangleCount, [&](size_t f) {
    if (mesh.triangles[f].n[0] < 0) shapes[f] = faceShape(mesh, mesh.triangles[f]);
  });

  // The corners of the triangles to shade, grouped by welded position (a counting sort).
  const std::vector<uint32_t> weld = weldPositions(mesh.positions);
  std::vector<uint32_t> start(positionCount + 1, 0);
  for (size_t f = 0; f < triangleCount; ++f)
    if (shapes[f].hasArea)
      for (uint32_t v : mesh.triangles[f].v) ++start[weld[v] + 1];
  for (size_t w = 0; w < positionCount; ++w) start[w + 1] += start[w];
  struct Corner {
    uint32_t face, k;
  };
  std::vector<Corner> corners(start.back());
  {
    std::vector<uint32_t> next(start.begin(), start.end() - 1);
    for (uint32_t f = 0; f < triangleCount; ++f)
      if (shapes[f].hasArea)
        for (uint32_t k = 0; k < 3; ++k) corners[next[weld[mesh.triangles[f].v[k]]]++] = {f, k};
  }

  // Each corner's normal. A little below the crease's cosine, so that faces meeting at exactly
  // the crease angle (a cube's at 90 degrees) are smoothed whichever way their products round.
  const double crease = double(creaseDegrees) * (kPi / 180.0);
  const double minCos = std::cos(crease) - 1e-6;
  std::vector<Vec3> cornerNormals(corners.size());
  const auto unit = [](double x, double y, double z, const Vec3& fallback) {
    const double length = std::sqrt(x * x + y * y + z * z);
    return length > 1e-9 ? Vec3(float(x / length), float(y / length), float(z / length)) : fallback;
  };
  // The angle-weighted sum of the unit normals of the faces at corners [first, end), those within
  // the crease of `own` only where one is given.
  const auto weighedSum = [&](uint32_t first, uint32_t end, const Vec3* own) {
    DVec3 sum{0, 0, 0};
    for (uint32_t o = first; o < end; ++o) {
      const FaceShape& other = shapes[corners[o].face];
      if (own && double(dot(*own, other.normal)) < minCos) continue;
      const double weight = other.angle[corners[o].k];
      sum = {sum.x + weight * other.normal.x, sum.y + weight * other.normal.y,
             sum.z + weight * other.normal.z};
    }
    return sum;
  };
  tbb::parallel_for(size_t(0), positionCount, [&](size_t w) {
    const uint32_t first = start[w], end = start[w + 1];
    if (first == end) return;
    // The cone holding the faces' normals here (axis, half-angle spread): a corner whose own
    // normal lies within the crease less the spread of the axis has every face within the crease,
    // and takes the sum over all of them, which weighedSum adds in the same order either way. So
    // a smooth vertex costs its faces, not their square, however many meet there.
    DVec3 m{0, 0, 0};
    for (uint32_t o = first; o < end; ++o) {
      const Vec3& n = shapes[corners[o].face].normal;
      m = {m.x + n.x, m.y + n.y, m.z + n.z};
    }
    const Vec3 axis = unit(m.x, m.y, m.z, Vec3(0.0f));
    double spread = isBlack(axis) ? kPi : 0.0;
    for (uint32_t o = first; o < end && spread < crease; ++o)
      spread = std::max(spread, std::acos(std::clamp(
                                    double(dot(axis, shapes[corners[o].face].normal)), -1.0, 1.0)));
    const DVec3 all = weighedSum(first, end, nullptr);
    for (uint32_t c = first; c < end; ++c) {
      const Vec3& own = shapes[corners[c].face].normal;
      const double fromAxis = std::acos(std::clamp(double(dot(own, axis)), -1.0, 1.0));
      const bool allWithin = minCos <= -1.0 || fromAxis + spread <= crease;
      if (!allWithin && end - first > kMostFacesCreasedAtAVertex) {
        // A vertex of more faces than modelling makes, with faces on both sides of the crease:
        // its own face's normal, rather than a wait quadratic in its faces.
        cornerNormals[c] = own;
        continue;
      }
      const DVec3 sum = allWithin ? all : weighedSum(first, end, &own);
      cornerNormals[c] = unit(sum.x, sum.y, sum.z, own);
    }
  });

  // The normals, once per position and value: where every face is smoothed, one per vertex. A
  // corner looks among the first few made at its position only, so that a position of thousands
  // of creased faces costs no square of them (its later normals may repeat a value: more
  // vertices, the same image).
  constexpr size_t kNormalsSearched = 32;
  MeshDesc out = mesh;
  out.normals.reserve(out.normals.size() + positionCount);
  for (size_t w = 0; w < positionCount; ++w) {
    const size_t first = out.normals.size();
    for (uint32_t c = start[w]; c < start[w + 1]; ++c) {
      const Vec3& n = cornerNormals[c];
      const size_t searched = std::min(out.normals.size(), first + kNormalsSearched);
      size_t index = first;
      while (index < searched && !sameValue(out.normals[index], n)) ++index;
      if (index == searched) {
        index = out.normals.size();
        out.normals.push_back(n);
      }
      out.triangles[corners[c].face].n[corners[c].k] = int32_t(index);
    }
  }
  return out;
}

}  // namespace candela
