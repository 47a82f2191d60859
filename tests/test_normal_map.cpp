// Normal maps: a texture of tangent-space normals tilts the shading normal (render/normal_map.h).
// Against closed forms: a plane under a directional light shades as its mapped normal says, with
// the bitangent following v (mirrored uvs mirror the map) and a normal that turns its back on the
// viewer mirrored; the normal pass of a plane and of a sphere is the mapped normal of its frame of
// uvs; a flat map changes nothing; MTL `norm` and the scene format's refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/constants.h"
#include "render/aov_layers.h"
#include "render_test_util.h"
#include "scene/read/obj_loader.h"
#include "texture_test_util.h"

namespace candela {
namespace {

namespace fs = std::filesystem;
using test::num;

struct D3 {
  double x, y, z;
};
D3 operator+(const D3& a, const D3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
D3 operator-(const D3& a, const D3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
D3 operator*(double s, const D3& a) { return {s * a.x, s * a.y, s * a.z}; }
double dot(const D3& a, const D3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
D3 cross(const D3& a, const D3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
D3 unit(const D3& a) { return (1.0 / std::sqrt(dot(a, a))) * a; }

// A folder of the test's files.
fs::path folder(const std::string& name) {
  const fs::path dir = fs::path(::testing::TempDir()) / name;
  fs::create_directories(dir);
  return dir;
}

// A 2 x 2 PNG of one RGB colour, and the tangent-space normal its texels decode to (2 c - 1, the
// bytes read linearly).
D3 writeFlatMap(const fs::path& path, uint8_t r, uint8_t g, uint8_t b) {
  std::vector<uint8_t> bytes;
  for (int i = 0; i < 4; ++i) {
    bytes.push_back(r);
    bytes.push_back(g);
    bytes.push_back(b);
  }
  EXPECT_TRUE(test::writeTestPng(path.string(), 2, 2, 3, bytes));
  return {2.0 * r / 255.0 - 1.0, 2.0 * g / 255.0 - 1.0, 2.0 * b / 255.0 - 1.0};
}

// A square of half-side 100 in the plane y = 0 facing +y, u growing along +x and v along -z (as a
// texture seen from above, top up, with -z up), or along +z with `mirrored`.
void writePlane(const fs::path& path, bool mirrored) {
  const double v0 = mirrored ? 0 : 1, v1 = 1 - v0;
  std::ofstream(path) << "v -100 0 -100\nv 100 0 -100\nv 100 0 100\nv -100 0 100\n"
                      << "vt 0 " << v0 << "\nvt 1 " << v0 << "\nvt 1 " << v1 << "\nvt 0 " << v1
                      << "\nf 1/1 4/4 3/3\nf 1/1 3/3 2/2\n";
}

struct Rendered {
  SceneData data;
  RenderResult result;
  std::vector<ImageLayer> layers;  // the normal pass
};

Rendered render(const std::string& json, const fs::path& dir) {
  Rendered r{test::loadTestScene(json, dir.string()), {}, {}};
  RenderOptions options;
  options.aovs = true;
  r.result = renderCpu(r.data.view(), options);
  r.layers = makeAovLayers(r.data, parseAovList("normal"), r.result.aovs);
  return r;
}

// The plane under a directional light, seen from above through pixel centres, one bounce.
std::string planeScene(const std::string& material, const D3& sunDirection, double irradiance) {
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

// Every pixel of the plane, mapped by a constant map of tangent-space normal `tangentNormal`, is
// rho E max(0, n . l) / pi for n = tangentNormal in (tangent x, bitangent -z or +z, normal y),
// and the normal pass shows n.
void expectTiltedPlane(bool mirrored) {
  const fs::path dir = folder(mirrored ? "normal_map_mirrored" : "normal_map_plane");
  writePlane(dir / "plane.obj", mirrored);
  const D3 t = writeFlatMap(dir / "n.png", 200, 90, 230);
  const double rho = 0.6, irradiance = 2;
  const D3 sun{0.3, -1.0, 0.5};
  const Rendered r = render(planeScene(R"({"type": "diffuse", "color": )" + num(rho) +
                                           R"(, "normal_map": {"texture": "n.png"}})",
                                       sun, irradiance),
                            dir);
  const D3 bitangent = mirrored ? D3{0, 0, 1} : D3{0, 0, -1};
  const D3 n = unit(t.x * D3{1, 0, 0} + t.y * bitangent + t.z * D3{0, 1, 0});
  const double cosine = dot(n, unit(-1.0 * sun));
  ASSERT_GT(cosine, 0.0);
  const double expected = rho * irradiance * cosine / kPi;
  ASSERT_EQ(r.layers.size(), 1u);
  for (uint32_t y = 0; y < 16; ++y)
    for (uint32_t x = 0; x < 24; ++x) {
      EXPECT_NEAR(r.result.image.at(x, y).x, expected, 2e-6 * expected) << x << "," << y;
      const float* normal = &r.layers[0].pixels[3 * (size_t(y) * 24 + x)];
      EXPECT_NEAR(normal[0], n.x, 2e-6);
      EXPECT_NEAR(normal[1], n.y, 2e-6);
      EXPECT_NEAR(normal[2], n.z, 2e-6);
    }
}

TEST(NormalMap, AConstantMapShadesAPlaneAsItsTiltedNormal) { expectTiltedPlane(false); }

TEST(NormalMap, MirroredUvsMirrorTheMap) { expectTiltedPlane(true); }

// Seen from low on the side its normals tilt away from, the mapped normal turns its back on the
// camera and has its tilt mirrored (Mitsuba 3's flip_invalid_normals, whose renders of this scene
// match candela's to float precision): every pixel is rho E max(0, n . l) / pi of the mirrored
// normal, which the normal pass shows, where it would otherwise be black.
TEST(NormalMap, ANormalFacingAwayFromTheViewerHasItsTiltMirrored) {
  const fs::path dir = folder("normal_map_flip");
  writePlane(dir / "plane.obj", false);
  const D3 t = writeFlatMap(dir / "n.png", 230, 128, 170);
  const double rho = 0.6, irradiance = 2;
  const D3 sun{0.2, -1.0, 0.4};
  const Rendered r = render(R"({
    "camera": {"width": 24, "height": 16, "fov": 50, "position": [-5, 2.5, 0],
               "look_at": [0, 0, 0], "spp": 1},
    "render": {"antialiasing": false, "max_depth": 1},
    "objects": [{"file": "plane.obj", "material": {"type": "diffuse", "color": )" +
                                num(rho) + R"(, "normal_map": {"texture": "n.png"}}}],
    "lights": [{"type": "directional", "direction": [0.2, -1, 0.4], "intensity": 2}]})",
                            dir);
  const D3 mapped = unit(t.x * D3{1, 0, 0} + t.y * D3{0, 0, -1} + t.z * D3{0, 1, 0});
  const D3 up{0, 1, 0};
  const Camera& c = r.data.camera;
  int checked = 0;
  for (uint32_t y = 0; y < 16; ++y)
    for (uint32_t x = 0; x < 24; ++x) {
      const Vec3 d = c.cameraToWorld * (c.inverseK * Vec3(x + 0.5f, y + 0.5f, 1.0f));
      if (!(d.y < 0)) continue;
      const D3 eye{c.position.x, c.position.y, c.position.z};
      const D3 hit = eye + (-eye.y / d.y) * D3{d.x, d.y, d.z};
      const D3 wo = unit(eye - hit);
      ASSERT_LT(dot(wo, mapped), 0.0);  // the map's normal turns its back on the camera
      const D3 n = unit(2 * dot(mapped, up) * up - mapped);
      const double expected = rho * irradiance * std::max(0.0, dot(n, unit(-1.0 * sun))) / kPi;
      EXPECT_NEAR(r.result.image.at(x, y).x, expected, 2e-6 * expected) << x << "," << y;
      const float* normal = &r.layers[0].pixels[3 * (size_t(y) * 24 + x)];
      EXPECT_NEAR(normal[0], n.x, 2e-6);
      EXPECT_NEAR(normal[1], n.y, 2e-6);
      EXPECT_NEAR(normal[2], n.z, 2e-6);
      ++checked;
    }
  EXPECT_GT(checked, 150);
}

// A map of the normal straight out, (0.5, 0.5, 1) exactly in a float (PFM) map, renders the plane
// as without it (up to the rounding of normalising the normal again).
TEST(NormalMap, AFlatMapChangesNothing) {
  const fs::path dir = folder("normal_map_flat");
  writePlane(dir / "plane.obj", false);
  {
    std::ofstream pfm(dir / "flat.pfm", std::ios::binary);
    pfm << "PF\n2 2\n-1\n";
    const float texel[3] = {0.5f, 0.5f, 1.0f};
    for (int i = 0; i < 4; ++i) pfm.write(reinterpret_cast<const char*>(texel), sizeof texel);
  }
  const D3 sun{0.3, -1.0, 0.5};
  const Rendered mapped = render(planeScene(R"({"type": "plastic", "color": 0.4, "roughness": 0.3,
                            "normal_map": {"texture": "flat.pfm"}})",
                                            sun, 2),
                                 dir);
  const Rendered plain =
      render(planeScene(R"({"type": "plastic", "color": 0.4, "roughness": 0.3})", sun, 2), dir);
  for (uint32_t y = 0; y < 16; ++y)
    for (uint32_t x = 0; x < 24; ++x)
      EXPECT_NEAR(mapped.result.image.at(x, y).x, plain.result.image.at(x, y).x,
                  1e-6 * plain.result.image.at(x, y).x)
          << x << "," << y;
}

// A sphere's frame follows its equirectangular uvs: the tangent along the azimuth u grows with,
// the bitangent towards +y (v grows towards the top pole). The normal pass at each pixel that
// sees the sphere is the map's normal in that frame, at the point the pixel's ray meets (its tilt
// mirrored where it turns its back on the camera, near the sphere's rim).
TEST(NormalMap, ASphereTiltsItsNormalsInTheFrameOfItsUvs) {
  const fs::path dir = folder("normal_map_sphere");
  const D3 t = writeFlatMap(dir / "n.png", 170, 60, 220);
  const Rendered r = render(R"({
    "camera": {"width": 24, "height": 24, "fov": 40, "position": [0, 0, 5], "look_at": [0, 0, 0],
               "spp": 1},
    "render": {"antialiasing": false, "max_depth": 1},
    "spheres": [{"position": [0, 0, 0], "radius": 1,
                 "material": {"type": "diffuse", "normal_map": {"texture": "n.png"}}}],
    "environment": {"color": 1}})",
                            dir);
  const Camera& c = r.data.camera;
  int checked = 0;
  for (uint32_t y = 0; y < 24; ++y)
    for (uint32_t x = 0; x < 24; ++x) {
      const Vec3 d = c.cameraToWorld * (c.inverseK * Vec3(x + 0.5f, y + 0.5f, 1.0f));
      const D3 o{c.position.x, c.position.y, c.position.z};
      const D3 dir3 = unit(D3{d.x, d.y, d.z});
      const double b = dot(o, dir3), disc = b * b - (dot(o, o) - 1.0);
      if (disc < 0.05) continue;                       // misses, or grazes the silhouette
      const D3 p = o + (-b - std::sqrt(disc)) * dir3;  // the unit normal, too
      if (p.x * p.x + p.z * p.z < 0.01) continue;      // near a pole, where u has no direction
      const D3 tangent = unit(D3{-p.z, 0, p.x});
      D3 bitangent = cross(p, tangent);
      if (dot(bitangent, D3{0, 1, 0} - p.y * p) < 0) bitangent = -1.0 * bitangent;
      D3 n = unit(t.x * tangent + t.y * bitangent + t.z * p);
      const D3 wo = unit(o - p);
      if (dot(wo, p) * dot(wo, n) <= 0) n = unit(2 * dot(n, p) * p - n);  // turned from the eye
      const float* normal = &r.layers[0].pixels[3 * (size_t(y) * 24 + x)];
      EXPECT_NEAR(normal[0], n.x, 2e-5) << x << "," << y;
      EXPECT_NEAR(normal[1], n.y, 2e-5) << x << "," << y;
      EXPECT_NEAR(normal[2], n.z, 2e-5) << x << "," << y;
      ++checked;
    }
  EXPECT_GT(checked, 100);
}

// The mapped normal is the shading normal of light-vertex connections too (render/light_path.h):
// in the small room of test::kSmallRoomWalls, a spot light lights a patch of a floor whose normals
// all tilt one way, and the camera sees only what that patch throws onto the ceiling and walls,
// most of it through light vertices on the patch. The image is the same with the connections as
// without them, over two seeds each (with the patch's light vertices left unmapped, 23 of the 24
// blocks differ, by up to 10 standard errors).
TEST(NormalMap, LightVertexConnectionsSeeTheMappedNormal) {
  const fs::path dir = folder("normal_map_room");
  writePlane(dir / "plane.obj", false);
  writeFlatMap(dir / "tilt.png", 220, 150, 190);
  const auto room = [&](int seed) {
    return R"({
      "camera": {"fov": 70, "position": [0, 2, 9], "look_at": [0, 5, 0], "width": 48,
                 "height": 32, "spp": 16},
      "render": {"max_depth": 3, "seed": )" +
           std::to_string(seed) + R"(},
      "spheres": [)" +
           std::string(test::kSmallRoomWalls) + R"(],
      "objects": [{"file": "plane.obj", "position": [0, 0.01, 0],
                   "material": {"type": "diffuse", "color": 0.8,
                                "normal_map": {"texture": "tilt.png"}}}],
      "lights": [{"type": "spot", "position": [0, 2, 0], "direction": [0, -1, 0],
                  "intensity": 400, "cutoff_angle": 40}]})";
  };
  const auto renderPair = [&](bool connections) {
    test::SeedPair p;
    for (int seed : {1, 2}) {
      SceneData data = test::loadTestScene(room(seed), dir.string());
      if (!connections) data.lightsStartingPaths = 0;
      EXPECT_EQ(data.view().lightPathLights, connections ? 1u : 0u);
      (seed == 1 ? p.a : p.b) = renderCpu(data.view(), RenderOptions{});
    }
    return p;
  };
  test::expectSameImage(renderPair(true), renderPair(false));
}

// MTL `norm` names a normal map, with `-s` as the other maps; other options are refused.
TEST(NormalMap, MtlNormReadsANormalMap) {
  const fs::path dir = folder("normal_map_mtl");
  writePlane(dir / "plane_only.obj", false);
  writeFlatMap(dir / "n.png", 128, 128, 255);
  std::ofstream(dir / "m.obj") << "mtllib m.mtl\nusemtl bricks\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                  "vt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n";
  std::ofstream(dir / "m.mtl") << "newmtl bricks\nKd 0.5 0.4 0.3\nnorm -s 2 3 n.png\n";
  const SceneData data = test::loadTestScene(
      R"({"camera": {"width": 4, "height": 4}, "objects": [{"file": "m.obj"}]})", dir.string());
  ASSERT_EQ(data.materials.size(), 1u);
  EXPECT_GE(data.materials[0].normalMap.index, 0);
  EXPECT_EQ(data.materials[0].normalMap.scaleU, 2.0f);
  EXPECT_EQ(data.materials[0].normalMap.scaleV, 3.0f);
  EXPECT_EQ(data.uvs.size(), data.positions.size());  // the map reads uvs: they are kept

  std::ofstream(dir / "m.mtl") << "newmtl bricks\nnorm -bm 0.5 n.png\n";
  try {
    test::loadTestScene(R"({"camera": {"width": 4, "height": 4}, "objects": [{"file": "m.obj"}]})",
                        dir.string());
    ADD_FAILURE() << "no error";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()),
              "test.json: objects[0].file: m.mtl:2: norm option \"-bm\" is not supported (only "
              "-s)");
  }
}

