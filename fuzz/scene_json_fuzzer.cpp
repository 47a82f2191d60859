// libFuzzer target: the input is a scene file's JSON text, with relative paths resolved from
// scenes/examples/, so that the seed scenes' meshes and sky are found. See docs/fuzzing.md.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_scene.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  candela::fuzz::limitToOneThread();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  candela::fuzz::loadAndTrace(std::string(reinterpret_cast<const char*>(data), size),
                              CANDELA_SOURCE_DIR "/scenes/examples");
  return 0;
}
