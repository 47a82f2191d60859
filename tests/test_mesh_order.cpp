// The order in which meshes keep their triangles (scene/mesh_order.h): spatial, not the file's.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "scene/mesh_order.h"
#include "scene/read/scene_loader.h"
#include "temp_dir.h"

namespace candela {
namespace {

Vec3 centroidOf(const MeshDesc& mesh, const MeshTriangle& t) {
  return (mesh.positions[t.v[0]] + mesh.positions[t.v[1]] + mesh.positions[t.v[2]]) / 3.0f;
}

// The length of the walk from each triangle's centroid to the next one's.
float walkLength(const MeshDesc& mesh) {
  float sum = 0.0f;
  for (size_t i = 1; i < mesh.triangles.size(); ++i)
    sum += length(centroidOf(mesh, mesh.triangles[i]) - centroidOf(mesh, mesh.triangles[i - 1]));
  return sum;
}

// Everything a triangle carries, to compare meshes as sets of triangles.
std::vector<std::tuple<uint32_t, uint32_t, uint32_t, int32_t, int32_t, uint32_t>> contents(
    const MeshDesc& mesh) {
  std::vector<std::tuple<uint32_t, uint32_t, uint32_t, int32_t, int32_t, uint32_t>> all;
  for (const MeshTriangle& t : mesh.triangles)
    all.emplace_back(t.v[0], t.v[1], t.v[2], t.n[1], t.t[2], t.material);
  std::sort(all.begin(), all.end());
  return all;
}

// Small triangles scattered in a box, in random order, come out as a short walk through space
// (a Morton curve), each with its own vertices, normals, uvs and material.
TEST(MeshOrder, PutsTrianglesNearInSpaceNearInTheArray) {
  std::mt19937 gen(5);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  MeshDesc mesh;
  for (uint32_t i = 0; i < 4000; ++i) {
    const Vec3 c(unit(gen), unit(gen), unit(gen));
    MeshTriangle t;
    for (int k = 0; k < 3; ++k) {
      t.v[k] = uint32_t(mesh.positions.size());
      t.n[k] = int32_t(i);
      t.t[k] = int32_t(2 * i);
      mesh.positions.push_back(c + Vec3(unit(gen), unit(gen), unit(gen)) * 0.01f);
    }
    t.material = i % 7;
    mesh.triangles.push_back(t);
  }
  const MeshDesc before = mesh;
  orderTrianglesSpatially(&mesh);
  EXPECT_EQ(contents(mesh), contents(before));
  // Random order walks about 0.66 per step; 4000 points on a Morton curve, about 0.1 or less.
  EXPECT_LT(walkLength(mesh), 0.2f * walkLength(before))
      << walkLength(mesh) << " against " << walkLength(before);
}

// A single triangle stays; triangles that all sit on one point keep the file's order.
TEST(MeshOrder, KeepsTheOrderWhereNothingTellsTrianglesApart) {
  MeshDesc one;
  one.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  one.triangles.resize(1);
  one.triangles[0].v[0] = 0, one.triangles[0].v[1] = 1, one.triangles[0].v[2] = 2;
  orderTrianglesSpatially(&one);
  EXPECT_EQ(one.triangles.size(), 1u);
  MeshDesc two = one;
  two.positions = {Vec3(1, 1, 1), Vec3(1, 1, 1), Vec3(1, 1, 1)};
  two.triangles.push_back(two.triangles[0]);
  two.triangles[0].material = 3;
  orderTrianglesSpatially(&two);
  EXPECT_EQ(two.triangles[0].material, 3u);
  EXPECT_EQ(two.triangles[1].material, 0u);
}

// Loading a scene keeps each mesh in spatial order: a file that lists triangles along x out of
// order comes back sorted along x.
TEST(MeshOrder, SceneLoadingKeepsMeshesInSpatialOrder) {
  test::TempDir dir;
  const int xs[] = {5, 0, 7, 3, 1, 6, 4, 2};
  std::string obj;
  for (int x : xs)
    obj += "v " + std::to_string(x) + " 0 0\nv " + std::to_string(x) + ".5 0 0\nv " +
           std::to_string(x) + " 1 0\n";
  for (int i = 0; i < 8; ++i)
    obj += "f " + std::to_string(3 * i + 1) + " " + std::to_string(3 * i + 2) + " " +
           std::to_string(3 * i + 3) + "\n";
  dir.write("row.obj", obj);
  const SceneDesc scene =
      parseSceneText(R"({"camera": {}, "objects": [{"file": "row.obj"}]})", "s.json", dir.path());
  const MeshDesc& mesh = *scene.objects.at(0).mesh;
  ASSERT_EQ(mesh.triangles.size(), 8u);
  for (size_t i = 0; i < 8; ++i)
    EXPECT_FLOAT_EQ(mesh.positions[mesh.triangles[i].v[0]].x, float(i)) << i;
}

}  // namespace
}  // namespace candela
