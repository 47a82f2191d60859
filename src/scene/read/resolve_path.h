// A file as a scene or a file it reads names it: relative to `folder` (the naming file's) unless
// absolute.
#pragma once

#include <filesystem>
#include <string>

namespace candela {

inline std::string resolvePath(const std::string& written, const std::string& folder) {
  const std::filesystem::path path(written);
  return path.is_absolute() ? written : (std::filesystem::path(folder) / path).string();
}

}  // namespace candela
