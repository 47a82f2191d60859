// Textures: the bilinear lookup against hand-computed values (sRGB table, wrap, v flip, scale),
// sphere and OBJ texture coordinates (v/vt/vn corners split into vertices), a textured quad's
// albedo in a furnace, and the messages of bad texture input.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "core/constants.h"
#include "core/texture.h"
#include "geometry/surface_uv.h"
#include "render_test_util.h"
#include "scene/flatten.h"
#include "scene/read/obj_loader.h"
#include "scene/read/scene_loader.h"
#include "scene/read/texture_reader.h"
#include "scene/scene_error.h"
#include "texture_test_util.h"

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#endif
#include <stb/stb_image_write.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace candela {
namespace test {

bool writeTestPng(const std::string& path, int width, int height, int channels,
                  const std::vector<uint8_t>& bytes) {
  return stbi_write_png(path.c_str(), width, height, channels, bytes.data(), width * channels) != 0;
}

// stb_image_write writes 8 bits a channel only; this writes the PNG by hand, with its deflate and
// CRC: each row a filter byte 0 and big-endian samples.
bool writeTestPng16(const std::string& path, int width, int height, int channels,
                    const std::vector<uint16_t>& samples) {
  std::vector<unsigned char> raw;
  for (int y = 0; y < height; ++y) {
    raw.push_back(0);
    for (int i = 0; i < width * channels; ++i) {
      const uint16_t v = samples[size_t(y) * width * channels + i];
      raw.push_back(static_cast<unsigned char>(v >> 8));
      raw.push_back(static_cast<unsigned char>(v & 0xff));
    }
  }
  int zlen = 0;
  unsigned char* z = stbi_zlib_compress(raw.data(), int(raw.size()), &zlen, 8);
  if (!z) return false;
  const std::string idat(reinterpret_cast<const char*>(z), size_t(zlen));
  STBIW_FREE(z);
  const auto be32 = [](uint32_t v) {
    return std::string{char(v >> 24), char((v >> 16) & 0xff), char((v >> 8) & 0xff),
                       char(v & 0xff)};
  };
  const auto chunk = [&](const std::string& type, const std::string& data) {
    std::string typed = type + data;
    const uint32_t crc =
        stbiw__crc32(reinterpret_cast<unsigned char*>(typed.data()), int(typed.size()));
    return be32(uint32_t(data.size())) + typed + be32(crc);
  };
  const char colourType[] = {0, 0, 4, 2, 6};  // by channel count: grey, grey + alpha, RGB, RGBA
  const std::string header = be32(uint32_t(width)) + be32(uint32_t(height)) +
                             std::string{16, colourType[channels], 0, 0, 0};
  std::ofstream out(path, std::ios::binary);
  out << std::string("\x89PNG\r\n\x1a\n", 8) << chunk("IHDR", header) << chunk("IDAT", idat)
      << chunk("IEND", "");
  return bool(out);
}

}  // namespace test

namespace {

std::vector<float> srgbTable() {
  std::vector<float> table;
  for (int i = 0; i < 256; ++i) table.push_back(srgbToLinearValue(float(i) / 255.0f));
  return table;
}

float srgb(int byte) { return srgbToLinearValue(float(byte) / 255.0f); }

// A 2x2 sRGB texture; top row (10, 20, 30, 255) (200, 100, 50, 0), bottom row (0, 0, 0, 255)
// (255, 255, 255, 128).
class TextureLookup : public ::testing::Test {
 protected:
  TextureLookup() {
    texture.width = texture.height = 2;
    texture.format = TextureFormat::Srgb8;
    pool.textures = &texture;
    pool.texels8 = texels.data();
    pool.srgbToLinear = table.data();
    ref.index = 0;
  }
  void expectNear(const TextureSample& s, const Vec3& rgb, float alpha) const {
    EXPECT_NEAR(s.rgb.x, rgb.x, 1e-6f);
    EXPECT_NEAR(s.rgb.y, rgb.y, 1e-6f);
    EXPECT_NEAR(s.rgb.z, rgb.z, 1e-6f);
    EXPECT_NEAR(s.alpha, alpha, 1e-6f);
  }

