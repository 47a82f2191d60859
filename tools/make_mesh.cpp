// candela_make_mesh: writes the default scene's procedural mesh, a twisted trefoil knot, as OBJ.
//
// The shape is a tube around the (2,3) torus knot whose cross-section has three lobes that turn
// around the tube as it runs, like a twisted rope. The mesh is a closed, watertight grid of
// kAlong x kAround vertices (each shared by six triangles, no seams), with per-vertex normals
// (area-weighted averages of the adjacent face normals) and counter-clockwise winding seen from
// outside, so each face's right-hand-rule normal points out of the tube. Units: the knot lies
// around the origin with z as its axis of threefold symmetry, spanning about [-3.0, 3.5] in x,
// [-3.4, 3.4] in y and [-1.6, 1.6] in z; strands stay at least 0.4 apart (no self-intersection).
//
// The output is a pure function of the constants below: numbers are printed with a fixed number
// of decimals, so the file is byte-for-byte reproducible (a CTest test checks the committed copy).
//
// Usage: candela_make_mesh [OUT.obj]   (standard output when no path is given)
#include <cmath>
#include <cstdio>
#include <vector>

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kP = 2, kQ = 3;          // torus knot: winds kP times around the axis, kQ through the hole
constexpr double kMajor = 2.0;         // torus radius the knot lies on
constexpr double kMinor = 1.0;         // how far the knot swings away from that radius
constexpr double kTube = 0.55;         // mean tube radius
constexpr double kLobeDepth = 0.12;    // lobe amplitude, relative to kTube
constexpr int kLobes = 3;              // lobes in the cross-section
constexpr int kTwists = 10;            // full turns of the lobes along the whole knot (integer: closes)
constexpr int kAlong = 180, kAround = 12;  // grid resolution: 2 * 180 * 12 = 4320 triangles

struct V3 {
  double x, y, z;
};
V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
V3 operator*(double s, V3 a) { return {s * a.x, s * a.y, s * a.z}; }
double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 cross(V3 a, V3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
double length(V3 a) { return std::sqrt(dot(a, a)); }
V3 normalize(V3 a) { return (1.0 / length(a)) * a; }

// The knot curve and its first two derivatives at parameter t in [0, 2 pi).
V3 knot(double t) {
  double r = kMajor + kMinor * std::cos(kQ * t);
  return {r * std::cos(kP * t), r * std::sin(kP * t), kMinor * std::sin(kQ * t)};
}
V3 knotD1(double t) {
  double r = kMajor + kMinor * std::cos(kQ * t), dr = -kQ * kMinor * std::sin(kQ * t);
  return {dr * std::cos(kP * t) - kP * r * std::sin(kP * t),
          dr * std::sin(kP * t) + kP * r * std::cos(kP * t), kQ * kMinor * std::cos(kQ * t)};
}
V3 knotD2(double t) {
  double r = kMajor + kMinor * std::cos(kQ * t), dr = -kQ * kMinor * std::sin(kQ * t);
  double ddr = -kQ * kQ * kMinor * std::cos(kQ * t);
  double c = std::cos(kP * t), s = std::sin(kP * t);
  return {ddr * c - 2 * kP * dr * s - kP * kP * r * c, ddr * s + 2 * kP * dr * c - kP * kP * r * s,
          -kQ * kQ * kMinor * std::sin(kQ * t)};
}

// Rounds to the printed precision and turns -0 into 0, so equal values always print alike.
double clean(double v) {
  double r = std::round(v * 1e5) / 1e5;
  return r == 0 ? 0.0 : r;
}

int vertexIndex(int i, int j) { return (i % kAlong) * kAround + (j % kAround); }

}  // namespace

