// Helpers for texture tests: small images written into a temporary folder (tests/temp_dir.h).
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/vec3.h"
#include "temp_dir.h"

namespace candela::test {

// Writes an 8-bit PNG of `channels` (1 to 4) channels, rows from the top; defined in
// test_textures.cpp (the tests' one stb_image_write).
bool writeTestPng(const std::string& path, int width, int height, int channels,
                  const std::vector<uint8_t>& bytes);

// The same with 16 bits a channel (`samples` as the values, rows from the top).
bool writeTestPng16(const std::string& path, int width, int height, int channels,
                    const std::vector<uint16_t>& samples);

// Writes a float PFM of `texels` ([r, g, b] each) in one row, left to right.
inline void writeRowPfm(const std::filesystem::path& path, const std::vector<Vec3>& texels) {
  std::ofstream pfm(path, std::ios::binary);
  pfm << "PF\n" << texels.size() << " 1\n-1\n";
  for (const Vec3& t : texels) {
    const float texel[3] = {t.x, t.y, t.z};
    pfm.write(reinterpret_cast<const char*>(texel), sizeof texel);
  }
}

// Expects an image of a texture of two stripes (`textured`, RGB floats) to render each pixel as
// one of the two images of the stripes' values alone (`first`, `second`) does, to rounding, but
// where the lookup blends a stripe's edge, and each in many pixels; the two must differ in every
// pixel by more than `apart` of first's red and green.
inline void expectEachPixelAsOneStripe(const std::vector<float>& textured,
                                       const std::vector<float>& first,
                                       const std::vector<float>& second, float apart) {
  ASSERT_EQ(textured.size(), first.size());
  ASSERT_EQ(textured.size(), second.size());
  int asFirst = 0, asSecond = 0;
  for (size_t i = 0; i < textured.size(); i += 3) {
    ASSERT_GT(std::fabs(first[i] - second[i]) + std::fabs(first[i + 1] - second[i + 1]),
              apart * (first[i] + first[i + 1]))
        << "pixel " << i / 3;
    bool isFirst = true, isSecond = true;
    for (int c = 0; c < 3; ++c) {
      isFirst &= std::fabs(textured[i + c] - first[i + c]) <= 1e-5f * first[i + c] + 1e-7f;
      isSecond &= std::fabs(textured[i + c] - second[i + c]) <= 1e-5f * second[i + c] + 1e-7f;
    }
    asFirst += isFirst;
    asSecond += isSecond;
  }
  // 24 columns over 1.2 repeats of 8 texels: three eighths of a repeat in each stripe's middle.
  const int pixels = int(textured.size() / 3);
  EXPECT_GT(asFirst, pixels / 4);
  EXPECT_GT(asSecond, pixels / 4);
  EXPECT_GT(asFirst + asSecond, pixels * 6 / 10);
}

}  // namespace candela::test
