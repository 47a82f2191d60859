// Reading Stanford PLY meshes (scene/read/ply_loader.h): the same polygons written as ASCII,
// little- and big-endian binary PLY read as the OBJ of them does (positions, normals, uvs and the
// triangles a quad and a pentagon become), other elements and properties skipped; each kind of
// broken file refused with one message naming the file, the element and its number.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "scene/read/obj_loader.h"
#include "scene/read/ply_loader.h"
#include "scene/read/scene_loader.h"
#include "scene/scene_error.h"

namespace candela {
namespace {

// The file `name` in a folder of the running test's own: ctest runs the tests in processes of
// their own at once, and two writing one bad.ply would read each other's bytes.
std::string writeFile(const std::string& name, const std::string& bytes) {
  const std::string folder = ::testing::TempDir() + "ply_" +
                             ::testing::UnitTest::GetInstance()->current_test_info()->name();
  std::filesystem::create_directories(folder);
  const std::string path = folder + "/" + name;
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

// A triangle, a quad and a convex pentagon over 8 vertices with normals and uvs.
const double kPositions[8][3] = {{0, 0, 0}, {1, 0, 0},      {1, 1, 0},   {0, 1, 0},
                                 {2, 0, 0}, {3, 0.5, 0.25}, {2.5, 1, 0}, {2, 1.25, 0.5}};
const std::vector<std::vector<uint32_t>> kFaces = {{0, 1, 3}, {1, 4, 6, 2}, {4, 5, 6, 7, 3}};

double normalOf(int v, int a) {
  return a == 2 ? 0.8 : (a == 0 ? 0.6 * (v % 2) : 0.6 * (1 - v % 2));
}
double uvOf(int v, int a) { return a == 0 ? 0.125 * v : 1 - 0.0625 * v; }

std::string objText() {
  std::string text;
  for (int v = 0; v < 8; ++v) {
    text += "v " + std::to_string(kPositions[v][0]) + " " + std::to_string(kPositions[v][1]) + " " +
            std::to_string(kPositions[v][2]) + "\n";
    text += "vn " + std::to_string(normalOf(v, 0)) + " " + std::to_string(normalOf(v, 1)) + " " +
            std::to_string(normalOf(v, 2)) + "\n";
    text += "vt " + std::to_string(uvOf(v, 0)) + " " + std::to_string(uvOf(v, 1)) + "\n";
  }
  for (const auto& face : kFaces) {
    text += "f";
    for (uint32_t v : face) {
      const std::string i = std::to_string(v + 1);
      text += " " + i + "/" + i + "/" + i;
    }
    text += "\n";
  }
  return text;
}

// Binary values in a byte order.
struct Packer {
  bool bigEndian;
  std::string bytes;
  template <typename T>
  void put(T value) {
    char b[sizeof(T)];
    std::memcpy(b, &value, sizeof b);
    if (bigEndian) std::reverse(b, b + sizeof b);
    bytes.append(b, sizeof b);
  }
};

// The mesh as PLY: positions in double, normals and uvs in float, an unused colour and a list
// property among the vertex's, a face property before the index list (ushort counts, uint
// indices), and an element of its own after the faces, all to be skipped.
std::string plyText(const std::string& format) {
  std::string header = "ply\r\nformat " + format + " 1.0\ncomment made by a test\n" +
                       "element vertex 8\nproperty double x\nproperty double y\nproperty double z\n"
                       "property float nx\nproperty float ny\nproperty float nz\n"
                       "property list uchar short extra\nproperty float s\nproperty float t\n"
                       "element face 3\nproperty uchar flags\n"
                       "property list ushort uint vertex_indices\n"
                       "element camera 1\nproperty float view_px\nend_header\n";
  if (format == "ascii") {
    std::string body;
    for (int v = 0; v < 8; ++v) {
      for (double p : kPositions[v]) body += std::to_string(p) + " ";
      for (int a = 0; a < 3; ++a) body += std::to_string(normalOf(v, a)) + " ";
      body += "2 -7 7 " + std::to_string(uvOf(v, 0)) + " " + std::to_string(uvOf(v, 1)) + "\n";
    }
    for (const auto& face : kFaces) {
      body += "3 " + std::to_string(face.size());
      for (uint32_t v : face) body += " " + std::to_string(v);
      body += "\n";
    }
    return header + body + "0.5\n";
  }
  Packer p{format == "binary_big_endian", ""};
  for (int v = 0; v < 8; ++v) {
    for (double x : kPositions[v]) p.put(x);
    for (int a = 0; a < 3; ++a) p.put(float(normalOf(v, a)));
    p.put(uint8_t(2));
    p.put(int16_t(-7));
    p.put(int16_t(7));
    p.put(float(uvOf(v, 0)));
    p.put(float(uvOf(v, 1)));
  }
  for (const auto& face : kFaces) {
    p.put(uint8_t(3));
    p.put(uint16_t(face.size()));
    for (uint32_t v : face) p.put(v);
  }
  p.put(0.5f);
  return header + p.bytes;
}

TEST(PlyLoader, AsciiAndBinaryOfEitherOrderReadAsTheObjOfTheSameFaces) {
  std::vector<std::shared_ptr<const TextureDesc>> textures;
  TextureLoader noTextures(textures, ".");
  const MeshDesc obj = loadObjFile(writeFile("same.obj", objText()), "same.obj", noTextures);
  ASSERT_EQ(obj.triangles.size(), 1u + 2u + 3u);
  for (const char* format : {"ascii", "binary_little_endian", "binary_big_endian"}) {
    SCOPED_TRACE(format);
    const std::string name = std::string("same_") + format + ".ply";
    const MeshDesc ply = loadPlyFile(writeFile(name, plyText(format)), name);
    ASSERT_EQ(ply.positions.size(), 8u);
    ASSERT_EQ(ply.normals.size(), 8u);
    ASSERT_EQ(ply.uvs.size(), 8u);
    for (size_t v = 0; v < 8; ++v) {
      for (int a = 0; a < 3; ++a) {
        EXPECT_EQ(ply.positions[v][a], obj.positions[v][a]);
        EXPECT_EQ(ply.normals[v][a], obj.normals[v][a]);
      }
      EXPECT_EQ(ply.uvs[v].x, obj.uvs[v].x);
      EXPECT_EQ(ply.uvs[v].y, obj.uvs[v].y);
    }
    ASSERT_EQ(ply.triangles.size(), obj.triangles.size());
    for (size_t i = 0; i < obj.triangles.size(); ++i)
      for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(ply.triangles[i].v[k], obj.triangles[i].v[k]);
        EXPECT_EQ(ply.triangles[i].n[k], obj.triangles[i].n[k]);
        EXPECT_EQ(ply.triangles[i].t[k], obj.triangles[i].t[k]);
      }
    ASSERT_EQ(ply.materials.size(), 1u);
    EXPECT_EQ(ply.materials[0].type, Material{}.type);
    EXPECT_TRUE(ply.warnings.empty());
  }
}

TEST(PlyLoader, ASceneObjectNamesAPlyFileInAnyCase) {
  const std::string path = writeFile("upper.PLY", plyText("binary_little_endian"));
  const SceneDesc scene = parseSceneText(
      R"({"camera": {"width": 4, "height": 4}, "objects": [{"file": ")" + path + R"("}]})",
      "s.json", ".");
  EXPECT_EQ(scene.objects[0].mesh->triangles.size(), 6u);
  EXPECT_TRUE(isPlyPath("a/b.Ply"));
  EXPECT_FALSE(isPlyPath("a/ply"));
  EXPECT_FALSE(isPlyPath("a.obj"));
}

// An element without properties takes no bytes, so its count bounds nothing: skipping it one by
// one once spun for 2^34 turns (found by ply_fuzzer).
TEST(PlyLoader, AnElementOfNoPropertiesIsSkippedAtOnceWhateverItsCount) {
  const std::string text =
      "ply\nformat ascii 1.0\nelement nothing 18446744073709551615\nelement vertex 3\n"
      "property float x\nproperty float y\nproperty float z\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  const MeshDesc mesh = loadPlyFile(writeFile("nothing.ply", text), "nothing.ply");
  EXPECT_EQ(mesh.triangles.size(), 1u);
}

// An ASCII PLY triangle whose vertices have the properties `colour` after x, y, z, each of
// `rows` a vertex's values.
std::string colouredTriangle(const std::string& colour, const std::string& rows) {
  return "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
         "property float z\n" +
         colour + "element face 1\nproperty list uchar int vertex_index\nend_header\n" + rows +
         "3 0 1 2\n";
}

// Display colours (sRGB) of uchar, ushort or float properties, made linear; the default material
// under them is diffuse 1, so that they are its colour.
TEST(PlyLoader, VertexColoursAreReadAsLinearColours) {
  const auto srgb = [](double s) {
    return s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4);
  };
  const MeshDesc mesh = loadPlyFile(
      writeFile("colours.ply",
                colouredTriangle("property uchar red\nproperty uchar green\nproperty uchar blue\n",
                                 "0 0 0 255 0 128\n1 0 0 0 255 0\n0 1 0 10 0 255\n")),
      "colours.ply");
  EXPECT_TRUE(mesh.warnings.empty());
  ASSERT_EQ(mesh.colors.size(), 3u);
  EXPECT_FLOAT_EQ(mesh.colors[0].x, 1.0f);
  EXPECT_NEAR(mesh.colors[0].z, srgb(128.0 / 255), 1e-6);
  EXPECT_NEAR(mesh.colors[2].x, srgb(10.0 / 255), 1e-7);
  EXPECT_FLOAT_EQ(mesh.colors[1].y, 1.0f);
  EXPECT_FLOAT_EQ(mesh.colors[1].z, 0.0f);
  ASSERT_EQ(mesh.materials.size(), 1u);
  EXPECT_FLOAT_EQ(mesh.materials[0].color.x, 1.0f);
  EXPECT_TRUE(mesh.normals.empty());
  EXPECT_TRUE(mesh.uvs.empty());

