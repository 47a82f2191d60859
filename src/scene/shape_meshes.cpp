// Built-in shapes as meshes; see shape_meshes.h.
#include "scene/shape_meshes.h"

#include <cmath>

#include "core/constants.h"

namespace candela {
namespace {

// Appends the corner (position, uv) and returns the index of both.
uint32_t addCorner(MeshDesc& mesh, Vec3 position, Vec2 uv) {
  mesh.positions.push_back(position);
  mesh.uvs.push_back(uv);
  return uint32_t(mesh.positions.size() - 1);
}

// Appends the flat triangle (a, b, c) of corners made by addCorner, its front where
// (b - a) x (c - a) points.
void addFlatTriangle(MeshDesc& mesh, uint32_t a, uint32_t b, uint32_t c) {
  MeshTriangle t;
  t.v[0] = a, t.v[1] = b, t.v[2] = c;
  t.n[0] = t.n[1] = t.n[2] = -1;
  t.t[0] = int32_t(a), t.t[1] = int32_t(b), t.t[2] = int32_t(c);
  t.material = 0;
  mesh.triangles.push_back(t);
}

// A flat quadrilateral centred on `centre`, u running along `halfU` and v along `halfV` (half its
// sides), its front towards halfU x halfV.
void addQuad(MeshDesc& mesh, Vec3 centre, Vec3 halfU, Vec3 halfV) {
  const uint32_t a = addCorner(mesh, centre - halfU - halfV, Vec2(0.0f, 0.0f));
  const uint32_t b = addCorner(mesh, centre + halfU - halfV, Vec2(1.0f, 0.0f));
  const uint32_t c = addCorner(mesh, centre + halfU + halfV, Vec2(1.0f, 1.0f));
  const uint32_t d = addCorner(mesh, centre - halfU + halfV, Vec2(0.0f, 1.0f));
  addFlatTriangle(mesh, a, b, c);
  addFlatTriangle(mesh, a, c, d);
}

// The circle of radius 0.5 about the y axis at angle `i` of kShapeCircleSegments: from -z at 0,
// through -x, +z and +x, so that angles rise counter-clockwise seen from +y.
Vec3 rimDirection(int i) {
  const double phi = 2.0 * kPi * double(i % kShapeCircleSegments) / kShapeCircleSegments;
  return Vec3(float(-std::sin(phi)), 0.0f, float(-std::cos(phi)));
}

// A disk of radius 0.5 centred at height y, facing +y (`up`) or -y, fanned from its centre; its uvs
// those of the square it is inscribed in as addQuad lays it: u along +x, v along -z facing up and
// along +z facing down.
void addDisk(MeshDesc& mesh, float y, bool up) {
  const float vz = up ? -1.0f : 1.0f;  // v's direction along z
  const auto corner = [&](Vec3 p) { return addCorner(mesh, p, Vec2(p.x + 0.5f, p.z * vz + 0.5f)); };
  const uint32_t centre = corner(Vec3(0.0f, y, 0.0f));
  const uint32_t first = uint32_t(mesh.positions.size());
  for (int i = 0; i < kShapeCircleSegments; ++i) corner(rimDirection(i) * 0.5f + Vec3(0, y, 0));
  for (int i = 0; i < kShapeCircleSegments; ++i) {
    const uint32_t a = first + uint32_t(i);
    const uint32_t b = first + uint32_t((i + 1) % kShapeCircleSegments);
    if (up)
      addFlatTriangle(mesh, centre, a, b);
    else
      addFlatTriangle(mesh, centre, b, a);
  }
}

MeshDesc rectangle() {
  MeshDesc mesh;
  addQuad(mesh, Vec3(0.0f), Vec3(0.5f, 0, 0), Vec3(0, 0, -0.5f));
  return mesh;
}

MeshDesc cube() {
  MeshDesc mesh;
  const float h = 0.5f;
  // Each face upright seen from outside with +y up; the top as the rectangle, the bottom seen
  // from below with +z up.
  addQuad(mesh, Vec3(0, 0, h), Vec3(h, 0, 0), Vec3(0, h, 0));
  addQuad(mesh, Vec3(0, 0, -h), Vec3(-h, 0, 0), Vec3(0, h, 0));
  addQuad(mesh, Vec3(h, 0, 0), Vec3(0, 0, -h), Vec3(0, h, 0));
  addQuad(mesh, Vec3(-h, 0, 0), Vec3(0, 0, h), Vec3(0, h, 0));
  addQuad(mesh, Vec3(0, h, 0), Vec3(h, 0, 0), Vec3(0, 0, -h));
  addQuad(mesh, Vec3(0, -h, 0), Vec3(h, 0, 0), Vec3(0, 0, h));
  return mesh;
}

MeshDesc disk() {
  MeshDesc mesh;
  addDisk(mesh, 0.0f, true);
  return mesh;
}

// A closed cylinder: its side shaded by the circle's normals, u once around from the seam at -z
// (so a label's middle faces +z) and v up; its caps flat, as disks.
MeshDesc cylinder() {
  MeshDesc mesh;
  const uint32_t first = uint32_t(mesh.positions.size());
  for (int i = 0; i <= kShapeCircleSegments; ++i) {
    const Vec3 d = rimDirection(i);
    const float u = float(i) / kShapeCircleSegments;
    addCorner(mesh, d * 0.5f + Vec3(0, -0.5f, 0), Vec2(u, 0.0f));
    addCorner(mesh, d * 0.5f + Vec3(0, 0.5f, 0), Vec2(u, 1.0f));
    mesh.normals.push_back(d);
  }
  // Corner k of the triangle (v, n): its position and uv v[k], its normal n[k].
  const auto addSmoothTriangle = [&](const uint32_t(&v)[3], const int32_t(&n)[3]) {
    MeshTriangle t;
    for (int k = 0; k < 3; ++k) {
      t.v[k] = v[k];
      t.n[k] = n[k];
      t.t[k] = int32_t(v[k]);
    }
    t.material = 0;
    mesh.triangles.push_back(t);
  };
  for (int i = 0; i < kShapeCircleSegments; ++i) {
    const uint32_t b0 = first + 2 * uint32_t(i), t0 = b0 + 1, b1 = b0 + 2, t1 = b0 + 3;
    addSmoothTriangle({b0, b1, t1}, {i, i + 1, i + 1});
    addSmoothTriangle({b0, t1, t0}, {i, i + 1, i});
  }
  addDisk(mesh, 0.5f, true);
  addDisk(mesh, -0.5f, false);
  return mesh;
}

}  // namespace

const std::vector<std::string>& shapeNames() {
  static const std::vector<std::string> names = {"rectangle", "disk", "cube", "cylinder"};
  return names;
}

MeshDesc shapeMesh(const std::string& name) {
  MeshDesc mesh = name == "rectangle" ? rectangle()
                  : name == "disk"    ? disk()
                  : name == "cube"    ? cube()
                                      : cylinder();
  mesh.materials.push_back(Material{});
  return mesh;
}

}  // namespace candela
