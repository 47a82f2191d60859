// Helpers for texture tests: a temporary folder and small images written into it.
#pragma once

#include <gtest/gtest.h>
#include <stdlib.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace candela::test {

// Writes an 8-bit PNG of `channels` (1 to 4) channels, rows from the top; defined in
// test_textures.cpp (the tests' one stb_image_write).
bool writeTestPng(const std::string& path, int width, int height, int channels,
                  const std::vector<uint8_t>& bytes);

// A fresh folder under the system's temp folder, removed with everything in it at the end.
class TextureDir {
 public:
  TextureDir() {
    std::string pattern = (std::filesystem::temp_directory_path() / "candela-tex-XXXXXX").string();
    path_ = mkdtemp(pattern.data());
  }
  ~TextureDir() { std::filesystem::remove_all(path_); }
  std::string path() const { return path_.string(); }
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  std::string write(const std::string& name, const std::string& contents) const {
    std::ofstream(path_ / name, std::ios::binary) << contents;
    return file(name);
  }

 private:
  std::filesystem::path path_;
};

}  // namespace candela::test
