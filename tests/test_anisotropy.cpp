// Anisotropic roughness (docs/scene-format.md, *Anisotropy*): a conductor or glass rougher along
// its surface's tangent, the direction its u grows in, turned about the normal by
// anisotropy_rotation. A plane and a sphere under a directional light, one bounce, render without
// noise: each pixel against the BSDF (itself held against Mitsuba 3 in test_bsdf_mitsuba.cpp) with
// the tangent worked out here from the uvs. A light subpath's vertex keeps its tangent; and the
// refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/sobol_sampler.h"
#include "geometry/bvh_tracer.h"
#include "render/bsdf.h"
#include "render/light_path.h"
#include "render_test_util.h"
#include "shading_normal_test_util.h"
#include "untextured_bsdf.h"

namespace candela {
namespace {

namespace fs = std::filesystem;
using test::num;

const Vec3 kSun(0.3f, -1.0f, 0.5f);
constexpr float kIrradiance = 2.0f;

// writeMappedPlane's square with its uvs transposed: u grows along +z and v along +x.
void writeTransposedPlane(const fs::path& path) {
  std::ofstream(path) << "v -100 0 -100\nv 100 0 -100\nv 100 0 100\nv -100 0 100\n"
                      << "vt 0 0\nvt 0 1\nvt 1 1\nvt 1 0\nf 1/1 4/4 3/3\nf 1/1 3/3 2/2\n";
}

Material brushed(float rotationDegrees) {
  Material m;
  m.type = MaterialType::Conductor;
  m.color = Vec3(1.0f);
  m.roughness = 0.5f;
  m.anisotropy = 0.8f;
  m.anisotropyRotation = rotationDegrees * kPi / 180.0f;
  return m;
}

std::string brushedJson(float rotationDegrees) {
  return R"({"type": "conductor", "color": 1, "roughness": 0.5, "anisotropy": 0.8,
             "anisotropy_rotation": )" +
         num(rotationDegrees) + "}";
}

// The radiance that a pixel centre's ray of `camera` sees where it meets the plane y = 0 (normal
// +y) of material m with tangent `tangent`, under planeUnderSun's light.
float planeRadiance(const Camera& camera, uint32_t x, uint32_t y, const Material& m,
                    const Vec3& tangent) {
  const Vec3 ray =
      normalize(camera.cameraToWorld * (camera.inverseK * Vec3(x + 0.5f, y + 0.5f, 1.0f)));
  const Vec3 up(0.0f, 1.0f, 0.0f);
  float pdf;
  return evalBsdf(untexturedBsdf(m, -ray, up, up, tangent), -normalize(kSun), &pdf).x * kIrradiance;
}

// Renders `obj` (written by `write`) of brushedJson(rotation) under the sun and expects each pixel
// to be planeRadiance with `tangent`; and, that the test can tell, some pixel to be more than 10%
// away from what the frame about the normal alone would give.
void expectBrushedPlane(const std::string& name, void (*write)(const fs::path&), float rotation,
                        const Vec3& tangent) {
  SCOPED_TRACE(name);
  const fs::path dir = test::mapTestFolder("anisotropy_" + name);
  write(dir / "plane.obj");
  const test::RenderedWithNormals r = test::renderWithNormals(
      test::planeUnderSun(brushedJson(rotation), DVec3{kSun.x, kSun.y, kSun.z}, kIrradiance), dir);
  const Material m = brushed(rotation);
  double largestChange = 0;
  for (uint32_t y = 0; y < r.data.camera.height; ++y)
    for (uint32_t x = 0; x < r.data.camera.width; ++x) {
      const float expected = planeRadiance(r.data.camera, x, y, m, tangent);
      EXPECT_NEAR(r.result.image.at(x, y).x, expected, 1e-4f * expected) << x << "," << y;
      const float aboutNormal = planeRadiance(r.data.camera, x, y, m, Vec3(0.0f));
      largestChange = std::max(largestChange, std::fabs(double(aboutNormal) / expected - 1));
    }
  EXPECT_GT(largestChange, 0.1);
}

void writeMappedPlane(const fs::path& path) { test::writeMappedPlane(path); }

TEST(Anisotropy, APlaneFollowsTheTangentOfItsUvs) {
  expectBrushedPlane("u_along_z", writeTransposedPlane, 0.0f, Vec3(0.0f, 0.0f, 1.0f));
  // Turned counter-clockwise seen from the front (+y): +x turns towards -z.
  expectBrushedPlane("turned_90", writeMappedPlane, 90.0f, Vec3(0.0f, 0.0f, -1.0f));
  expectBrushedPlane("turned_30", writeMappedPlane, 30.0f,
                     Vec3(std::cos(kPi / 6), 0.0f, -std::sin(kPi / 6)));
}

// A sphere's tangent runs along its azimuth, the direction its u grows in (-z, 0, x) at the unit
// direction (x, y, z) from its centre: brushed metal turned on a lathe about the y axis.
TEST(Anisotropy, ASphereIsBrushedAlongItsAzimuth) {
  const fs::path dir = test::mapTestFolder("anisotropy_sphere");
  const test::RenderedWithNormals r = test::renderWithNormals(R"({
    "camera": {"width": 24, "height": 24, "fov": 40, "position": [0, 0, 5], "look_at": [0, 0, 0],
               "spp": 1},
    "render": {"antialiasing": false, "max_depth": 1},
    "spheres": [{"position": [0, 0, 0], "radius": 1, "material": )" +
                                                                  brushedJson(0.0f) + R"(}],
    "lights": [{"type": "directional", "direction": [-0.4, -0.5, -1], "intensity": 2}]})",
                                                              dir);
  const Material m = brushed(0.0f);
  const Vec3 toSun = normalize(Vec3(0.4f, 0.5f, 1.0f));
  int lit = 0, changed = 0;
  test::forEachSphereHit(r.data.camera, 1.0, [&](uint32_t x, uint32_t y, const DVec3& d) {
    const Vec3 n(float(d.x), float(d.y), float(d.z));
    const Vec3 wo = normalize(r.data.camera.position - n);
    const auto radiance = [&](const Vec3& tangent) {
      float pdf;
      return evalBsdf(untexturedBsdf(m, wo, n, n, tangent), toSun, &pdf).x * 2.0f;
    };
    const float expected = radiance(Vec3(-n.z, 0.0f, n.x));
    EXPECT_NEAR(r.result.image.at(x, y).x, expected, 2e-3f * expected + 1e-6f) << x << "," << y;
    if (expected < 0.01f) return;
    ++lit;
    changed += std::fabs(radiance(Vec3(0.0f)) / expected - 1.0f) > 0.1f;
  });
  EXPECT_GT(lit, 60);
  EXPECT_GT(changed, 20);  // from the frame about the normal alone
}

