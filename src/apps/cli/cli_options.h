// Parsed command-line options of the subcommands, and the validators they share.
#pragma once

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "backends/renderer.h"

namespace candela::cli {

// `candela render`; an absent optional keeps the scene file's value.
struct RenderCommandOptions {
  std::vector<std::string> scenes;  // one still, one animation, or a sequence of stills
  std::string output;  // image file, or a folder for a sequence; empty: under out/
  std::optional<uint32_t> spp;
  std::optional<uint64_t> seed;
  std::optional<uint32_t> maxDepth;
  std::string crop;  // --crop X,Y,W,H: that part of the image (CameraDesc::crop); empty: all
  int threads = 0;  // 0: all cores
  Backend backend = Backend::Auto;
  CpuEngine cpuEngine = CpuEngine::Auto;
  bool quiet = false;
  std::string stats;  // --stats FILE.json: write the render's measured figures (stills only)
  std::string aovs;    // --aov depth,normal,...: render passes (docs/aovs.md); empty: none
  bool denoise = false;  // --denoise: Open Image Denoise on the image (apps/cli/oidn_denoiser.h)
  bool noBvh = false;  // --no-bvh: brute force over all primitives (benchmarks only)
  // --frame N: frame N of the scene's animation block as one image, as a still renders
  std::optional<uint32_t> frame;
  // Sequences only (see sequence_command.h); `sequenceOptionGiven` says whether any was set.
  std::string format;               // png, exr or pfm; empty: png
  std::string frames;               // "A:B", start inclusive, end exclusive; empty: all
  bool overwrite = false;           // re-render frames that already exist
  std::string video;                // encode the frames to this file with ffmpeg
  std::optional<double> fps;        // video frame rate; default: the animation's, else 24
  bool sequenceOptionGiven() const { return sequenceOptionName() != nullptr; }
  // The first sequence option given, as spelled on the command line; null if none was.
  const char* sequenceOptionName() const {
    if (!format.empty()) return "--format";
    if (!frames.empty()) return "--frames";
    if (overwrite) return "--overwrite";
    if (!video.empty()) return "--video";
    if (fps.has_value()) return "--fps";
    return nullptr;
  }
};

// `candela info`.
struct InfoOptions {
  std::string scene;
};

// `candela devices`.
struct DevicesOptions {
  int threads = 0;  // as render's --threads; 0: all cores
};

// Accepts plain decimal integers only and strips leading zeros, because CLI11 would otherwise
// read "010" as octal, "0x10" as hex and wrap "-1" around for unsigned types.
inline CLI::Validator decimalInteger(bool positive, uint64_t max) {
  return CLI::Validator(
      [positive, max](std::string& text) -> std::string {
        const bool digits =
            !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
        if (!digits) return "expected a non-negative whole number, got '" + text + "'";
        const size_t first = text.find_first_not_of('0');
        text = first == std::string::npos ? "0" : text.substr(first);
        if (positive && text == "0") return "expected a positive whole number, got 0";
        // Compared as decimal text, so that no conversion can wrap or clamp a larger number.
        const std::string largest = std::to_string(max);
        if (text.size() > largest.size() || (text.size() == largest.size() && text > largest))
          return "expected a whole number of at most " + largest + ", got " + text;
        return {};
      },
      positive ? "POSITIVE" : "");
}

// A finite number above 0 (CLI::PositiveNumber lets NaN through).
inline CLI::Validator finitePositiveNumber() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double value = 0;
        if (!CLI::detail::lexical_cast(text, value) || !std::isfinite(value) || !(value > 0))
          return "expected a finite positive number, got '" + text + "'";
        return {};
      },
      "POSITIVE");
}

// Accepts the names of cpuEngineFromName.
inline CLI::Validator cpuEngineChoice() {
  return CLI::Validator(
      [](std::string& name) -> std::string {
        CpuEngine ignored;
        if (cpuEngineFromName(name, &ignored)) return {};
        return "expected auto, embree or bvh, got '" + name + "'";
      },
      "{auto,embree,bvh}");
}

// Accepts the names of backendFromName.
inline CLI::Validator backendChoice() {
  return CLI::Validator(
      [](std::string& name) -> std::string {
        Backend ignored;
        if (backendFromName(name, &ignored)) return {};
        return "expected auto, cpu or cuda, got '" + name + "'";
      },
      "{auto,cpu,cuda}");
}

}  // namespace candela::cli
