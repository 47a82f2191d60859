// Light selection for next-event estimation: the light tree (render/light_tree.h) that picks a
// light by its importance at the shading point, the environment's share of the picks, and the
// lone point light that needs no pick.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "render/light_selection.h"
#include "render_test_util.h"
#include "scene/frame_scene.h"
#include "scene/light_tree_build.h"
#include "temp_dir.h"
#include "test_random.h"

namespace candela {
namespace {

// Uniform random inputs of the tests below.
struct RandomInputs {
  std::mt19937 gen;
  float next() { return std::uniform_real_distribution<float>(0.0f, 1.0f)(gen); }
  Vec3 inBox(float half) { return Vec3(next(), next(), next()) * (2 * half) - Vec3(half); }
  Vec3 direction() { return test::randomUnitVector(gen); }
};

// A scene of `triangles` random emissive triangles (random sizes, orientations and radiances),
// two sphere lights and two point lights, in a box of half-size 10; its files go to `dir`.
SceneDesc randomLightsDesc(const test::TempDir& dir, int triangles, uint32_t seed) {
  RandomInputs rng{std::mt19937(seed)};
  std::string obj, mtl;
  for (int i = 0; i < triangles; ++i) {
    const Vec3 c = rng.inBox(10.0f);
    const float size = 0.05f + 2.0f * rng.next() * rng.next();
    for (int v = 0; v < 3; ++v) {
      const Vec3 p = c + rng.inBox(size);
      obj +=
          "v " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
    }
  }
  for (int m = 0; m < 3; ++m) {
    mtl +=
        "newmtl e" + std::to_string(m) + "\nKd 0 0 0\nKe " + std::to_string(1 + 3 * m) + " 2 1\n";
  }
  obj = "mtllib lights.mtl\n" + obj;
  for (int i = 0; i < triangles; ++i) {
    obj += "usemtl e" + std::to_string(i % 3) + "\nf " + std::to_string(3 * i + 1) + " " +
           std::to_string(3 * i + 2) + " " + std::to_string(3 * i + 3) + "\n";
  }
  dir.write("lights.mtl", mtl);
  const std::string path = dir.write("lights.obj", obj);
  return parseSceneText(R"({"camera": {"width": 4, "height": 4},
      "objects": [{"file": ")" +
                            path + R"("}],
      "lights": [{"type": "sphere", "position": [3, 4, -2], "radius": 0.5, "intensity": 200},
                 {"type": "sphere", "position": [-6, 1, 5], "radius": 2, "intensity": 50},
                 {"position": [1, -7, 2], "intensity": 30},
                 {"position": [8, 8, 8], "intensity": 300, "color": [1, 0.5, 0.25]}]})",
                        "test.json", ".");
}

SceneData randomLights(const test::TempDir& dir, int triangles, uint32_t seed) {
  return flattenScene(randomLightsDesc(dir, triangles, seed));
}

// Whether light l can send any light to p, where a surface reflects only into the hemisphere
// around n (zero: every direction).
bool canReach(const SceneView& v, const Light& l, const Vec3& p, const Vec3& n) {
  const bool anyDirection = lengthSquared(n) == 0.0f;
  switch (l.type) {
    case LightType::Point:
      return anyDirection || dot(n, l.position - p) > 0.0f;
    case LightType::Sphere: {
      const Sphere& s = v.spheres[l.shape];
      return anyDirection || dot(n, s.center - p) > -s.radius;
    }
    case LightType::Triangle: {
      const Triangle& t = v.triangles[l.shape];
      const Vec3 &p0 = v.positions[t.v[0]], &p1 = v.positions[t.v[1]], &p2 = v.positions[t.v[2]];
      if (!(dot(cross(p1 - p0, p2 - p0), p - p0) > 0.0f)) return false;  // behind it
      return anyDirection || dot(n, p0 - p) > 0.0f || dot(n, p1 - p) > 0.0f ||
             dot(n, p2 - p) > 0.0f;
    }
    case LightType::Environment:
      break;
    case LightType::Directional:
      return anyDirection || dot(n, l.direction) < 0.0f;
  }
  return true;
}

