// Render passes (render/aov.h, render/aov_layers.h) against closed forms: the depth of a plane and
// a sphere seen by a known camera, normals, positions, ids, albedo through a mirror, the mean and
// nearest-sample rules at an edge, and a beauty image that passes leave bit-identical.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include "render/aov_layers.h"
#include "render_test_util.h"

namespace fs = std::filesystem;

namespace candela {
namespace {

using test::loadTestScene;

struct AovRender {
  SceneData scene;
  RenderResult result;
  std::vector<ImageLayer> layers;
  const ImageLayer& layer(const char* name) const {
    for (const ImageLayer& l : layers)
      if (l.name == name) return l;
    throw std::runtime_error(std::string("no layer ") + name);
  }
  float at(const char* name, uint32_t x, uint32_t y, uint32_t c = 0) const {
    const ImageLayer& l = layer(name);
    return l.pixels[l.channels.size() * (size_t(y) * l.width + x) + c];
  }
  Vec3 at3(const char* name, uint32_t x, uint32_t y) const {
    return {at(name, x, y, 0), at(name, x, y, 1), at(name, x, y, 2)};
  }
};

const char* kAll =
    "depth,distance,normal,normal_camera,albedo,position,instance,material,direct,emission,alpha";

AovRender renderAovs(const std::string& json, const std::string& baseDir = ".", int threads = 0,
                     const char* passes = kAll) {
  AovRender r{loadTestScene(json, baseDir), {}, {}};
  RenderOptions options;
  options.threads = threads;
  options.aovs = true;
  r.result = renderCpu(r.scene.view(), options);
  r.layers = makeAovLayers(r.scene, parseAovList(passes), r.result.aovs);
  return r;
}

// A square quad in the plane z = 0, facing +z, spanning [x0, x1] x [-100, 100].
std::string writeQuad(const fs::path& dir, const std::string& name, float x0, float x1) {
  fs::create_directories(dir);
  std::ofstream(dir / name) << "v " << x0 << " -100 0\nv " << x1 << " -100 0\nv " << x1
                            << " 100 0\nv " << x0 << " 100 0\nf 1 2 3 4\n";
  return name;
}

fs::path tempDir(const char* name) {
  return fs::temp_directory_path() / (std::string("candela_aov_") + name);
}

bool same(const Vec3& a, const Vec3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

constexpr float kInf = std::numeric_limits<float>::infinity();

TEST(Aovs, UnknownPassNamesAreRefusedWithTheKnownOnes) {
  try {
    parseAovList("depth,normals");
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "unknown render pass \"normals\"; the passes are: depth, distance, normal, "
              "normal_camera, albedo, position, instance, material, flow, backward_flow, direct, "
              "emission, alpha, uv, object_coordinates");
  }
  const std::vector<Aov> aovs = parseAovList(" normal , depth,normal");
  ASSERT_EQ(aovs.size(), 2u);
  EXPECT_EQ(aovs[0], Aov::Normal);
  EXPECT_EQ(aovs[1], Aov::Depth);
}

// A plane at z = -d before the default camera (at the origin, looking down -z): depth d at every
// pixel, distance d |K^-1 (u, v, 1)| through the pixel centre, position = centre + distance * dir.
TEST(Aovs, PlaneDepthDistancePositionAndNormalAreClosedForms) {
  const fs::path dir = tempDir("plane");
  writeQuad(dir, "quad.obj", -100, 100);
  const float d = 7.5f;
  const AovRender r = renderAovs(R"({
    "camera": {"width": 20, "height": 10, "fov": 90, "spp": 2},
    "render": {"antialiasing": false},
    "objects": [{"file": "quad.obj", "position": [0, 0, -7.5], "color": [0.1, 0.2, 0.3]}],
    "lights": [{"position": [0, 0, 0], "intensity": 100}]
  })", dir.string());
  const float f = 20.0f / 2.0f;  // fov 90: fx = fy = width / 2
  for (uint32_t y = 0; y < 10; ++y)
    for (uint32_t x = 0; x < 20; ++x) {
      const float cx = (x + 0.5f - 10.0f) / f, cy = (y + 0.5f - 5.0f) / f;
      const float norm = std::sqrt(cx * cx + cy * cy + 1.0f);
      EXPECT_NEAR(r.at("depth", x, y), d, 1e-5f * d) << x << "," << y;
      EXPECT_NEAR(r.at("distance", x, y), d * norm, 1e-5f * d) << x << "," << y;
      // OpenCV camera: +y down, so the world direction is (cx, -cy, -1) / norm.
      const Vec3 p = r.at3("position", x, y);
      EXPECT_NEAR(p.x, d * cx, 1e-5f * d);
      EXPECT_NEAR(p.y, -d * cy, 1e-5f * d);
      EXPECT_NEAR(p.z, -d, 1e-5f * d);
      EXPECT_TRUE(same(r.at3("normal", x, y), Vec3(0, 0, 1)));
      const Vec3 nc = r.at3("normal_camera", x, y);  // facing the camera: -z in OpenCV axes
      EXPECT_NEAR(nc.x, 0.0f, 1e-6f);
      EXPECT_NEAR(nc.y, 0.0f, 1e-6f);
      EXPECT_NEAR(nc.z, -1.0f, 1e-6f);
      const Vec3 a = r.at3("albedo", x, y);
      EXPECT_FLOAT_EQ(a.x, 0.1f);
      EXPECT_FLOAT_EQ(a.y, 0.2f);
      EXPECT_FLOAT_EQ(a.z, 0.3f);
      EXPECT_EQ(r.at("instance", x, y), 1.0f);  // no spheres: object 0 is instance 1
    }
  fs::remove_all(dir);
}

// A unit sphere 5 before a camera looking at it, the image centre on its axis: depth 4 there and
// the normal pointing at the camera; the corners see the background.
TEST(Aovs, SphereCentreFacesTheCameraAndTheBackgroundIsInfinitelyFar) {
  const AovRender r = renderAovs(R"({
    "camera": {"width": 15, "height": 15, "fov": 30, "spp": 4, "position": [0, 0, 5]},
    "render": {"antialiasing": false},
    "spheres": [{"position": [0, 0, 0], "radius": 1, "color": 0.5}],
    "lights": [{"position": [0, 3, 3], "intensity": 100}]
  })");
  EXPECT_NEAR(r.at("depth", 7, 7), 4.0f, 1e-5f);
  EXPECT_NEAR(r.at("distance", 7, 7), 4.0f, 1e-5f);
  const Vec3 n = r.at3("normal", 7, 7);
  EXPECT_NEAR(n.x, 0.0f, 1e-6f);
  EXPECT_NEAR(n.y, 0.0f, 1e-6f);
  EXPECT_NEAR(n.z, 1.0f, 1e-6f);
  EXPECT_EQ(r.at("instance", 7, 7), 1.0f);
  EXPECT_EQ(r.at("material", 7, 7), 1.0f);
  EXPECT_EQ(r.at("depth", 0, 0), kInf);
  EXPECT_EQ(r.at("distance", 0, 0), kInf);
  EXPECT_TRUE(same(r.at3("normal", 0, 0), Vec3(0.0f)));
  EXPECT_TRUE(same(r.at3("position", 0, 0), Vec3(0.0f)));
  EXPECT_TRUE(same(r.at3("albedo", 0, 0), Vec3(0.0f)));
  EXPECT_EQ(r.at("instance", 0, 0), 0.0f);
  EXPECT_EQ(r.at("material", 0, 0), 0.0f);
  // Off-centre pixels: the normal is (p - centre) / radius.
  for (uint32_t x = 5; x < 10; ++x) {
    const Vec3 p = r.at3("position", x, 6), nn = r.at3("normal", x, 6);
    EXPECT_NEAR(length(p), 1.0f, 1e-5f);
    EXPECT_NEAR(dot(nn, p), 1.0f, 1e-5f);
  }
}

