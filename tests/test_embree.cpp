// The CPU's Embree engine against candela's own: the same hits ray by ray, the same images up to
// rounding, and frames of an animation (refits) as a fresh build of each frame renders them.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "backends/cpu/cpu_engine.h"
#include "backends/cpu/cpu_renderer.h"
#include "image_difference.h"
#include "render_test_util.h"
#include "scene/animation.h"
#include "scene/frame_scene.h"
#include "temp_dir.h"
#include "test_random.h"

#if defined(CANDELA_HAS_EMBREE)
#include "backends/cpu/embree_scene.h"
#include "core/rotation.h"
#include "geometry/bvh_traverse.h"
#endif

namespace candela {
namespace {

#if !defined(CANDELA_HAS_EMBREE)

TEST(Embree, EngineIsAbsent) {
  EXPECT_FALSE(embreeAvailable());
  EXPECT_EQ(resolveCpuEngine(CpuEngine::Auto, false, kEmbreeFromTriangles, 0), CpuEngine::Bvh);
  EXPECT_THROW(resolveCpuEngine(CpuEngine::Embree, false, 0, 0), BackendError);
  GTEST_SKIP() << "this build has no Embree (CANDELA_EMBREE): its engine tests do not apply";
}

#else

constexpr uint32_t kNone = 0xffffffffu;

TEST(Embree, EngineChoice) {
  EXPECT_TRUE(embreeAvailable());
  const uint64_t many = kSphereBlocksUpTo + 1, few = kSphereBlocksUpTo;
  EXPECT_EQ(resolveCpuEngine(CpuEngine::Auto, false, kEmbreeFromTriangles, many),
            CpuEngine::Embree);
  EXPECT_EQ(resolveCpuEngine(CpuEngine::Auto, false, kEmbreeFromTriangles - 1, many),
            CpuEngine::Bvh);
  // Below the triangle count, few spheres (in blocks) still favour Embree, with or without
  // triangles; an empty scene goes to the own BVH.
  EXPECT_EQ(resolveCpuEngine(CpuEngine::Auto, false, 32, few), CpuEngine::Embree);
  EXPECT_EQ(resolveCpuEngine(CpuEngine::Auto, false, 0, few), CpuEngine::Embree);
  EXPECT_EQ(resolveCpuEngine(CpuEngine::Auto, false, 0, many), CpuEngine::Bvh);
  EXPECT_EQ(resolveCpuEngine(CpuEngine::Auto, false, 0, 0), CpuEngine::Bvh);
  EXPECT_EQ(resolveCpuEngine(CpuEngine::Auto, true, kEmbreeFromTriangles, 0), CpuEngine::Bvh);
  EXPECT_EQ(resolveCpuEngine(CpuEngine::Bvh, false, kEmbreeFromTriangles, 0), CpuEngine::Bvh);
  EXPECT_EQ(resolveCpuEngine(CpuEngine::Embree, false, 0, many), CpuEngine::Embree);  // asked for
  EXPECT_THROW(resolveCpuEngine(CpuEngine::Embree, true, 0, 0), BackendError);
  CpuEngine e;
  EXPECT_TRUE(cpuEngineFromName("EMBREE", &e));
  EXPECT_EQ(e, CpuEngine::Embree);
  EXPECT_FALSE(cpuEngineFromName("optix", &e));
}

// Random spheres (some large, so that rays start inside them) and random triangles in a box;
// 40 spheres go into the engine's sphere BVH, up to kSphereBlocksUpTo into its sphere blocks;
// up to kTriangleBlocksUpTo triangles go into its triangle blocks, more to Embree.
SceneData randomScene(uint32_t seed, int sphereCount = 40, int triangleCount = 400) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<float> u(-4.0f, 4.0f), r(0.05f, 1.5f);
  SceneData s;
  for (int i = 0; i < sphereCount; ++i) s.spheres.push_back(Sphere{Vec3(u(gen), u(gen), u(gen)), r(gen), 0});
  for (int i = 0; i < triangleCount; ++i) {
    const Vec3 a(u(gen), u(gen), u(gen));
    const uint32_t first = uint32_t(s.positions.size());
    s.positions.insert(s.positions.end(), {a, a + test::randomUnitVector(gen) * r(gen),
                                           a + test::randomUnitVector(gen) * r(gen)});
    s.triangles.push_back(Triangle{{first, first + 1, first + 2}, 0});
  }
  return s;
}

// randomScene's spheres, and objects that repeat one mesh of 100 random triangles (3 instances
// of it, then an object of its own, then 2 more instances), placed by random rotations, scales
// (one mirroring) and translations, every other triangle half transparent: a scene the Embree
// engine traces through instances.
SceneData instancedScene(uint32_t seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f), angle(0.0f, 360.0f);
  SceneData s = randomScene(seed, 10);
  s.positions.clear();
  s.triangles.clear();
  MeshPrototype prototype;
  for (uint32_t i = 0; i < 100; ++i) {
    const Vec3 a(u(gen), u(gen), u(gen));
    for (const Vec3& p :
         {a, a + test::randomUnitVector(gen) * 0.8f, a + test::randomUnitVector(gen) * 0.8f})
      prototype.positions.push_back(p);
  }
  const auto place = [&](const PaddedVector<Vec3>& positions, int32_t repeats, float scaleX) {
    MeshInstance object;
    object.firstTriangle = uint32_t(s.triangles.size());
    object.triangleCount = uint32_t(positions.size() / 3);
    object.firstVertex = uint32_t(s.positions.size());
    object.vertexCount = uint32_t(positions.size());
    const Mat3 r = eulerRotation(Vec3(angle(gen), angle(gen), angle(gen)));
    const Vec3 scale(scaleX, 1.5f, 1.5f);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) object.linear.m[i][j] = r.m[i][j] * scale[j];
    object.translation = Vec3(u(gen), u(gen), u(gen)) * 3.0f;
    object.prototype = repeats;
    for (const Vec3& p : positions) s.positions.push_back(object.translation + object.linear * p);
    for (uint32_t t = 0; t < object.triangleCount; ++t)
      s.triangles.push_back(Triangle{{object.firstVertex + 3 * t, object.firstVertex + 3 * t + 1,
                                      object.firstVertex + 3 * t + 2},
                                     t % 2});
    s.meshInstances.objects.push_back(object);
  };
  for (float scaleX : {1.5f, 2.0f, -1.5f}) place(prototype.positions, 0, scaleX);
  PaddedVector<Vec3> own(prototype.positions.begin(), prototype.positions.begin() + 60);
  place(own, -1, 1.0f);
  for (float scaleX : {1.0f, 0.7f}) place(prototype.positions, 0, scaleX);
  prototype.firstInstance = 0;
  prototype.instanceCount = 5;
  // Every other triangle is half transparent: a stochastic alpha test, of the world's ray.
  s.alphaMasks = {AlphaMask(), AlphaMask{0.5f}};
  s.meshInstances.prototypes.push_back(prototype);
  return s;
}

