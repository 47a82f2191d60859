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
#include "render_test_util.h"
#include "scene/read/obj_loader.h"
#include "shading_normal_test_util.h"
#include "texture_test_util.h"

namespace candela {
namespace {

namespace fs = std::filesystem;
using test::num;

// A 2 x 2 PNG of one RGB colour, and the tangent-space normal its texels decode to (2 c - 1, the
// bytes read linearly).
DVec3 writeFlatMap(const fs::path& path, uint8_t r, uint8_t g, uint8_t b) {
  std::vector<uint8_t> bytes;
  for (int i = 0; i < 4; ++i) {
    bytes.push_back(r);
    bytes.push_back(g);
    bytes.push_back(b);
  }
  EXPECT_TRUE(test::writeTestPng(path.string(), 2, 2, 3, bytes));
  return {2.0 * r / 255.0 - 1.0, 2.0 * g / 255.0 - 1.0, 2.0 * b / 255.0 - 1.0};
}

// Every pixel of the plane, mapped by a constant map of tangent-space normal `tangentNormal`, is
// rho E max(0, n . l) / pi for n = tangentNormal in (tangent x, bitangent -z or +z, normal y),
// and the normal pass shows n.
void expectTiltedPlane(bool mirrored) {
  const fs::path dir = test::mapTestFolder(mirrored ? "normal_map_mirrored" : "normal_map_plane");
  test::writeMappedPlane(dir / "plane.obj", mirrored);
  const DVec3 t = writeFlatMap(dir / "n.png", 200, 90, 230);
  const double rho = 0.6, irradiance = 2;
  const DVec3 sun{0.3, -1.0, 0.5};
  const test::RenderedWithNormals r =
      test::renderWithNormals(test::planeUnderSun(R"({"type": "diffuse", "color": )" + num(rho) +
                                                      R"(, "normal_map": {"texture": "n.png"}})",
                                                  sun, irradiance),
                              dir);
  const DVec3 bitangent = mirrored ? DVec3{0, 0, 1} : DVec3{0, 0, -1};
  const DVec3 n = unit(t.x * DVec3{1, 0, 0} + t.y * bitangent + t.z * DVec3{0, 1, 0});
  const double cosine = dot(n, unit(-1.0 * sun));
  ASSERT_GT(cosine, 0.0);
  test::expectUniformPlane(r, rho * irradiance * cosine / kPi, n, 2e-6);
}

TEST(NormalMap, AConstantMapShadesAPlaneAsItsTiltedNormal) { expectTiltedPlane(false); }

TEST(NormalMap, MirroredUvsMirrorTheMap) { expectTiltedPlane(true); }

// A map turned or mirrored on the surface turns or mirrors its tangent frame with it: turned 90
// degrees counter-clockwise, the image's x runs along +v (-z on the plane) and its y along -u;
// mirrored by a scale of -1 in u, or read in a mirrored copy of its wrap, its x runs along -u.
TEST(NormalMap, ATurnedOrMirroredMapTurnsItsFrame) {
  const fs::path dir = test::mapTestFolder("normal_map_turned");
  test::writeMappedPlane(dir / "plane.obj");
  const DVec3 t = writeFlatMap(dir / "n.png", 200, 90, 230);
  const double rho = 0.6, irradiance = 2;
  const DVec3 sun{0.3, -1.0, 0.5};
  const DVec3 u{1, 0, 0}, v{0, 0, -1}, up{0, 1, 0};
  struct Case {
    const char* transform;
    DVec3 imageX, imageY;
  };
  for (const Case& c :
       {Case{R"("rotation": 90)", v, -1.0 * u}, Case{R"("scale": [-1, 1])", -1.0 * u, v},
        Case{R"("rotation": 180, "offset": [0.3, 0.2])", -1.0 * u, -1.0 * v},
        Case{R"("offset": [1, 0], "wrap": "mirror")", -1.0 * u, v},
        Case{R"("offset": [-1, 1], "wrap": ["mirror", "mirror"])", -1.0 * u, -1.0 * v},
        Case{R"("offset": [1, 0], "wrap": "clamp")", u, v}}) {
    SCOPED_TRACE(c.transform);
    const test::RenderedWithNormals r = test::renderWithNormals(
        test::planeUnderSun(R"({"type": "diffuse", "color": )" + num(rho) +
                                R"(, "normal_map": {"texture": "n.png", )" + c.transform + "}}",
                            sun, irradiance),
        dir);
    const DVec3 n = unit(t.x * c.imageX + t.y * c.imageY + t.z * up);
    const double cosine = dot(n, unit(-1.0 * sun));
    ASSERT_GT(cosine, 0.0);
    test::expectUniformPlane(r, rho * irradiance * cosine / kPi, n, 2e-6);
  }
}

// Seen from low on the side its normals tilt away from, the mapped normal turns its back on the
// camera and has its tilt mirrored (Mitsuba 3's flip_invalid_normals, whose renders of this scene
// match candela's to float precision): every pixel is rho E max(0, n . l) / pi of the mirrored
// normal, which the normal pass shows, where it would otherwise be black.
TEST(NormalMap, ANormalFacingAwayFromTheViewerHasItsTiltMirrored) {
  const fs::path dir = test::mapTestFolder("normal_map_flip");
  test::writeMappedPlane(dir / "plane.obj", false);
  const DVec3 t = writeFlatMap(dir / "n.png", 230, 128, 170);
  const double rho = 0.6, irradiance = 2;
  const DVec3 sun{0.2, -1.0, 0.4};
  const test::RenderedWithNormals r =
      test::renderWithNormals(R"({
    "camera": {"width": 24, "height": 16, "fov": 50, "position": [-5, 2.5, 0],
               "look_at": [0, 0, 0], "spp": 1},
    "render": {"antialiasing": false, "max_depth": 1},
    "objects": [{"file": "plane.obj", "material": {"type": "diffuse", "color": )" +
                                  num(rho) + R"(, "normal_map": {"texture": "n.png"}}}],
    "lights": [{"type": "directional", "direction": [0.2, -1, 0.4], "intensity": 2}]})",
                              dir);
  const DVec3 mapped = unit(t.x * DVec3{1, 0, 0} + t.y * DVec3{0, 0, -1} + t.z * DVec3{0, 1, 0});
  const DVec3 up{0, 1, 0};
  const Camera& c = r.data.camera;
  int checked = 0;
  for (uint32_t y = 0; y < 16; ++y)
    for (uint32_t x = 0; x < 24; ++x) {
      const Vec3 d = c.cameraToWorld * (c.inverseK * Vec3(x + 0.5f, y + 0.5f, 1.0f));
      if (!(d.y < 0)) continue;
      const DVec3 eye{c.position.x, c.position.y, c.position.z};
      const DVec3 hit = eye + (-eye.y / d.y) * DVec3{d.x, d.y, d.z};
      const DVec3 wo = unit(eye - hit);
      ASSERT_LT(dot(wo, mapped), 0.0);  // the map's normal turns its back on the camera
      const DVec3 n = unit(2 * dot(mapped, up) * up - mapped);
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
  const fs::path dir = test::mapTestFolder("normal_map_flat");
  test::writeMappedPlane(dir / "plane.obj", false);
  {
    std::ofstream pfm(dir / "flat.pfm", std::ios::binary);
    pfm << "PF\n2 2\n-1\n";
    const float texel[3] = {0.5f, 0.5f, 1.0f};
    for (int i = 0; i < 4; ++i) pfm.write(reinterpret_cast<const char*>(texel), sizeof texel);
  }
  const DVec3 sun{0.3, -1.0, 0.5};
  const test::RenderedWithNormals mapped = test::renderWithNormals(
      test::planeUnderSun(R"({"type": "plastic", "color": 0.4, "roughness": 0.3,
                            "normal_map": {"texture": "flat.pfm"}})",
                          sun, 2),
      dir);
  const test::RenderedWithNormals plain = test::renderWithNormals(
      test::planeUnderSun(R"({"type": "plastic", "color": 0.4, "roughness": 0.3})", sun, 2), dir);
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
  const fs::path dir = test::mapTestFolder("normal_map_sphere");
  const DVec3 t = writeFlatMap(dir / "n.png", 170, 60, 220);
  const test::RenderedWithNormals r = test::renderWithNormals(R"({
    "camera": {"width": 24, "height": 24, "fov": 40, "position": [0, 0, 5], "look_at": [0, 0, 0],
               "spp": 1},
    "render": {"antialiasing": false, "max_depth": 1},
    "spheres": [{"position": [0, 0, 0], "radius": 1,
                 "material": {"type": "diffuse", "normal_map": {"texture": "n.png"}}}],
    "environment": {"color": 1}})",
                                                              dir);
  const DVec3 o = dvec3(r.data.camera.position);
  const int checked =
      test::forEachSphereHit(r.data.camera, 1.0, [&](uint32_t x, uint32_t y, const DVec3& p) {
        const DVec3 tangent = unit(DVec3{-p.z, 0, p.x});
        DVec3 bitangent = cross(p, tangent);
        if (dot(bitangent, DVec3{0, 1, 0} - p.y * p) < 0) bitangent = -1.0 * bitangent;
        const DVec3 n = unit(t.x * tangent + t.y * bitangent + t.z * p);
        test::expectMappedNormal(r, x, y, n, p, unit(o - p), 2e-5);
      });
  EXPECT_GT(checked, 100);
}

// The mapped normal is the shading normal of light-vertex connections too (render/light_path.h):
// in the small room of test::kSmallRoomWalls, a spot light lights a patch of a floor whose normals
// all tilt one way, and the camera sees only what that patch throws onto the ceiling and walls,
// most of it through light vertices on the patch. The image is the same with the connections as
// without them, over two seeds each (with the patch's light vertices left unmapped, 23 of the 24
// blocks differ, by up to 10 standard errors).
TEST(NormalMap, LightVertexConnectionsSeeTheMappedNormal) {
  const fs::path dir = test::mapTestFolder("normal_map_room");
  test::writeMappedPlane(dir / "plane.obj", false);
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
  const fs::path dir = test::mapTestFolder("normal_map_mtl");
  test::writeMappedPlane(dir / "plane_only.obj", false);
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
              "-s, -o and -clamp)");
  }
}

TEST(NormalMap, TheSceneFormatRefusesWhatItCannotBe) {
  const fs::path dir = test::mapTestFolder("normal_map_errors");
  writeFlatMap(dir / "n.png", 128, 128, 255);
  const auto error = [&](const std::string& material) {
    return test::materialError(dir, material);
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