// Spheres are numbered first, then objects, then lights (point lights too, though they are never
// seen); materials in the order the entities append them.
TEST(Aovs, InstanceAndMaterialIdsNameWhatEachPixelShows) {
  const fs::path dir = tempDir("ids");
  writeQuad(dir, "quad.obj", -100, 100);
  const AovRender r = renderAovs(R"({
    "camera": {"width": 40, "height": 20, "fov": 90, "spp": 4, "position": [0, 0, 10]},
    "render": {"antialiasing": false},
    "spheres": [{"position": [-6, 0, 0], "radius": 3, "color": [1, 0, 0]},
                {"position": [6, 0, 0], "radius": 3, "material": "mirror"}],
    "objects": [{"file": "quad.obj", "position": [0, 0, -20], "color": 0.5}],
    "lights": [{"position": [0, 8, 8], "intensity": 1000},
               {"type": "sphere", "position": [0, 0, 0], "radius": 1, "intensity": 10}]
  })", dir.string());
  const auto id = [&](uint32_t x, uint32_t y) { return int(r.at("instance", x, y)); };
  const auto mat = [&](uint32_t x, uint32_t y) { return int(r.at("material", x, y)); };
  // Pixel columns: x = 20 + 20 * X / 10 for a point at depth 10 (fx = 20).
  EXPECT_EQ(id(8, 10), 1);    // left sphere, centre at X = -6
  EXPECT_EQ(id(32, 10), 2);   // right sphere, X = 6
  EXPECT_EQ(id(20, 10), 5);   // the sphere light: 2 spheres + 1 object + light index 1 + 1
  EXPECT_EQ(id(20, 2), 3);    // the quad behind, between and above them
  EXPECT_EQ(mat(8, 10), 1);
  EXPECT_EQ(mat(32, 10), 2);
  EXPECT_EQ(mat(20, 10), 3);  // the sphere light's emitter comes after the spheres' materials
  EXPECT_EQ(mat(20, 2), 4);
  fs::remove_all(dir);
}

