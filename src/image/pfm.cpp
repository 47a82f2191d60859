// PFM codec (portable float map): an ASCII header, then raw 32-bit floats, rows bottom-to-top.
//
// The header is "PF\n<width> <height>\n<scale>\n"; a negative scale means little-endian data.
// We always write little-endian with scale -1, byte by byte, so the output is the same on any
// host.
#include <cmath>
#include <cstring>
#include <sstream>

#include "image/image_codecs.h"
#include "image/image_io.h"

namespace candela {

namespace {

void appendFloat(std::string* out, float f, bool littleEndian) {
  uint32_t bits;
  std::memcpy(&bits, &f, sizeof bits);
  for (int b = 0; b < 4; ++b) {
    const int shift = littleEndian ? 8 * b : 8 * (3 - b);
    out->push_back(char((bits >> shift) & 0xffu));
  }
}

float readFloat(const unsigned char* p, bool littleEndian) {
  uint32_t bits = 0;
  for (int b = 0; b < 4; ++b) {
    const int shift = littleEndian ? 8 * b : 8 * (3 - b);
    bits |= uint32_t(p[b]) << shift;
  }
  float f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

// A PFM of w x h pixels of n channels each (1, 2 or 3), rows from the top: grey "Pf" for one
// channel, else "PF" with three, two channels (a flow field) padded with a zero third, as flow
// datasets' PFMs are. PFM rows run from the bottom.
std::string encodeRows(uint32_t w, uint32_t h, const float* pixels, size_t n) {
  const size_t written = n == 1 ? 1 : 3;
  std::string out = std::string(n == 1 ? "Pf" : "PF") + "\n" + std::to_string(w) + " " +
                    std::to_string(h) + "\n-1.0\n";
  out.reserve(out.size() + 4 * written * size_t(w) * h);
  for (uint32_t row = h; row-- > 0;) {
    const float* p = pixels + n * w * row;
    for (uint32_t x = 0; x < w; ++x, p += n)
      for (size_t c = 0; c < written; ++c) appendFloat(&out, c < n ? p[c] : 0.0f, true);
  }
  return out;
}

}  // namespace

std::string encodePfm(const ImageRGB& image) {
  return encodeRows(image.width, image.height, image.pixels.data(), 3);
}

std::string encodePfm(const ImageLayer& layer) {
  const size_t n = layer.channels.size();
  if (n < 1 || n > 3)
    throw ImageWriteError("PFM holds 1, 2 or 3 channels, not " + std::to_string(n));
  if (layer.pixels.size() != n * size_t(layer.width) * layer.height)
    throw ImageWriteError("layer " + layer.name + " does not match its size");
  return encodeRows(layer.width, layer.height, layer.pixels.data(), n);
}

ImageRGB decodePfm(const std::string& bytes) {
  std::istringstream header(bytes);
  std::string magic;
  long long width = 0, height = 0;
  double scale = 0;
  if (!(header >> magic >> width >> height >> scale) || (magic != "PF" && magic != "Pf"))
    throw ImageWriteError("not a PFM file (bad header)");
  if (width <= 0 || height <= 0 || scale == 0 || !std::isfinite(scale))
    throw ImageWriteError("not a PFM file (bad size or scale in header)");
  constexpr long long kMaxSide = 1 << 20;
  if (width > kMaxSide || height > kMaxSide)
    throw ImageWriteError("PFM image of " + std::to_string(width) + " x " + std::to_string(height) +
                          " pixels: at most " + std::to_string(kMaxSide) + " a side is read");
  // Exactly one whitespace character separates the header from the data.
  const size_t dataStart = size_t(header.tellg()) + 1;
  const size_t channels = magic == "PF" ? 3 : 1;
  const size_t expected = size_t(width) * size_t(height) * channels * 4;
  if (dataStart > bytes.size() || bytes.size() - dataStart < expected)
    throw ImageWriteError("truncated PFM file: expected " + std::to_string(expected) +
                          " bytes of pixel data");

  const bool littleEndian = scale < 0;
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data()) + dataStart;
  ImageRGB image{uint32_t(width), uint32_t(height)};
  for (uint32_t y = 0; y < image.height; ++y) {
    const uint32_t row = image.height - 1 - y;  // file rows run bottom-to-top
    for (uint32_t x = 0; x < image.width; ++x) {
      const unsigned char* p = data + 4 * channels * (size_t(row) * image.width + x);
      const float r = readFloat(p, littleEndian);
      const float g = channels == 3 ? readFloat(p + 4, littleEndian) : r;
      const float b = channels == 3 ? readFloat(p + 8, littleEndian) : r;
      image.set(x, y, Vec3(r, g, b));
    }
  }
  return image;
}

}  // namespace candela
