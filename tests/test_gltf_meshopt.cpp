// EXT_meshopt_compression (scene/read/gltf_meshopt.h): a quad's positions, octahedral normals,
// exponent-coded uvs and indices (as triangles and as a sequence), each encoded by
// meshoptimizer's own encoders into a buffer beside a fallback that holds no bytes, read back as
// the numbers encoded (positions and indices exactly, the filtered ones within their codes'
// steps), from a .glb and a .gltf; a stream or parameters the extension does not allow refused
// with the JSON path; a build without meshoptimizer refuses a file that requires it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "gltf_test_util.h"
#include "scene/read/gltf_loader.h"
#include "scene/read/gltf_meshopt.h"
#include "scene/read/texture_reader.h"
#include "scene/scene_error.h"
#include "temp_dir.h"

#ifdef CANDELA_HAS_MESHOPT
#include <meshoptimizer.h>
#endif

namespace candela {
namespace {

using test::GltfFile;
using test::TempDir;

std::string loadError(const std::string& path) { return test::gltfLoadError(path, "m.glb"); }

#ifdef CANDELA_HAS_MESHOPT
MeshDesc load(const std::string& path) { return test::loadGltfMesh(path, "m.glb"); }

// Appends `stream` to the file's buffer 0 and adds a view of `decodedLength` bytes over the
// fallback buffer 1 whose EXT_meshopt_compression names it; the view's index.
int addCompressedView(GltfFile& f, const std::vector<unsigned char>& stream, size_t count,
                      size_t stride, const char* mode, const char* filter, size_t* fallbackAt,
                      bool strided) {
  while (f.buffer.size() % 4) f.buffer += '\0';
  const size_t offset = f.buffer.size();
  f.buffer.append(reinterpret_cast<const char*>(stream.data()), stream.size());
  nlohmann::json e = {{"buffer", 0},          {"byteOffset", offset}, {"byteLength", stream.size()},
                      {"byteStride", stride}, {"count", count},       {"mode", mode}};
  if (filter) e["filter"] = filter;
  nlohmann::json view = {{"buffer", 1},
                         {"byteOffset", *fallbackAt},
                         {"byteLength", count * stride},
                         {"extensions", {{"EXT_meshopt_compression", e}}}};
  if (strided) view["byteStride"] = stride;
  *fallbackAt += count * stride;
  f.doc["bufferViews"].push_back(view);
  return int(f.doc["bufferViews"].size() - 1);
}

// Four vertices of a quad in z = 0.5, their normals tilted, uvs from 0 to 3.25.
const float kPositions[4][3] = {{0, 0, 0.5f}, {1, 0, 0.5f}, {1, 1, 0.5f}, {0, 1, 0.5f}};
const float kNormals[4][4] = {
    {0.6f, 0, 0.8f, 0}, {0, 0.6f, 0.8f, 0}, {-0.6f, 0, 0.8f, 0}, {0, 0, 1, 0}};
const float kUvs[4][2] = {{0, 0}, {3.25f, 0}, {3.25f, 1.5f}, {0.001f, 1.5f}};
const uint32_t kTriangles[6] = {0, 1, 2, 0, 2, 3};

// The quad: positions (floats), normals (OCTAHEDRAL into normalized bytes), uvs (EXPONENTIAL
// floats) and indices (TRIANGLES, shorts) in one primitive, a second primitive of indices as an
// INDICES sequence (ints); every view compressed over the fallback buffer 1.
GltfFile compressedQuad() {
  GltfFile f;
  size_t fallback = 0;
  const auto encodeVertices = [](const void* data, size_t count, size_t stride) {
    std::vector<unsigned char> out(meshopt_encodeVertexBufferBound(count, stride));
    out.resize(meshopt_encodeVertexBuffer(out.data(), out.size(), data, count, stride));
    return out;
  };
  const int pv = addCompressedView(f, encodeVertices(kPositions, 4, 12), 4, 12, "ATTRIBUTES",
                                   nullptr, &fallback, true);
  int8_t octahedral[4][4];
  meshopt_encodeFilterOct(octahedral, 4, 4, 8, &kNormals[0][0]);
  const int nv = addCompressedView(f, encodeVertices(octahedral, 4, 4), 4, 4, "ATTRIBUTES",
                                   "OCTAHEDRAL", &fallback, true);
  uint32_t exponents[4][2];
  meshopt_encodeFilterExp(exponents, 4, 8, 15, &kUvs[0][0]);
  const int tv = addCompressedView(f, encodeVertices(exponents, 4, 8), 4, 8, "ATTRIBUTES",
                                   "EXPONENTIAL", &fallback, true);
  std::vector<unsigned char> triangles(meshopt_encodeIndexBufferBound(6, 4));
  triangles.resize(meshopt_encodeIndexBuffer(triangles.data(), triangles.size(), kTriangles, 6));
  const int iv = addCompressedView(f, triangles, 6, 2, "TRIANGLES", nullptr, &fallback, false);
  std::vector<unsigned char> sequence(meshopt_encodeIndexSequenceBound(3, 4));
  const uint32_t one[3] = {3, 1, 0};
  sequence.resize(meshopt_encodeIndexSequence(sequence.data(), sequence.size(), one, 3));
  const int sv = addCompressedView(f, sequence, 3, 4, "INDICES", nullptr, &fallback, false);
  const auto accessor = [](int view, int componentType, const char* type, size_t count,
                           bool normalized) {
    nlohmann::json a = {
        {"bufferView", view}, {"componentType", componentType}, {"count", count}, {"type", type}};
    if (normalized) a["normalized"] = true;
    return a;
  };
  f.doc["accessors"] = nlohmann::json::array(
      {accessor(pv, 5126, "VEC3", 4, false), accessor(nv, 5120, "VEC3", 4, true),
       accessor(tv, 5126, "VEC2", 4, false), accessor(iv, 5123, "SCALAR", 6, false),
       accessor(sv, 5125, "SCALAR", 3, false)});
  const nlohmann::json attributes = {{"POSITION", 0}, {"NORMAL", 1}, {"TEXCOORD_0", 2}};
  f.doc["meshes"] =
      nlohmann::json::array({nlohmann::json{{"primitives",
                                             {{{"attributes", attributes}, {"indices", 3}},
                                              {{"attributes", attributes}, {"indices", 4}}}}}});
  f.doc["nodes"] = nlohmann::json::array({nlohmann::json{{"mesh", 0}}});
  f.moreBuffers.push_back({{"byteLength", fallback},
                           {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}});
  f.doc["extensionsUsed"] = {"EXT_meshopt_compression", "KHR_mesh_quantization"};
  f.doc["extensionsRequired"] = {"EXT_meshopt_compression", "KHR_mesh_quantization"};
  return f;
}

void expectQuad(const MeshDesc& mesh) {
  ASSERT_EQ(mesh.triangles.size(), 3u);
  ASSERT_EQ(mesh.positions.size(), 8u);  // each primitive its own copy
  for (size_t v = 0; v < 8; ++v)
    for (int a = 0; a < 3; ++a) EXPECT_EQ(mesh.positions[v][a], kPositions[v % 4][a]) << v;
  const uint32_t expected[3][3] = {{0, 1, 2}, {0, 2, 3}, {7, 5, 4}};
  for (size_t t = 0; t < 3; ++t)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(mesh.triangles[t].v[k], expected[t][k]) << t;
  ASSERT_EQ(mesh.normals.size(), 8u);
  for (size_t v = 0; v < 8; ++v)
    for (int a = 0; a < 3; ++a)
      EXPECT_NEAR(mesh.normals[v][a], kNormals[v % 4][a], 0.02) << v;  // 8-bit octahedral codes
  ASSERT_EQ(mesh.uvs.size(), 8u);
  for (size_t v = 0; v < 8; ++v) {
    // 15-bit mantissas under the exponent of the pair's larger value; v turned to candela's.
    const float* uv = kUvs[v % 4];
    const double step = std::ldexp(std::max(std::fabs(uv[0]), std::fabs(uv[1])), -14);
    EXPECT_NEAR(mesh.uvs[v].x, uv[0], step) << v;
    EXPECT_NEAR(mesh.uvs[v].y, 1 - uv[1], step) << v;
  }
}

TEST(GltfMeshopt, CompressedViewsReadAsTheNumbersEncoded) {
  ASSERT_TRUE(gltfMeshoptDecoding());
  TempDir dir;
  const GltfFile f = compressedQuad();
  {
    SCOPED_TRACE(".glb");
    expectQuad(load(dir.write("quad.glb", f.glb())));
  }
  {
    SCOPED_TRACE(".gltf");
    expectQuad(load(dir.write("quad.gltf", f.gltf())));
  }
  {
    SCOPED_TRACE("a placeholder not tagged as a fallback");
    GltfFile untagged = f;
    untagged.moreBuffers[0].erase("extensions");
    expectQuad(load(dir.write("untagged.glb", untagged.glb())));
  }
}

TEST(GltfMeshopt, StreamsAndParametersTheExtensionDoesNotAllowAreRefused) {
  TempDir dir;
  struct Case {
    const char* name;
    std::function<void(nlohmann::json&)> breakIt;  // the extension object of view 0, 1 or 3
    int view;
    std::string expected;
  };
  const std::string at = "m.glb: bufferViews[";
  const std::string ext = "].extensions.EXT_meshopt_compression";
  const std::vector<Case> cases = {
      {"an unknown mode", [](nlohmann::json& e) { e["mode"] = "POINTS"; }, 0,
       at + "0" + ext + ".mode: expected ATTRIBUTES, TRIANGLES or INDICES, got \"POINTS\""},
      {"a stride meshopt cannot take", [](nlohmann::json& e) { e["byteStride"] = 6; }, 0,
       at + "0" + ext +
           ".byteStride: expected a multiple of 4 from 4 to 256 for ATTRIBUTES, got 6"},
      {"a filter on indices", [](nlohmann::json& e) { e["filter"] = "OCTAHEDRAL"; }, 3,
       at + "3" + ext + ".filter: only ATTRIBUTES take a filter, got \"OCTAHEDRAL\""},
      {"an octahedral stride", [](nlohmann::json& e) { e["byteStride"] = 12; }, 1,
       at + "1" + ext + ".byteStride: expected 4 or 8 for OCTAHEDRAL, got 12"},
      {"an unknown filter", [](nlohmann::json& e) { e["filter"] = "ZIP"; }, 0,
       at + "0" + ext +
           ".filter: expected NONE, OCTAHEDRAL, QUATERNION or EXPONENTIAL, got \"ZIP\""},
      {"triangles of 4 indices", [](nlohmann::json& e) { e["count"] = 4; }, 3,
       at + "3" + ext + ".count: expected a multiple of 3 for TRIANGLES, got 4"},
      {"a stream cut short", [](nlohmann::json& e) { e["byteLength"] = 3; }, 0,
       at + "0" + ext + ": the ATTRIBUTES stream does not decode (meshoptimizer's error -2)"},
      {"bytes past the buffer", [](nlohmann::json& e) { e["byteOffset"] = 1000; }, 0,
       at + "0" + ext + ": bytes 1000 to 1"},
      {"no such buffer", [](nlohmann::json& e) { e["buffer"] = 7; }, 0,
       at + "0" + ext + ".buffer: buffer 7 does not exist (2 buffers)"},
      {"a count beyond its stream", [](nlohmann::json& e) { e["count"] = 100000000; }, 0,
       at + "0" + ext + ": 100000000 elements of 12 bytes cannot come from a stream of "},
      {"no count", [](nlohmann::json& e) { e.erase("count"); }, 0,
       at + "0" + ext + ".count: expected a number, got none"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    GltfFile f = compressedQuad();
    c.breakIt(f.doc["bufferViews"][size_t(c.view)]["extensions"]["EXT_meshopt_compression"]);
    const std::string error = loadError(dir.write("broken.glb", f.glb()));
    EXPECT_EQ(error.substr(0, c.expected.size()), c.expected) << error;
  }
}
#endif

TEST(GltfMeshopt, ABuildWithoutMeshoptimizerRefusesAFileThatRequiresIt) {
  if (gltfMeshoptDecoding()) GTEST_SKIP() << "this build reads meshopt (the tests above)";
  TempDir dir;
  GltfFile f;
  f.doc["extensionsRequired"] = {"EXT_meshopt_compression"};
  EXPECT_EQ(loadError(dir.write("a.glb", f.glb())),
            "m.glb: extensionsRequired: the file requires EXT_meshopt_compression, and this "
            "build of candela reads no such files (built without libmeshoptimizer-dev)");
}

}  // namespace
}  // namespace candela
