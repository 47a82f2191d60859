// libFuzzer target: the input is a PLY file, rendered by a fixed small scene. See docs/fuzzing.md.
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
  "objects": [{"file": "m.ply", "rotation": [10, 20, 30], "smooth": 60}]
})";

std::string folder;  // this process's own, so that parallel jobs never share files

void removeFolder() {
  std::remove((folder + "/m.ply").c_str());
  rmdir(folder.c_str());
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  candela::fuzz::limitToOneThread();
  char pattern[] = "/tmp/candela-ply-fuzz-XXXXXX";
  if (!mkdtemp(pattern)) std::abort();
  folder = pattern;
  std::atexit(removeFolder);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::FILE* file = std::fopen((folder + "/m.ply").c_str(), "wb");
  if (!file) std::abort();
  std::fwrite(data, 1, size, file);
  std::fclose(file);
  candela::fuzz::loadAndTrace(kScene, folder);
  return 0;
}
