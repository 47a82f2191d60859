// Image files: float round trips, PFM orientation, the 8-bit encoding formulas, PNG bytes on
// disk, and the failure guarantees of writeImage (no partial file, no stray temporary file).
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "image/atomic_file.h"
#include "image/image_io.h"

#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_ONLY_PNG
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wshadow"
#endif
#include <stb/stb_image.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace fs = std::filesystem;

namespace candela {
namespace {

// A fresh, empty directory per test, removed afterwards.
class ImageIoTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("candela_image_io_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  // Every entry of the directory, to catch stray temporary files.
  std::vector<std::string> listing() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir_))
      names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

  fs::path dir_;
};

// Distinct, awkward values in every channel: fractions, tiny, huge, negative, zero.
ImageRGB testImage(uint32_t w, uint32_t h) {
  ImageRGB image(w, h);
  for (size_t i = 0; i < image.pixels.size(); ++i)
    image.pixels[i] =
        float(i) * 0.1f - 1.0f + (i % 7 == 0 ? 1e-30f : 0.0f) + (i % 11 == 0 ? 3.4e30f : 0.0f);
  return image;
}

void expectSamePixels(const ImageRGB& a, const ImageRGB& b) {
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  for (size_t i = 0; i < a.pixels.size(); ++i) ASSERT_EQ(a.pixels[i], b.pixels[i]) << "at " << i;
}

TEST_F(ImageIoTest, PfmRoundTripIsExact) {
  const ImageRGB image = testImage(7, 5);
  writeImage(path("a.pfm"), image, OutputDesc{});
  expectSamePixels(image, readImage(path("a.pfm")));
}

TEST_F(ImageIoTest, ExrRoundTripIsExact) {
  const ImageRGB image = testImage(9, 4);
  writeImage(path("a.exr"), image, OutputDesc{});
  expectSamePixels(image, readImage(path("a.exr")));
}

