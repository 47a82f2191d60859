// tinyobjloader's code, compiled here so that the sanitizers and the fuzzer's coverage see inside
// it: the system's libtinyobjloader is not instrumented. The executable's definitions take the
// place of the shared library's.
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
