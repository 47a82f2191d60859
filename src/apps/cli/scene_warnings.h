// The scene's warnings (SceneDesc::warnings: what its files leave to a default that their author
// may not have meant), one "candela: warning: ..." line each on stderr, as errors are printed.
#pragma once

#include <cstdio>
#include <string>

#include "scene/scene_desc.h"

namespace candela::cli {

inline void printSceneWarnings(const SceneDesc& desc) {
  for (const std::string& warning : desc.warnings)
    std::fprintf(stderr, "candela: warning: %s\n", warning.c_str());
}

}  // namespace candela::cli