TEST(LightTree, ALonePointLightIsSampledWithoutAPick) {
  const SceneData lone = test::loadTestScene(R"({
    "camera": {"width": 4, "height": 4, "fov": 40},
    "lights": [{"position": [0, 1, 0], "intensity": 2}]})");
  EXPECT_TRUE(lone.view().loneDeltaLight);
  EXPECT_TRUE(lone.lightTree.empty());
  EXPECT_EQ(lightSelectPmf(lone.view(), 0, Vec3(0.0f), Vec3(0, 1, 0)), 1.0f);
}

// Two point lights or more are picked through the tree, by their importance at the point.
TEST(LightTree, SeveralPointLightsArePickedByTheTree) {
  const SceneData data = test::loadTestScene(R"({
    "camera": {"width": 4, "height": 4, "fov": 40},
    "lights": [{"position": [0, 1, 0], "intensity": 2},
               {"position": [0, 5, 0], "intensity": 3}]})");
  ASSERT_EQ(data.lights.size(), 2u);
  EXPECT_FALSE(data.view().loneDeltaLight);
  EXPECT_FALSE(data.lightTree.empty());
  // The nearer light is picked more often at a point below both, and the picks sum to one.
  const float near = lightSelectPmf(data.view(), 0, Vec3(0.0f), Vec3(0, 1, 0));
  const float far = lightSelectPmf(data.view(), 1, Vec3(0.0f), Vec3(0, 1, 0));
  EXPECT_GT(near, far);
  EXPECT_NEAR(near + far, 1.0f, 1e-6f);
  // A point's cluster has radius 0: nothing in the tree is denormal.
  const LightTreeNode& root = data.lightTree[0];
  for (int k = 0; k < 2; ++k) EXPECT_EQ(root.radius[k], 0.0f) << "cluster " << k;
  for (int k = 0; k < kLightTreeWidth; ++k)
    for (float v :
         {root.centerX[k], root.centerY[k], root.centerZ[k], root.radius[k], root.axisX[k],
          root.axisY[k], root.axisZ[k], root.cosThetaO[k], root.sinThetaO[k], root.power[k]})
      EXPECT_NE(std::fpclassify(v), FP_SUBNORMAL) << "cluster " << k;
}

// The environment takes half the picks beside other lights, however large the scene's bounds
// (a ground sphere of radius 1000 once made its estimated power dwarf a lamp's); alone, all.
TEST(LightTree, EnvironmentTakesHalfThePicksBesideOtherLights) {
  const SceneData data = test::loadTestScene(R"({
    "camera": {"width": 4, "height": 4, "fov": 40},
    "environment": {"color": 0.5},
    "spheres": [{"position": [0, -1000, 0], "radius": 1000}],
    "lights": [{"type": "sphere", "position": [0, 5, 0], "radius": 1, "intensity": 10},
               {"type": "sphere", "position": [0, 5, 3], "radius": 1, "intensity": 30}]})");
  const SceneView view = data.view();
  ASSERT_EQ(view.lightCount, 3u);
  ASSERT_GE(view.environment.light, 0);
  EXPECT_EQ(view.infiniteLightShare, 0.5f);
  ASSERT_EQ(view.infiniteLightCount, 1u);
  const Vec3 p(0, 1, 0), n(0, 1, 0);
  EXPECT_EQ(lightSelectPmf(view, uint32_t(view.environment.light), p, n), 0.5f);
  float pmf = 0, remapped = 0;
  EXPECT_EQ(selectLight(view, p, n, 0.25f, &pmf, &remapped), view.environment.light);
  EXPECT_EQ(pmf, 0.5f);
  EXPECT_EQ(remapped, 0.5f);  // 0.25's place in the environment's share [0, 0.5)
  EXPECT_NE(selectLight(view, p, n, 0.75f, &pmf, &remapped), view.environment.light);
  EXPECT_NEAR(lightSelectPmf(view, 0, p, n) + lightSelectPmf(view, 1, p, n), 0.5f, 1e-6f);

  const SceneData alone = test::loadTestScene(R"({
    "camera": {"width": 4, "height": 4, "fov": 40}, "environment": {"color": 0.5},
    "spheres": [{"position": [0, -1000, 0], "radius": 1000}]})");
  EXPECT_EQ(alone.view().infiniteLightShare, 1.0f);
  EXPECT_TRUE(alone.lightTree.empty());
  EXPECT_EQ(selectLight(alone.view(), p, n, 0.9f, &pmf, &remapped), alone.view().environment.light);
  EXPECT_EQ(pmf, 1.0f);
}