// The leaves Embree is given (embree_scene.h): copies of the vertices below
// kIndexedLeavesFromTriangles, indices into the shared vertices from 0 triangles on.
constexpr uint32_t kLeafKinds[] = {kIndexedLeavesFromTriangles, 0};

// Closest hits and shadow queries agree with testing every primitive (candela's own tests),
// to the rounding of the two triangle tests: where the nearest primitive differs, the two hits
// lie at the same distance (two primitives crossing there). With either kind of leaves.
TEST(Embree, HitsMatchBruteForceRayByRay) {
  for (uint32_t indexedFrom : kLeafKinds) {
    for (uint32_t seed : {1u, 2u, 3u, 4u, 8u, 10u}) {
      // Seed 10: few enough triangles for the triangle blocks.
      const SceneData scene = seed == 8    ? instancedScene(seed)
                              : seed == 10 ? randomScene(seed, 10, int(kTriangleBlocksUpTo))
                                           : randomScene(seed, seed == 4 ? 10 : 40);
      const SceneView view = scene.view();
      EmbreeScene embree(nullptr, indexedFrom);
      embree.update(scene, SceneChange::Structure);
      EXPECT_EQ(embree.instanceCount(), seed == 8 ? 5u : 0u);
      EXPECT_EQ(embree.tracer().triangleBlocks.blockCount != 0,
                seed == 10 && widestTriangleBlock() != 0);
      const EmbreeTracer tracer = embree.tracer();
      std::mt19937 gen(seed + 100);
      std::uniform_real_distribution<float> u(-5.0f, 5.0f);
      int hits = 0, occludedAgree = 0, shadowRays = 0;
      for (int i = 0; i < 4000; ++i) {
        Ray ray;
        ray.origin = Vec3(u(gen), u(gen), u(gen));
        ray.direction = test::randomUnitVector(gen) * (0.5f + float(i % 3));  // not unit length
        if (i % 4 == 0) ray.tMax = 3.0f;
        Hit expected, got;
        const bool found = intersectClosestBruteForce(view, ray, &expected);
        ASSERT_EQ(tracer.closest(ray, &got), found) << "seed " << seed << " ray " << i;
        if (found) {
          ++hits;
          // Relative, and absolute at the scene's scale: within an instance Embree tests the
          // triangle in its object space, so a hit next to the origin is off by that space's
          // rounding.
          const float tolerance = 1e-4f * expected.t + 1e-6f;
          EXPECT_NEAR(got.t, expected.t, tolerance) << "ray " << i;
          if (got.prim == expected.prim && expected.prim >= scene.spheres.size()) {
            EXPECT_NEAR(got.b1, expected.b1, 1e-4f);
            EXPECT_NEAR(got.b2, expected.b2, 1e-4f);
          } else if (got.prim != expected.prim) {
            EXPECT_NEAR(got.t, expected.t, 0.1f * tolerance) << "ray " << i;
          }
        }
        // A shadow query skipping nothing, the nearest primitive, or a random one.
        uint32_t skip = kNone;
        if (i % 3 == 1 && found) skip = expected.prim;
        if (i % 3 == 2) skip = uint32_t(gen() % view.primitiveCount());
        ++shadowRays;
        occludedAgree += tracer.occluded(ray, skip) == intersectAnyBruteForce(view, ray, skip);
      }
      EXPECT_GT(hits, seed == 10 ? 500 : 1000);
      // Only a ray grazing an edge within rounding may be answered differently.
      EXPECT_GE(occludedAgree, shadowRays - 2) << "seed " << seed;
    }
  }
}

