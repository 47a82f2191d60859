// Which EXR channels an image read takes (environment maps and float textures): R, G and B, a
// grey file's Y alone or its luminance-chroma (Y, RY, BY), and a clear refusal of anything else
// (an EXR of depth alone rendered as a black sky before).
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <ImfRgbaFile.h>
#include <ImfTiledOutputFile.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "image/image_io.h"
#include "temp_dir.h"

namespace candela {
namespace {

constexpr int kWidth = 5, kHeight = 3;

// A file of FLOAT channels `names`, channel c of pixel i holding value(c, i).
void writeChannels(const std::string& path, const std::vector<std::string>& names) {
  Imf::Header header(kWidth, kHeight);
  std::vector<std::vector<float>> planes;
  for (size_t c = 0; c < names.size(); ++c) {
    header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
    planes.emplace_back(kWidth * kHeight);
    for (int i = 0; i < kWidth * kHeight; ++i) planes[c][i] = 0.25f * float(c + 1) + 0.01f * i;
  }
  Imf::FrameBuffer frame;
  for (size_t c = 0; c < names.size(); ++c)
    frame.insert(names[c], Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(planes[c].data()),
                                      sizeof(float), sizeof(float) * kWidth));
  Imf::OutputFile file(path.c_str(), header);
  file.setFrameBuffer(frame);
  file.writePixels(kHeight);
}

std::string errorOf(const std::string& path) {
  try {
    readImage(path);
  } catch (const ImageWriteError& e) {
    return e.what();
  }
  return "no error";
}

TEST(ExrChannels, YAloneIsGrey) {
  const test::TempDir dir;
  const std::string path = dir.file("grey.exr");
  writeChannels(path, {"Y"});
  const ImageRGB image = readImage(path);
  ASSERT_EQ(image.width, uint32_t(kWidth));
  ASSERT_EQ(image.height, uint32_t(kHeight));
  for (int i = 0; i < kWidth * kHeight; ++i)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(image.pixels[3 * i + c], 0.25f + 0.01f * i) << i;
}

TEST(ExrChannels, RgbIsReadWhateverElseTheFileHolds) {
  const test::TempDir dir;
  const std::string path = dir.file("rgba.exr");
  writeChannels(path, {"R", "G", "B", "A", "Y"});
  const ImageRGB image = readImage(path);
  for (int i = 0; i < kWidth * kHeight; ++i)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(image.pixels[3 * i + c], 0.25f * (c + 1) + 0.01f * i);
}

TEST(ExrChannels, LuminanceChromaIsConvertedToRgb) {
  const test::TempDir dir;
  const std::string path = dir.file("yc.exr");
  const Imf::Rgba colour(0.8f, 0.4f, 0.1f, 1.0f);
  const int width = 6, height = 4;  // chroma is subsampled 2 x 2
  std::vector<Imf::Rgba> pixels(width * height, colour);
  {
    Imf::RgbaOutputFile file(path.c_str(), width, height, Imf::WRITE_YC);
    file.setFrameBuffer(pixels.data(), 1, width);
    file.writePixels(height);
  }
  const ImageRGB image = readImage(path);
  ASSERT_EQ(image.width, uint32_t(width));
  ASSERT_EQ(image.height, uint32_t(height));
  // Halves, and the colour through luminance and two chroma ratios (the file keeps those to a
  // few of their bits): within 2% a channel.
  for (int i = 0; i < width * height; ++i) {
    EXPECT_NEAR(image.pixels[3 * i], 0.8f, 0.016f) << i;
    EXPECT_NEAR(image.pixels[3 * i + 1], 0.4f, 0.008f) << i;
    EXPECT_NEAR(image.pixels[3 * i + 2], 0.1f, 0.002f) << i;
  }
}

// Files are read in bands of rows on several threads: every lossless compression, scanlines or
// tiles, and a data window that does not start at (0, 0), read back exactly, band edges included.
TEST(ExrChannels, BandsOfRowsReadEveryCompressionAndLayout) {
  const test::TempDir dir;
  const int width = 7, height = 600;  // three bands of 256 rows
  const Imath::Box2i window(Imath::V2i(3, -7), Imath::V2i(3 + width - 1, -7 + height - 1));
  std::vector<float> planes[3];
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < width * height; ++i) planes[c].push_back(float(c) + 1e-3f * float(i));
  const auto frameOf = [&] {
    Imf::FrameBuffer frame;
    for (int c = 0; c < 3; ++c)
      frame.insert(std::string(1, "RGB"[c]),
                   Imf::Slice::Make(Imf::FLOAT, planes[c].data(), window, sizeof(float),
                                    sizeof(float) * width));
    return frame;
  };
  const auto headerOf = [&](Imf::Compression compression) {
    Imf::Header header(window, window);
    header.compression() = compression;
    for (const char* name : {"R", "G", "B"})
      header.channels().insert(name, Imf::Channel(Imf::FLOAT));
    return header;
  };
  const auto expectExact = [&](const std::string& path) {
    const ImageRGB image = readImage(path);
    ASSERT_EQ(image.width, uint32_t(width));
    ASSERT_EQ(image.height, uint32_t(height));
    for (int i = 0; i < width * height; ++i)
      for (int c = 0; c < 3; ++c)
        ASSERT_EQ(image.pixels[3 * i + c], planes[c][i]) << path << " " << i;
  };
  for (const Imf::Compression compression :
       {Imf::NO_COMPRESSION, Imf::RLE_COMPRESSION, Imf::ZIPS_COMPRESSION, Imf::ZIP_COMPRESSION,
        Imf::PIZ_COMPRESSION}) {
    const std::string path = dir.file("scan" + std::to_string(int(compression)) + ".exr");
    {
      Imf::OutputFile file(path.c_str(), headerOf(compression));
      file.setFrameBuffer(frameOf());
      file.writePixels(height);
    }
    expectExact(path);
  }
  const std::string tiled = dir.file("tiled.exr");
  {
    Imf::Header header = headerOf(Imf::ZIP_COMPRESSION);
    header.setTileDescription(Imf::TileDescription(64, 64, Imf::ONE_LEVEL));
    Imf::TiledOutputFile file(tiled.c_str(), header);
    file.setFrameBuffer(frameOf());
    file.writeTiles(0, file.numXTiles() - 1, 0, file.numYTiles() - 1);
  }
  expectExact(tiled);
}

TEST(ExrChannels, OtherChannelsAreRefusedByName) {
  const test::TempDir dir;
  const std::string expected = "expected the channels R, G and B (or Y, for a grey image), got ";
  const struct {
    std::string file;
    std::vector<std::string> channels;
    std::string named;
  } cases[] = {{"depth.exr", {"Z"}, "Z"},
               {"layers.exr", {"beauty.R", "beauty.G", "beauty.B"}, "beauty.B, beauty.G, beauty.R"},
               {"red.exr", {"R", "G"}, "G, R"}};
  for (const auto& c : cases) {
    writeChannels(dir.file(c.file), c.channels);
    const std::string message = errorOf(dir.file(c.file));
    // The path leads the message, as every image error's does.
    EXPECT_EQ(message, dir.file(c.file) + ": " + expected + c.named);
  }
}

}  // namespace
}  // namespace candela