// Checks, at `trials` random points, the properties that PicksFollowTheirPmf... below names;
// adds to *behind the triangles seen that cannot reach the point, to *behindWithoutPmf those of
// them with pmf 0.
void expectPicksFollowTheirPmfs(const SceneView& view, int trials, int* behind,
                                int* behindWithoutPmf) {
  RandomInputs rng{std::mt19937(99)};
  for (int trial = 0; trial < trials; ++trial) {
    const Vec3 p = rng.inBox(12.0f);
    const Vec3 n = trial % 4 == 3 ? Vec3(0.0f) : rng.direction();
    std::vector<double> pmfs(view.lightCount);
    double sum = 0;
    for (uint32_t i = 0; i < view.lightCount; ++i) {
      pmfs[i] = lightSelectPmf(view, i, p, n);
      sum += pmfs[i];
      if (canReach(view, view.lights[i], p, n)) {
        EXPECT_GT(pmfs[i], 0.0) << "light " << i << ", trial " << trial;
      } else if (view.lights[i].type == LightType::Triangle) {
        ++*behind;
        *behindWithoutPmf += pmfs[i] == 0.0;
      }
    }
    EXPECT_LE(sum, 1.0 + 1e-5) << trial;
    std::vector<int> picked(view.lightCount, 0);
    // Each light's picks take one interval of u, whose place in it comes back as the remapped
    // number: from 0 to 1 as u crosses the interval.
    std::vector<std::vector<float>> remappedOf(view.lightCount);
    int none = 0;
    const int draws = 20000;
    for (int k = 0; k < draws; ++k) {
      float pmf = 0, remapped = -1;
      const int i = selectLight(view, p, n, (k + 0.5f) / draws, &pmf, &remapped);
      if (i < 0) {
        ++none;
        continue;
      }
      ASSERT_EQ(pmf, float(pmfs[size_t(i)])) << i;
      ++picked[size_t(i)];
      ASSERT_GE(remapped, 0.0f);
      ASSERT_LT(remapped, 1.0f);
      remappedOf[size_t(i)].push_back(remapped);
    }
    for (uint32_t i = 0; i < view.lightCount; ++i) {
      const std::vector<float>& r = remappedOf[i];
      if (r.size() < 50) continue;
      EXPECT_TRUE(std::is_sorted(r.begin(), r.end())) << "light " << i << ", trial " << trial;
      const float step = 2.0f / float(r.size());
      EXPECT_LT(r.front(), step) << "light " << i << ", trial " << trial;
      EXPECT_GT(r.back(), 1.0f - step) << "light " << i << ", trial " << trial;
    }
    // Stratified u: off by a few picks per tree level at most.
    EXPECT_NEAR(none, (1.0 - sum) * draws, 8.0) << trial;
    for (uint32_t i = 0; i < view.lightCount; ++i)
      EXPECT_NEAR(picked[i], pmfs[i] * draws, 8.0) << "light " << i << ", trial " << trial;
  }
}

// Among random lights at random points: the pick's pmf is the one MIS recomputes from the
// light's trail, bit for bit; picks follow the pmfs; no light that can send light to the point
// has pmf 0 (the tree's bound errs only towards more), and most triangles that turn their backs
// on the point have pmf 0. A pick may end at a node whose clusters all turn out unable to reach
// the point (their bounds are tighter than their parent's): it then finds no light, which only
// the pmfs' sum below 1 accounts for.
TEST(LightTree, PicksFollowTheirPmfWhichMissesNoLightThatReachesThePoint) {
  test::TempDir dir;
  const SceneData data = randomLights(dir, 300, 7);
  const SceneView view = data.view();
  ASSERT_EQ(view.lightCount, 304u);
  ASSERT_FALSE(view.loneDeltaLight);
  int behind = 0, behindWithoutPmf = 0;
  expectPicksFollowTheirPmfs(view, 40, &behind, &behindWithoutPmf);
  EXPECT_GT(behind, 1000);  // the test saw many lights that cannot reach the point
  EXPECT_GT(behindWithoutPmf, 0.9 * behind);
}