// Packets of rays (closestPacket, occludedPacket) find what the rays find one at a time: bundles
// of 1 to 16 nearly parallel rays from one point, as a pixel's camera rays are, and bundles of
// unrelated rays, some cut short by tMax, one not finite, over spheres in blocks and in their
// BVH; shadow rays skip nothing, the primitive they hit first, or a random one.
// Packets against single rays with the instruction set Embree picks for this CPU, and with AVX2
// and SSE4.2 forced: below AVX-512 Embree has no 16-wide packets and traces them through its
// ray-stream path, which ignores the valid mask (it read the unused lanes, and its checks
// aborted on them). Also through instances, where Embree's coherent 16-wide occlusion packets
// never returned. With either kind of leaves.
class EmbreePackets : public ::testing::TestWithParam<const char*> {};

TEST_P(EmbreePackets, QueriesMatchRayByRay) {
  for (uint32_t indexedFrom : kLeafKinds) {
    for (uint32_t seed : {5u, 6u, 9u, 11u}) {
      // Seed 11: in triangle blocks, whose packets go ray by ray.
      const SceneData scene = seed == 9    ? instancedScene(seed)
                              : seed == 11 ? randomScene(seed, 10, 40)
                                           : randomScene(seed, seed == 6 ? 10 : 40);
      EmbreeScene embree(*GetParam() ? GetParam() : nullptr, indexedFrom);
      embree.update(scene, SceneChange::Structure);
      const EmbreeTracer tracer = embree.tracer();
      std::mt19937 gen(seed + 200);
      std::uniform_real_distribution<float> u(-5.0f, 5.0f), jitter(-0.02f, 0.02f);
      int hits = 0, blocks = 0;
      for (int bundle = 0; bundle < 300; ++bundle) {
        const uint32_t n = 1 + uint32_t(bundle) % EmbreeTracer::kPacketWidth;
        const bool coherent = bundle % 2 == 0;
        const Vec3 origin(u(gen), u(gen), u(gen));
        const Vec3 axis = test::randomUnitVector(gen);
        Ray rays[EmbreeTracer::kPacketWidth];
        for (uint32_t i = 0; i < n; ++i) {
          rays[i].origin = coherent ? origin : Vec3(u(gen), u(gen), u(gen));
          rays[i].direction = coherent ? axis + Vec3(jitter(gen), jitter(gen), jitter(gen))
                                       : test::randomUnitVector(gen);
          if (i % 5 == 3) rays[i].tMax = 2.0f;
        }
        if (bundle % 7 == 0) rays[n - 1].direction = Vec3(std::nanf(""), 0.0f, 1.0f);
        Hit packet[EmbreeTracer::kPacketWidth];
        tracer.closestPacket(rays, n, packet);
        for (uint32_t i = 0; i < n; ++i) {
          Hit single;
          const bool found = tracer.closest(rays[i], &single);
          ASSERT_EQ(packet[i].valid(), found) << "bundle " << bundle << " ray " << i;
          if (!found) continue;
          ++hits;
          EXPECT_NEAR(packet[i].t, single.t, 1e-5f * single.t) << "bundle " << bundle;
          if (packet[i].prim == single.prim) {
            EXPECT_NEAR(packet[i].b1, single.b1, 1e-5f);
            EXPECT_NEAR(packet[i].b2, single.b2, 1e-5f);
          }
        }
        uint32_t skip[EmbreeTracer::kPacketWidth];
        for (uint32_t i = 0; i < n; ++i) {
          skip[i] = kNone;
          if (i % 3 == 1 && packet[i].valid()) skip[i] = packet[i].prim;
          if (i % 3 == 2) skip[i] = uint32_t(gen() % scene.view().primitiveCount());
        }
        bool blocked[EmbreeTracer::kPacketWidth];
        tracer.occludedPacket(rays, skip, n, blocked);
        for (uint32_t i = 0; i < n; ++i) {
          const bool single = tracer.occluded(rays[i], skip[i]);
          blocks += single;
          EXPECT_EQ(blocked[i], single) << "bundle " << bundle << " ray " << i;
        }
      }
      EXPECT_GT(hits, seed == 11 ? 300 : 500) << "seed " << seed;
      EXPECT_GT(blocks, 300) << "seed " << seed;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Embree, EmbreePackets, ::testing::Values("", "isa=avx2", "isa=sse4.2"),
                         [](const ::testing::TestParamInfo<const char*>& param) {
                           const std::string config = param.param;
                           return config.empty()         ? std::string("NativeIsa")
                                  : config == "isa=avx2" ? std::string("Avx2")
                                                         : std::string("Sse42");
                         });

TEST(Embree, NonFiniteRaysHitNothing) {
  const SceneData scene = randomScene(7);
  EmbreeScene embree;
  embree.update(scene, SceneChange::Structure);
  Ray ray;
  ray.origin = Vec3(0.0f);
  ray.direction = Vec3(std::nanf(""), 1.0f, 0.0f);
  Hit hit;
  EXPECT_FALSE(embree.tracer().closest(ray, &hit));
  EXPECT_FALSE(embree.tracer().occluded(ray, kNone));
}

TEST(Embree, EmptySceneIsAllMiss) {
  SceneData empty;
  EmbreeScene embree;
  embree.update(empty, SceneChange::Structure);
  Ray ray;
  ray.origin = Vec3(0.0f);
  ray.direction = Vec3(0.0f, 0.0f, -1.0f);
  Hit hit;
  EXPECT_FALSE(embree.tracer().closest(ray, &hit));
  EXPECT_FALSE(embree.tracer().occluded(ray, kNone));
}

RenderResult renderWith(CpuEngine engine, const SceneDesc& scene) {
  SceneDesc desc = scene;
  if (engine == CpuEngine::Embree) desc.ownBvh = OwnBvh::None;
  const SceneData data = flattenScene(desc);
  CpuRenderer renderer(engine);
  renderer.setScene(data, SceneChange::Structure);
  return renderer.render(RenderOptions{});
}

// The Embree engine's image of `scene` is the own BVH's up to rounding: their difference is far
// below the noise between two seeds.
void expectEnginesAgree(SceneDesc scene) {
  const ImageRGB own = renderWith(CpuEngine::Bvh, scene).image;
  const ImageRGB embree = renderWith(CpuEngine::Embree, scene).image;
  scene.render.seed = 99;
  const ImageRGB otherSeed = renderWith(CpuEngine::Bvh, scene).image;
  const double noise = test::relMseAgainst(own.pixels, otherSeed.pixels);
  EXPECT_GT(noise, 0.0);
  EXPECT_LT(test::relMseAgainst(own.pixels, embree.pixels), 0.05 * noise)
      << "noise between seeds " << noise;
}

// A ball of 8 x 6 quads (96 triangles, enough to be traced as instances) whose lower half is
// half transparent (MTL d 0.5: a stochastic alpha test, which hashes the world's ray) where
// `veiled`.
std::string ballObj(bool veiled = true) {
  std::string obj = "mtllib ball.mtl\n";
  for (int j = 0; j <= 6; ++j)
    for (int i = 0; i < 8; ++i) {
      const float theta = 3.14159265f * float(j) / 6.0f, phi = 6.2831853f * float(i) / 8.0f;
      obj += "v " + std::to_string(std::sin(theta) * std::cos(phi)) + " " +
             std::to_string(std::cos(theta)) + " " +
             std::to_string(std::sin(theta) * std::sin(phi)) + "\n";
    }
  for (int j = 0; j < 6; ++j) {
    obj += j < 3 || !veiled ? "usemtl solid\n" : "usemtl veil\n";
    for (int i = 0; i < 8; ++i) {
      const int a = j * 8 + i + 1, b = j * 8 + (i + 1) % 8 + 1;
      obj += "f " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(b + 8) +
             " " + std::to_string(a + 8) + "\n";
    }
  }
  return obj;
}

// Both engines trace the same sample streams; paths part only where a hit point differs by
// rounding, so the images differ by far less than the noise of one seed against another. The
// room's 30 triangles alone go into triangle blocks; with a ball of 96 more, to Embree, and at
// 20 spp a pixel's camera rays then go to it as a packet of 16 and one of 4, and so do the shadow
// rays from their first hits (the scene's four lights are few enough: render/render_pixel.h).
TEST(Embree, RendersTheSameImageAsTheOwnBvhUpToRounding) {
  const test::TempDir temp;
  const std::string ball = temp.write("ball.obj", ballObj(false));
  temp.write("ball.mtl", "newmtl solid\nKd 0.7 0.7 0.7\n");
  const std::string dir = std::string(CANDELA_SOURCE_DIR) + "/scenes/meshes/cornell/";
  for (const bool withBall : {false, true}) {
    const std::string json = R"({"camera": {"width": 48, "height": 40, "fov": 40, "spp": 20,
          "position": [2.78, 2.73, -8.0], "look_at": [2.78, 2.73, 0]},
      "render": {"max_depth": 6},
      "environment": {"color": [0.2, 0.3, 0.4]},
      "spheres": [{"position": [1.8, 0.8, 2], "radius": 0.8, "material": {"type": "glass"}},
                  {"position": [3.8, 0.8, 3], "radius": 0.8, "material": {"type": "mirror"}},
                  {"position": [2.8, 4.5, 2.5], "radius": 0.3,
                   "material": {"type": "emissive", "radiance": 5}}],
      "objects": [)" + std::string(withBall ? R"({"file": ")" + ball +
                                                    R"(", "position": [3.2, 2.6, 3.5]},)"
                                              : "") +
                             R"({"file": ")" + dir + R"(white.obj", "color": [0.7, 0.7, 0.7]},
                  {"file": ")" + dir + R"(red.obj", "color": [0.6, 0.1, 0.1]},
                  {"file": ")" + dir + R"(lamp.obj", "material": {"type": "emissive",
                   "radiance": [17, 12, 4]}}]})";
    const SceneDesc scene = parseSceneText(json, "test.json", ".");
    SceneDesc forEmbree = scene;
    forEmbree.ownBvh = OwnBvh::None;
    EmbreeScene embree;
    embree.update(flattenScene(forEmbree), SceneChange::Structure);
    EXPECT_EQ(embree.tracer().triangleBlocks.blockCount != 0,
              !withBall && widestTriangleBlock() != 0);
    expectEnginesAgree(scene);
  }
}

