// What an input file (scene, mesh, material library, image) must be before it is read: a
// regular file, of at most kMaxInputFileBytes. A FIFO would block the reader forever and a device
// such as /dev/zero fill memory; a directory or a socket is no file to read. Host only.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <system_error>

namespace candela {

// Generous for real meshes and maps (8 M triangles of OBJ text are about 0.5 GiB), finite for
// anything else.
constexpr uint64_t kMaxInputFileBytes = uint64_t(4) << 30;

// Why `path` cannot be read as an input file, or "" when it can (or does not exist: opening it
// then says so).
inline std::string inputFileProblem(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (error || status.type() == fs::file_type::not_found) return "";
  if (status.type() == fs::file_type::directory) return "Is a directory";  // as the system says
  if (status.type() != fs::file_type::regular)
    return "not a regular file: a pipe, socket or device cannot be read as one";
  const uintmax_t size = fs::file_size(path, error);
  if (!error && size > kMaxInputFileBytes)
    return std::to_string(size >> 20) + " MiB, larger than the " +
           std::to_string(kMaxInputFileBytes >> 30) + " GiB an input file may be";
  return "";
}

}  // namespace candela