  std::vector<uint8_t> texels = {10, 20, 30, 255, 200, 100, 50, 0, 0, 0, 0, 255, 255, 255, 255, 128};
  std::vector<float> table = srgbTable();
  Texture texture;
  TexturePool pool;
  TextureRef ref;
};

TEST_F(TextureLookup, TexelCentresDecodeSrgbAndFlipV) {
  // v = 0 is the bottom row: (0.25, 0.75) is the top-left texel, (0.25, 0.25) the bottom-left.
  expectNear(lookupTexture(pool, ref, 0.25f, 0.75f), Vec3(srgb(10), srgb(20), srgb(30)), 1.0f);
  expectNear(lookupTexture(pool, ref, 0.75f, 0.75f), Vec3(srgb(200), srgb(100), srgb(50)), 0.0f);
  expectNear(lookupTexture(pool, ref, 0.25f, 0.25f), Vec3(0.0f), 1.0f);
  expectNear(lookupTexture(pool, ref, 0.75f, 0.25f), Vec3(1.0f), 128.0f / 255.0f);
}

TEST_F(TextureLookup, BilinearBetweenCentres) {
  // (0.375, 0.625) lies a quarter of the way from the top-left centre to each neighbour.
  const float w00 = 0.75f * 0.75f, w10 = 0.25f * 0.75f, w01 = 0.75f * 0.25f, w11 = 0.25f * 0.25f;
  const Vec3 expected(w00 * srgb(10) + w10 * srgb(200) + w11 * 1.0f,
                      w00 * srgb(20) + w10 * srgb(100) + w11 * 1.0f,
                      w00 * srgb(30) + w10 * srgb(50) + w11 * 1.0f);
  expectNear(lookupTexture(pool, ref, 0.375f, 0.625f), expected,
             w00 + w01 + w11 * 128.0f / 255.0f);
}

TEST_F(TextureLookup, RepeatsInBothDirections) {
  // u = 0 lies halfway between the last column's centre and the first's.
  const Vec3 topMean = 0.5f * (Vec3(srgb(10), srgb(20), srgb(30)) +
                               Vec3(srgb(200), srgb(100), srgb(50)));
  expectNear(lookupTexture(pool, ref, 0.0f, 0.75f), topMean, 0.5f);
  expectNear(lookupTexture(pool, ref, 0.5f, 0.75f), topMean, 0.5f);
  // Far outside [0, 1), as the cat's uvs are.
  expectNear(lookupTexture(pool, ref, 7.25f, -2.25f), Vec3(srgb(10), srgb(20), srgb(30)), 1.0f);
  expectNear(lookupTexture(pool, ref, -0.75f, 3.25f), Vec3(0.0f), 1.0f);
  // NaN coordinates read a texel instead of memory outside the texture.
  const TextureSample s = lookupTexture(pool, ref, NAN, NAN);
  EXPECT_TRUE(std::isfinite(s.rgb.x) && std::isfinite(s.alpha));
}

TEST_F(TextureLookup, ScaleMultipliesUvFirst) {
  ref.scaleU = 2.0f;
  ref.scaleV = -2.0f;
  // (0.125 * 2, 0.375 * -2) = (0.25, -0.75), which repeats to (0.25, 0.25): bottom-left.
  expectNear(lookupTexture(pool, ref, 0.125f, 0.375f), Vec3(0.0f), 1.0f);
  expectNear(lookupTexture(pool, ref, 0.125f, 0.125f), Vec3(srgb(10), srgb(20), srgb(30)), 1.0f);
}

TEST_F(TextureLookup, OffsetAddsAfterTheScale) {
  ref.scaleU = 2.0f;
  ref.offsetU = 0.5f;
  ref.offsetV = -0.5f;
  // (0.375 * 2 + 0.5, 0.25 - 0.5) = (1.25, -0.25), which repeats to (0.25, 0.75): top-left.
  expectNear(lookupTexture(pool, ref, 0.375f, 0.25f), Vec3(srgb(10), srgb(20), srgb(30)), 1.0f);
  expectNear(lookupTexture(pool, ref, 0.125f, 0.25f), Vec3(srgb(200), srgb(100), srgb(50)), 0.0f);
}

TEST_F(TextureLookup, RotationTurnsTheImageCounterClockwise) {
  ref.rotationCos = 0.0f;  // 90 degrees
  ref.rotationSin = 1.0f;
  // Turned a quarter counter-clockwise, the image's top-right texel lies top-left, its top-left
  // bottom-left: the lookup at (u, v) reads the image at (v, -u).
  expectNear(lookupTexture(pool, ref, 0.25f, 0.75f), Vec3(srgb(200), srgb(100), srgb(50)), 0.0f);
  expectNear(lookupTexture(pool, ref, 0.25f, 0.25f), Vec3(srgb(10), srgb(20), srgb(30)), 1.0f);
  expectNear(lookupTexture(pool, ref, 0.75f, 0.25f), Vec3(0.0f), 1.0f);
}

TEST_F(TextureLookup, LinearAndFloatFormats) {
  texture.format = TextureFormat::Linear8;
  expectNear(lookupTexture(pool, ref, 0.25f, 0.75f), Vec3(10.0f, 20.0f, 30.0f) / 255.0f, 1.0f);
  const std::vector<float> floats = {0.5f, 2.0f, 0.0f, 1.0f, 1.5f, 0.0f, 4.0f, 0.5f,
                                     0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f};
  texture.format = TextureFormat::Float;
  pool.texelsF = floats.data();
  expectNear(lookupTexture(pool, ref, 0.5f, 0.75f), Vec3(1.0f, 1.0f, 2.0f), 0.75f);
}

TEST(SphereUv, EquirectangularWithVUp) {
  const auto expectUv = [](const Vec3& d, float u, float v) {
    const Vec2 uv = sphereUv(d);
    EXPECT_NEAR(uv.x, u, 1e-6f) << d.x << " " << d.y << " " << d.z;
    EXPECT_NEAR(uv.y, v, 1e-6f) << d.x << " " << d.y << " " << d.z;
  };
  expectUv(Vec3(0, 0, -1), 0.5f, 0.5f);  // what the default camera sees at the centre
  expectUv(Vec3(1, 0, 0), 0.75f, 0.5f);
  expectUv(Vec3(-1, 0, 0), 0.25f, 0.5f);
  expectUv(Vec3(0, 0, 1), 0.0f, 0.5f);  // the seam, wrapped from 1
  expectUv(Vec3(0, 1, 0), 0.5f, 1.0f);  // top pole
  expectUv(Vec3(0, -1, 0), 0.5f, 0.0f);  // bottom pole: v = 0
  const float s = std::sqrt(0.5f);
  expectUv(Vec3(0, s, -s), 0.5f, 0.75f);
}

// The reader hashes what a texture holds (scene/frame_scene.cpp keeps a frame's pool while the
// hashes stay): two files with the same texels hash alike, a texel or the decoding apart do not.
TEST(TextureHash, FollowsTheContentNotTheFile) {
  test::TempDir dir;
  ASSERT_TRUE(test::writeTestPng(dir.file("a.png"), 3, 1, 3, {1, 2, 3, 4, 5, 6, 7, 8, 9}));
  ASSERT_TRUE(test::writeTestPng(dir.file("b.png"), 3, 1, 3, {1, 2, 3, 4, 5, 6, 7, 8, 9}));
  ASSERT_TRUE(test::writeTestPng(dir.file("c.png"), 3, 1, 3, {1, 2, 3, 4, 5, 6, 7, 8, 10}));
  SceneDesc desc;
  TextureLoader loader(desc.textures, dir.path());
  const auto hash = [&](const std::string& file, TextureUse use) {
    return desc.textures[size_t(loader.load(dir.file(file), use).index)]->contentHash;
  };
  const uint64_t a = hash("a.png", TextureUse::Color);
  EXPECT_EQ(hash("b.png", TextureUse::Color), a);
  EXPECT_NE(hash("c.png", TextureUse::Color), a);
  EXPECT_NE(hash("a.png", TextureUse::Linear), a);  // the same bytes read as linear values
}

// A quad of four positions with a seam (vertex 1's second uv) and a crease (its second normal),
// under the material of `mtl` (an MTL file's text, or "" for the default).
ObjectDesc seamedQuad(const test::TempDir& dir, TextureLoader& loader, const std::string& mtl) {
  if (!mtl.empty()) dir.write("q.mtl", mtl);
  const std::string obj =
      dir.write("q.obj", std::string(mtl.empty() ? "" : "mtllib q.mtl\nusemtl m\n") +
                             "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                             "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0.25 0.7\n"
                             "vn 0 0 1\nvn 0 1 0\n"
                             "f 1/1/1 2/2/1 3/3/1\nf 1/5/1 3/3/1 4/4/1\nf 1/1/2 3/3/1 4/4/1\n");
  ObjectDesc object;
  object.file = obj;
  object.mesh = std::make_shared<const MeshDesc>(loadObjFile(obj, "q.obj", loader));
  return object;
}

// Corners that pair a position with another uv (a seam) or normal become separate vertices.
TEST(ObjUv, VtIsReadAndSeamsSplitVertices) {
  test::TempDir dir;
  SceneDesc desc;
  TextureLoader loader(desc.textures, dir.path());
  ASSERT_TRUE(test::writeTestPng(dir.file("two.png"), 2, 1, 3, {40, 160, 230, 250, 120, 20}));
  const ObjectDesc object = seamedQuad(dir, loader, "newmtl m\nmap_Kd two.png\n");
  const MeshDesc& mesh = *object.mesh;
  ASSERT_EQ(mesh.uvs.size(), 5u);
  EXPECT_EQ(mesh.uvs[4].x, 0.5f);
  EXPECT_EQ(mesh.uvs[4].y, 0.25f);  // the third component is ignored
  EXPECT_EQ(mesh.triangles[1].t[0], 4);
  EXPECT_EQ(mesh.triangles[2].t[0], 0);

  desc.objects.push_back(object);
  const SceneData s = flattenSceneContents(desc);
  ASSERT_EQ(s.uvs.size(), s.positions.size());
  // Vertex 1 (0-based 0) appears with (vt 1, vn 1), (vt 5, vn 1) and (vt 1, vn 2): three vertices.
  EXPECT_EQ(s.positions.size(), 6u);
  ASSERT_EQ(s.triangles.size(), 3u);
  const uint32_t a = s.triangles[0].v[0], b = s.triangles[1].v[0], c = s.triangles[2].v[0];
  EXPECT_NE(a, b);
  EXPECT_NE(a, c);
  EXPECT_NE(b, c);
  for (uint32_t v : {a, b, c}) EXPECT_EQ(s.positions[v].x, 0.0f);
  EXPECT_EQ(s.uvs[a].x, 0.0f);
  EXPECT_EQ(s.uvs[b].x, 0.5f);
  EXPECT_EQ(s.uvs[b].y, 0.25f);
  EXPECT_EQ(s.uvs[c].x, 0.0f);
  // Shared corners with equal attributes stay shared.
  EXPECT_EQ(s.triangles[0].v[2], s.triangles[1].v[1]);
  const GeometryView g = s.view();
  const Vec2 mid = triangleUv(g, s.triangles[0], 0.5f, 0.25f);  // b0 = 0.25
  EXPECT_FLOAT_EQ(mid.x, 0.75f);  // 0.25 * 0 + 0.5 * 1 + 0.25 * 1
  EXPECT_FLOAT_EQ(mid.y, 0.25f);  // 0.25 * 0 + 0.5 * 0 + 0.25 * 1
}

// Uvs that no material of the object reads (no texture, no alpha mask) are left out, and split no
// vertices at seams: only the crease splits one. A textured material set on the object in the
// scene takes them again.
TEST(ObjUv, UvsThatNoMaterialReadsSplitNoVertices) {
  test::TempDir dir;
  SceneDesc desc;
  TextureLoader loader(desc.textures, dir.path());
  desc.objects.push_back(seamedQuad(dir, loader, ""));
  const SceneData plain = flattenSceneContents(desc);
  EXPECT_TRUE(plain.uvs.empty());
  EXPECT_EQ(plain.positions.size(), 5u);  // vertex 1 with vn 1 and with vn 2

  ASSERT_TRUE(test::writeTestPng(dir.file("two.png"), 2, 1, 3, {40, 160, 230, 250, 120, 20}));
  Material textured;
  textured.colorTexture.index = loader.load(dir.file("two.png"), TextureUse::Color).index;
  ASSERT_GE(textured.colorTexture.index, 0);
  desc.objects[0].material = textured;
  const SceneData seamed = flattenSceneContents(desc);
  EXPECT_EQ(seamed.positions.size(), 6u);
  EXPECT_EQ(seamed.uvs.size(), 6u);
}

// two.png, a 2x1 texture, and quad.obj, a quad of uvs [0,1]^2 facing +z that spans x in [-1, 1]
// (`header`: lines before its vertices, `use` before its face), both in `dir`. Returns the start
// of a camera (the caller adds its spp) that sees the quad through two pixel columns, one on
// each texel's centre (fov 30 at distance 1 / tan(15 deg)).
std::string writeTwoTexelQuad(const test::TempDir& dir, const std::string& header = "",
                              const std::string& use = "") {
  EXPECT_TRUE(test::writeTestPng(dir.file("two.png"), 2, 1, 3, {40, 160, 230, 250, 120, 20}));
  dir.write("quad.obj", header + "v -1 -9 0\nv 1 -9 0\nv 1 9 0\nv -1 9 0\nvt 0 0\nvt 1 0\n" +
                            "vt 1 1\nvt 0 1\n" + use + "f 1/1 2/2 3/3 4/4\n");
  return R"("camera": {"width": 2, "height": 16, "fov": 30, "position": [0, 0, 3.7320508],)";
}

// The linear colours of two.png's texels.
const float kTwoLeft[3] = {srgb(40), srgb(160), srgb(230)};
const float kTwoRight[3] = {srgb(250), srgb(120), srgb(20)};

// A quad of uvs [0,1]^2 textured by a 2x1 image, seen through exactly two pixel columns whose
// centres fall on the two texel centres (u = 0.25 and 0.75), under a uniform white environment
// with max_depth 1: each column's radiance is its texel's albedo.
TEST(TextureRender, QuadShowsEachTexelsAlbedoInAFurnace) {
  test::TempDir dir;
  const std::string json = "{" + writeTwoTexelQuad(dir) + R"( "spp": 2048},
    "render": {"max_depth": 1, "antialiasing": false},
    "objects": [{"file": "quad.obj", "color": {"texture": "two.png"}}],
    "environment": {"color": 1}
  })";
  const RenderResult r = test::renderTestScene(json, 0, dir.path());
  for (int c = 0; c < 3; ++c) {
    const test::RegionStats l = test::regionStats(r.image, 0, 0, 1, 16, c);
    const test::RegionStats rr = test::regionStats(r.image, 1, 0, 2, 16, c);
    EXPECT_NEAR(l.mean, kTwoLeft[c], 4 * l.standardError() + 2e-3) << "channel " << c;
    EXPECT_NEAR(rr.mean, kTwoRight[c], 4 * rr.standardError() + 2e-3) << "channel " << c;
  }
}

