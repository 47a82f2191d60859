// Normals computed for meshes whose file gives none (scene/vertex_normals.h), against closed forms:
// a tessellated sphere's vertex normals are its radii, a cube's corners keep their faces' normals
// below a 90-degree crease and take the diagonal at it, and a seam of repeated vertices shades as
// one surface. The scene's `smooth` angle reaches the renderer's arrays.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "scene/flatten.h"
#include "scene/read/scene_loader.h"
#include "scene/scene_error.h"
#include "scene/vertex_normals.h"

namespace candela {
namespace {

MeshTriangle flatTriangle(uint32_t a, uint32_t b, uint32_t c) {
  return MeshTriangle{{a, b, c}, {-1, -1, -1}, 0};
}

// A latitude-longitude sphere of unit radius, counter-clockwise seen from outside.
MeshDesc uvSphere(int rings, int segments) {
  MeshDesc m;
  m.positions.push_back(Vec3(0, 1, 0));
  for (int i = 1; i < rings; ++i) {
    const double theta = kPi * i / rings;
    for (int j = 0; j < segments; ++j) {
      const double phi = 2 * kPi * j / segments;
      m.positions.push_back(Vec3(float(std::sin(theta) * std::cos(phi)), float(std::cos(theta)),
                                 float(-std::sin(theta) * std::sin(phi))));
    }
  }
  m.positions.push_back(Vec3(0, -1, 0));
  const auto at = [&](int ring, int j) {
    return uint32_t(1 + (ring - 1) * segments + j % segments);
  };
  const uint32_t south = uint32_t(m.positions.size() - 1);
  for (int j = 0; j < segments; ++j) {
    m.triangles.push_back(flatTriangle(0, at(1, j), at(1, j + 1)));
    for (int i = 1; i + 1 < rings; ++i) {
      m.triangles.push_back(flatTriangle(at(i, j), at(i + 1, j), at(i + 1, j + 1)));
      m.triangles.push_back(flatTriangle(at(i, j), at(i + 1, j + 1), at(i, j + 1)));
    }
    m.triangles.push_back(flatTriangle(at(rings - 1, j), south, at(rings - 1, j + 1)));
  }
  return m;
}

// The side of a cylinder of unit radius around y, `rings` rows of quads, the first column of
// vertices repeated as a last one (as exporters write a uv seam).
MeshDesc cylinderWithSeam(int rings, int segments) {
  MeshDesc m;
  for (int i = 0; i <= rings; ++i)
    for (int j = 0; j <= segments; ++j) {
      const double phi = 2 * kPi * (j % segments) / segments;
      m.positions.push_back(Vec3(float(std::cos(phi)), float(i), float(-std::sin(phi))));
    }
  const auto at = [&](int i, int j) { return uint32_t(i * (segments + 1) + j); };
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      m.triangles.push_back(flatTriangle(at(i, j), at(i, j + 1), at(i + 1, j + 1)));
      m.triangles.push_back(flatTriangle(at(i, j), at(i + 1, j + 1), at(i + 1, j)));
    }
  return m;
}

Vec3 faceNormalOf(const MeshDesc& m, const MeshTriangle& t) {
  return normalize(
      cross(m.positions[t.v[1]] - m.positions[t.v[0]], m.positions[t.v[2]] - m.positions[t.v[0]]));
}

// The largest angle, in degrees, between a corner's normal and `radius` at its position.
template <typename Radius>
double worstAngle(const MeshDesc& m, Radius radius) {
  double worst = 0;
  for (const MeshTriangle& t : m.triangles)
    for (int k = 0; k < 3; ++k) {
      const Vec3 n = t.n[k] >= 0 ? m.normals[t.n[k]] : faceNormalOf(m, t);
      const double c = std::fmin(1.0, double(dot(normalize(n), radius(m.positions[t.v[k]]))));
      worst = std::fmax(worst, std::acos(c) * 180 / kPi);
    }
  return worst;
}

double worstAngleOnSphere(const MeshDesc& m) {
  return worstAngle(m, [](const Vec3& p) { return normalize(p); });
}

// Each side face of a cylinder subtends 180 degrees at a vertex between rings and 90 at an edge
// ring, whichever diagonal splits it, so the angle-weighted normal is the radius exactly.
TEST(VertexNormals, ACylindersNormalsAreItsRadiiAcrossItsSeam) {
  const MeshDesc flat = cylinderWithSeam(3, 16);
  const MeshDesc smooth = withComputedNormals(flat, 180);
  const auto onCylinder = [](const MeshDesc& m) {
    return worstAngle(m, [](const Vec3& p) { return normalize(Vec3(p.x, 0, p.z)); });
  };
  EXPECT_NEAR(onCylinder(flat), 180.0 / 16, 1e-3);  // half a face's angle
  EXPECT_LT(onCylinder(smooth), 1e-4);
  // One normal per distinct position: the seam's two copies of a position take one.
  EXPECT_EQ(smooth.normals.size(), 4u * 16u);
  EXPECT_EQ(smooth.positions.size(), flat.positions.size());
  for (size_t i = 0; i < flat.triangles.size(); ++i)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(smooth.triangles[i].v[k], flat.triangles[i].v[k]);
}

// On a sphere the rings above and below a vertex differ, so its normal is not exactly the
// radius, but it converges to it as the tessellation refines (second order), where a face's
// normal stays off by half a face's angle.
TEST(VertexNormals, ASpheresNormalsConvergeToItsRadii) {
  const double coarse = worstAngleOnSphere(withComputedNormals(uvSphere(12, 24), 180));
  const double fine = worstAngleOnSphere(withComputedNormals(uvSphere(48, 96), 180));
  EXPECT_LT(coarse, 1.0);
  EXPECT_LT(fine, coarse / 8);
  EXPECT_GT(worstAngleOnSphere(uvSphere(48, 96)), 1.0);
  EXPECT_EQ(withComputedNormals(uvSphere(12, 24), 180).normals.size(),
            uvSphere(12, 24).positions.size());
}

// A unit cube of 12 triangles, each face split along a different diagonal pattern, so that a face
// meets a corner with one triangle (90 degrees) or two (45 each).
MeshDesc cube() {
  MeshDesc m;
  for (int i = 0; i < 8; ++i)
    m.positions.push_back(Vec3(float(i & 1), float(i >> 1 & 1), float(i >> 2)));
  const uint32_t faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : faces) {
    m.triangles.push_back(flatTriangle(q[0], q[1], q[2]));
    m.triangles.push_back(flatTriangle(q[0], q[2], q[3]));
  }
  return m;
}

