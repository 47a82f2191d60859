// Flattening finds the objects that repeat a mesh (render/mesh_instances.h): where each object's
// triangles and vertices lie, the transform that placed them, and the prototype's object-space
// vertices (split vertices included); no repeat where the splits or the winding differ, and none
// at all where an own BVH reorders the triangles.
#include <gtest/gtest.h>

#include <string>

#include "scene/flatten.h"
#include "scene/read/scene_loader.h"
#include "temp_dir.h"

namespace candela {
namespace {

// Two faces that give their shared edge's vertices different normals: two split vertices.
const char* kCrease =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvn 0 0 1\nvn 0.6 0 0.8\n"
    "f 1//1 2//1 3//1\nf 2//2 4//2 3//2\n";
const char* kOther = "v 0 0 0\nv 2 0 0\nv 0 2 0\nf 1 2 3\n";

SceneDesc sceneOf(const std::string& objects) {
  return parseSceneText(R"({"camera": {"width": 8, "height": 8}, "objects": )" + objects + "}",
                        "repeats.json", ".");
}

TEST(MeshRepeats, ObjectsOfOneMeshShareAPrototype) {
  const test::TempDir dir;
  const std::string a = dir.write("crease.obj", kCrease);
  const std::string b = dir.write("other.obj", kOther);
  SceneDesc desc = sceneOf(R"([
      {"file": ")" + a + R"(", "position": [1, 2, 3]},
      {"file": ")" + b + R"("},
      {"file": ")" + a + R"(", "rotation": [0, 90, 30], "scale": 2, "position": [0, 0, -4]},
      {"file": ")" + a + R"(", "scale": [-1, 1, 1]},
      {"file": ")" + a + R"(", "scale": [-2, 1, 1], "position": [5, 0, 0]},
      {"file": ")" + a + R"(", "smooth": false}])");
  desc.ownBvh = OwnBvh::None;
  const SceneData s = flattenScene(desc);
  const MeshInstances& repeats = s.meshInstances;
  ASSERT_EQ(repeats.objects.size(), 6u);

  // Each object's triangles and vertices follow the previous object's.
  uint32_t triangle = 0, vertex = 0;
  for (const MeshInstance& object : repeats.objects) {
    EXPECT_EQ(object.firstTriangle, triangle);
    EXPECT_EQ(object.firstVertex, vertex);
    triangle += object.triangleCount;
    vertex += object.vertexCount;
  }
  EXPECT_EQ(triangle, s.triangles.size());
  EXPECT_EQ(vertex, s.positions.size());
  EXPECT_EQ(repeats.objects[0].vertexCount, 6u);  // 4 positions + 2 split
  EXPECT_EQ(repeats.objects[5].vertexCount, 4u);  // no normals: no splits

  // The unmirrored pair and the mirrored pair (whose winding is reversed) repeat a prototype
  // each; the other mesh, and the crease without its normals, are their own.
  ASSERT_EQ(repeats.prototypes.size(), 2u);
  EXPECT_EQ(repeats.objects[0].prototype, 0);
  EXPECT_EQ(repeats.objects[1].prototype, -1);
  EXPECT_EQ(repeats.objects[2].prototype, 0);
  EXPECT_EQ(repeats.objects[3].prototype, 1);
  EXPECT_EQ(repeats.objects[4].prototype, 1);
  EXPECT_EQ(repeats.objects[5].prototype, -1);
  EXPECT_EQ(repeats.prototypes[0].firstInstance, 0u);
  EXPECT_EQ(repeats.prototypes[0].instanceCount, 2u);
  EXPECT_EQ(repeats.prototypes[1].firstInstance, 3u);
  EXPECT_EQ(repeats.prototypes[1].instanceCount, 2u);

  // Every instance's vertices are its transform of the prototype's, split vertices included.
  for (uint32_t i : {0u, 2u, 3u, 4u}) {
    const MeshInstance& object = repeats.objects[i];
    const MeshPrototype& prototype = repeats.prototypes[uint32_t(object.prototype)];
    ASSERT_EQ(prototype.positions.size(), object.vertexCount);
    for (uint32_t k = 0; k < object.vertexCount; ++k) {
      const Vec3 placed = object.translation + object.linear * prototype.positions[k];
      const Vec3 flattened = s.positions[object.firstVertex + k];
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(placed[c], flattened[c], 1e-5f) << "object " << i << " vertex " << k;
    }
  }
}

TEST(MeshRepeats, NoneWhereAnOwnBvhReordersTheTriangles) {
  const test::TempDir dir;
  const std::string a = dir.write("crease.obj", kCrease);
  SceneDesc desc = sceneOf(R"([{"file": ")" + a + R"("}, {"file": ")" + a + R"("}])");
  desc.ownBvh = OwnBvh::Sah;
  const SceneData s = flattenScene(desc);
  EXPECT_TRUE(s.meshInstances.objects.empty());
  EXPECT_TRUE(s.meshInstances.prototypes.empty());
}

}  // namespace
}  // namespace candela