// A light subpath's vertex on a brushed floor keeps the floor's tangent, with which every
// connection to it evaluates the floor's BSDF: there, as at a camera path's vertex, the turned
// direction of u's growth, not the frame about the normal alone.
TEST(Anisotropy, ALightVertexKeepsItsTangent) {
  const fs::path dir = test::mapTestFolder("anisotropy_light_vertex");
  test::writeMappedPlane(dir / "plane.obj");
  const SceneData data = test::loadTestScene(R"({
    "camera": {"width": 4, "height": 4},
    "objects": [{"file": "plane.obj", "material": )" +
                                                 brushedJson(45.0f) + R"(}],
    "lights": [{"position": [0, 1, 0], "intensity": 10}]})",
                                             dir.string());
  const SceneView view = data.view();
  ASSERT_EQ(view.lightPathLights, 1u);
  const BvhTracer tracer{&view};
  const Vec3 expected = normalize(Vec3(1.0f, 0.0f, -1.0f));
  int valid = 0;
  for (uint32_t i = 0; i < 64; ++i) {
    SampleStream rng(1, i, 0, 1);
    RayCounters counters;
    LightVertex lv;
    traceLightVertex(view, tracer, rng, counters, 0.0f, &lv);
    if (!lv.valid) continue;
    ++valid;
    EXPECT_NEAR(std::fabs(dot(normalize(lv.tangent), expected)), 1.0f, 1e-5f) << i;
  }
  EXPECT_GT(valid, 20);
}

