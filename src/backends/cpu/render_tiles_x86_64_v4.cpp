// The render loop compiled for x86-64-v4: CMakeLists.txt gives this file -march=x86-64-v4
// -fno-weak, and backends/cpu/tile_renderer.h says why. Only CPUs with AVX-512 run it.
#include "backends/cpu/render_tiles.h"

#if !defined(__AVX512VL__)
#error "render_tiles_x86_64_v4.cpp is built with -march=x86-64-v4 (CMakeLists.txt)"
#endif

namespace candela {

TileRenderer x86_64V4TileRenderer() { return tileRendererOfThisFile("x86-64-v4"); }

}  // namespace candela