TEST(VertexNormals, EdgesSharperThanTheCreaseStaySharp) {
  const MeshDesc sharp = withComputedNormals(cube(), 89);
  for (const MeshTriangle& t : sharp.triangles)
    for (int k = 0; k < 3; ++k) {
      ASSERT_GE(t.n[k], 0);
      const Vec3 n = sharp.normals[t.n[k]];
      const Vec3 face = faceNormalOf(sharp, t);
      EXPECT_EQ(n.x, face.x);
      EXPECT_EQ(n.y, face.y);
      EXPECT_EQ(n.z, face.z);
    }
  EXPECT_EQ(sharp.normals.size(), 24u);  // each corner of the cube, once per face
}

TEST(VertexNormals, EdgesAtTheCreaseAngleAreSmoothedWeightedByAngle) {
  // Each face subtends 90 degrees at every corner however it is split, so the corner's normal is
  // the diagonal; weighted by area, a face split there would count twice.
  const MeshDesc round = withComputedNormals(cube(), 90);
  EXPECT_EQ(round.normals.size(), 8u);
  for (const MeshTriangle& t : round.triangles)
    for (int k = 0; k < 3; ++k) {
      const Vec3 p = round.positions[t.v[k]];
      const Vec3 diagonal = normalize(p - Vec3(0.5f));
      const Vec3 n = round.normals[t.n[k]];
      EXPECT_NEAR(n.x, diagonal.x, 1e-6);
      EXPECT_NEAR(n.y, diagonal.y, 1e-6);
      EXPECT_NEAR(n.z, diagonal.z, 1e-6);
    }
}

// A fan of n triangles around the apex of a cone of half-angle `opening` (radians; pi/2 is a
// flat disk), the apex at the origin, the rim at height -cos(opening).
MeshDesc coneFan(int n, double opening) {
  MeshDesc m;
  m.positions.push_back(Vec3(0.0f));
  for (int i = 0; i < n; ++i) {
    const double phi = 2 * kPi * i / n;
    m.positions.push_back(Vec3(float(std::sin(opening) * std::cos(phi)), float(-std::cos(opening)),
                               float(-std::sin(opening) * std::sin(phi))));
  }
  for (int i = 0; i < n; ++i)
    m.triangles.push_back(flatTriangle(0, uint32_t(1 + i), uint32_t(1 + (i + 1) % n)));
  return m;
}