// A light sample's first number is the pick's place within the light's share where the pick is
// likely (then a pair of numbers stays stratified over the picked lights' surfaces together),
// and the sample's own number where the place would keep too few bits (a light among hundreds).
TEST(LightTree, ALikelyPickHandsOnItsPlaceAsItsSamplesFirstNumber) {
  test::TempDir dir;
  const SceneData data = randomLights(dir, 2000, 5);
  const SceneView view = data.view();
  RandomInputs rng{std::mt19937(17)};
  int placed = 0, owned = 0;
  for (int trial = 0; trial < 20; ++trial) {
    const Vec3 p = rng.inBox(12.0f), n = rng.direction();
    for (int k = 0; k < 500; ++k) {
      const float u = (k + 0.5f) / 500;
      // The stand-in is the stream's next number; either way the stream moves on by one.
      SampleStream stream(7, uint64_t(trial), uint32_t(k), 500), expected = stream;
      const float own = expected.next1D(), after = expected.next1D();
      float pmf = 0, place = -1, u1 = u, pmfForSample = 0;
      const int light = selectLight(view, p, n, u, &pmf, &place);
      EXPECT_EQ(selectLightForSample(view, p, n, stream, &u1, &pmfForSample), light);
      EXPECT_EQ(stream.next1D(), after);
      if (light < 0) continue;
      EXPECT_EQ(pmfForSample, pmf);
      if (pmf >= kPickPlaceReusedFrom) {
        EXPECT_EQ(u1, place) << "trial " << trial << ", u " << u;
        ++placed;
      } else {
        EXPECT_EQ(u1, own) << "trial " << trial << ", u " << u;
        ++owned;
      }
    }
  }
  // Both cases came up often: lights that take much of a point's picks (a near sphere or point
  // light, a near triangle) and the many small shares of 2,000 triangles.
  EXPECT_GT(placed, 500);
  EXPECT_GT(owned, 500);
}

// The angle between two directions, accurate also near 0.
double angleBetween(const Vec3& a, const Vec3& b) {
  const double ax = a.x, ay = a.y, az = a.z, bx = b.x, by = b.y, bz = b.z;
  const double cx = ay * bz - az * by, cy = az * bx - ax * bz, cz = ax * by - ay * bx;
  return std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), ax * bx + ay * by + az * bz);
}

// A cluster's bounds, as the pick reads them.
struct ClusterBounds {
  Vec3 centre, axis;
  float reach;
  double thetaO;
};

// Checks that cluster k of node `index` and its ancestors bound the lights below it: their
// shapes lie in each sphere, their emitting normals in each cone, and a cluster's power is its
// children's sum. Returns the cluster's power.
double expectClusterHoldsItsLights(const SceneView& view, uint32_t index, int k,
                                   std::vector<ClusterBounds> ancestors) {
  const LightTreeNode& node = view.lightTree[index];
  ancestors.push_back({Vec3(node.centerX[k], node.centerY[k], node.centerZ[k]),
                       Vec3(node.axisX[k], node.axisY[k], node.axisZ[k]),
                       node.radius[k] * (1.0f + 1e-5f) + 1e-5f,
                       std::acos(std::clamp(double(node.cosThetaO[k]), -1.0, 1.0)) + 1e-5});
  const uint32_t child = node.child[k];
  if (!(child & kLightTreeLeaf)) {
    double sum = 0;
    for (int c = 0; c < kLightTreeWidth && view.lightTree[child].child[c] != 0; ++c)
      sum += expectClusterHoldsItsLights(view, child, c, ancestors);
    EXPECT_NEAR(node.power[k], sum, 1e-5 * sum) << "node " << index << ", cluster " << k;
    return node.power[k];
  }
  const Light& l = view.lights[child & ~kLightTreeLeaf];
  EXPECT_GT(node.power[k], 0.0f);
  for (const ClusterBounds& b : ancestors) {
    switch (l.type) {
      case LightType::Point:
        EXPECT_LE(length(l.position - b.centre), b.reach);
        EXPECT_GE(b.thetaO, 3.14159);
        break;
      case LightType::Sphere: {
        const Sphere& s = view.spheres[l.shape];
        EXPECT_LE(length(s.center - b.centre), b.reach);
        EXPECT_GE(b.thetaO, 3.14159);
        break;
      }
      case LightType::Triangle: {
        const Triangle& t = view.triangles[l.shape];
        const Vec3 &p0 = view.positions[t.v[0]], &p1 = view.positions[t.v[1]],
                   &p2 = view.positions[t.v[2]];
        for (const Vec3& p : {p0, p1, p2}) EXPECT_LE(length(p - b.centre), b.reach);
        EXPECT_LE(angleBetween(cross(p1 - p0, p2 - p0), b.axis), b.thetaO);
        break;
      }
      case LightType::Environment:
      case LightType::Directional:
        ADD_FAILURE() << "a light at infinity is not in the tree";
    }
  }
  return node.power[k];
}