// An MTL map_Ke makes the face an emitter whose radiance is Ke times the texture: seen directly,
// each texel's column shows 2 x its colour.
TEST(TextureRender, MapKeEmitsTheTextureSeenDirectly) {
  test::TempDir dir;
  dir.write("lamp.mtl", "newmtl lamp\nKe 2 2 2\nmap_Ke two.png\n");
  const std::string json = "{" + writeTwoTexelQuad(dir, "mtllib lamp.mtl\n", "usemtl lamp\n") +
                           R"( "spp": 4},
    "render": {"max_depth": 1, "antialiasing": false},
    "objects": [{"file": "quad.obj"}]
  })";
  const RenderResult r = test::renderTestScene(json, 0, dir.path());
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(test::regionStats(r.image, 0, 0, 1, 16, c).mean, 2 * kTwoLeft[c], 1e-5) << c;
    EXPECT_NEAR(test::regionStats(r.image, 1, 0, 2, 16, c).mean, 2 * kTwoRight[c], 1e-5) << c;
  }
}

// As a light, a textured emitter (a 2x1 texture across a ceiling quad) lights a floor as two
// untextured quads of its two colours do: the same radiance at every point, so the same image up
// to noise. This checks the light samples' texture lookups and the texture's share in the power.
TEST(TextureRender, MapKeLightsLikeTheSameColoursUntextured) {
  test::TempDir dir;
  ASSERT_TRUE(test::writeTestPng(dir.file("two.png"), 2, 1, 3, {255, 60, 0, 0, 60, 255}));
  dir.write("lamp.mtl", "newmtl lamp\nKe 3 3 3\nmap_Ke two.png\n");
  // The ceiling at y = 2, facing down (counter-clockwise seen from below), u along x.
  dir.write("textured.obj",
            "mtllib lamp.mtl\nv -1 2 -1\nv 1 2 -1\nv 1 2 1\nv -1 2 1\nvt 0 0\nvt 1 0\nvt 1 1\n"
            "vt 0 1\nusemtl lamp\nf 1/1 2/2 3/3 4/4\n");
  const float red[3] = {srgb(255), srgb(60), srgb(0)}, blue[3] = {srgb(0), srgb(60), srgb(255)};
  const auto quad = [](float x0, float x1) {
    return "v " + std::to_string(x0) + " 2 -1\nv " + std::to_string(x1) + " 2 -1\nv " +
           std::to_string(x1) + " 2 1\nv " + std::to_string(x0) + " 2 1\nf 1 2 3 4\n";
  };
  dir.write("left.obj", quad(-1, 0));
  dir.write("right.obj", quad(0, 1));
  const auto rgb = [](const float c[3]) {
    return "[" + std::to_string(3 * c[0]) + ", " + std::to_string(3 * c[1]) + ", " +
           std::to_string(3 * c[2]) + "]";
  };
  const std::string common = R"("camera": {"width": 32, "height": 32, "fov": 60,
      "position": [0, 1.2, 3], "look_at": [0, 0, 0], "spp": 256},
    "render": {"max_depth": 1}, "spheres": [{"position": [0, -1000, 0], "radius": 1000}],)";
  const RenderResult textured = test::renderTestScene(
      "{" + common + R"("objects": [{"file": "textured.obj"}]})", 0, dir.path());
  const RenderResult plain = test::renderTestScene(
      "{" + common + R"("objects": [{"file": "left.obj", "material": {"type": "emissive",
      "radiance": )" + rgb(red) + R"(}}, {"file": "right.obj", "material": {"type": "emissive",
      "radiance": )" + rgb(blue) + "}}]}",
      0, dir.path());
  // The floor's left and right halves (below the horizon line of the ceiling's view).
  for (uint32_t x0 : {0u, 16u})
    for (int c = 0; c < 3; ++c) {
      const test::RegionStats a = test::regionStats(textured.image, x0, 20, x0 + 16, 32, c);
      const test::RegionStats b = test::regionStats(plain.image, x0, 20, x0 + 16, 32, c);
      EXPECT_GT(b.mean, 0.0);
      EXPECT_NEAR(a.mean, b.mean, 4 * std::hypot(a.standardError(), b.standardError()) + 1e-4)
          << "half at " << x0 << ", channel " << c;
    }
}

