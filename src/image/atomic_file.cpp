// Whole-file I/O for image files: temporary file + fsync + rename, and whole-file reads.
#include "image/atomic_file.h"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#if defined(_WIN32)
#include <process.h>
#define CANDELA_GETPID _getpid
#else
#include <signal.h>
#include <unistd.h>
#define CANDELA_GETPID getpid
#endif

#include "core/input_file.h"
#include "image/image_io.h"

namespace fs = std::filesystem;

namespace candela {

namespace {

// Unique per process and per call, so concurrent writers never share a temporary file.
std::string temporaryPathFor(const fs::path& target) {
  static std::atomic<unsigned> counter{0};
  const std::string name = "." + target.filename().string() + ".tmp-" +
                           std::to_string(CANDELA_GETPID()) + "-" + std::to_string(counter++);
  return (target.parent_path() / name).string();
}

[[noreturn]] void fail(const std::string& path, const std::string& reason) {
  throw ImageWriteError(path + ": " + reason);
}

// Writes all bytes and makes them durable before the rename publishes them.
bool writeAndSync(std::FILE* file, const std::string& bytes) {
  if (std::fwrite(bytes.data(), 1, bytes.size(), file) != bytes.size()) return false;
  if (std::fflush(file) != 0) return false;
#if !defined(_WIN32)
  if (fsync(fileno(file)) != 0) return false;
#endif
  return true;
}

// The file a symbolic link points to, so that the rename replaces that file and keeps the link.
std::string followLink(const std::string& path) {
  std::error_code error;
  if (!fs::is_symlink(path, error)) return path;
  const fs::path target = fs::weakly_canonical(path, error);
  return error ? path : target.string();
}

}  // namespace

StagedFile::StagedFile(const std::string& path, const std::string& bytes)
    : path_(path), target_(followLink(path)) {
  const fs::path target(target_);
  if (target.filename().empty()) fail(path, "not a file name");
  const fs::path dir = target.parent_path();
  std::error_code ec;
  if (!dir.empty() && !fs::is_directory(dir, ec))
    fail(path, fs::exists(dir, ec) ? "'" + dir.string() + "' is not a folder"
                                   : "directory '" + dir.string() + "' does not exist");

  const std::string temp = temporaryPathFor(target);
  std::FILE* file = std::fopen(temp.c_str(), "wb");
  if (!file)
    fail(path, std::string("cannot create a file in that directory: ") + std::strerror(errno));
  const bool written = writeAndSync(file, bytes);
  const int writeErrno = errno;
  if (std::fclose(file) != 0 || !written) {
    const int err = written ? errno : writeErrno;
    std::remove(temp.c_str());
    fail(path, std::string("write failed: ") + std::strerror(err));
  }
  temp_ = temp;
}

StagedFile::~StagedFile() {
  if (!temp_.empty()) std::remove(temp_.c_str());
}

void StagedFile::commit() {
  if (std::rename(temp_.c_str(), target_.c_str()) != 0) {
    const int err = errno;
    std::remove(temp_.c_str());
    temp_.clear();
    fail(path_, std::string("cannot replace the file: ") + std::strerror(err));
  }
  temp_.clear();
}

void writeFileAtomically(const std::string& path, const std::string& bytes) {
  StagedFile(path, bytes).commit();
}

size_t removeStaleTemporaryFiles(const std::string& dir) {
  std::error_code error;
  size_t removed = 0;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir, error)) {
    const std::string name = entry.path().filename().string();
    const size_t tmp = name.rfind(".tmp-");
    if (name.empty() || name[0] != '.' || tmp == std::string::npos) continue;
    const size_t dash = name.find('-', tmp + 5);
    if (dash == std::string::npos) continue;
    const std::string pid = name.substr(tmp + 5, dash - tmp - 5);
    if (pid.empty() || pid.size() > 9 || pid.find_first_not_of("0123456789") != std::string::npos)
      continue;
#if !defined(_WIN32)
    // kill(pid, 0) probes without signalling: ESRCH means no such process.
    if (kill(pid_t(std::stol(pid)), 0) == 0 || errno != ESRCH) continue;
#endif
    if (fs::remove(entry.path(), error)) ++removed;
  }
  return removed;
}

std::string readFileBytes(const std::string& path) {
  const std::string problem = inputFileProblem(path);
  if (!problem.empty()) fail(path, problem);
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, std::string("cannot open: ") + std::strerror(errno));
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (in.bad()) fail(path, "read failed");
  return bytes.str();
}

}  // namespace candela
