// libFuzzer target: the input is a IES file, the profile of a spot light in a fixed small scene.
// See docs/fuzzing.md.
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
  "spheres": [{"position": [0, 0, 0], "radius": 1}, {"position": [0, -1001, 0], "radius": 1000}],
  "lights": [{"type": "spot", "position": [1, 3, 1], "look_at": [0, 0, 0], "intensity": 10,
              "cutoff_angle": 170, "profile": "m.ies", "up": [1, 0, 0]}]
})";

std::string folder;  // this process's own, so that parallel jobs never share files

void removeFolder() {
  std::remove((folder + "/m.ies").c_str());
  rmdir(folder.c_str());
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  candela::fuzz::limitToOneThread();
  char pattern[] = "/tmp/candela-ies-fuzz-XXXXXX";
  if (!mkdtemp(pattern)) std::abort();
  folder = pattern;
  std::atexit(removeFolder);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::FILE* file = std::fopen((folder + "/m.ies").c_str(), "wb");
  if (!file) std::abort();
  std::fwrite(data, 1, size, file);
  std::fclose(file);
  candela::fuzz::loadAndTrace(kScene, folder);
  return 0;
}
