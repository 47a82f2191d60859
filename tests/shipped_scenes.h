// The scene files the project ships (scenes/ and scenes/examples/), for tests that must hold on
// every one of them.
#pragma once

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace candela::test {

inline std::vector<std::string> shippedScenes() {
  std::vector<std::string> files;
  for (const char* folder : {"/scenes", "/scenes/examples"})
    for (const std::filesystem::directory_entry& e :
         std::filesystem::directory_iterator(std::string(CANDELA_SOURCE_DIR) + folder))
      if (e.path().extension() == ".json") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace candela::test
