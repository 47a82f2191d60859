// Rendering with the one-level tree of `--no-bvh` (every ray against every primitive, as the
// benchmarks' "no bounding box" rows do) must give the same image: the BVH may only change speed.
#include <gtest/gtest.h>

#include <fstream>

#include "render_test_util.h"

namespace candela {
namespace {

TEST(BruteForce, TraversalWithoutBvhGivesTheSameImage) {
  const std::string obj = ::testing::TempDir() + "brute_force_tetra.obj";
  std::ofstream(obj) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  const std::string json = R"({
    "camera": {"width": 40, "height": 30, "fov": 50, "position": [0, 1.5, 6], "look_at": [0, 0.5, 0], "spp": 4},
    "render": {"max_depth": 5},
    "spheres": [{"position": [0, -1000, 0], "radius": 1000, "color": 0.7},
                {"position": [-1.2, 0.5, 0], "radius": 0.5, "material": "glass"},
                {"position": [1.2, 0.5, 0], "radius": 0.5, "material": "mirror"}],
    "objects": [{"file": ")" + obj + R"(", "position": [0, 0.01, 0], "color": [0.8, 0.3, 0.2]}],
    "lights": [{"position": [2, 4, 3], "intensity": 800},
               {"type": "sphere", "position": [-3, 3, 1], "radius": 0.4, "intensity": 300}]})";
  const RenderResult withBvh = renderCpu(test::loadTestScene(json).view(), RenderOptions{});
  SceneDesc desc = parseSceneText(json, "test.json", ".");
  desc.ownBvh = OwnBvh::Flat;
  const SceneData flat = flattenScene(desc);
  EXPECT_EQ(flat.bvh.leafCount, 1u) << "8 triangles and 4 spheres fit one leaf of 255";
  const RenderResult bruteForce = renderCpu(flat.view(), RenderOptions{});
  // A tie between two primitives at exactly the same t could go either way: a few values at most.
  size_t differing = 0;
  for (size_t i = 0; i < withBvh.image.pixels.size(); ++i)
    differing += withBvh.image.pixels[i] != bruteForce.image.pixels[i];
  EXPECT_LE(differing, withBvh.image.pixels.size() / 100);
  EXPECT_EQ(withBvh.rays.total(), bruteForce.rays.total());
  EXPECT_GT(withBvh.rays.shadow, 0u);
}

}  // namespace
}  // namespace candela
