// The version `candela --version` prints.
#pragma once

namespace candela::cli {

#ifdef CANDELA_VERSION
inline constexpr const char* kVersion = CANDELA_VERSION;
#else
// Keep in step with project(candela VERSION ...) in CMakeLists.txt.
inline constexpr const char* kVersion = "0.1.0";
#endif

}  // namespace candela::cli