// Albedo follows perfect mirrors: a mirror sphere inside a room sphere shows the room's colour,
// untinted by the mirror; the ids still name the mirror. An emitter's albedo is its radiance
// clamped to [0, 1].
TEST(Aovs, AlbedoThroughAMirrorIsTheMirroredSurfacesColour) {
  const AovRender r = renderAovs(R"({
    "camera": {"width": 9, "height": 9, "fov": 20, "spp": 4, "position": [0, 0, 5]},
    "render": {"antialiasing": false, "max_depth": 3},
    "spheres": [{"position": [0, 0, 0], "radius": 1, "material": "mirror", "color": 0.5},
                {"position": [0, 0, 0], "radius": 100, "color": [0.2, 0.4, 0.6]}],
    "lights": [{"position": [0, 3, 3], "intensity": 100}]
  })");
  const Vec3 a = r.at3("albedo", 4, 4);
  EXPECT_FLOAT_EQ(a.x, 0.2f);
  EXPECT_FLOAT_EQ(a.y, 0.4f);
  EXPECT_FLOAT_EQ(a.z, 0.6f);
  EXPECT_EQ(r.at("instance", 4, 4), 1.0f);
  EXPECT_NEAR(r.at("depth", 4, 4), 4.0f, 1e-5f);
  const AovRender e = renderAovs(R"({
    "camera": {"width": 9, "height": 9, "fov": 20, "spp": 4, "position": [0, 0, 5]},
    "render": {"antialiasing": false},
    "spheres": [{"position": [0, 0, 0], "radius": 1,
                 "material": {"type": "emissive", "radiance": [3, 0.25, 0]}}]
  })");
  const Vec3 ea = e.at3("albedo", 4, 4);
  EXPECT_TRUE(same(ea, Vec3(1.0f, 0.25f, 0.0f)));
}