void expectTreeBoundsItsLights(const SceneView& view) {
  ASSERT_GT(view.lightTreeNodeCount, 0u);
  for (int k = 0; k < kLightTreeWidth && view.lightTree[0].child[k] != 0; ++k)
    expectClusterHoldsItsLights(view, 0, k, {});
}

// A frame whose lights keep their shapes, bounds and powers (a moving camera) keeps the last
// frame's light tree; any other builds it, so that a frame's tree is the one it would have
// rendered alone, whatever frames came before: a dimming emitter, a moving point light, a light
// that loses its power and one that gets it back.
TEST(LightTree, AFrameKeepsTheTreeOnlyWhereItsLightsAreTheSame) {
  test::TempDir dir;
  SceneDesc desc = randomLightsDesc(dir, 300, 7);
  FrameScene frames;
  const SceneData& first = frames.prepare(desc);
  const LightTreeNode* built = first.lightTree.data();
  expectTreeBoundsItsLights(first.view());

  desc.camera.position = Vec3(1, 2, 3);
  EXPECT_EQ(frames.prepare(desc).lightTree.data(), built) << "the tree was built again";
  EXPECT_EQ(frames.change(), SceneChange::Values);

  const auto expectFreshTree = [&](const char* what) {
    const SceneData& data = frames.prepare(desc);
    ASSERT_EQ(frames.change(), SceneChange::Values) << what;
    const SceneData fresh = flattenScene(desc);
    ASSERT_EQ(data.lightTree.size(), fresh.lightTree.size()) << what;
    EXPECT_EQ(std::memcmp(data.lightTree.data(), fresh.lightTree.data(),
                          fresh.lightTree.size() * sizeof(LightTreeNode)),
              0)
        << what;
    for (size_t i = 0; i < fresh.lights.size(); ++i)
      ASSERT_EQ(data.lights[i].trail, fresh.lights[i].trail) << what << ", light " << i;
  };
  auto mesh = std::make_shared<MeshDesc>(*desc.objects[0].mesh);
  mesh->materials[1].radiance *= 40.0f;
  desc.objects[0].mesh = mesh;
  expectFreshTree("a third of the triangles brighten");
  desc.lights[3].position = Vec3(-9, 2, -9);
  expectFreshTree("a point light moves");
  const float intensity = desc.lights[2].intensity;
  desc.lights[2].intensity = 0.0f;
  expectFreshTree("a point light goes out");
  desc.lights[2].intensity = intensity;
  expectFreshTree("and comes back");
}