TEST(NormalMap, TheSceneFormatRefusesWhatItCannotBe) {
  const fs::path dir = folder("normal_map_errors");
  writeFlatMap(dir / "n.png", 128, 128, 255);
  const auto error = [&](const std::string& material) {
    try {
      parseSceneText(
          R"({"camera": {"width": 4, "height": 4}, "materials": {"m": )" + material + "}}",
          "s.json", dir.string());
    } catch (const SceneError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_EQ(error(R"({"type": "diffuse", "normal_map": {"texture": "n.png"}})"), "(no error)");
  EXPECT_EQ(error(R"({"type": "emissive", "radiance": 1, "normal_map": {"texture": "n.png"}})"),
            "s.json: materials.m.normal_map: not used by an \"emissive\" material");
  EXPECT_EQ(error(R"({"type": "diffuse", "normal_map": "n.png"})"),
            "s.json: materials.m.normal_map: expected a texture object {\"texture\": file, "
            "\"scale\": [su, sv]}, got a string \"n.png\"");
  EXPECT_EQ(error(R"({"type": "diffuse", "normal_map": {"texture": "missing.png"}})")
                .rfind("s.json: materials.m.normal_map.texture: cannot read the texture: ", 0),
            0u);
  EXPECT_EQ(error(R"({"type": "diffuse", "normal_map": {"texture": "n.png", "scale": [1, 0]}})"),
            "s.json: materials.m.normal_map.scale[1]: expected a finite, non-zero number, got 0");
}

}  // namespace
}  // namespace candela
