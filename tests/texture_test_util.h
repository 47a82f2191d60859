// Helpers for texture tests: small images written into a temporary folder (tests/temp_dir.h).
#pragma once

#include <gtest/gtest.h>

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

}  // namespace candela::test