std::string loadError(const std::string& json, const std::string& baseDir) {
  try {
    parseSceneText(json, "scene.json", baseDir);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no SceneError)";
}

TEST(TextureErrors, JsonMessagesNameThePath) {
  test::TempDir dir;
  ASSERT_TRUE(test::writeTestPng(dir.file("ok.png"), 1, 1, 3, {1, 2, 3}));
  const auto scene = [](const std::string& material) {
    return R"({"camera": {}, "spheres": [{"position": [0, 0, 0], "radius": 1, "material": )" +
           material + "}]}";
  };
  const std::string missing = loadError(
      scene(R"({"type": "diffuse", "color": {"texture": "wood.png"}})"), dir.path());
  EXPECT_EQ(missing.rfind("scene.json: spheres[0].material.color.texture: cannot read the texture: ",
                          0),
            0u)
      << missing;
  EXPECT_NE(missing.find("wood.png"), std::string::npos) << missing;
  // A file of another kind is named with every format a texture may be.
  EXPECT_EQ(
      loadError(scene(R"({"type": "diffuse", "color": {"texture": "wood.json"}})"), dir.path()),
      "scene.json: spheres[0].material.color.texture: cannot read the texture: " +
          dir.file("wood.json") +
          ": unsupported image format '.json', expected .png, .jpg, .jpeg, .webp, .exr, .pfm or "
          ".hdr");
  EXPECT_EQ(loadError(scene(R"({"type": "diffuse", "color": {"texture": "ok.png", "scale": [1, 0]}})"),
                      dir.path()),
            "scene.json: spheres[0].material.color.scale[1]: expected a finite, non-zero number, "
            "got 0");
  EXPECT_EQ(loadError(scene(R"({"type": "diffuse", "color": {"texture": "ok.png", "scale": 2}})"),
                      dir.path()),
            "scene.json: spheres[0].material.color.scale: expected an array of 2 finite, non-zero "
            "numbers, got 2");
  EXPECT_EQ(loadError(scene(R"({"type": "glass", "color": {"texture": "ok.png"}})"), dir.path()),
            "scene.json: spheres[0].material.color: a texture on a field that takes none (expected "
            "a number or an array of 3 numbers)");
  EXPECT_EQ(loadError(scene(R"({"type": "emissive", "radiance": {"texture": "ok.png", "a": 1}})"),
                      dir.path()),
            "scene.json: spheres[0].material.radiance.a: unknown key, expected one of \"texture\", "
            "\"checkerboard\", \"scale\", \"offset\", \"rotation\", \"wrap\", \"filter\"");
}

