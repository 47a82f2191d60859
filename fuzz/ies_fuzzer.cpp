// libFuzzer target: the input is an IES file, the profile of a spot light in a fixed small scene.
// See docs/fuzzing.md.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_scene.h"

namespace {

const char* const kScene = R"({
  "camera": {"width": 8, "height": 8, "fov": 60, "position": [0, 0, 5], "look_at": [0, 0, 0]},
  "spheres": [{"position": [0, 0, 0], "radius": 1}, {"position": [0, -1001, 0], "radius": 1000}],
  "lights": [{"type": "spot", "position": [1, 3, 1], "look_at": [0, 0, 0], "intensity": 10,
              "cutoff_angle": 170, "profile": "m.ies", "up": [1, 0, 0]}]
})";

std::string folder;  // makeInputFolder's

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  candela::fuzz::limitToOneThread();
  folder = candela::fuzz::makeInputFolder("ies", {"m.ies"});
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  candela::fuzz::writeInput(folder + "/m.ies", data, size);
  candela::fuzz::loadAndTrace(kScene, folder);
  return 0;
}
