// An object that holds one node of a glTF file ("gltf_node"): that node's meshes and its
// children's, in the node's own frame (its transform and its parents' left out, its children's
// kept), so that the scene places and animates the node as one object; objects of one file may
// each hold another node. A name the file lacks or repeats, and the key where it means nothing,
// are refused with their JSON paths.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "gltf_material_test_util.h"
#include "render_test_util.h"
#include "scene/read/scene_loader.h"
#include "scene/scene_error.h"
#include "temp_dir.h"

namespace candela {
namespace {

using test::TempDir;

// The quad [-1, 1]^2 (z = 0) under three nodes: "table" moved by (10, 0, 0) and scaled by 2,
// holding "lamp" (the quad again, moved up 3 and turned 90 degrees about x); "chair" moved by
// (0, 0, -5) beside it, under a root "room" moved by (100, 0, 0).
test::GltfFile room() {
  test::GltfFile f = test::quad(nlohmann::json(), -1);
  const double s = 0.70710678118654752;  // sin 45 degrees: a quaternion of 90 about x
  f.doc["nodes"] = nlohmann::json::array(
      {{{"name", "room"}, {"translation", {100, 0, 0}}, {"children", {1, 3}}},
       {{"name", "table"},
        {"mesh", 0},
        {"translation", {10, 0, 0}},
        {"scale", {2, 2, 2}},
        {"children", {2}}},
       {{"name", "lamp"}, {"mesh", 0}, {"translation", {0, 3, 0}}, {"rotation", {s, 0, 0, s}}},
       {{"name", "chair"}, {"mesh", 0}, {"translation", {0, 0, -5}}}});
  f.doc["scenes"] = {{{"nodes", {0}}}};
  return f;
}

std::string sceneOf(const std::string& objects) {
  return R"({"camera": {"width": 4, "height": 4}, "objects": [)" + objects + "]}";
}

// The mesh's bounds, [min x, min y, min z, max x, max y, max z].
std::array<float, 6> bounds(const MeshDesc& mesh) {
  std::array<float, 6> b{1e30f, 1e30f, 1e30f, -1e30f, -1e30f, -1e30f};
  for (const Vec3& p : mesh.positions)
    for (int k = 0; k < 3; ++k) {
      b[k] = std::min(b[k], p[k]);
      b[3 + k] = std::max(b[3 + k], p[k]);
    }
  return b;
}

TEST(GltfNodePick, AnObjectHoldsOneNodeInItsOwnFrame) {
  TempDir dir;
  dir.write("room.gltf", room().gltf());
  const SceneDesc scene =
      parseSceneText(sceneOf(R"({"file": "room.gltf"}, {"file": "room.gltf", "gltf_node": "table"},
                 {"file": "room.gltf", "gltf_node": "chair", "position": [1, 2, 3]},
                 {"file": "room.gltf", "gltf_node": "lamp"},
                 {"file": "room.gltf", "gltf_node": "table", "scale": 3})"),
                     "s.json", dir.path());
  // The whole file: three quads, the room's move in each.
  EXPECT_EQ(scene.objects[0].mesh->triangles.size(), 6u);
  EXPECT_EQ(bounds(*scene.objects[0].mesh)[0], 99.0f);
  // The table alone with its lamp: the table's quad as it is (its move and scale left out), the
  // lamp under it moved up 3 and turned to stand in y = 3 along z, as the table's frame has it.
  const MeshDesc& table = *scene.objects[1].mesh;
  EXPECT_EQ(table.triangles.size(), 4u);
  const std::array<float, 6> t = bounds(table);
  EXPECT_EQ(t[0], -1.0f);
  EXPECT_EQ(t[3], 1.0f);
  EXPECT_EQ(t[1], -1.0f);
  EXPECT_NEAR(t[4], 3.0f, 1e-6);
  EXPECT_NEAR(t[2], -1.0f, 1e-6);
  EXPECT_NEAR(t[5], 1.0f, 1e-6);
  int atLampHeight = 0;
  for (const Vec3& p : table.positions) atLampHeight += std::fabs(p.y - 3.0f) < 1e-6f;
  EXPECT_EQ(atLampHeight, 4);
  // The chair: the quad alone, at the origin of its own frame; the object's placement is the
  // scene's.
  const std::array<float, 6> c = bounds(*scene.objects[2].mesh);
  EXPECT_EQ(c[0], -1.0f);
  EXPECT_EQ(c[2], 0.0f);
  EXPECT_EQ(c[5], 0.0f);
  EXPECT_EQ(scene.objects[2].position.x, 1.0f);
  // The lamp, a leaf: its own turn left out too.
  EXPECT_EQ(bounds(*scene.objects[3].mesh)[5], 0.0f);
  // Objects of one file and node share one mesh.
  EXPECT_EQ(scene.objects[1].mesh, scene.objects[4].mesh);
  EXPECT_NE(scene.objects[0].mesh, scene.objects[1].mesh);
}

std::string errorOf(const std::string& objects, const test::GltfFile& file) {
  TempDir dir;
  dir.write("room.gltf", file.gltf());
  dir.write("box.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  return test::loadError(sceneOf(objects), dir.path());
}

TEST(GltfNodePick, WhatNamesNoOneNodeIsRefusedWithItsPath) {
  EXPECT_EQ(errorOf(R"({"file": "room.gltf", "gltf_node": "tabel"})", room()),
            "test.json: objects[0].gltf_node: room.gltf: the file has no node \"tabel\" (did you "
            "mean \"table\"?); its nodes: \"room\", \"table\", \"lamp\", \"chair\"");
  test::GltfFile twice = room();
  twice.doc["nodes"][3]["name"] = "table";
  EXPECT_EQ(
      errorOf(R"({"file": "room.gltf", "gltf_node": "table"})", twice),
      "test.json: objects[0].gltf_node: room.gltf: the file names 2 nodes \"table\" (nodes[1] "
      "and nodes[3]); expected a name that one node has");
  EXPECT_EQ(errorOf(R"({"file": "box.obj", "gltf_node": "table"})", room()),
            "test.json: objects[0].gltf_node: a glTF file's node, and \"box.obj\" is not a glTF "
            "file");
  EXPECT_EQ(errorOf(R"({"shape": "cube", "gltf_node": "table"})", room()),
            "test.json: objects[0].gltf_node: a glTF file's node, and the object is a cube");
  EXPECT_EQ(errorOf(R"({"file": "room.gltf", "gltf_node": ""})", room()),
            "test.json: objects[0].gltf_node: expected the name of one of the file's nodes, got a "
            "string \"\"");
}

}  // namespace
}  // namespace candela