// Objects that repeat a mesh go to Embree as instances (two prototypes here: the ball, and the
// ball mirrored, whose winding is reversed), between runs of objects of their own; one instance
// is an area light (its shadow rays skip the light's triangle), and the balls' half-transparent
// faces are alpha-tested through the instances. The image is the own BVH's up to rounding.
TEST(Embree, RepeatedMeshesTracedAsInstancesRenderAsTheOwnBvhDoes) {
  const test::TempDir dir;
  const std::string ball = dir.write("ball.obj", ballObj());
  dir.write("ball.mtl", "newmtl solid\nKd 0.7 0.7 0.7\nnewmtl veil\nKd 0.2 0.5 0.8\nd 0.5\n");
  const std::string cornell = std::string(CANDELA_SOURCE_DIR) + "/scenes/meshes/cornell/";
  const std::string json = R"({"camera": {"width": 48, "height": 40, "fov": 40, "spp": 20,
        "position": [2.78, 2.73, -8.0], "look_at": [2.78, 2.73, 0]},
    "render": {"max_depth": 5},
    "environment": {"color": [0.2, 0.3, 0.4]},
    "lights": [{"type": "point", "position": [2.78, 5.0, 1.0], "intensity": 300}],
    "objects": [
      {"file": ")" + ball + R"(", "position": [1.5, 1.0, 2.0], "scale": 0.9},
      {"file": ")" + ball + R"(", "position": [2.8, 4.2, 2.5], "scale": 0.4,
       "material": {"type": "emissive", "radiance": [8, 6, 3]}},
      {"file": ")" + cornell +
                           R"(red.obj", "color": [0.6, 0.1, 0.1]},
      {"file": ")" + ball + R"(", "position": [3.8, 1.0, 3.0], "scale": [-0.9, 0.9, 0.9],
       "rotation": [0, 40, 0]},
      {"file": ")" + ball + R"(", "position": [2.6, 2.6, 3.5], "scale": [-0.6, 1.2, 0.6],
       "rotation": [30, 0, 20]},
      {"file": ")" + cornell +
                           R"(white.obj", "color": [0.7, 0.7, 0.7]}]})";
  const SceneDesc scene = parseSceneText(json, "test.json", ".");

  SceneDesc forEmbree = scene;
  forEmbree.ownBvh = OwnBvh::None;
  EmbreeScene embree;
  embree.update(flattenScene(forEmbree), SceneChange::Structure);
  EXPECT_EQ(embree.instanceCount(), 4u);

  expectEnginesAgree(scene);
}