TEST(TextureErrors, MtlMessagesNameFileAndLine) {
  test::TempDir dir;
  SceneDesc desc;
  TextureLoader loader(desc.textures, dir.path());
  const std::string obj =
      dir.write("m.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n");
  const auto error = [&](const std::string& mtl) -> std::string {
    dir.write("m.mtl", mtl);
    try {
      loadObjFile(obj, "meshes/m.obj", loader);
    } catch (const SceneError& e) {
      return e.what();
    }
    return "(no SceneError)";
  };
  const std::string missing = error("newmtl a\nKd 1 1 1\nmap_d mask.png\n");
  EXPECT_EQ(missing.rfind("meshes/m.mtl:3: cannot read the texture: ", 0), 0u) << missing;
  EXPECT_NE(missing.find("mask.png"), std::string::npos) << missing;
  EXPECT_EQ(error("newmtl a\nd 1.5\n"), "meshes/m.mtl:2: expected d between 0 and 1, got \"1.5\"");
  EXPECT_EQ(error("newmtl a\nmap_Kd -o a.png\n"), "meshes/m.mtl:2: map_Kd -o: expected an offset");
  EXPECT_EQ(error("newmtl a\nmap_Kd -o inf a.png\n"),
            "meshes/m.mtl:2: map_Kd -o: expected finite offsets, got \"inf\"");
  EXPECT_EQ(error("newmtl a\n\nTr x\n"), "meshes/m.mtl:3: expected Tr between 0 and 1, got \"x\"");
  EXPECT_EQ(error("newmtl a\nmap_Kd -mm 0 1 a.png\n"),
            "meshes/m.mtl:2: map_Kd option \"-mm\" is not supported (only -s, -o and -clamp)");
  EXPECT_EQ(error("newmtl a\nmap_Kd -clamp yes a.png\n"),
            "meshes/m.mtl:2: map_Kd -clamp: expected on or off, got \"yes\"");
  dir.write("bad.png", "not a png");
  const std::string unreadable = error("newmtl a\nmap_Kd bad.png\n");
  EXPECT_EQ(unreadable.rfind("meshes/m.mtl:2: cannot read the texture: ", 0), 0u) << unreadable;
}

