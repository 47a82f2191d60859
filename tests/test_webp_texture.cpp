// WebP textures (image/webp_decode.cpp): a lossless file, encoded by libwebp's own encoder, reads
// back as its texels (RGBA and RGB), as a scene's texture it is the same texture as the PNG of the
// same texels, glTF's EXT_texture_webp is read in place of its fallback source, and a file that is
// not WebP inside is refused with its name; a build without libwebp refuses WebP by name.
#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "gltf_material_test_util.h"
#include "image/image_io.h"
#include "scene/read/texture_reader.h"
#include "scene/scene_error.h"
#include "temp_dir.h"
#include "texture_test_util.h"

#ifdef CANDELA_HAS_WEBP
#include <webp/encode.h>
#endif

namespace candela {
namespace {

using test::TempDir;

#ifdef CANDELA_HAS_WEBP
// A lossless WebP of `rgba` (4 bytes a texel, rows from the top), or of its RGB where !alpha.
std::string losslessWebp(int width, int height, const std::vector<uint8_t>& rgba, bool alpha) {
  uint8_t* out = nullptr;
  size_t size = 0;
  if (alpha) {
    size = WebPEncodeLosslessRGBA(rgba.data(), width, height, 4 * width, &out);
  } else {
    std::vector<uint8_t> rgb;
    for (size_t i = 0; i < rgba.size(); ++i)
      if (i % 4 != 3) rgb.push_back(rgba[i]);
    size = WebPEncodeLosslessRGB(rgb.data(), width, height, 3 * width, &out);
  }
  std::string bytes(reinterpret_cast<const char*>(out), size);
  WebPFree(out);
  EXPECT_GT(size, 0u);
  return bytes;
}

const std::vector<uint8_t> kRgba = {10, 200, 40, 255, 250, 100, 160, 128,
                                    0,  0,   0,  0,   255, 255, 255, 255};

TEST(WebpTexture, ALosslessFileReadsAsItsTexels) {
  ASSERT_TRUE(webpDecoding());
  TempDir dir;
  const ImageRgba rgba = readImageRgba(dir.write("a.webp", losslessWebp(2, 2, kRgba, true)));
  EXPECT_EQ(rgba.width, 2u);
  EXPECT_EQ(rgba.height, 2u);
  EXPECT_EQ(rgba.channels, 4u);
  EXPECT_EQ(rgba.bits, 8u);
  EXPECT_EQ(rgba.pixels8, kRgba);
  // Without alpha: three channels, every texel opaque.
  const ImageRgba rgb = readImageRgba(dir.write("b.WEBP", losslessWebp(2, 2, kRgba, false)));
  EXPECT_EQ(rgb.channels, 3u);
  for (size_t i = 0; i < kRgba.size(); ++i)
    EXPECT_EQ(rgb.pixels8[i], i % 4 == 3 ? 255 : kRgba[i]) << i;
  // Its bytes held in memory, as a glTF file's buffer view holds them.
  EXPECT_EQ(decodeImageRgbaBytes(losslessWebp(2, 2, kRgba, true), "m.glb").pixels8, kRgba);
}

TEST(WebpTexture, AsASceneTextureItIsThePngOfItsTexels) {
  TempDir dir;
  dir.write("t.webp", losslessWebp(2, 2, kRgba, true));
  ASSERT_TRUE(test::writeTestPng(dir.file("t.png"), 2, 2, 4, kRgba));
  std::vector<std::shared_ptr<const TextureDesc>> textures;
  TextureLoader loader(textures, dir.path());
  for (const TextureUse use : {TextureUse::Color, TextureUse::Linear}) {
    const LoadedTexture webp = loader.load(dir.file("t.webp"), use);
    const LoadedTexture png = loader.load(dir.file("t.png"), use);
    EXPECT_TRUE(webp.hasAlpha);
    const TextureDesc& a = *textures.at(size_t(webp.index));
    const TextureDesc& b = *textures.at(size_t(png.index));
    EXPECT_EQ(a.format, b.format);
    EXPECT_EQ(a.texels8, b.texels8);
    EXPECT_EQ(a.texelsF, b.texelsF);
  }
}

// EXT_texture_webp: the WebP image in place of the texture's fallback PNG source.
TEST(WebpTexture, GltfReadsTheWebpSourceBeforeItsFallback) {
  TempDir dir;
  nlohmann::json m = test::pbr(0, 0.5);
  m["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
  test::GltfFile f = test::quad(nlohmann::json::array({m}));
  f.addImage(test::pngBytes(dir));  // image 0: the PNG fallback, test::kTexels
  const std::string webp = losslessWebp(2, 2, kRgba, true);
  f.addImage(webp);
  f.doc["images"][1]["mimeType"] = "image/webp";
  f.doc["textures"] = nlohmann::json::array(
      {nlohmann::json{{"source", 0}, {"extensions", {{"EXT_texture_webp", {{"source", 1}}}}}}});
  f.doc["extensionsUsed"] = {"EXT_texture_webp"};
  const auto loaded = test::load(dir.write("w.glb", f.glb()));
  const Material& plastic = loaded->mesh.materials.at(0);
  const TextureDesc& t = *loaded->textures.at(size_t(plastic.colorTexture.index));
  EXPECT_EQ(t.width, 2u);
  EXPECT_EQ(t.height, 2u);  // the WebP's size, not the fallback's 2 x 1
  // Without a fallback, as a file that requires the extension writes it.
  f.doc["textures"][0].erase("source");
  f.doc["extensionsRequired"] = {"EXT_texture_webp"};
  const auto required = test::load(dir.write("r.glb", f.glb()));
  EXPECT_EQ(required->textures.at(0)->height, 2u);
  // The WebP image's bytes broken: refused under the image's path.
  f.doc["textures"][0]["extensions"]["EXT_texture_webp"]["source"] = 0;
  f.doc["images"][0]["mimeType"] = "image/webp";
  f.buffer.replace(f.buffer.find("\x89PNG"), 4, "RIFF");
  try {
    test::load(dir.write("b.glb", f.glb()));
    ADD_FAILURE() << "no error";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("images[0]: "), std::string::npos) << e.what();
  }
}

TEST(WebpTexture, AFileThatIsNotWebpInsideIsRefusedByName) {
  TempDir dir;
  std::string broken = losslessWebp(2, 2, kRgba, true);
  broken.resize(broken.size() / 2);
  try {
    readImageRgba(dir.write("cut.webp", broken));
    ADD_FAILURE() << "no error";
  } catch (const ImageWriteError& e) {
    EXPECT_EQ(std::string(e.what()),
              dir.file("cut.webp") + ": not a readable WebP image (its pixels)");
  }
}
#endif

TEST(WebpTexture, ABuildWithoutLibwebpRefusesWebpByName) {
  if (webpDecoding()) GTEST_SKIP() << "this build reads WebP (the tests above)";
  TempDir dir;
  try {
    readImageRgba(dir.write("a.webp", std::string("RIFF\x10\0\0\0WEBPVP8L", 16)));
    ADD_FAILURE() << "no error";
  } catch (const ImageWriteError& e) {
    EXPECT_EQ(std::string(e.what()), dir.file("a.webp") +
                                         ": a WebP image, and this build of candela reads none "
                                         "(built without libwebp-dev)");
  }
}

}  // namespace
}  // namespace candela