TEST(Anisotropy, TheSceneFormatRefusesWhatItCannotBe) {
  const auto error = test::sphereMaterialError;
  EXPECT_EQ(error(R"({"type": "glass", "roughness": 0.3, "anisotropy": 0.5,
                      "anisotropy_rotation": -45})"),
            "(no error)");
  EXPECT_EQ(error(R"({"type": "conductor", "anisotropy": 1.5})"),
            "test.json: spheres[0].material.anisotropy: expected an anisotropy in [0, 1], got 1.5");
  EXPECT_EQ(error(R"({"type": "conductor", "anisotropy_rotation": 30})"),
            "test.json: spheres[0].material.anisotropy_rotation: turns the tangent of an "
            "anisotropic material; expected an \"anisotropy\" above 0 beside it");
  EXPECT_EQ(error(R"({"type": "plastic", "anisotropy": 0.5})"),
            "test.json: spheres[0].material.anisotropy: not used by a \"plastic\" material");
  EXPECT_EQ(error(R"({"type": "diffuse", "anisotropy": 0.5})"),
            "test.json: spheres[0].material.anisotropy: not used by a \"diffuse\" material");
}

// A mesh without uvs has no tangent to follow: a warning says so, and the frame about the normal
// alone orients the roughness (as Mitsuba 3's does).
TEST(Anisotropy, AMeshWithoutUvsIsWarnedOf) {
  const fs::path dir = test::mapTestFolder("anisotropy_no_uvs");
  std::ofstream(dir / "tri.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  const SceneDesc scene = parseSceneText(R"({"camera": {"width": 4, "height": 4},
    "objects": [{"file": "tri.obj", "material": {"type": "conductor", "roughness": 0.4,
                                                 "anisotropy": 0.5}}]})",
                                         "s.json", dir.string());
  ASSERT_EQ(scene.warnings.size(), 1u);
  EXPECT_EQ(scene.warnings[0],
            "s.json: objects[0]: its material is anisotropic, but tri.obj has no texture "
            "coordinates (\"vt\"): its roughness follows a tangent that the normal alone gives");
}

// MTL's PBR extension, as Blender writes it: `aniso` is a metal's (Kd 0: docs/scene-format.md,
// MTL materials) anisotropy and `anisor` its
// rotation as a fraction of a full turn; a plastic (a material with a Kd) keeps an isotropic
// coat, with a warning, and a value outside [0, 1] is refused at its line.
TEST(Anisotropy, MtlAnisoMakesABrushedMetal) {
  const fs::path dir = test::mapTestFolder("anisotropy_mtl");
  std::ofstream(dir / "quad.obj") << "mtllib quad.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                  << "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                                  << "usemtl steel\nf 1/1 2/2 3/3\nusemtl paint\nf 1/1 3/3 4/4\n";
  const auto load = [&](const std::string& steelAniso) {
    std::ofstream(dir / "quad.mtl") << "newmtl steel\nKd 0 0 0\nKs 0.8 0.8 0.8\nPr 0.4\naniso "
                                    << steelAniso << "\nanisor 0.25\n"
                                    << "newmtl paint\nKd 0.5 0.1 0.1\nKs 0.5 0.5 0.5\naniso 0.5\n";
    return parseSceneText(R"({"camera": {"width": 4, "height": 4},
                              "objects": [{"file": "quad.obj"}]})",
                          "s.json", dir.string());
  };
  const SceneDesc scene = load("0.6");
  const std::vector<Material>& materials = scene.objects[0].mesh->materials;
  ASSERT_EQ(materials.size(), 2u);
  EXPECT_EQ(materials[0].type, MaterialType::Conductor);
  EXPECT_FLOAT_EQ(materials[0].roughness, 0.4f);
  EXPECT_FLOAT_EQ(materials[0].anisotropy, 0.6f);
  EXPECT_FLOAT_EQ(materials[0].anisotropyRotation, kPi / 2);
  EXPECT_EQ(materials[1].type, MaterialType::Plastic);
  EXPECT_EQ(materials[1].anisotropy, 0.0f);
  ASSERT_EQ(scene.warnings.size(), 1u);
  EXPECT_EQ(scene.warnings[0],
            "s.json: objects[0].file: quad.mtl:10: \"aniso\" not used: material \"paint\" has a "
            "diffuse colour, so it is a plastic, whose coat is isotropic");
  try {
    load("1.5");
    ADD_FAILURE() << "no error";
  } catch (const SceneError& e) {
    EXPECT_STREQ(
        e.what(),
        "s.json: objects[0].file: quad.mtl:5: expected aniso between 0 and 1, got \"1.5\"");
  }
}

}  // namespace
}  // namespace candela