// However many faces meet at a vertex, the work stays near linear: where they all lie within the
// crease (a flat disk's centre) their sum serves every corner; where they spread wider (a cone's
// apex) past 4096 faces each corner keeps its own face's normal.
TEST(VertexNormals, AVertexOfManyFacesCostsNoSquareOfThem) {
  const MeshDesc disk = withComputedNormals(coneFan(200000, kPi / 2), 30);
  for (const MeshTriangle& t : disk.triangles) {
    const Vec3 n = disk.normals[t.n[0]];
    EXPECT_NEAR(n.y, 1.0f, 1e-6f);
  }
  const MeshDesc apex = withComputedNormals(coneFan(20000, kPi / 4), 30);
  for (const MeshTriangle& t : apex.triangles) {
    const Vec3 n = apex.normals[t.n[0]], face = faceNormalOf(apex, t);
    EXPECT_NEAR(dot(n, face), 1.0f, 1e-6f);
  }
  // Below the cap the apex's corners average the faces within the crease of their own.
  const MeshDesc small = withComputedNormals(coneFan(64, kPi / 4), 30);
  const Vec3 n = small.normals[small.triangles[0].n[0]],
             face = faceNormalOf(small, small.triangles[0]);
  EXPECT_LT(dot(n, face), 0.9999f);
  EXPECT_GT(dot(n, face), 0.9f);
}

TEST(VertexNormals, TheFilesNormalsAndFacesOfNoAreaAreKept) {
  MeshDesc m = cube();
  m.normals.push_back(Vec3(0, 0, 1));
  m.triangles[0].n[0] = m.triangles[0].n[1] = m.triangles[0].n[2] = 0;
  m.triangles.push_back(flatTriangle(0, 1, 1));  // no area
  const MeshDesc out = withComputedNormals(m, 180);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(out.triangles[0].n[k], 0);
    EXPECT_EQ(out.triangles.back().n[k], -1);
  }
  EXPECT_EQ(out.normals[0].z, 1.0f);
  for (size_t i = 1; i + 1 < out.triangles.size(); ++i)
    for (int k = 0; k < 3; ++k) EXPECT_GE(out.triangles[i].n[k], 1);
}

std::string writeObj(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

const char* kTwoFaces = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 1\nf 1 2 3\nf 2 4 3\n";

SceneDesc sceneWith(const std::string& object) {
  return parseSceneText(R"({"camera": {"width": 8, "height": 8}, "objects": [)" + object + "]}",
                        "s.json", ".");
}

TEST(VertexNormals, TheSceneSmoothAngleGivesTheRendererNormals) {
  const std::string obj = writeObj("two_faces.obj", kTwoFaces);
  // The two faces meet at 54.7 degrees: smoothed at 60, sharp at 50 and without an angle.
  const SceneData at60 = flattenScene(sceneWith(R"({"file": ")" + obj + R"(", "smooth": 60})"));
  ASSERT_EQ(at60.normals.size(), at60.positions.size());
  ASSERT_EQ(at60.positions.size(), 4u);
  for (const auto& n : at60.normals) EXPECT_FALSE(n.isNone());
  const SceneData at50 = flattenScene(sceneWith(R"({"file": ")" + obj + R"(", "smooth": 50})"));
  EXPECT_EQ(at50.positions.size(), 6u);  // the shared edge's two vertices split
  const SceneData plain = flattenScene(sceneWith(R"({"file": ")" + obj + R"("})"));
  EXPECT_TRUE(plain.normals.empty());
  const SceneData off = flattenScene(sceneWith(R"({"file": ")" + obj + R"(", "smooth": false})"));
  EXPECT_TRUE(off.normals.empty());
}

TEST(VertexNormals, ObjectsPlacingOneFileAtOneAngleShareItsMesh) {
  const std::string obj = writeObj("two_faces2.obj", kTwoFaces);
  const SceneDesc s = sceneWith(R"({"file": ")" + obj + R"(", "smooth": 60},
                                   {"file": ")" +
                                obj + R"(", "smooth": 60, "position": [3, 0, 0]},
                                   {"file": ")" +
                                obj + R"(", "smooth": 30},
                                   {"file": ")" +
                                obj + R"("})");
  EXPECT_EQ(s.objects[0].mesh, s.objects[1].mesh);
  EXPECT_NE(s.objects[0].mesh, s.objects[2].mesh);
  EXPECT_NE(s.objects[0].mesh, s.objects[3].mesh);
  EXPECT_TRUE(s.objects[3].mesh->normals.empty());
}

TEST(VertexNormals, AnAngleOutOfRangeIsRefused) {
  const std::string obj = writeObj("two_faces3.obj", kTwoFaces);
  const std::string expected =
      "s.json: objects[0].smooth: expected true, false or a crease angle in degrees (above 0, up "
      "to 180), got ";
  for (const std::string value : {"0", "-30", "180.5", "1e+39"}) {
    try {
      sceneWith(R"({"file": ")" + obj + R"(", "smooth": )" + value + "}");
      ADD_FAILURE() << value << " was accepted";
    } catch (const SceneError& e) {
      EXPECT_EQ(std::string(e.what()), expected + value);
    }
  }
}

}  // namespace
}  // namespace candela
