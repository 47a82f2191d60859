// The render loop compiled for the build's own target (backends/cpu/tile_renderer.h).
#include "backends/cpu/render_tiles.h"

namespace candela {

TileRenderer baselineTileRenderer() {
#if defined(__x86_64__)
  return tileRendererOfThisFile("x86-64");
#else
  return tileRendererOfThisFile("baseline");
#endif
}

}  // namespace candela
