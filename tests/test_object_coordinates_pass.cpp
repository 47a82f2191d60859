// The object_coordinates pass (docs/aovs.md): each hit's place in its object's own frame,
// normalised to [0, 1] over the object's box, however the object is placed or posed.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "render/aov_layers.h"
#include "render_test_util.h"
#include "scene/animation.h"
#include "scene/flatten.h"
#include "scene/instance_poses.h"
#include "scene/mesh_layout.h"
#include "scene/read/scene_loader.h"
#include "temp_dir.h"

namespace candela {
namespace {

struct CoordinatesRender {
  SceneData scene;
  ImageLayer layer;
  Vec3 at(uint32_t x, uint32_t y) const {
    const size_t i = 3 * (size_t(y) * layer.width + x);
    return {layer.pixels[i], layer.pixels[i + 1], layer.pixels[i + 2]};
  }
};

CoordinatesRender renderCoordinates(const std::string& json, const std::string& baseDir) {
  SceneDesc desc = parseSceneText(json, "test.json", baseDir);
  layOutForPasses(desc, {Aov::ObjectCoordinates});
  CoordinatesRender r{flattenScene(desc), ImageLayer()};
  RenderOptions options;
  options.aovs = true;
  const RenderResult result = renderCpu(r.scene.view(), options);
  r.layer = makeAovLayers(r.scene, {Aov::ObjectCoordinates}, result.aovs)[0];
  return r;
}

// A quad of [-100, 100]^2 at z = 0 in its file, placed at (1, -2, -7.5) and scaled by (0.05,
// 0.1, 1) before the default camera (fov 90): through each pixel centre that meets it, the point
// taken back to the file's frame and over its box; the box is flat in z, so z is 0.5 there.
TEST(ObjectCoordinatesPass, AMeshsPointsAreInItsFilesBoxWhereverItIsPlaced) {
  test::TempDir dir;
  dir.write("quad.obj", "v -100 -100 0\nv 100 -100 0\nv 100 100 0\nv -100 100 0\nf 1 2 3 4\n");
  const CoordinatesRender r = renderCoordinates(R"({
    "camera": {"width": 20, "height": 10, "fov": 90, "spp": 2},
    "render": {"antialiasing": false},
    "objects": [{"file": "quad.obj", "position": [1, -2, -7.5], "scale": [0.05, 0.1, 1],
                 "color": 0.5}]
  })",
                                                dir.path());
  int inside = 0;
  for (uint32_t y = 0; y < 10; ++y)
    for (uint32_t x = 0; x < 20; ++x) {
      const float px = 7.5f * (x + 0.5f - 10.0f) / 10.0f, py = -7.5f * (y + 0.5f - 5.0f) / 10.0f;
      const float fx = (px - 1.0f) / 0.05f, fy = (py + 2.0f) / 0.1f;  // in the file's frame
      const Vec3 c = r.at(x, y);
      if (std::fabs(fx) > 100.0f || std::fabs(fy) > 100.0f) {
        EXPECT_EQ(c.x, 0.0f) << x << "," << y;  // the background, as the position pass
        continue;
      }
      ++inside;
      EXPECT_NEAR(c.x, (fx + 100.0f) / 200.0f, 1e-4f) << x << "," << y;
      EXPECT_NEAR(c.y, (fy + 100.0f) / 200.0f, 1e-4f) << x << "," << y;
      EXPECT_NEAR(c.z, 0.5f, 1e-6f) << x << "," << y;
    }
  EXPECT_GT(inside, 40);
  EXPECT_LT(inside, 200);
}

// A sphere of radius 2 seen from +x: its unit sphere's point, over [-1, 1]^3, at each pixel.
TEST(ObjectCoordinatesPass, ASpheresPointsAreOnItsUnitSpheresBox) {
  const uint32_t size = 15;
  const double fov = 30, distance = 9, radius = 2;
  const CoordinatesRender r = renderCoordinates(R"({
    "camera": {"width": 15, "height": 15, "fov": 30, "spp": 2, "position": [9, 0, 0],
               "look_at": [0, 0, 0]},
    "render": {"antialiasing": false},
    "spheres": [{"position": [0, 0, 0], "radius": 2, "color": 0.5}]
  })",
                                                ".");
  for (uint32_t y : {3u, 7u, 10u})
    for (uint32_t x : {4u, 7u, 11u}) {
      const std::array<double, 3> d =
          test::sphereHitSeenFromPlusX(size, size, fov, distance, radius, x, y);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(r.at(x, y)[k], 0.5 * (d[k] + 1.0), 1e-4) << x << y;
    }
  EXPECT_NEAR(r.at(7, 7).x, 1.0f, 1e-4f);
}