// The environment is an emitter too: a sample that leaves the scene before any other surface
// records its radiance clamped to [0, 1], seen straight or through a mirror, while depth and
// normal still say background.
TEST(Aovs, AlbedoOfTheEnvironmentIsItsClampedRadiance) {
  const AovRender r = renderAovs(R"({
    "camera": {"width": 9, "height": 9, "fov": 20, "spp": 4, "position": [0, 0, 5]},
    "render": {"antialiasing": false},
    "environment": {"color": [3, 0.25, 0]},
    "spheres": [{"position": [0, 0, 0], "radius": 1, "material": "mirror"}]
  })");
  EXPECT_TRUE(same(r.at3("albedo", 0, 0), Vec3(1.0f, 0.25f, 0.0f)));
  EXPECT_TRUE(same(r.at3("albedo", 4, 4), Vec3(1.0f, 0.25f, 0.0f)));
  EXPECT_EQ(r.at("depth", 0, 0), kInf);
  EXPECT_TRUE(same(r.at3("normal", 0, 0), Vec3(0.0f)));
  EXPECT_EQ(r.at("instance", 4, 4), 1.0f);
}

// A translucent sheet's albedo is all it scatters, reflected and let through (at most 1), so that
// a denoiser sees the colour of a backlit leaf; at max_depth 1 as after it.
TEST(Aovs, AlbedoOfATranslucentSheetIsItsColourPlusItsTransmittance) {
  for (const char* depth : {"1", "4"}) {
    SCOPED_TRACE(std::string("max_depth ") + depth);
    const AovRender r = renderAovs(R"({
      "camera": {"width": 9, "height": 9, "fov": 20, "spp": 4, "position": [0, 0, 5]},
      "render": {"antialiasing": false, "max_depth": )" +
                                   std::string(depth) + R"(},
      "spheres": [{"position": [0, 0, 0], "radius": 1, "material": {"type": "diffuse",
                   "color": [0.2, 0.5, 0.1], "transmittance": [0.3, 0.7, 0.4]}}],
      "lights": [{"position": [0, 3, 3], "intensity": 100}]
    })");
    EXPECT_TRUE(same(r.at3("albedo", 4, 4), Vec3(0.5f, 1.0f, 0.5f)));
  }
}

// At an edge, filtered passes are means over the samples (albedo over all of them, depth over
// those that hit) while the id passes take the sample nearest the pixel centre.
TEST(Aovs, EdgePixelsAverageFilteredPassesAndTakeIdsFromTheNearestSample) {
  const fs::path dir = tempDir("edge");
  // fov 90, width 16: pixel 8 spans x/z in [0, 1/8); the quad covers 30% of it, its left part.
  const float d = 4.0f, edge = 0.3f * d / 8.0f;
  writeQuad(dir, "quad.obj", -100, edge);
  const AovRender r = renderAovs(R"({
    "camera": {"width": 16, "height": 4, "fov": 90, "spp": 256},
    "objects": [{"file": "quad.obj", "position": [0, 0, -4], "color": 1}]
  })", dir.string());
  const float covered = r.at("albedo", 8, 1);
  EXPECT_GT(covered, 0.3f - 4 * 0.03f);  // binomial: sd sqrt(0.3 * 0.7 / 256) ~ 0.03
  EXPECT_LT(covered, 0.3f + 4 * 0.03f);
  EXPECT_NEAR(r.at("depth", 8, 1), d, 1e-5f * d);  // the hits all lie on the plane
  EXPECT_EQ(r.at("instance", 8, 1), 0.0f);         // the centre sees the background
  EXPECT_EQ(r.at("instance", 7, 1), 1.0f);
  EXPECT_EQ(r.at("albedo", 7, 1), 1.0f);
  EXPECT_EQ(r.at("instance", 9, 1), 0.0f);
  EXPECT_EQ(r.at("depth", 9, 1), kInf);
  fs::remove_all(dir);
}