// Lights without power are never picked; without any, nothing is.
TEST(LightTree, LightsWithoutPowerAreNeverPicked) {
  std::string lights = R"({"position": [0, 1, 0], "intensity": 0},
                          {"position": [0, 1, 0], "intensity": 2},
                          {"type": "sphere", "position": [0, 5, 0], "radius": 1, "intensity": 3},
                          {"position": [0, 1, 0], "intensity": 1, "color": 0})";
  const SceneData data =
      test::loadTestScene(R"({"camera": {"width": 4, "height": 4}, "lights": [)" + lights + "]}");
  const SceneView view = data.view();
  EXPECT_EQ(view.lights[0].trail, kNotInLightTree);
  EXPECT_EQ(view.lights[3].trail, kNotInLightTree);
  for (float u : {0.0f, 0.3f, 0.99999994f}) {
    float pmf, remapped;
    const int i = selectLight(view, Vec3(0, -3, 0), Vec3(0.0f), u, &pmf, &remapped);
    EXPECT_TRUE(i == 1 || i == 2) << u;
  }
  std::vector<uint64_t> trails;
  EXPECT_TRUE(buildLightTree(std::vector<LightBounds>(3), &trails).empty());
  EXPECT_EQ(trails, std::vector<uint64_t>(3, kNotInLightTree));
}

// Faces that face one way keep one narrow cone however many are united: the cone of two equal
// cones is that cone (rounding once made it the whole sphere, losing orientation culling).
TEST(LightTree, FacesOfOneOrientationKeepANarrowCone) {
  RandomInputs rng{std::mt19937(8)};
  std::vector<LightBounds> lights(64);
  for (LightBounds& l : lights) {
    l.lo = l.hi = rng.inBox(10.0f);
    l.axis = Vec3(1, 3, 3);  // not of unit length: its normalised dot with itself rounds below 1
    l.cosThetaO = 1.0;
    l.power = 1.0;
  }
  std::vector<uint64_t> trails;
  const std::vector<LightTreeNode> nodes = buildLightTree(lights, &trails);
  ASSERT_GT(nodes.size(), size_t(1));
  for (const LightTreeNode& node : nodes)
    for (int k = 0; k < kLightTreeWidth; ++k) {
      if (node.power[k] > 0.0f) {
        EXPECT_GT(node.cosThetaO[k], 0.9999f);
      }
    }
}

// The tree does not depend on the order in which the lights come (the engines number a scene's
// emissive triangles differently): each light gets the same trail, the tree the same nodes. Among
// the lights are the halves of rectangles (equal boxes, cones and powers) and lights on one
// point, which no split tells apart.
TEST(LightTree, IsTheSameWhateverTheLightsOrder) {
  RandomInputs rng{std::mt19937(12)};
  std::vector<LightBounds> lights;
  for (int i = 0; i < 300; ++i) {
    LightBounds l;
    l.lo = rng.inBox(10.0f);
    l.hi = l.lo + Vec3(rng.next(), rng.next(), 0.0f);
    l.axis = Vec3(0, 0, 1);
    l.power = 1.0 + (i % 3);
    l.anchor = l.lo + (i % 2 ? Vec3(0.1f, 0.2f, 0) : Vec3(0.2f, 0.1f, 0));  // two halves alike
    lights.push_back(l);
    if (i % 2 == 0) lights.push_back(lights.back());
    lights.back().anchor = l.lo + Vec3(0.3f, 0.1f, 0);
  }
  for (int i = 0; i < 40; ++i) {
    LightBounds l;
    l.lo = l.hi = Vec3(1, 2, 3);
    l.cosThetaO = -1.0;
    l.power = 2.0;
    l.anchor = Vec3(float(i), 0, 0);
    lights.push_back(l);
  }
  std::vector<uint32_t> shuffled(lights.size());
  for (uint32_t i = 0; i < shuffled.size(); ++i) shuffled[i] = i;
  std::shuffle(shuffled.begin(), shuffled.end(), rng.gen);
  std::vector<LightBounds> reordered;
  for (uint32_t i : shuffled) reordered.push_back(lights[i]);

  std::vector<uint64_t> trails, reorderedTrails;
  const std::vector<LightTreeNode> nodes = buildLightTree(lights, &trails);
  const std::vector<LightTreeNode> reorderedNodes = buildLightTree(reordered, &reorderedTrails);
  ASSERT_EQ(nodes.size(), reorderedNodes.size());
  for (uint32_t i = 0; i < shuffled.size(); ++i)
    ASSERT_EQ(reorderedTrails[i], trails[shuffled[i]]) << "light " << shuffled[i];
  for (size_t n = 0; n < nodes.size(); ++n)
    for (int k = 0; k < kLightTreeWidth; ++k) {
      EXPECT_EQ(reorderedNodes[n].power[k], nodes[n].power[k]);
      const uint32_t child = reorderedNodes[n].child[k];
      const bool leaf = (child & kLightTreeLeaf) && reorderedNodes[n].power[k] > 0.0f;
      EXPECT_EQ(leaf ? shuffled[child & ~kLightTreeLeaf] | kLightTreeLeaf : child,
                nodes[n].child[k]);
    }
}