int main(int argc, char** argv) {
  if (argc > 2) {
    std::fprintf(stderr, "usage: %s [OUT.obj]\n", argv[0]);
    return 2;
  }
  // Vertices: a ring of kAround points around the curve at each of kAlong stations. The ring is
  // laid out in the Frenet frame (N, B), which closes on itself because the curve does.
  std::vector<V3> pos;
  for (int i = 0; i < kAlong; ++i) {
    double t = 2 * kPi * i / kAlong;
    V3 d1 = knotD1(t), d2 = knotD2(t);
    V3 tangent = normalize(d1);
    V3 binormal = normalize(cross(d1, d2));  // the knot's curvature never vanishes
    V3 normal = cross(binormal, tangent);
    for (int j = 0; j < kAround; ++j) {
      double v = 2 * kPi * j / kAround;
      double radius = kTube * (1 + kLobeDepth * std::cos(kLobes * v + kTwists * t));
      V3 offset = radius * (std::cos(v) * normal + std::sin(v) * binormal);
      V3 p = knot(t) + offset;
      pos.push_back({clean(p.x), clean(p.y), clean(p.z)});
    }
  }
  // Two triangles per grid cell. Along v the ring turns from N to B, and N x B = T, so going
  // (i,j) -> (i,j+1) -> (i+1,j+1) is counter-clockwise seen from outside the tube.
  std::vector<int> tris;
  for (int i = 0; i < kAlong; ++i) {
    for (int j = 0; j < kAround; ++j) {
      int a = vertexIndex(i, j), b = vertexIndex(i, j + 1);
      int c = vertexIndex(i + 1, j + 1), d = vertexIndex(i + 1, j);
      tris.insert(tris.end(), {a, b, c, a, c, d});
    }
  }
  // Vertex normals: the sum of the adjacent faces' cross products weights each face by its area.
  std::vector<V3> nrm(pos.size(), V3{0, 0, 0});
  double volume6 = 0;  // six times the enclosed volume: positive iff the faces point outwards
  for (size_t f = 0; f < tris.size(); f += 3) {
    V3 p0 = pos[tris[f]], p1 = pos[tris[f + 1]], p2 = pos[tris[f + 2]];
    V3 n = cross(p1 - p0, p2 - p0);
    for (int k = 0; k < 3; ++k) nrm[tris[f + k]] = nrm[tris[f + k]] + n;
    volume6 += dot(p0, cross(p1, p2));
  }
  for (V3& n : nrm) {
    n = normalize(n);
    n = {clean(n.x), clean(n.y), clean(n.z)};
  }
  // Refuse to write a mesh whose winding disagrees with its normals.
  for (size_t f = 0; f < tris.size(); f += 3) {
    V3 n = cross(pos[tris[f + 1]] - pos[tris[f]], pos[tris[f + 2]] - pos[tris[f]]);
    for (int k = 0; k < 3; ++k) {
      if (dot(n, nrm[tris[f + k]]) <= 0) {
        std::fprintf(stderr, "make_mesh: face %zu is wound against its vertex normals\n", f / 3);
        return 1;
      }
    }
  }
  if (volume6 <= 0) {
    std::fprintf(stderr, "make_mesh: the faces point inwards\n");
    return 1;
  }

  FILE* out = argc == 2 ? std::fopen(argv[1], "wb") : stdout;
  if (!out) {
    std::fprintf(stderr, "make_mesh: cannot write %s\n", argv[1]);
    return 1;
  }
  std::fprintf(out, "# Twisted trefoil knot, written by candela's tools/make_mesh.cpp. Do not edit:\n");
  std::fprintf(out, "# regenerate with `build/candela_make_mesh scenes/meshes/trefoil.obj`.\n");
  std::fprintf(out, "# %zu vertices, %zu triangles, counter-clockwise seen from outside.\n",
               pos.size(), tris.size() / 3);
  std::fprintf(out, "o trefoil\n");
  for (const V3& p : pos) std::fprintf(out, "v %.5f %.5f %.5f\n", p.x, p.y, p.z);
  for (const V3& n : nrm) std::fprintf(out, "vn %.5f %.5f %.5f\n", n.x, n.y, n.z);
  for (size_t f = 0; f < tris.size(); f += 3) {
    int a = tris[f] + 1, b = tris[f + 1] + 1, c = tris[f + 2] + 1;  // OBJ indices start at 1
    std::fprintf(out, "f %d//%d %d//%d %d//%d\n", a, a, b, b, c, c);
  }
  bool ok = std::ferror(out) == 0;
  if (out != stdout) ok = std::fclose(out) == 0 && ok;
  if (!ok) {
    std::fprintf(stderr, "make_mesh: error while writing the mesh\n");
    return 1;
  }
  return 0;
}
