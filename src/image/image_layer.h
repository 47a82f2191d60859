// ImageLayer: an image of named float channels beside the RGB image, such as one render pass
// (depth, normals, ids), as a multi-layer EXR stores it: channel "name.X" for name "name".
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace candela {

struct ImageLayer {
  std::string name;                   // "depth", "normal", ...
  std::vector<std::string> channels;  // "Z", or "X", "Y", "Z"; in the EXR "depth.Z"
  bool integer = false;  // whole numbers in [0, 2^24] (ids): stored as EXR UINT channels
  // The image's own channel, its alpha: in the EXR "A" beside R, G, B (the RGBA image every
  // reader composites), not "alpha.A".
  bool ofImage = false;
  uint32_t width = 0, height = 0;
  std::vector<float> pixels;  // channels.size() * width * height, interleaved, rows from the top

  ImageLayer() = default;
  ImageLayer(std::string n, std::vector<std::string> c, bool isInteger, uint32_t w, uint32_t h)
      : name(std::move(n)), channels(std::move(c)), integer(isInteger), width(w), height(h),
        pixels(channels.size() * w * h, 0.0f) {}
};

// The channels of an EXR file as read back: every channel as float, with whether it was UINT.
struct ExrChannel {
  std::string name;  // the full name, "depth.Z"
  bool isUint = false;
  std::vector<float> pixels;  // width * height, rows from the top
};

struct ExrChannels {
  uint32_t width = 0, height = 0;
  std::vector<ExrChannel> channels;  // in the file's (alphabetical) order
};

}  // namespace candela
