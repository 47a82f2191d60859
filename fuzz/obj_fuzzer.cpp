// libFuzzer target: the input is an OBJ file, optionally followed by a line "#--mtl--" and the
// text of the MTL file "m.mtl" beside it; a fixed small scene renders it. See docs/fuzzing.md.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_scene.h"

namespace {

const char* const kScene = R"({
  "camera": {"width": 8, "height": 8, "fov": 60, "position": [0, 0, 5], "look_at": [0, 0, 0]},
  "lights": [{"position": [1, 2, 5], "intensity": 10}],
  "objects": [{"file": "m.obj", "rotation": [10, 20, 30]}]
})";

std::string folder;  // makeInputFolder's

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  candela::fuzz::limitToOneThread();
  folder = candela::fuzz::makeInputFolder("obj", {"m.obj", "m.mtl"});
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  const std::string separator = "#--mtl--\n";
  const size_t split = input.find(separator);
  const std::string obj = input.substr(0, split);
  const std::string mtl = split == std::string::npos ? "" : input.substr(split + separator.size());
  candela::fuzz::writeInput(folder + "/m.obj", obj.data(), obj.size());
  candela::fuzz::writeInput(folder + "/m.mtl", mtl.data(), mtl.size());
  candela::fuzz::loadAndTrace(kScene, folder);
  return 0;
}
