// Built-in shapes ("shape": "rectangle", "disk", "cube", "cylinder"). Their meshes against the
// test's own geometry: bounds, areas, volumes and closure, outward fronts, normals and uvs; then
// rendered: orthographic views of glowing shapes covering the pixels their outlines do, scaled
// and turned, and a 2 x 2 texture upright on every face seen from outside; then the refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "render_test_util.h"
#include "scene/shape_meshes.h"
#include "texture_test_util.h"

namespace candela {
namespace {

constexpr double kPiD = 3.14159265358979323846;

struct D3 {
  double x, y, z;
};
D3 d3(Vec3 v) { return {v.x, v.y, v.z}; }
D3 sub(D3 a, D3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
D3 cross(D3 a, D3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
double dot(D3 a, D3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
double length(D3 a) { return std::sqrt(dot(a, a)); }

// A triangle's corners and its (unnormalized, front-facing) normal (b - a) x (c - a).
struct Corners {
  D3 p[3];
  D3 normal() const { return cross(sub(p[1], p[0]), sub(p[2], p[0])); }
  D3 centroid() const {
    return {(p[0].x + p[1].x + p[2].x) / 3, (p[0].y + p[1].y + p[2].y) / 3,
            (p[0].z + p[1].z + p[2].z) / 3};
  }
};
Corners corners(const MeshDesc& mesh, const MeshTriangle& t) {
  return {{d3(mesh.positions[t.v[0]]), d3(mesh.positions[t.v[1]]), d3(mesh.positions[t.v[2]])}};
}

double area(const MeshDesc& mesh) {
  double sum = 0;
  for (const MeshTriangle& t : mesh.triangles) sum += length(corners(mesh, t).normal()) / 2;
  return sum;
}

// The volume the triangles enclose by the divergence theorem: positive where fronts face out.
double signedVolume(const MeshDesc& mesh) {
  double sum = 0;
  for (const MeshTriangle& t : mesh.triangles) {
    const Corners c = corners(mesh, t);
    sum += dot(c.p[0], cross(c.p[1], c.p[2])) / 6;
  }
  return sum;
}

// Whether every edge, matched by its corners' positions, is met once each way: a closed surface
// whose faces agree on which side is out.
bool closedAndConsistent(const MeshDesc& mesh) {
  std::map<std::tuple<float, float, float, float, float, float>, int> edges;
  for (const MeshTriangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const Vec3 a = mesh.positions[t.v[k]], b = mesh.positions[t.v[(k + 1) % 3]];
      ++edges[{a.x, a.y, a.z, b.x, b.y, b.z}];
    }
  for (const auto& [edge, count] : edges) {
    const auto& [ax, ay, az, bx, by, bz] = edge;
    const auto back = edges.find({bx, by, bz, ax, ay, az});
    if (count != 1 || back == edges.end() || back->second != 1) return false;
  }
  return true;
}

// The area of the regular kShapeCircleSegments-gon inscribed in a circle of radius 0.5.
double circleArea() {
  const double n = kShapeCircleSegments;
  return n / 2 * 0.25 * std::sin(2 * kPiD / n);
}

TEST(ShapeMeshes, FillTheUnitBoxWithTheirAreasAndVolumes) {
  const double disk = circleArea();
  const double side = kShapeCircleSegments * std::sin(kPiD / kShapeCircleSegments);  // its width
  struct Expected {
    const char* name;
    double area, volume;
    D3 extent;
  };
  for (const Expected& e :
       {Expected{"rectangle", 1.0, 0.0, {1, 0, 1}}, Expected{"disk", disk, 0.0, {1, 0, 1}},
        Expected{"cube", 6.0, 1.0, {1, 1, 1}},
        Expected{"cylinder", side + 2 * disk, disk, {1, 1, 1}}}) {
    SCOPED_TRACE(e.name);
    const MeshDesc mesh = shapeMesh(e.name);
    D3 lo{1e9, 1e9, 1e9}, hi{-1e9, -1e9, -1e9};
    for (const Vec3& p : mesh.positions) {
      lo = {std::min(lo.x, double(p.x)), std::min(lo.y, double(p.y)), std::min(lo.z, double(p.z))};
      hi = {std::max(hi.x, double(p.x)), std::max(hi.y, double(p.y)), std::max(hi.z, double(p.z))};
    }
    for (const auto& [low, high, extent] :
         {std::tuple{lo.x, hi.x, e.extent.x}, std::tuple{lo.y, hi.y, e.extent.y},
          std::tuple{lo.z, hi.z, e.extent.z}}) {
      EXPECT_NEAR(low, -extent / 2, 1e-7);
      EXPECT_NEAR(high, extent / 2, 1e-7);
    }
    EXPECT_NEAR(area(mesh), e.area, 1e-6 * e.area);
    EXPECT_NEAR(signedVolume(mesh), e.volume, 1e-6);
    if (e.volume > 0) {
      EXPECT_TRUE(closedAndConsistent(mesh));
    }
    ASSERT_EQ(mesh.materials.size(), 1u);
    EXPECT_EQ(mesh.materials[0].type, Material{}.type);
  }
  EXPECT_NEAR(circleArea(), kPiD / 4, 1.01e-4 * kPiD / 4);  // the polygon's deficit, as documented
}

// Fronts face away from the centre (up, for the flat shapes); the cylinder's side carries the
// circle's normals at its corners, the rest is flat.
TEST(ShapeMeshes, FrontsFaceOutAndTheCylinderIsShadedRound) {
  for (const std::string& name : shapeNames()) {
    SCOPED_TRACE(name);
    const MeshDesc mesh = shapeMesh(name);
    const bool flat = name == "rectangle" || name == "disk";
    for (const MeshTriangle& t : mesh.triangles) {
      const Corners c = corners(mesh, t);
      const D3 n = c.normal();
      ASSERT_GT(length(n), 0.0);
      if (flat)
        ASSERT_GT(n.y, 0.999 * length(n));
      else
        ASSERT_GT(dot(n, c.centroid()), 0.0);
      if (t.n[0] < 0) {
        ASSERT_TRUE(t.n[1] < 0 && t.n[2] < 0);
        continue;
      }
      ASSERT_EQ(name, "cylinder");
      ASSERT_LT(std::fabs(n.y), 1e-9);  // only the side is smooth
      for (int k = 0; k < 3; ++k) {
        const D3 normal = d3(mesh.normals[t.n[k]]);
        const D3 p = c.p[k];
        EXPECT_NEAR(length(normal), 1.0, 1e-6);
        EXPECT_NEAR(normal.x, 2 * p.x, 1e-6);  // radial: the rim's point over its radius 0.5
        EXPECT_NEAR(normal.y, 0.0, 0.0);
        EXPECT_NEAR(normal.z, 2 * p.z, 1e-6);
      }
    }
  }
}

// uvs: the flat faces as the square they lie in (u along +x; v along -z facing up, +z facing
// down, +y on the sides); the cylinder's side u once around from -z through -x, v up.
TEST(ShapeMeshes, UvsFollowTheDocumentedLayout) {
  for (const std::string& name : shapeNames()) {
    SCOPED_TRACE(name);
    const MeshDesc mesh = shapeMesh(name);
    ASSERT_EQ(mesh.uvs.size(), mesh.positions.size());
    for (const MeshTriangle& t : mesh.triangles) {
      const D3 n = corners(mesh, t).normal();
      for (int k = 0; k < 3; ++k) {
        ASSERT_GE(t.t[k], 0);
        const Vec2 uv = mesh.uvs[t.t[k]];
        const Vec3 p = mesh.positions[t.v[k]];
        ASSERT_TRUE(uv.x >= 0 && uv.x <= 1 && uv.y >= 0 && uv.y <= 1);
        if (t.n[0] >= 0) {  // the cylinder's side
          double phi = std::atan2(-p.x, -p.z);
          if (phi < 0 || (phi < 1e-6 && uv.x > 0.5)) phi += 2 * kPiD;  // the seam's far copy
          EXPECT_NEAR(uv.x, phi / (2 * kPiD), 1e-6);
          EXPECT_NEAR(uv.y, p.y + 0.5, 1e-7);
        } else if (std::fabs(n.y) > 0.5 * length(n)) {  // facing up or down
          EXPECT_NEAR(uv.x, p.x + 0.5, 1e-7);
          EXPECT_NEAR(uv.y, (n.y > 0 ? -p.z : p.z) + 0.5, 1e-7);
        } else {  // the cube's sides: u to the right seen from outside, v up
          const D3 right = cross({0, 1, 0}, n);
          EXPECT_NEAR(uv.x, dot(d3(p), right) / length(right) + 0.5, 1e-7);
          EXPECT_NEAR(uv.y, p.y + 0.5, 1e-7);
        }
      }
    }
  }
}

// A 64 x 64 orthographic view 4 units across (16 pixels a unit) of one glowing object, pixel
// centres only: 1 where the object is seen, 0 elsewhere.
std::vector<int> coverage(const std::string& object, const std::string& cameraPlace) {
  const RenderResult r = test::renderTestScene(
      R"({"camera": {"width": 64, "height": 64, "projection": "orthographic", "view_width": 4,
                     "spp": 1, )" +
      cameraPlace + R"(},
          "render": {"antialiasing": false, "max_depth": 1},
          "materials": {"glow": {"type": "emissive", "radiance": 1}},
          "objects": [)" +
      object + "]}");
  std::vector<int> seen;
  for (uint32_t y = 0; y < 64; ++y)
    for (uint32_t x = 0; x < 64; ++x) {
      const float v = r.image.at(x, y)[0];
      EXPECT_TRUE(v == 0.0f || v == 1.0f) << x << "," << y << ": " << v;
      seen.push_back(v == 1.0f);
    }
  return seen;
}

// Expects `seen` to be 1 exactly at the pixels whose centre (a, b) across the image (a to the
// right, b up, in units) `inside` holds, but within 0.01 of its `edge` distance.
template <typename Inside>
void expectOutline(const std::vector<int>& seen, Inside inside) {
  int covered = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const double a = (x + 0.5 - 32) / 16, b = -(y + 0.5 - 32) / 16;
      const auto [in, margin] = inside(a, b);
      if (margin < 0.01) continue;
      covered += in;
      ASSERT_EQ(seen[y * 64 + x], in ? 1 : 0) << x << "," << y;
    }
  EXPECT_GT(covered, 100);
}

// A box of half sides (ha, hb) about (ca, cb) and a disk of radius r about it, as expectOutline
// takes them.
auto box(double ca, double cb, double ha, double hb) {
  return [=](double a, double b) {
    const double da = ha - std::fabs(a - ca), db = hb - std::fabs(b - cb);
    return std::pair{da > 0 && db > 0, std::min(std::fabs(da), std::fabs(db))};
  };
}
auto round(double ca, double cb, double r) {
  return [=](double a, double b) {
    const double d = r - std::hypot(a - ca, b - cb);
    return std::pair{d > 0, std::fabs(d)};
  };
}

// A cylinder 2 wide and 3 tall at (0.3, -0.2, -5): from the front a 2 x 3 rectangle, from above
// (image up along -z) a disk of radius 1; turned 90 degrees about x it lies along z and the front
// sees the disk. Then a cube 1.5 wide, and a disk and a rectangle turned to face +z.
TEST(Shapes, ScaledAndTurnedCoverTheirOutlines) {
  const std::string cylinder = R"({"shape": "cylinder", "scale": [2, 3, 2],
                                   "position": [0.3, -0.2, -5], "material": "glow")";
  const std::string front = R"("position": [0, 0, 5])";
  expectOutline(coverage(cylinder + "}", front), box(0.3, -0.2, 1, 1.5));
  expectOutline(coverage(cylinder + "}", R"("position": [0, 10, -5], "rotation": [-90, 0, 0])"),
                round(0.3, 0, 1));
  expectOutline(coverage(cylinder + R"(, "rotation": [90, 0, 0]})", front), round(0.3, -0.2, 1));
  expectOutline(coverage(R"({"shape": "cube", "scale": 1.5, "position": [-0.5, 0.25, 0],
                             "material": "glow"})",
                         front),
                box(-0.5, 0.25, 0.75, 0.75));
  expectOutline(coverage(R"({"shape": "disk", "scale": 2.5, "rotation": [90, 0, 0],
                             "material": "glow"})",
                         front),
                round(0, 0, 1.25));
  expectOutline(coverage(R"({"shape": "rectangle", "scale": [3, 1, 1], "rotation": [90, 0, 0],
                             "position": [0, 0.4, 0], "material": "glow"})",
                         front),
                box(0, 0.4, 1.5, 0.5));
}