// Renders `json` with "MAX_DEPTH" replaced by `maxDepth`: its image, and with passes its direct
// light pass.
struct DirectAndImage {
  std::vector<float> image, direct;
};
DirectAndImage renderDirect(std::string json, uint32_t maxDepth) {
  json.replace(json.find("MAX_DEPTH"), 9, std::to_string(maxDepth));
  const AovRender r = renderAovs(json, ".", 2, "direct");
  return {r.result.image.pixels, r.layer("direct").pixels};
}

// The direct light pass is what the image would be at max_depth 1, from the same samples:
// emitters (a sphere light, an emissive face) and the environment seen at the first hit, through
// a mirror or glass or by the first hit's scattered ray, and next-event estimation there. Light
// subpaths are off: a render at max_depth 1 starts none, and would draw other numbers. Every
// sample's direct light is part of its radiance, so the image is nowhere below the pass.
TEST(Aovs, DirectLightIsTheImageAtMaxDepthOne) {
  const std::string json = R"({
    "camera": {"width": 24, "height": 16, "spp": 8, "position": [0, 0, 30], "fov": 50},
    "render": {"max_depth": MAX_DEPTH, "light_paths": "off"},
    "environment": {"color": [0.1, 0.1, 0.2]},
    "spheres": [{"position": [0, -1000, 0], "radius": 990, "color": 0.75},
                {"position": [-6, 0, 0], "radius": 4, "material": "mirror"},
                {"position": [6, 0, 0], "radius": 4, "material": {"type": "glass", "ior": 1.5}},
                {"position": [0, 0, -5], "radius": 3,
                 "material": {"type": "plastic", "color": [0.7, 0.1, 0.1], "roughness": 0.3}},
                {"position": [0, 12, -8], "radius": 1,
                 "material": {"type": "emissive", "radiance": 20}}],
    "lights": [{"type": "sphere", "position": [0, 15, 10], "radius": 2, "intensity": 5e4}]
  })";
  const DirectAndImage deep = renderDirect(json, 6), shallow = renderDirect(json, 1);
  ASSERT_EQ(deep.direct.size(), shallow.image.size());
  EXPECT_EQ(std::memcmp(deep.direct.data(), shallow.image.data(), deep.direct.size() * 4), 0);
  // The direct pass at max_depth 1 is the image itself.
  EXPECT_EQ(std::memcmp(shallow.direct.data(), shallow.image.data(), deep.direct.size() * 4), 0);
  double indirect = 0.0;
  for (size_t i = 0; i < deep.image.size(); ++i) {
    EXPECT_GE(deep.image[i], deep.direct[i]) << i;
    indirect += deep.image[i] - deep.direct[i];
  }
  EXPECT_GT(indirect, 0.0);
}

// Light-vertex connections carry light that has scattered twice: none of it is direct. With a
// lone point light, next-event estimation at the first hit draws no numbers, so a render at
// max_depth 1 (which starts no light subpaths) shows the same direct light to the bit.
TEST(Aovs, DirectLightLeavesOutTheLightVertexConnections) {
  const std::string json = R"({
    "camera": {"width": 24, "height": 16, "spp": 8, "position": [0, 0, 30], "fov": 50},
    "render": {"max_depth": MAX_DEPTH, "light_paths": "on"},
    "spheres": [{"position": [0, -1000, 0], "radius": 990, "color": 0.75},
                {"position": [0, 0, -5], "radius": 3, "color": [0.7, 0.3, 0.1]}],
    "lights": [{"position": [0, 4, 0], "intensity": 2000}]
  })";
  const DirectAndImage deep = renderDirect(json, 6), shallow = renderDirect(json, 1);
  EXPECT_EQ(std::memcmp(deep.direct.data(), shallow.image.data(), deep.direct.size() * 4), 0);
  EXPECT_NE(std::memcmp(deep.image.data(), shallow.image.data(), deep.image.size() * 4), 0);
}

