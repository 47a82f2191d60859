// Encoding rendered frames into a video with ffmpeg (optional; found on PATH when installed).
#pragma once

#include <string>

namespace candela::cli {

// The full path of `program` on PATH, or "" when it is not there.
std::string findOnPath(const std::string& program);

struct VideoJob {
  std::string folder;   // of the frames, named frame_0000.png, ...
  int digits = 4;       // of the frame numbers in their names
  unsigned first = 0;   // number of the first frame
  unsigned count = 0;   // frames to encode
  double fps = 24;
  std::string output;   // e.g. "orbit.mp4"
};

// Runs ffmpeg: H.264 in yuv420p (plays everywhere), odd sizes scaled down to even ones as
// yuv420p requires. Whatever their names, the folder and the output reach ffmpeg as file names:
// never as options (a leading '-'), protocols ("name:") or frame number patterns ('%'). Throws
// CliError (exit 1) when ffmpeg is missing, with how to install it, or when it fails; the frames
// are never touched.
void encodeVideo(const VideoJob& job);

}  // namespace candela::cli