// A texture of four texels (red, green at the top; blue, white below) glowing on each face of
// each shape at the origin, read by the nearest texel and seen straight on from outside: each
// quarter of the face shows the texel in that corner of the image, upright. A rectangle seen from
// below shows nothing: it glows from its front, as every face here does.
TEST(Shapes, TexturesLieUprightOnEveryFaceSeenFromOutside) {
  const test::TempDir dir;
  ASSERT_TRUE(test::writeTestPng(dir.file("corners.png"), 2, 2, 3,
                                 {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255}));
  const auto render = [&](const std::string& shape, const std::string& cameraPlace) {
    return test::renderTestScene(
        R"({"camera": {"width": 64, "height": 64, "projection": "orthographic",
                       "view_width": 4, "spp": 1, )" +
            cameraPlace + R"(},
            "render": {"antialiasing": false, "max_depth": 1},
            "objects": [{"shape": ")" +
            shape + R"(", "material": {"type": "emissive",
              "radiance": {"texture": "corners.png", "filter": "nearest"}}}]})",
        0, dir.path());
  };
  struct View {
    const char* camera;
    std::vector<const char*> shapes;
  };
  const std::vector<View> views = {
      {R"("position": [0, 0, 5])", {"cube", "cylinder"}},
      {R"("position": [0, 0, -5], "rotation": [0, 180, 0])", {"cube"}},
      {R"("position": [5, 0, 0], "rotation": [0, 90, 0])", {"cube"}},
      {R"("position": [-5, 0, 0], "rotation": [0, -90, 0])", {"cube"}},
      {R"("position": [0, 5, 0], "rotation": [-90, 0, 0])",
       {"rectangle", "disk", "cube", "cylinder"}},
      {R"("position": [0, -5, 0], "rotation": [90, 0, 0])", {"cube", "cylinder"}}};
  // The pixel whose centre lies nearest (a, b) units right of and above the image's centre.
  const auto at = [](const RenderResult& r, double a, double b) {
    return r.image.at(uint32_t(a * 16 + 32), uint32_t(32 - b * 16));
  };
  for (const View& view : views)
    for (const char* shape : view.shapes) {
      SCOPED_TRACE(std::string(shape) + " seen from " + view.camera);
      const RenderResult r = render(shape, view.camera);
      const double q = 0.28;  // a quarter's middle, inside the disk's and the cylinder's outline
      for (const auto& [a, b, texel] :
           {std::tuple{-q, q, Vec3(1, 0, 0)}, std::tuple{q, q, Vec3(0, 1, 0)},
            std::tuple{-q, -q, Vec3(0, 0, 1)}, std::tuple{q, -q, Vec3(1, 1, 1)}}) {
        const Vec3 seen = at(r, a, b);
        EXPECT_TRUE(seen.x == texel.x && seen.y == texel.y && seen.z == texel.z)
            << "at (" << a << ", " << b << "): " << seen.x << " " << seen.y << " " << seen.z;
      }
      EXPECT_EQ(at(r, 1.9, 1.9).x, 0.0f);  // beyond the shape
    }
  const RenderResult below =
      render("rectangle", R"("position": [0, -5, 0], "rotation": [90, 0, 0])");
  for (uint32_t y = 0; y < 64; ++y)
    for (uint32_t x = 0; x < 64; ++x) ASSERT_EQ(below.image.at(x, y)[0], 0.0f);
}