// Every light of a large tree is reached by following its trail, within the depth a trail holds,
// including lights that all sit at one point (no split separates them).
TEST(LightTree, TrailsLeadToTheirLights) {
  for (const bool together : {false, true}) {
    RandomInputs rng{std::mt19937(3)};
    std::vector<LightBounds> lights(20000);
    for (LightBounds& l : lights) {
      l.lo = l.hi = together ? Vec3(1, 2, 3) : rng.inBox(100.0f);
      l.cosThetaO = -1.0;
      l.power = 0.5 + rng.next();
    }
    std::vector<uint64_t> trails;
    const std::vector<LightTreeNode> nodes = buildLightTree(lights, &trails);
    for (uint32_t i = 0; i < lights.size(); ++i) {
      uint64_t trail = trails[i];
      uint32_t node = 0, depth = 0;
      for (;; ++depth) {
        ASSERT_LT(depth, kMaxLightTreeDepth);
        const uint32_t child = nodes[node].child[trail & 7u];
        trail >>= kLightTreeTrailBits;
        if (child & kLightTreeLeaf) {
          EXPECT_EQ(child & ~kLightTreeLeaf, i);
          break;
        }
        node = child;
      }
      if (together) {
        EXPECT_LE(depth, 5u);  // balanced: 8^5 > 20000
      }
    }
  }
}

#if CANDELA_LIGHT_TREE_SSE
// The host's SSE lanes compute what a CUDA thread computes lane by lane, bit for bit.
TEST(LightTree, SseLanesMatchTheScalarImportance) {
  test::TempDir dir;
  const SceneData data = randomLights(dir, 200, 11);
  RandomInputs rng{std::mt19937(5)};
  for (const LightTreeNode& node : data.lightTree) {
    for (int trial = 0; trial < 20; ++trial) {
      const Vec3 p = rng.inBox(12.0f);
      const Vec3 n = trial % 3 == 0 ? Vec3(0.0f) : rng.direction();
      float sse[8];
      _mm_storeu_ps(sse, lightClusterImportanceSse(node, 0, p, n));
      _mm_storeu_ps(sse + 4, lightClusterImportanceSse(node, 4, p, n));
      for (int k = 0; k < kLightTreeWidth; ++k)
        EXPECT_EQ(sse[k], lightClusterImportanceLane(node, k, p, n)) << k;
    }
  }
}

// A node whose clusters share one box and one cone (a quad's two triangles) shares by power: on
// the host in SSE lanes, on the GPU by prefixEnds, the same bits.
TEST(LightTree, SharesByPowerAreTheGpusSums) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> power(0.0f, 10.0f);
  for (int trial = 0; trial < 50; ++trial) {
    LightTreeNode node{};
    node.byPower = 1;
    const int clusters = 1 + trial % kLightTreeWidth;
    for (int k = 0; k < clusters; ++k) node.power[k] = trial % 5 == 0 && k == 0 ? 0.0f : power(rng);
    ClusterShares host, gpu;
    clusterShares(node, Vec3(1.0f, 2.0f, 3.0f), Vec3(0.0f, 1.0f, 0.0f), &host);
    gpu.positive = 0;
    for (int k = 0; k < kLightTreeWidth; ++k) {
      gpu.importance[k] = node.power[k];
      gpu.positive |= (node.power[k] > 0.0f ? 1 : 0) << k;
    }
    prefixEnds(&gpu);
    EXPECT_EQ(host.positive, gpu.positive);
    for (int k = 0; k < kLightTreeWidth; ++k) {
      EXPECT_EQ(host.importance[k], gpu.importance[k]) << k;
      EXPECT_EQ(host.ends[k], gpu.ends[k]) << k;
    }
  }
}
#endif

}  // namespace
}  // namespace candela