TEST_F(ImageIoTest, PfmHeaderAndBottomToTopRows) {
  ImageRGB image(2, 2);
  image.set(0, 0, Vec3(1, 2, 3));  // top-left
  image.set(1, 1, Vec3(4, 5, 6));  // bottom-right
  writeImage(path("o.pfm"), image, OutputDesc{});

  std::ifstream in(path("o.pfm"), std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string header = "PF\n2 2\n-1.0\n";
  ASSERT_EQ(bytes.size(), header.size() + 2 * 2 * 3 * 4);
  EXPECT_EQ(bytes.substr(0, header.size()), header);
  // The first stored row is the bottom one: its second pixel is the bottom-right (4, 5, 6),
  // and the file is little-endian.
  float first[6];
  std::memcpy(first, bytes.data() + header.size(), sizeof first);
  EXPECT_EQ(first[3], 4.0f);
  EXPECT_EQ(first[5], 6.0f);

  const ImageRGB back = readImage(path("o.pfm"));
  EXPECT_EQ(back.at(0, 0).x, 1.0f);
  EXPECT_EQ(back.at(0, 0).z, 3.0f);
  EXPECT_EQ(back.at(1, 1).y, 5.0f);
}

// The contract's formulas, computed independently of the implementation.
uint8_t expectedPower(double l, double gamma, double exposure) {
  const double v = std::min(1.0, std::max(0.0, l * std::pow(2.0, exposure)));
  return uint8_t(std::floor(std::pow(v, 1.0 / gamma) * 255.0 + 0.5));
}

uint8_t expectedSrgb(double l) {
  const double v = std::min(1.0, std::max(0.0, l));
  const double e = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055;
  return uint8_t(std::floor(e * 255.0 + 0.5));
}

const float kSamples[] = {0.0f, 1e-6f, 0.001f, 0.0031308f, 0.01f, 0.18f,
                          0.5f, 0.73f, 0.999f, 1.0f,       1.5f,  1e10f};

TEST(Encode8bit, Gamma22) {
  OutputDesc out;  // gamma 2.2, no exposure
  for (float l : kSamples) EXPECT_EQ(encode8bit(l, out), expectedPower(l, out.gamma, 0)) << l;
  EXPECT_EQ(encode8bit(0.0f, out), 0);
  EXPECT_EQ(encode8bit(1.0f, out), 255);
  EXPECT_EQ(encode8bit(7.0f, out), 255);  // clamped
  EXPECT_EQ(encode8bit(-3.0f, out), 0);
  EXPECT_EQ(encode8bit(0.5f, out), 186);  // 0.5^(1/2.2) * 255 = 186.08
}

TEST(Encode8bit, OtherGamma) {
  OutputDesc out;
  out.gamma = 1.0f;
  EXPECT_EQ(encode8bit(0.5f, out), 128);  // 127.5 rounds up
  out.gamma = 2.4f;
  for (float l : kSamples) EXPECT_EQ(encode8bit(l, out), expectedPower(l, out.gamma, 0)) << l;
}

TEST(Encode8bit, Srgb) {
  OutputDesc out;
  out.curve = GammaCurve::Srgb;
  for (float l : kSamples) EXPECT_EQ(encode8bit(l, out), expectedSrgb(l)) << l;
  EXPECT_EQ(encode8bit(0.002f, out), 7);   // linear segment: 0.02584 * 255 = 6.59
  EXPECT_EQ(encode8bit(0.18f, out), 118);  // mid grey
  EXPECT_EQ(encode8bit(2.0f, out), 255);
}

// Tone maps bring every exposed value into [0, 1] by their curves, before the display curve:
// Reinhard's v / (1 + v), and the ACES fit, which passes 1 at v = 7.24 (2.51 / 2.43 > 1, so it is
// clamped).
TEST(Encode8bit, ToneMaps) {
  OutputDesc out;
  out.toneMap = ToneMap::Reinhard;
  for (float l : kSamples) EXPECT_EQ(encode8bit(l, out), expectedPower(l / (1.0 + l), 2.2, 0)) << l;
  EXPECT_EQ(encode8bit(1.0f, out), expectedPower(0.5, 2.2, 0));
  EXPECT_LT(encode8bit(30.0f, out), 255);  // 30 / 31 = 0.968: still below white
  out.exposure = 1.0f;                     // the exposure comes first: 0.5 is 1, which maps to 0.5
  EXPECT_EQ(encode8bit(0.5f, out), expectedPower(0.5, 2.2, 0));

  out = OutputDesc{};
  out.toneMap = ToneMap::Aces;
  out.curve = GammaCurve::Srgb;
  const auto aces = [](double v) {
    return std::min(1.0, v * (2.51 * v + 0.03) / (v * (2.43 * v + 0.59) + 0.14));
  };
  for (float l : kSamples) EXPECT_EQ(encode8bit(l, out), expectedSrgb(aces(l))) << l;
  EXPECT_EQ(encode8bit(0.18f, out), 141);  // aces 0.2669, in sRGB 0.5531: 141.04
  EXPECT_EQ(encode8bit(5.0f, out), 253);   // aces 0.9853
  EXPECT_EQ(encode8bit(10.0f, out), 255);  // aces 1.009, clamped
  EXPECT_EQ(encode8bit(1e30f, out), 255);
  EXPECT_EQ(encode8bit(std::numeric_limits<float>::infinity(), out), 255);
  EXPECT_EQ(encode8bit(std::nanf(""), out), 0);
}

TEST(Encode8bit, Exposure) {
  OutputDesc out;
  out.exposure = 1.0f;  // one stop brighter: 0.25 encodes like 0.5
  EXPECT_EQ(encode8bit(0.25f, out), expectedPower(0.5, out.gamma, 0));
  EXPECT_EQ(encode8bit(0.6f, out), 255);  // 1.2 clamps
  out.exposure = -2.0f;
  for (float l : kSamples) EXPECT_EQ(encode8bit(l, out), expectedPower(l, out.gamma, -2)) << l;
}

TEST(Encode8bit, SeedConventionExposure) {
  // The contract: -17.59 stops (= -2.2 log2 255) makes the seed's white, 255^2.2, about 1.
  OutputDesc out;
  out.exposure = -17.59f;
  const float seedWhite = float(std::pow(255.0, 2.2));
  EXPECT_NEAR(seedWhite * std::exp2(-17.59), 1.0, 0.005);
  EXPECT_EQ(encode8bit(seedWhite, out), 255);
  // The seed's value for L was min(255, L^(1/2.2)); they agree to within one level.
  for (double seedValue : {10.0, 64.0, 128.0, 200.0, 254.0}) {
    const float l = float(std::pow(seedValue, 2.2));
    EXPECT_NEAR(encode8bit(l, out), seedValue, 1.0) << seedValue;
  }
}

TEST_F(ImageIoTest, PngDecodesToTheEncodedBytes) {
  ImageRGB image(3, 2);
  for (size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = float(i) / 5.0f - 0.1f;
  OutputDesc out;
  out.curve = GammaCurve::Srgb;
  out.exposure = 0.5f;
  writeImage(path("p.png"), image, out);

  int w = 0, h = 0, n = 0;
  unsigned char* data = stbi_load(path("p.png").c_str(), &w, &h, &n, 0);
  ASSERT_NE(data, nullptr);
  EXPECT_EQ(w, 3);
  EXPECT_EQ(h, 2);
  EXPECT_EQ(n, 3);
  for (size_t i = 0; i < image.pixels.size(); ++i)
    EXPECT_EQ(data[i], encode8bit(image.pixels[i], out)) << "at " << i;
  stbi_image_free(data);
}

TEST_F(ImageIoTest, MissingDirectoryFailsAndLeavesNothing) {
  const std::string target = path("no/such/dir/x.png");
  try {
    writeImage(target, testImage(2, 2), OutputDesc{});
    FAIL() << "expected ImageWriteError";
  } catch (const ImageWriteError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(target), std::string::npos) << message;
    EXPECT_NE(message.find("does not exist"), std::string::npos) << message;
  }
  EXPECT_TRUE(listing().empty());
  // A file where the folder should be is named as such.
  std::ofstream(path("file")) << "x";
  try {
    writeImage(path("file/x.png"), testImage(2, 2), OutputDesc{});
    FAIL() << "expected ImageWriteError";
  } catch (const ImageWriteError& e) {
    EXPECT_EQ(std::string(e.what()),
              path("file/x.png") + ": '" + path("file") + "' is not a folder");
  }
}

TEST_F(ImageIoTest, UnwritableTargetFailsAndLeavesNoTemporaryFile) {
  // The target is an existing directory, so the final rename fails after the temporary file
  // was written: the temporary file must be cleaned up.
  fs::create_directories(path("taken.png"));
  EXPECT_THROW(writeImage(path("taken.png"), testImage(2, 2), OutputDesc{}), ImageWriteError);
  EXPECT_EQ(listing(), std::vector<std::string>{"taken.png"});
}

TEST_F(ImageIoTest, NoTemporaryFileAfterSuccess) {
  for (const char* name : {"a.png", "a.exr", "a.pfm"}) writeImage(path(name), testImage(4, 3), {});
  writeImage(path("a.pfm"), testImage(5, 5), {});  // replacing an existing file
  EXPECT_EQ(listing(), (std::vector<std::string>{"a.exr", "a.pfm", "a.png"}));
  EXPECT_EQ(readImage(path("a.pfm")).width, 5u);
}

// Files that appear together or not at all: nothing is in place before commit, and a staged file
// that is never committed leaves nothing behind.
TEST_F(ImageIoTest, StagedFilesAppearOnlyWhenCommitted) {
  {
    StagedFile a(path("a.json"), "{}");
    StagedFile b(path("b.png"), "png");
    EXPECT_FALSE(fs::exists(path("a.json")));
    a.commit();
    EXPECT_TRUE(fs::exists(path("a.json")));
  }  // b is dropped uncommitted
  EXPECT_EQ(listing(), std::vector<std::string>{"a.json"});
}

TEST_F(ImageIoTest, WritingThroughALinkKeepsTheLink) {
  writeFileAtomically(path("real.txt"), "old");
  fs::create_symlink("real.txt", path("link.txt"));
  writeFileAtomically(path("link.txt"), "new");
  EXPECT_TRUE(fs::is_symlink(path("link.txt")));
  EXPECT_EQ(readFileBytes(path("real.txt")), "new");
}

TEST_F(ImageIoTest, UnsupportedExtensionIsRejected) {
  EXPECT_TRUE(isSupportedImagePath("x.png"));
  EXPECT_TRUE(isSupportedImagePath("dir.v2/x.EXR"));
  EXPECT_TRUE(isSupportedImagePath("x.Pfm"));
  EXPECT_FALSE(isSupportedImagePath("x.bmp"));
  EXPECT_FALSE(isSupportedImagePath("png"));
  EXPECT_FALSE(isSupportedImagePath("dir.png/x"));
  try {
    writeImage(path("x.bmp"), testImage(2, 2), OutputDesc{});
    FAIL() << "expected ImageWriteError";
  } catch (const ImageWriteError& e) {
    EXPECT_NE(std::string(e.what()).find("unsupported image format '.bmp'"), std::string::npos)
        << e.what();
  }
  EXPECT_TRUE(listing().empty());
  EXPECT_THROW(readImage(path("x.png")), ImageWriteError);
}

TEST_F(ImageIoTest, ReadingGarbageFails) {
  std::ofstream(path("bad.pfm")) << "P6\n1 1\n255\nxyz";
  std::ofstream(path("short.pfm")) << "PF\n4 4\n-1.0\nabc";
  std::ofstream(path("bad.exr")) << "not an exr";
  EXPECT_THROW(readImage(path("bad.pfm")), ImageWriteError);
  EXPECT_THROW(readImage(path("short.pfm")), ImageWriteError);
  EXPECT_THROW(readImage(path("bad.exr")), ImageWriteError);
  EXPECT_THROW(readImage(path("missing.pfm")), ImageWriteError);
}

TEST_F(ImageIoTest, APfmWiderThanItsLimitSaysSo) {
  std::ofstream(path("wide.pfm")) << "PF\n1100000 1\n-1.0\n";
  try {
    readImage(path("wide.pfm"));
    FAIL() << "no error";
  } catch (const ImageWriteError& e) {
    EXPECT_NE(std::string(e.what()).find("1100000 x 1 pixels: at most 1048576 a side"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace candela