// Objects naming one shape share its mesh, as objects naming one file do.
TEST(Shapes, ObjectsOfOneShapeShareItsMesh) {
  const SceneDesc scene = parseSceneText(R"({"camera": {"width": 4, "height": 4},
      "objects": [{"shape": "cube"}, {"shape": "cube", "position": [2, 0, 0]},
                  {"shape": "disk"}]})",
                                         "s.json", ".");
  ASSERT_EQ(scene.objects.size(), 3u);
  EXPECT_EQ(scene.objects[0].mesh, scene.objects[1].mesh);
  EXPECT_NE(scene.objects[0].mesh, scene.objects[2].mesh);
  EXPECT_EQ(scene.objects[0].mesh->triangles.size(), 12u);
  EXPECT_EQ(scene.objects[0].shape, "cube");
  EXPECT_TRUE(scene.objects[0].file.empty());
}

std::string objectError(const std::string& object) {
  return test::loadError(R"({"camera": {"width": 4, "height": 4}, "objects": [)" + object + "]}",
                         ".");
}

TEST(Shapes, RefusesWhatIsNotAShape) {
  EXPECT_EQ(objectError(R"({"shape": "cub"})"),
            "test.json: objects[0].shape: expected one of \"rectangle\", \"disk\", \"cube\", "
            "\"cylinder\", got a string \"cub\", did you mean \"cube\"?");
  EXPECT_EQ(objectError(R"({"shape": 3})"),
            "test.json: objects[0].shape: expected one of \"rectangle\", \"disk\", \"cube\", "
            "\"cylinder\", got 3");
  EXPECT_EQ(objectError(R"({"shape": "sphere"})"),
            "test.json: objects[0].shape: expected \"rectangle\", \"disk\", \"cube\" or "
            "\"cylinder\"; a sphere goes in \"spheres\", exact, with a \"radius\"");
  EXPECT_EQ(objectError(R"({"shape": "cube", "file": "cube.obj"})"),
            "test.json: objects[0]: expected either \"file\" or \"shape\", got both");
  EXPECT_EQ(objectError(R"({"shape": "cube", "gltf_variant": "red"})"),
            "test.json: objects[0].gltf_variant: a glTF file's variant, and the object is a cube");
  EXPECT_EQ(objectError(R"({"shape": "cube", "scale": [1, 0, 1]})").substr(0, 37),
            "test.json: objects[0].scale[1]: expec");
}

}  // namespace
}  // namespace candela