// The orbit example's frames (the camera moves: values; the knot turns: a refit of Embree's
// BVH) through one resident renderer, each as a renderer built for that frame alone renders it.
TEST(Embree, AnimationFramesRenderAsFreshBuilds) {
  SceneDesc orbit = loadSceneFile(std::string(CANDELA_SOURCE_DIR) + "/scenes/orbit.json");
  orbit.camera.width = 40;
  orbit.camera.height = 30;
  orbit.render.spp = 2;
  orbit.ownBvh = OwnBvh::None;
  FrameScene frames;
  CpuRenderer resident(CpuEngine::Embree);
  bool sawMotion = false;
  for (uint32_t f = 0; f < 4; ++f) {
    const SceneDesc still = sceneAtFrame(orbit, f);
    resident.setScene(frames.prepare(still), frames.change());
    sawMotion = sawMotion || frames.change() == SceneChange::Motion;
    const ImageRGB image = resident.render(RenderOptions{}).image;
    const ImageRGB fresh = renderWith(CpuEngine::Embree, still).image;
    EXPECT_LT(test::relMseAgainst(fresh.pixels, image.pixels), 1e-6) << "frame " << f;
  }
  EXPECT_TRUE(sawMotion);
}

// The glTF example's skinned and morphed meshes, posed anew each frame (its shutter closed): each
// frame after the first is a refit on both engines, and renders as a renderer built for that
// frame alone does.
TEST(Embree, PosedMeshFramesRefitAndRenderAsFreshBuilds) {
  SceneDesc example =
      loadSceneFile(std::string(CANDELA_SOURCE_DIR) + "/scenes/examples/gltf_animation.json");
  example.camera.width = 40;
  example.camera.height = 30;
  example.render.spp = 2;
  example.animation->shutterOpen = example.animation->shutterClose = 0.0f;
  for (CpuEngine engine : {CpuEngine::Embree, CpuEngine::Bvh}) {
    SCOPED_TRACE(engine == CpuEngine::Embree ? "Embree" : "own BVH");
    example.ownBvh = engine == CpuEngine::Embree ? OwnBvh::None : OwnBvh::Sah;
    FrameScene frames;
    CpuRenderer resident(engine);
    int motions = 0;
    for (uint32_t f = 10; f < 14; ++f) {
      const SceneDesc still = sceneAtFrame(example, f);
      resident.setScene(frames.prepare(still), frames.change());
      motions += frames.change() == SceneChange::Motion;
      const ImageRGB image = resident.render(RenderOptions{}).image;
      const ImageRGB fresh = renderWith(engine, still).image;
      EXPECT_LT(test::relMseAgainst(fresh.pixels, image.pixels), 1e-6) << "frame " << f;
    }
    EXPECT_EQ(motions, 3);
  }
}