// The poses' model box takes each pixel's object coordinates back to a point of its model, and
// the pose takes that on to the world: the point the position pass saw there (the 2D-3D
// correspondence of docs/aovs.md), for a turned, scaled box off its file's origin, a sphere and a
// rectangle light.
TEST(ObjectCoordinatesPass, ThePosesModelBoxTakesEachPixelBackToTheWorld) {
  test::TempDir dir;
  dir.write("box.obj",
            "v 1 -2 0.5\nv 3 -2 0.5\nv 3 0 0.5\nv 1 0 0.5\n"
            "v 1 -2 1.5\nv 3 -2 1.5\nv 3 0 1.5\nv 1 0 1.5\n"
            "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n");
  SceneDesc desc = parseSceneText(R"({
    "camera": {"width": 40, "height": 30, "fov": 70, "spp": 1, "position": [0, 0, 0],
               "look_at": [0, 0, -1]},
    "render": {"antialiasing": false},
    "objects": [{"file": "box.obj", "position": [-5, 1.5, -9], "rotation": [25, 40, -15],
                 "scale": [1.5, 0.8, 1.2], "color": 0.5}],
    "spheres": [{"position": [2.5, -1, -9], "radius": 1.5, "color": 0.5}],
    "lights": [{"type": "rectangle", "position": [1, 3, -10], "direction": [0.2, -0.3, 1],
                "size": [2.5, 1.5], "intensity": 1}]
  })",
                                  "test.json", dir.path());
  const std::vector<Aov> aovs = {Aov::Instance, Aov::Position, Aov::ObjectCoordinates};
  layOutForPasses(desc, aovs);
  const SceneData scene = flattenScene(desc);
  RenderOptions options;
  options.aovs = true;
  const std::vector<ImageLayer> layers =
      makeAovLayers(scene, aovs, renderCpu(scene.view(), options).aovs);
  const std::vector<InstancePose> poses = instancePoses(desc);

  std::vector<int> seen(poses.size() + 1, 0);
  for (size_t i = 0; i < size_t(40 * 30); ++i) {
    const uint32_t number = uint32_t(layers[0].pixels[i]);
    ++seen[number];
    if (number == 0) continue;
    const InstancePose& pose = poses[number - 1];
    ASSERT_EQ(pose.number, number);
    ASSERT_TRUE(pose.modelBox) << pose.name;
    Vec3 model;
    for (int k = 0; k < 3; ++k) {
      const float c = layers[2].pixels[3 * i + k];
      model[k] = pose.modelBox->lo[k] + c * (pose.modelBox->hi[k] - pose.modelBox->lo[k]);
    }
    const Vec3 world = pose.linear * model + pose.position;
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(world[k], layers[1].pixels[3 * i + k], 2e-3f) << pose.name << " at " << i;
  }
  for (size_t number = 1; number < seen.size(); ++number)
    EXPECT_GT(seen[number], 15) << poses[number - 1].name;
  EXPECT_GT(seen[0], 100);
}

// The glTF example's tentacle and flower, posed anew each frame by their animation: their
// vertices' object coordinates are those of the mesh as the file binds it, the same in every
// frame and in a still posed at the clock's start, while the vertices move.
TEST(ObjectCoordinatesPass, APosedMeshKeepsItsBoundMeshsCoordinates) {
  SceneDesc example =
      loadSceneFile(std::string(CANDELA_SOURCE_DIR) + "/scenes/examples/gltf_animation.json");
  example.animation->shutterOpen = example.animation->shutterClose = 0.0f;
  layOutForPasses(example, {Aov::ObjectCoordinates});
  const SceneData early = flattenScene(sceneAtFrame(example, 3));
  const SceneData late = flattenScene(sceneAtFrame(example, 18));
  ASSERT_EQ(early.objectCoordinates.size(), early.positions.size());
  ASSERT_EQ(late.objectCoordinates.size(), late.positions.size());
  size_t moved = 0;
  for (size_t v = 0; v < early.positions.size(); ++v) {
    moved += lengthSquared(early.positions[v] - late.positions[v]) > 1e-6f;
    EXPECT_EQ(early.objectCoordinates[v].x, late.objectCoordinates[v].x) << v;
    EXPECT_EQ(early.objectCoordinates[v].y, late.objectCoordinates[v].y) << v;
    EXPECT_EQ(early.objectCoordinates[v].z, late.objectCoordinates[v].z) << v;
    for (int k = 0; k < 3; ++k) {
      EXPECT_GE(early.objectCoordinates[v][k], 0.0f);
      EXPECT_LE(early.objectCoordinates[v][k], 1.0f);
    }
  }
  EXPECT_GT(moved, early.positions.size() / 2);

  SceneDesc still = example;
  still.animation.reset();
  still.objects[0].meshMotion.reset();
  still.objects[0].mesh = sceneAtFrame(example, 18).objects[0].mesh;
  const SceneData posed = flattenScene(still);
  ASSERT_EQ(posed.objectCoordinates.size(), early.objectCoordinates.size());
  for (size_t v = 0; v < posed.objectCoordinates.size(); ++v)
    EXPECT_EQ(posed.objectCoordinates[v].y, early.objectCoordinates[v].y) << v;
}

// Without the pass nothing is laid out, and a frame that asks for it is a new structure.
TEST(ObjectCoordinatesPass, OnlyARenderWithThePassLaysThemOut) {
  SceneDesc desc = parseSceneText(R"({"camera": {},
    "spheres": [{"position": [0, 0, 0], "radius": 1}],
    "lights": [{"type": "rectangle", "position": [0, 3, 0], "direction": [0, -1, 0],
                "size": [2, 1], "intensity": 1}]})",
                                  "test.json", ".");
  EXPECT_TRUE(flattenScene(desc).objectCoordinates.empty());
  layOutForPasses(desc, {Aov::ObjectCoordinates});
  const SceneData laidOut = flattenScene(desc);
  ASSERT_EQ(laidOut.objectCoordinates.size(), 4u);  // the rectangle light's corners
  EXPECT_EQ(laidOut.objectCoordinates[2].x, 1.0f);
  EXPECT_EQ(laidOut.objectCoordinates[2].y, 1.0f);
  EXPECT_EQ(laidOut.objectCoordinates[2].z, 0.5f);
}

}  // namespace
}  // namespace candela