// Each file is read once per use; -s scales (v as u where only u is given), -o offsets (v 0
// where only u is given; w not used) and -clamp on clamps.
TEST(TextureLoading, EachFileOnceWithScaleAndOffsetFromMtl) {
  test::TempDir dir;
  ASSERT_TRUE(test::writeTestPng(dir.file("t.png"), 1, 1, 4, {1, 2, 3, 4}));
  ASSERT_TRUE(test::writeTestPng(dir.file("g.png"), 1, 1, 1, {7}));
  dir.write("m.mtl",
            "newmtl a\nmap_Kd -s 2 3 1 -clamp on -o 0.25 0.5 1 t.png\nmap_d t.png\nnewmtl b\n"
            "Kd 0.5 0.5 0.5\nmap_Kd -clamp off -o 0.75 ./t.png\nTr 0.25\nmap_d g.png\n");
  const std::string obj = dir.write(
      "m.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\nusemtl b\nf 1 3 2\n");
  SceneDesc desc;
  TextureLoader loader(desc.textures, dir.path());
  const MeshDesc mesh = loadObjFile(obj, "m.obj", loader);
  ASSERT_EQ(mesh.materials.size(), 2u);
  const Material& a = mesh.materials[0];
  const Material& b = mesh.materials[1];
  // t.png as a colour (sRGB) once, as a mask (linear) once, g.png as a mask.
  ASSERT_EQ(desc.textures.size(), 3u);
  EXPECT_EQ(a.colorTexture.index, b.colorTexture.index);
  EXPECT_EQ(desc.textures[size_t(a.colorTexture.index)]->format, TextureFormat::Srgb8);
  EXPECT_EQ(a.colorTexture.scaleU, 2.0f);
  EXPECT_EQ(a.colorTexture.scaleV, 3.0f);
  EXPECT_EQ(a.colorTexture.offsetU, 0.25f);
  EXPECT_EQ(a.colorTexture.offsetV, 0.5f);
  EXPECT_EQ(b.colorTexture.scaleU, 1.0f);
  EXPECT_EQ(b.colorTexture.offsetU, 0.75f);
  EXPECT_EQ(b.colorTexture.offsetV, 0.0f);
  // -clamp on holds the edge texels beyond [0, 1]; off (the default) repeats.
  EXPECT_EQ(a.colorTexture.wrapS, TextureWrap::Clamp);
  EXPECT_EQ(a.colorTexture.wrapT, TextureWrap::Clamp);
  EXPECT_EQ(b.colorTexture.wrapS, TextureWrap::Repeat);
  EXPECT_EQ(a.alpha.texture.wrapS, TextureWrap::Repeat);
  EXPECT_EQ(a.color.x, 1.0f);  // no Kd: the texture alone
  EXPECT_EQ(b.color.x, 0.5f);  // Kd tints the texture
  EXPECT_EQ(a.alpha.channel, 3u);  // t.png has an alpha channel
  EXPECT_EQ(desc.textures[size_t(a.alpha.texture.index)]->format, TextureFormat::Linear8);
  EXPECT_EQ(b.alpha.channel, 0u);  // g.png has none: its grey is the mask
  EXPECT_FLOAT_EQ(b.alpha.constant, 0.75f);
}

