// An object that holds one group of an OBJ file ("obj_group"): the faces after the `g` or `o`
// statements of that name, with their own vertices, normals and uvs alone, so that one file's
// parts are placed, given materials and animated as objects of their own. A name the file lacks,
// and the key where it means nothing, are refused with their JSON paths.
#include <gtest/gtest.h>

#include <string>

#include "render_test_util.h"
#include "scene/read/scene_loader.h"
#include "scene/scene_error.h"
#include "temp_dir.h"

namespace candela {
namespace {

using test::TempDir;

// A chair (one triangle with normals and uvs), a table top (a quad) under `g`, and the chair's
// second triangle further on, after a group of the same name again; v 7 is used by no face.
const char* kRoom =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
    "v 5 5 5\nv 6 5 5\nv 6 6 5\nv 9 9 9\nv 5 6 5\n"
    "vn 0 0 1\nvn 0 0 -1\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
    "o chair\nf 1/1/1 2/2/1 3/3/1\n"
    "g table top\nf 5 6 7 9\n"
    "g chair\nf 1/1/2 3/3/2 4/4/2\n";

std::string sceneOf(const std::string& objects) {
  return R"({"camera": {"width": 4, "height": 4}, "objects": [)" + objects + "]}";
}

TEST(ObjGroupPick, AnObjectHoldsOneGroupsFacesAndTheirVerticesAlone) {
  TempDir dir;
  dir.write("room.obj", kRoom);
  const SceneDesc scene =
      parseSceneText(sceneOf(R"({"file": "room.obj"}, {"file": "room.obj", "obj_group": "chair"},
                 {"file": "room.obj", "obj_group": "table top", "position": [1, 2, 3]},
                 {"file": "room.obj", "obj_group": "chair", "scale": 2})"),
                     "s.json", dir.path());
  // The whole file: its four triangles and nine vertices.
  EXPECT_EQ(scene.objects[0].mesh->triangles.size(), 4u);
  EXPECT_EQ(scene.objects[0].mesh->positions.size(), 9u);
  // The chair: both its triangles (of both its groups), the four corners of the unit square, the
  // two normals and four uvs they use, each corner still pointing at its own.
  const MeshDesc& chair = *scene.objects[1].mesh;
  ASSERT_EQ(chair.triangles.size(), 2u);
  EXPECT_EQ(chair.positions.size(), 4u);
  EXPECT_EQ(chair.normals.size(), 2u);
  EXPECT_EQ(chair.uvs.size(), 4u);
  for (const MeshTriangle& t : chair.triangles)
    for (int corner = 0; corner < 3; ++corner) {
      const Vec3 p = chair.positions[t.v[corner]];
      EXPECT_LE(p.x, 1.0f);
      EXPECT_EQ(p.z, 0.0f);
      // Each corner's uv is its position's (x, y), as the file pairs them.
      ASSERT_GE(t.t[corner], 0);
      EXPECT_EQ(chair.uvs[size_t(t.t[corner])].x, p.x);
      EXPECT_EQ(chair.uvs[size_t(t.t[corner])].y, p.y);
      ASSERT_GE(t.n[corner], 0);
    }
  float normalZ[2];
  for (int k = 0; k < 2; ++k) normalZ[k] = chair.normals[size_t(chair.triangles[k].n[0])].z;
  EXPECT_EQ(normalZ[0] * normalZ[1], -1.0f);  // one triangle's normals up, the other's down
  // The table top: the quad's two triangles and four corners; v 8, used by nothing, is in no
  // group's mesh.
  const MeshDesc& table = *scene.objects[2].mesh;
  EXPECT_EQ(table.triangles.size(), 2u);
  EXPECT_EQ(table.positions.size(), 4u);
  for (const Vec3& p : table.positions) {
    EXPECT_GE(p.x, 5.0f);
    EXPECT_LE(p.x, 6.0f);
    EXPECT_EQ(p.z, 5.0f);
  }
  EXPECT_TRUE(table.normals.empty());
  // Objects of one file and group share one mesh.
  EXPECT_EQ(scene.objects[1].mesh, scene.objects[3].mesh);
}

std::string errorOf(const std::string& objects, const std::string& obj = kRoom) {
  TempDir dir;
  dir.write("room.obj", obj);
  dir.write("box.ply",
            "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
            "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
            "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  return test::loadError(sceneOf(objects), dir.path());
}

TEST(ObjGroupPick, WhatNamesNoGroupIsRefusedWithItsPath) {
  EXPECT_EQ(errorOf(R"({"file": "room.obj", "obj_group": "Chair"})"),
            "test.json: objects[0].obj_group: room.obj: the file has no faces in a group or object "
            "\"Chair\" (did you mean \"chair\"?); those with faces: \"chair\", \"table top\"");
  EXPECT_EQ(errorOf(R"({"file": "room.obj", "obj_group": "chair"})",
                    "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"),
            "test.json: objects[0].obj_group: room.obj: no face of the file lies in a named group "
            "or object (\"g\" or \"o\"), so none in \"chair\"");
  EXPECT_EQ(errorOf(R"({"file": "room.obj", "obj_group": "lamp"})",
                    "v 0 0 0\nv 1 0 0\nv 0 1 0\ng chair\nf 1 2 3\ng lamp\n"),
            "test.json: objects[0].obj_group: room.obj: the file has no faces in a group or object "
            "\"lamp\"; those with faces: \"chair\"");
  EXPECT_EQ(errorOf(R"({"file": "box.ply", "obj_group": "chair"})"),
            "test.json: objects[0].obj_group: an OBJ file's group, and \"box.ply\" is not an OBJ "
            "file");
  EXPECT_EQ(errorOf(R"({"shape": "cube", "obj_group": "chair"})"),
            "test.json: objects[0].obj_group: an OBJ file's group, and the object is a cube");
  EXPECT_EQ(errorOf(R"({"file": "room.obj", "obj_group": ""})"),
            "test.json: objects[0].obj_group: expected the name of one of the file's groups "
            "(\"g\") or objects (\"o\"), got a string \"\"");
}

}  // namespace
}  // namespace candela