// Of 500 random rays, how many find the primitive through `embree` that testing every
// primitive of `scene` finds (or nothing where that finds nothing).
int agreeingHits(const EmbreeScene& embree, const SceneData& scene, std::mt19937& gen) {
  std::uniform_real_distribution<float> u(-5.0f, 5.0f);
  int agree = 0;
  for (int i = 0; i < 500; ++i) {
    Ray ray;
    ray.origin = Vec3(u(gen), u(gen), u(gen));
    ray.direction = test::randomUnitVector(gen);
    Hit expected, got;
    const bool found = intersectClosestBruteForce(scene.view(), ray, &expected);
    agree += embree.tracer().closest(ray, &got) == found && (!found || got.prim == expected.prim);
  }
  return agree;
}

// A refit (SceneChange::Motion) of a scene whose objects repeat meshes otherwise than the scene
// built last builds Embree's scene anew: the same triangles, first as instances, then as objects
// of their own, then as instances again, each time traced as testing every triangle traces them.
TEST(Embree, RefitToOtherRepeatsBuildsAnew) {
  const SceneData instanced = instancedScene(10);
  SceneData own = instanced;
  own.meshInstances.prototypes.clear();
  for (MeshInstance& object : own.meshInstances.objects) object.prototype = -1;
  for (uint32_t indexedFrom : kLeafKinds) {
    EmbreeScene embree(nullptr, indexedFrom);
    std::mt19937 gen(11);
    int step = 0;
    for (const SceneData* scene : std::vector<const SceneData*>{&instanced, &own, &instanced}) {
      embree.update(*scene, step == 0 ? SceneChange::Structure : SceneChange::Motion);
      EXPECT_EQ(embree.instanceCount(), scene == &own ? 0u : 5u) << "step " << step;
      EXPECT_GE(agreeingHits(embree, *scene, gen), 498) << "step " << step;
      ++step;
    }
  }
}