  const MeshDesc f = loadPlyFile(
      writeFile("float_colours.ply",
                colouredTriangle("property float diffuse_red\nproperty float diffuse_green\n"
                                 "property float diffuse_blue\n",
                                 "0 0 0 0.5 0 0\n1 0 0 0 1 0\n0 1 0 0 0 1\n")),
      "float_colours.ply");
  ASSERT_EQ(f.colors.size(), 3u);
  EXPECT_NEAR(f.colors[0].x, srgb(0.5), 1e-6);

  const MeshDesc w = loadPlyFile(
      writeFile("wide_colours.ply",
                colouredTriangle("property ushort r\nproperty ushort g\nproperty ushort b\n",
                                 "0 0 0 65535 0 0\n1 0 0 0 65535 0\n0 1 0 0 0 32768\n")),
      "wide_colours.ply");
  ASSERT_EQ(w.colors.size(), 3u);
  EXPECT_NEAR(w.colors[2].z, srgb(32768.0 / 65535), 1e-6);

  // Two of the three are no colour.
  const MeshDesc p = loadPlyFile(
      writeFile("partial.ply", colouredTriangle("property uchar red\nproperty uchar green\n",
                                                "0 0 0 255 0\n1 0 0 0 255\n0 1 0 10 0\n")),
      "partial.ply");
  EXPECT_TRUE(p.colors.empty());
  EXPECT_FLOAT_EQ(p.materials[0].color.x, 0.8f);
}

std::string errorOf(const std::string& bytes) {
  try {
    loadPlyFile(writeFile("bad.ply", bytes), "bad.ply");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

const std::string kAsciiHeader =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
    "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";

TEST(PlyLoader, BrokenHeadersAreRefusedAtTheirLine) {
  EXPECT_EQ(errorOf("v 0 0 0\n"),
            "bad.ply:1: expected \"ply\" on the first line (a Stanford PLY file), got \"v 0 0 0\"");
  EXPECT_EQ(errorOf("ply\nformat binary 1.0\nend_header\n"),
            "bad.ply:2: unknown format \"binary\" (expected ascii, binary_little_endian or "
            "binary_big_endian)");
  EXPECT_EQ(errorOf("ply\nformat ascii 1.0\nproperty float x\n"),
            "bad.ply:3: a property before any element");
  EXPECT_EQ(errorOf("ply\nformat ascii 1.0\nelement vertex 1\nproperty real x\n"),
            "bad.ply:4: unknown property type \"real\" (expected char, uchar, short, ushort, int, "
            "uint, float or double)");
  EXPECT_EQ(errorOf("ply\nformat ascii 1.0\nelement vertex -1\n"),
            "bad.ply:3: expected \"element NAME COUNT\" with a whole COUNT, got \"element vertex "
            "-1\"");
  EXPECT_EQ(errorOf("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"),
            "bad.ply:4: the header ends without \"end_header\"");
  EXPECT_EQ(errorOf("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float "
                    "y\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"),
            "bad.ply:3: the vertex element has no property z");
  EXPECT_EQ(errorOf("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float "
                    "y\nproperty float z\nend_header\n0 0 0\n"),
            "bad.ply: expected a mesh, got no faces (a point cloud?)");
}

// A number below the smallest double reads as 0, as in an OBJ file.
TEST(PlyLoader, ANumberBelowTheSmallestDoubleIsZero) {
  const MeshDesc mesh = loadPlyFile(
      writeFile("tiny.ply", kAsciiHeader + "0 0 1e-400\n1 0 0\n0 1 0\n3 0 1 2\n"), "tiny.ply");
  EXPECT_EQ(mesh.positions[0].z, 0.0f);
}

TEST(PlyLoader, BrokenAsciiBodiesAreRefusedAtTheirLine) {
  EXPECT_EQ(errorOf(kAsciiHeader + "0 0 0\n1 0 0\n0 1 zero\n3 0 1 2\n"),
            "bad.ply:12: vertex 2: expected a number, got \"zero\"");
  EXPECT_EQ(errorOf(kAsciiHeader + "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"),
            "bad.ply:13: face 0: vertex index 3 out of range (3 vertices)");
  EXPECT_EQ(errorOf(kAsciiHeader + "0 0 0\n1 0 0\n0 1 0\n2 0 1\n"),
            "bad.ply:13: face 0: a face of 2 corners; expected at least 3");
  EXPECT_EQ(errorOf(kAsciiHeader + "0 0 0\n1 0 0\n0 1 nan\n3 0 1 2\n"),
            "bad.ply:12: vertex 2: z is nan; expected a finite number");
  EXPECT_EQ(errorOf(kAsciiHeader + "0 0 0\n1 0 0\n0 1 1e39\n3 0 1 2\n"),
            "bad.ply:12: vertex 2: z is 1e+39, beyond single precision");
  EXPECT_EQ(errorOf(kAsciiHeader + "0 0 0\n1 0 0\n0 1 1e400\n3 0 1 2\n"),
            "bad.ply:12: vertex 2: the number \"1e400\" is out of range");
  EXPECT_EQ(errorOf(kAsciiHeader + "0 0 0\n1 0 0\n0 1 0\n3 0 1.5 2\n"),
            "bad.ply:13: face 0: expected an integer of type int, got \"1.5\"");
  EXPECT_EQ(errorOf(kAsciiHeader + "0 0 0\n1 0 0\n0 1 0\n"),
            "bad.ply:13: face 0: the file ends here");
  const std::string floatColours =
      "property float red\nproperty float green\nproperty float blue\n";
  EXPECT_EQ(errorOf(colouredTriangle(floatColours, "0 0 0 1 1 1\n1 0 0 1.5 0 0\n0 1 0 0 0 0\n")),
            "bad.ply:14: vertex 1: red is 1.5; expected a colour from 0 to 1");
  EXPECT_EQ(errorOf(colouredTriangle(floatColours, "0 0 0 1 1 1\n1 0 0 1 -0.5 0\n0 1 0 0 0 0\n")),
            "bad.ply:14: vertex 1: green is -0.5; expected a colour from 0 to 1");
}

// A little-endian header for `vertices` vertices and one face, before its binary body.
std::string binaryHeader(const std::string& vertices) {
  return "ply\nformat binary_little_endian 1.0\nelement vertex " + vertices +
         "\nproperty float x\nproperty float y\nproperty float z\nelement face 1\n"
         "property list uint int vertex_indices\nend_header\n";
}

TEST(PlyLoader, BrokenBinaryBodiesAreRefusedByElement) {
  Packer p{false, ""};
  for (float x : {0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f}) p.put(x);
  EXPECT_EQ(errorOf(binaryHeader("3") + p.bytes), "bad.ply: vertex 2: the file ends here");
  Packer nan{false, ""};
  for (float x : {0.0f, 0.0f, std::numeric_limits<float>::quiet_NaN()}) nan.put(x);
  EXPECT_EQ(errorOf(binaryHeader("3") + nan.bytes),
            "bad.ply: vertex 0: z is nan; expected a finite number");
  // A count no file could hold is refused before anything is reserved for it.
  Packer full{false, ""};
  for (int i = 0; i < 9; ++i) full.put(0.5f * float(i % 3 == i / 3));
  full.put(uint32_t(4000000000u));
  EXPECT_EQ(errorOf(binaryHeader("3") + full.bytes),
            "bad.ply: face 0: a list of 4000000000 items, more than the file holds");
  EXPECT_EQ(errorOf(binaryHeader("3000000000") + full.bytes),
            "bad.ply: vertex 3: the file ends here");
  EXPECT_EQ(errorOf(binaryHeader("5000000000")),
            "bad.ply:3: 5000000000 vertices, more than a mesh may have (4294967294)");
}

}  // namespace
}  // namespace candela
