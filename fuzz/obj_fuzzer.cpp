// libFuzzer target: the input is an OBJ file, optionally followed by a line "#--mtl--" and the
// text of the MTL file "m.mtl" beside it; a fixed small scene renders it. See docs/fuzzing.md.
#include <stdlib.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "fuzz_scene.h"

namespace {

const char* const kScene = R"({
  "camera": {"width": 8, "height": 8, "fov": 60, "position": [0, 0, 5], "look_at": [0, 0, 0]},
  "lights": [{"position": [1, 2, 5], "intensity": 10}],
  "objects": [{"file": "m.obj", "rotation": [10, 20, 30]}]
})";

std::string folder;  // this process's own, so that parallel jobs never share files

void writeFile(const std::string& name, const std::string& text) {
  std::FILE* file = std::fopen((folder + "/" + name).c_str(), "wb");
  if (!file) std::abort();
  std::fwrite(text.data(), 1, text.size(), file);
  std::fclose(file);
}

void removeFolder() {
  for (const char* name : {"/m.obj", "/m.mtl"}) std::remove((folder + name).c_str());
  rmdir(folder.c_str());
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  candela::fuzz::limitToOneThread();
  char pattern[] = "/tmp/candela-obj-fuzz-XXXXXX";
  if (!mkdtemp(pattern)) std::abort();
  folder = pattern;
  std::atexit(removeFolder);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  const std::string separator = "#--mtl--\n";
  const size_t split = input.find(separator);
  writeFile("m.obj", input.substr(0, split));
  writeFile("m.mtl", split == std::string::npos ? "" : input.substr(split + separator.size()));
  candela::fuzz::loadAndTrace(kScene, folder);
  return 0;
}