// Embree traces the vertices of the scene given last, wherever its arrays lie: a copy of the
// scene given as new values (SceneChange::Values: the same geometry, its arrays elsewhere), then
// a copy whose every vertex moved (a refit), each traced as testing every triangle traces it
// after the arrays given before were overwritten. With either kind of leaves; indexed ones read
// the vertices as they trace.
TEST(Embree, TracesTheVerticesOfTheSceneGivenLast) {
  for (uint32_t indexedFrom : kLeafKinds) {
    for (const int kind : {0, 1, 2}) {  // Embree's triangles, instances, triangle blocks
      const bool instances = kind == 1;
      SceneData first = instances   ? instancedScene(21)
                        : kind == 2 ? randomScene(21, 10, 40)
                                    : randomScene(21, 10);
      EmbreeScene embree(nullptr, indexedFrom);
      embree.update(first, SceneChange::Structure);
      SceneData copy = first;
      embree.update(copy, SceneChange::Values);
      std::fill(first.positions.begin(), first.positions.end(), Vec3(0.0f));
      for (MeshPrototype& prototype : first.meshInstances.prototypes)
        std::fill(prototype.positions.begin(), prototype.positions.end(), Vec3(0.0f));
      std::mt19937 gen(22);
      EXPECT_GE(agreeingHits(embree, copy, gen), 498) << "values, kind " << kind;

      SceneData moved = copy;
      for (Vec3& p : moved.positions) p += Vec3(0.5f, -0.25f, 0.0f);
      for (MeshInstance& object : moved.meshInstances.objects)
        object.translation += Vec3(0.5f, -0.25f, 0.0f);
      embree.update(moved, SceneChange::Motion);
      std::fill(copy.positions.begin(), copy.positions.end(), Vec3(0.0f));
      for (MeshPrototype& prototype : copy.meshInstances.prototypes)
        std::fill(prototype.positions.begin(), prototype.positions.end(), Vec3(0.0f));
      EXPECT_GE(agreeingHits(embree, moved, gen), 498) << "motion, kind " << kind;
    }
  }
}

// A scene in triangle blocks whose next frame masks a material goes to Embree, whose filters
// apply the mask, and back to blocks when the mask is gone.
TEST(Embree, TriangleBlocksGiveWayToEmbreeForAlphaMasks) {
  if (widestTriangleBlock() == 0) GTEST_SKIP() << "this CPU has no triangle blocks (AVX2 and FMA)";
  SceneData scene = randomScene(23, 10, 40);
  EmbreeScene embree;
  embree.update(scene, SceneChange::Structure);
  EXPECT_NE(embree.tracer().triangleBlocks.blockCount, 0u);
  EXPECT_EQ(embree.tracer().triangles, nullptr);
  std::mt19937 gen(24);
  EXPECT_GE(agreeingHits(embree, scene, gen), 498);

  scene.alphaMasks = {AlphaMask{0.5f}};
  embree.update(scene, SceneChange::Values);
  EXPECT_EQ(embree.tracer().triangleBlocks.blockCount, 0u);
  EXPECT_NE(embree.tracer().triangles, nullptr);

  scene.alphaMasks.clear();
  embree.update(scene, SceneChange::Structure);
  EXPECT_NE(embree.tracer().triangleBlocks.blockCount, 0u);
  EXPECT_GE(agreeingHits(embree, scene, gen), 498);
}

