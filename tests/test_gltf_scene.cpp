// A glTF file where a scene file is expected (loadSceneFile, `candela render model.glb`): the
// whole file as the object, its camera or else one that frames its bounds, its lights or else a
// soft sun under a pale sky.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/rotation.h"
#include "gltf_test_util.h"
#include "scene/camera_resolve.h"
#include "scene/read/scene_loader.h"
#include "scene/scene_error.h"
#include "temp_dir.h"

namespace candela {
namespace {

using test::GltfFile;
using test::TempDir;

// A tetrahedron's four corners, placed by a node moved by (10, 2, -3) and scaled by 4: the file's
// bounds are [8, 14] x [0, 6] x [-5, 1] (the corners below, times 4, moved).
GltfFile tetrahedron() {
  GltfFile f;
  const int p = f.addFloats(
      {-0.5f, -0.5f, -0.5f, 1, -0.5f, -0.5f, -0.5f, 1, -0.5f, -0.5f, -0.5f, 1}, "VEC3", 3);
  const int i =
      f.addAccessor(std::vector<uint16_t>{0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3}, 5123, "SCALAR", 12);
  f.doc["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", p}}}, {"indices", i}}}}}};
  f.doc["nodes"] = {{{"mesh", 0}, {"translation", {10, 2, -3}}, {"scale", {4, 4, 4}}}};
  f.doc["scenes"] = {{{"nodes", {0}}}};
  return f;
}

// Where camera `cam` images world point p, in pixels.
Vec2 pixelOf(const Camera& cam, const Vec3& p) {
  Mat3 k;
  EXPECT_TRUE(invert(cam.inverseK, &k));
  const Vec3 c = cam.cameraToWorld.transposed() * (p - cam.position);
  const Vec3 h = k * (c / c.z);
  EXPECT_GT(c.z, 0.0f);
  return Vec2(h.x, h.y);
}

TEST(GltfScene, ABareFileIsFramedAndLitByASunUnderASky) {
  TempDir dir;
  const std::string path = dir.write("tet.glb", tetrahedron().glb());
  const SceneDesc scene = loadSceneFile(path);
  ASSERT_EQ(scene.objects.size(), 1u);
  EXPECT_EQ(scene.objects[0].file, dir.path() + "/tet.glb");
  EXPECT_EQ(scene.objects[0].mesh->triangles.size(), 4u);
  ASSERT_EQ(scene.lights.size(), 1u);
  EXPECT_EQ(scene.lights[0].type, LightType::Directional);
  EXPECT_FLOAT_EQ(scene.environment.color.x, 0.6f);
  EXPECT_EQ(scene.camera.width, 960u);
  EXPECT_EQ(scene.camera.height, 540u);
  // It looks at the bounds' centre, and sees all of their corners.
  ASSERT_TRUE(scene.camera.lookAt);
  EXPECT_NEAR(scene.camera.lookAt->x, 11, 1e-5);
  EXPECT_NEAR(scene.camera.lookAt->y, 3, 1e-5);
  EXPECT_NEAR(scene.camera.lookAt->z, -2, 1e-5);
  const Camera cam = resolveCamera(scene.camera, scene.file);
  double left = 960, right = 0, top = 540, bottom = 0;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 p(corner & 1 ? 14.0f : 8.0f, corner & 2 ? 6.0f : 0.0f, corner & 4 ? 1.0f : -5.0f);
    const Vec2 px = pixelOf(cam, p);
    left = std::min(left, double(px.x));
    right = std::max(right, double(px.x));
    top = std::min(top, double(px.y));
    bottom = std::max(bottom, double(px.y));
  }
  EXPECT_GT(left, 0);
  EXPECT_LT(right, 960);
  EXPECT_GT(top, 0);
  EXPECT_LT(bottom, 540);
  // Framed, not lost in the distance: the bounds span at least half of the image's height.
  EXPECT_GT(bottom - top, 270);
}

TEST(GltfScene, AFilesCameraAndLightsStageIt) {
  TempDir dir;
  GltfFile f = tetrahedron();
  f.doc["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.7}, {"znear", 0.1}}}}};
  f.doc["extensionsUsed"] = {"KHR_lights_punctual"};
  f.doc["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "point"}, {"intensity", 50}}};
  f.doc["nodes"].push_back({{"camera", 0}, {"translation", {11, 3, 20}}});
  f.doc["nodes"].push_back(
      {{"translation", {11, 12, 0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  f.doc["scenes"][0]["nodes"] = {0, 1, 2};
  const SceneDesc scene = loadSceneFile(dir.write("staged.gltf", f.gltf()));
  EXPECT_EQ(scene.camera.gltfFile, dir.path() + "/staged.gltf");
  ASSERT_EQ(scene.lights.size(), 1u);
  EXPECT_EQ(scene.lights[0].type, LightType::Point);
  EXPECT_FLOAT_EQ(scene.lights[0].position.y, 12.0f);
  EXPECT_EQ(scene.environment.color.x, 0.0f);  // no sky: the file's lights alone
  EXPECT_TRUE(scene.warnings.empty());
}

TEST(GltfScene, ABrokenFileIsRefusedUnderItsName) {
  TempDir dir;
  GltfFile f = tetrahedron();
  f.doc["meshes"][0]["primitives"][0]["indices"] = 7;
  const std::string path = dir.write("broken.glb", f.glb());
  try {
    loadSceneFile(path);
    ADD_FAILURE() << "a broken file was taken";
  } catch (const SceneError& e) {
    // tinygltf's own check, under the file's name.
    EXPECT_EQ(std::string(e.what()), path + ": primitive indices accessor out of bounds");
  }
}

}  // namespace
}  // namespace candela