// JSON's "offset" shifts where the image starts, after the scale (MTL's -o: above).
TEST(TextureLoading, OffsetsFromJson) {
  test::TempDir dir;
  ASSERT_TRUE(test::writeTestPng(dir.file("t.png"), 1, 1, 3, {1, 2, 3}));
  const SceneData data = test::loadTestScene(R"({"camera": {}, "spheres": [{"position": [0, 0, 0],
      "radius": 1, "material": {"type": "diffuse", "color": {"texture": "t.png",
      "scale": [2, 3], "offset": [0.25, -1.5]}}}]})",
                                             dir.path());
  EXPECT_EQ(data.materials[0].colorTexture.offsetU, 0.25f);
  EXPECT_EQ(data.materials[0].colorTexture.offsetV, -1.5f);
  EXPECT_EQ(loadError(R"({"camera": {}, "spheres": [{"position": [0, 0, 0], "radius": 1,
      "material": {"type": "diffuse", "color": {"texture": "t.png", "offset": [1]}}}]})",
                      dir.path()),
            "scene.json: spheres[0].material.color.offset: expected an array of 2 finite numbers, "
            "got an array [1]");
}

TEST(TextureLoading, SixteenBitPngKeepsItsPrecision) {
  test::TempDir dir;
  // Two RGBA texels; 0x8000 is 0.500008 where an 8-bit file can say 0.498 or 0.502.
  ASSERT_TRUE(test::writeTestPng16(dir.file("t16.png"), 2, 1, 4,
                                   {0x8000, 0x0101, 0xffff, 0x4000, 0, 0x1234, 0xfedc, 0xffff}));
  ASSERT_TRUE(test::writeTestPng16(dir.file("g16.png"), 1, 1, 1, {0x8000}));
  SceneDesc desc;
  TextureLoader loader(desc.textures, dir.path());
  const LoadedTexture colour = loader.load(dir.file("t16.png"), TextureUse::Color);
  const LoadedTexture mask = loader.load(dir.file("t16.png"), TextureUse::Linear);
  const LoadedTexture grey = loader.load(dir.file("g16.png"), TextureUse::Linear);
  EXPECT_TRUE(colour.hasAlpha);
  EXPECT_FALSE(grey.hasAlpha);
  const TextureDesc& c = *desc.textures[size_t(colour.index)];
  const TextureDesc& m = *desc.textures[size_t(mask.index)];
  const TextureDesc& g = *desc.textures[size_t(grey.index)];
  for (const TextureDesc* t : {&c, &m, &g}) EXPECT_EQ(t->format, TextureFormat::Float);
  ASSERT_EQ(c.texelsF.size(), 8u);
  const auto unit = [](uint16_t v) { return float(v) / 65535.0f; };
  // Colour channels from sRGB, alpha linear.
  EXPECT_NEAR(c.texelsF[0], srgbToLinearValue(unit(0x8000)), 1e-7f);
  EXPECT_NEAR(c.texelsF[0], 0.214048f, 2e-6f);  // sRGB 0.500008 (8-bit 128 gives 0.215861)
  EXPECT_NEAR(c.texelsF[1], unit(0x0101) / 12.92f, 1e-9f);
  EXPECT_FLOAT_EQ(c.texelsF[2], 1.0f);
  EXPECT_NEAR(c.texelsF[3], unit(0x4000), 1e-7f);
  EXPECT_NEAR(c.texelsF[5], srgbToLinearValue(unit(0x1234)), 1e-7f);
  EXPECT_FLOAT_EQ(c.texelsF[7], 1.0f);
  // A mask reads every channel linearly; a grey file fills R, G and B, alpha 1.
  EXPECT_NEAR(m.texelsF[0], unit(0x8000), 1e-7f);
  EXPECT_NEAR(m.texelsF[6], unit(0xfedc), 1e-7f);
  ASSERT_EQ(g.texelsF.size(), 4u);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(g.texelsF[size_t(i)], unit(0x8000), 1e-7f);
  EXPECT_FLOAT_EQ(g.texelsF[3], 1.0f);
}

// The command line: a bad texture exits 2 with one line and writes nothing.
TEST(TextureCli, MissingTextureExitsTwoAndWritesNothing) {
  test::TempDir dir;
  dir.write("s.json", R"({"camera": {"width": 4, "height": 4},
    "spheres": [{"position": [0, 0, -3], "radius": 1, "color": {"texture": "gone.png"}}]})");
  const std::string command = "cd '" + dir.path() + "' && '" + CANDELA_BINARY +
                              "' render s.json -o out.png > /dev/null 2> err.txt";
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  std::ifstream in(dir.file("err.txt"));
  std::string line, rest;
  std::getline(in, line);
  EXPECT_FALSE(std::getline(in, rest)) << "one line only";
  EXPECT_EQ(line.rfind("candela: error: s.json: spheres[0].color.texture: cannot read the texture",
                       0),
            0u)
      << line;
  EXPECT_FALSE(std::filesystem::exists(dir.file("out.png")));
}

}  // namespace
}  // namespace candela