// Indexed leaves from kIndexedLeavesFromTriangles triangles on, and with them far fewer bytes:
// Embree's leaves then hold no copy of the vertices.
TEST(Embree, IndexedLeavesFromTheirTriangleCount) {
  SceneData scene;
  std::mt19937 gen(23);
  std::uniform_real_distribution<float> u(-4.0f, 4.0f);
  for (uint32_t i = 0; i < kIndexedLeavesFromTriangles; ++i) {
    const Vec3 a(u(gen), u(gen), u(gen));
    const uint32_t first = uint32_t(scene.positions.size());
    scene.positions.insert(scene.positions.end(), {a, a + test::randomUnitVector(gen) * 0.1f,
                                                   a + test::randomUnitVector(gen) * 0.1f});
    scene.triangles.push_back(Triangle{{first, first + 1, first + 2}, 0});
  }
  const auto bytesPerTriangle = [&](uint32_t indexedFrom) {
    EmbreeScene embree(nullptr, indexedFrom);
    embree.update(scene, SceneChange::Structure);
    return double(embree.bytes()) / double(scene.triangles.size());
  };
  const double indexed = bytesPerTriangle(kIndexedLeavesFromTriangles);
  const double copies = bytesPerTriangle(kIndexedLeavesFromTriangles + 1);
  EXPECT_LT(indexed, 0.7 * copies) << indexed << " against " << copies << " bytes per triangle";
}

// Two knots of one mesh, instances of it, through the frames of an animation: one turns and the
// other shrinks, refits that move their instances. Each frame renders as a renderer built for
// that frame alone renders it.
TEST(Embree, AnimatedInstancesRenderAsFreshBuilds) {
  const std::string knot = std::string(CANDELA_SOURCE_DIR) + "/scenes/meshes/trefoil.obj";
  const std::string red = std::string(CANDELA_SOURCE_DIR) + "/scenes/meshes/cornell/red.obj";
  const std::string json = R"({"camera": {"width": 40, "height": 30, "fov": 60, "spp": 2,
        "position": [0, 0, 30], "look_at": [0, 0, 0]},
    "environment": {"color": [0.5, 0.6, 0.7]},
    "lights": [{"type": "point", "position": [0, 20, 20], "intensity": 20000}],
    "objects": [
      {"id": "spin", "file": ")" +
                           knot + R"(", "position": [-6, 0, 0], "scale": 1.5},
      {"file": ")" + red + R"(", "position": [-3, -8, -10], "scale": 3},
      {"id": "shrink", "file": ")" +
                           knot + R"(", "position": [6, 0, 0], "scale": 1.5}],
    "animation": {"frames": 4, "tracks": [
      {"target": "spin", "property": "rotation", "keys": [[0, [0, 0, 0]], [3, [30, 90, 0]]]},
      {"target": "shrink", "property": "scale", "keys": [[0, 1.5], [3, 0.5]]}]}})";
  SceneDesc animated = parseSceneText(json, "test.json", ".");
  animated.ownBvh = OwnBvh::None;
  FrameScene frames;
  CpuRenderer resident(CpuEngine::Embree);
  int motions = 0;
  for (uint32_t f = 0; f < 4; ++f) {
    const SceneDesc still = sceneAtFrame(animated, f);
    const SceneData& data = frames.prepare(still);
    EXPECT_EQ(data.meshInstances.prototypes.size(), 1u) << "frame " << f;
    resident.setScene(data, frames.change());
    motions += frames.change() == SceneChange::Motion;
    const ImageRGB image = resident.render(RenderOptions{}).image;
    const ImageRGB fresh = renderWith(CpuEngine::Embree, still).image;
    EXPECT_LT(test::relMseAgainst(fresh.pixels, image.pixels), 1e-6) << "frame " << f;
  }
  EXPECT_EQ(motions, 3);
}

#endif

}  // namespace
}  // namespace candela
