// Whole-file reading; see text_file.h.
#include "scene/read/text_file.h"

#include <cerrno>
#include <cstdio>
#include <system_error>

#include "core/input_file.h"

namespace candela {

static std::string describeErrno(int error) {
  return std::error_code(error, std::generic_category()).message();
}

bool readTextFile(const std::string& path, std::string* contents, std::string* reason) {
  *reason = inputFileProblem(path);
  if (!reason->empty()) return false;
  errno = 0;
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (file == nullptr) {
    *reason = describeErrno(errno != 0 ? errno : ENOENT);
    return false;
  }
  std::string data;
  char buffer[1 << 16];
  size_t count = 0;
  while ((count = std::fread(buffer, 1, sizeof buffer, file)) > 0) {
    data.append(buffer, count);
    if (data.size() > kMaxInputFileBytes) {  // it grew while being read
      std::fclose(file);
      *reason = "larger than an input file may be";
      return false;
    }
  }
  // A directory opens fine on POSIX and only fails here, with EISDIR.
  const bool failed = std::ferror(file) != 0;
  const int error = errno;
  std::fclose(file);
  if (failed) {
    *reason = describeErrno(error != 0 ? error : EIO);
    return false;
  }
  *contents = std::move(data);
  return true;
}

}  // namespace candela
