// ffmpeg invocation for `candela render --video`; see video.h.
#include "apps/cli/video.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <vector>

#include "apps/cli/cli_error.h"

extern char** environ;

namespace candela::cli {

std::string findOnPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  if (!path) return "";
  const std::string dirs = path;
  size_t start = 0;
  while (start <= dirs.size()) {
    size_t end = dirs.find(':', start);
    if (end == std::string::npos) end = dirs.size();
    const std::string dir = end > start ? dirs.substr(start, end - start) : ".";
    const std::string candidate = dir + "/" + program;
    if (::access(candidate.c_str(), X_OK) == 0 && !std::filesystem::is_directory(candidate))
      return candidate;
    start = end + 1;
  }
  return "";
}

namespace {

// ffmpeg takes an argument that starts with '-' for an option and one that starts with "name:"
// for a URL of that protocol; the file protocol's URL is the path, whatever it holds.
std::string fileUrl(const std::string& path) { return "file:" + path; }

// The image2 demuxer's pattern of the frame names: a '%' of the folder's name is written "%%".
std::string framePattern(const std::string& folder, int digits) {
  std::string escaped;
  for (const char c : folder) escaped += c == '%' ? std::string("%%") : std::string(1, c);
  return (std::filesystem::path(escaped) / ("frame_%0" + std::to_string(digits) + "d.png"))
      .string();
}

}  // namespace

void encodeVideo(const VideoJob& job) {
  const std::string ffmpeg = findOnPath("ffmpeg");
  if (ffmpeg.empty())
    throw CliError(kExitFailure,
                   "--video " + job.output +
                       ": ffmpeg was not found on PATH, so no video was made (the frames are "
                       "kept). Install it (Debian/Ubuntu: apt-get install ffmpeg; macOS: brew "
                       "install ffmpeg) and run the same command again: existing frames are "
                       "skipped, so only the video is made");
  const std::filesystem::path parent = std::filesystem::path(job.output).parent_path();
  std::error_code ec;
  if (!parent.empty()) std::filesystem::create_directories(parent, ec);

  char fps[32];
  std::snprintf(fps, sizeof fps, "%.9g", job.fps);
  const std::vector<std::string> args = {
      ffmpeg, "-hide_banner", "-loglevel", "error", "-y", "-framerate", fps, "-start_number",
      std::to_string(job.first), "-f", "image2", "-pattern_type", "sequence", "-i",
      fileUrl(framePattern(job.folder, job.digits)), "-frames:v", std::to_string(job.count),
      // yuv420p needs even sizes: round each down to even (a 1-pixel crop at most).
      "-vf", "scale=trunc(iw/2)*2:trunc(ih/2)*2", "-c:v", "libx264", "-pix_fmt", "yuv420p",
      fileUrl(job.output)};
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);

  pid_t pid = 0;
  if (posix_spawn(&pid, ffmpeg.c_str(), nullptr, nullptr, argv.data(), environ) != 0)
    throw CliError(kExitFailure, "--video " + job.output + ": cannot run " + ffmpeg);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw CliError(kExitFailure, "--video " + job.output + ": ffmpeg failed (see its message "
                                 "above); the frames are kept");
}

}  // namespace candela::cli