// The emission pass holds the emitting surfaces seen at the first hit: an emissive sphere's
// radiance where the camera sees it, nothing where it sees the environment or the sphere in a
// mirror, all of which the direct light pass holds.
TEST(Aovs, EmissionIsTheEmittersSeenAtTheFirstHit) {
  const AovRender r = renderAovs(R"({
    "camera": {"width": 21, "height": 9, "fov": 40, "spp": 4, "position": [0, 0, 10]},
    "render": {"antialiasing": false},
    "environment": {"color": [0.5, 0.25, 0.125]},
    "spheres": [{"position": [-2, 0, 0], "radius": 1,
                 "material": {"type": "emissive", "radiance": [3, 2, 1]}},
                {"position": [2.5, 0, 0], "radius": 1, "material": "mirror"}]
  })", ".", 2, "emission,direct");
  EXPECT_TRUE(same(r.at3("emission", 6, 4), Vec3(3.0f, 2.0f, 1.0f)));  // the emitter
  EXPECT_TRUE(same(r.at3("direct", 6, 4), Vec3(3.0f, 2.0f, 1.0f)));
  EXPECT_TRUE(same(r.at3("emission", 10, 0), Vec3(0.0f)));  // the environment
  EXPECT_TRUE(same(r.at3("direct", 10, 0), Vec3(0.5f, 0.25f, 0.125f)));
  // The mirror's left side shows the emitter; the direct pass has it, the emission pass not.
  bool mirrored = false;
  for (uint32_t x = 11; x < 21; ++x) {
    EXPECT_TRUE(same(r.at3("emission", x, 4), Vec3(0.0f))) << x;
    mirrored |= r.at("direct", x, 4, 0) > 1.0f;
  }
  EXPECT_TRUE(mirrored);
}

// Passes draw no random numbers: the beauty image is bit-identical with and without them, and the
// passes themselves do not depend on the thread count.
TEST(Aovs, BeautyIsBitIdenticalWithAndWithoutPasses) {
  const std::string json = R"({
    "camera": {"width": 24, "height": 16, "spp": 8, "position": [0, 0, 30], "fov": 50},
    "render": {"max_depth": 6},
    "environment": {"color": [0.1, 0.1, 0.2]},
    "spheres": [{"position": [0, -1000, 0], "radius": 990, "color": 0.75},
                {"position": [-6, 0, 0], "radius": 4, "material": "mirror"},
                {"position": [6, 0, 0], "radius": 4, "material": {"type": "glass", "ior": 1.5}},
                {"position": [0, 0, -5], "radius": 3,
                 "material": {"type": "plastic", "color": [0.7, 0.1, 0.1], "roughness": 0.3}}],
    "lights": [{"type": "sphere", "position": [0, 15, 10], "radius": 2, "intensity": 5e4}]
  })";
  const SceneData scene = loadTestScene(json);
  RenderOptions plain;
  plain.threads = 2;
  const RenderResult a = renderCpu(scene.view(), plain);
  RenderOptions withAovs = plain;
  withAovs.aovs = true;
  const RenderResult b = renderCpu(scene.view(), withAovs);
  EXPECT_TRUE(a.aovs.empty());
  ASSERT_EQ(a.image.pixels.size(), b.image.pixels.size());
  EXPECT_EQ(std::memcmp(a.image.pixels.data(), b.image.pixels.data(),
                        a.image.pixels.size() * sizeof(float)),
            0);
  EXPECT_EQ(a.rays.camera, b.rays.camera);
  EXPECT_EQ(a.rays.bounce, b.rays.bounce);
  EXPECT_EQ(a.rays.shadow, b.rays.shadow);

  withAovs.threads = 1;
  const RenderResult c = renderCpu(scene.view(), withAovs);
  const std::vector<Aov> all = parseAovList(kAll);
  const std::vector<ImageLayer> lb = makeAovLayers(scene, all, b.aovs);
  const std::vector<ImageLayer> lc = makeAovLayers(scene, all, c.aovs);
  for (size_t i = 0; i < lb.size(); ++i)
    EXPECT_EQ(std::memcmp(lb[i].pixels.data(), lc[i].pixels.data(),
                          lb[i].pixels.size() * sizeof(float)),
              0)
        << lb[i].name;
}

}  // namespace
}  // namespace candela
