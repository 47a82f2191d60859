// PNG codec: 8-bit RGB or RGBA through stb_image_write, encoded in memory.
#include <algorithm>
#include <climits>
#include <cmath>

#include "image/image_codecs.h"
#include "image/image_io.h"

// The one stb_image_write implementation in the project; static so that it cannot clash with
// another copy linked from elsewhere, and without stdio because image_io.cpp writes the file.
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#define STBI_WRITE_NO_STDIO
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-function"
#endif
#include <stb_image_write.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace candela {

namespace {

void appendBytes(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data), size_t(size));
}

// 8-bit bytes of `channels` per pixel (3 or 4) as a PNG.
std::string pngOf(const std::vector<uint8_t>& bytes, uint32_t width, uint32_t height,
                  int channels) {
  // stb works with int sizes and strides.
  if (width > uint32_t(INT_MAX / 4) || height > uint32_t(INT_MAX))
    throw ImageWriteError("image too large for PNG");
  std::string png;
  if (!stbi_write_png_to_func(appendBytes, &png, int(width), int(height), channels, bytes.data(),
                              int(channels * width)))
    throw ImageWriteError("PNG encoding failed");
  return png;
}

}  // namespace

std::string encodePng(const ImageRGB& image, const OutputDesc& output) {
  std::vector<uint8_t> bytes(image.pixels.size());
  for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = encode8bit(image.pixels[i], output);
  return pngOf(bytes, image.width, image.height, 3);
}

std::string encodePng(const ImageRGB& image, const OutputDesc& output,
                      const std::vector<float>& alpha) {
  const size_t pixels = size_t(image.width) * image.height;
  if (alpha.size() != pixels) throw ImageWriteError("the alpha channel does not match the image");
  std::vector<uint8_t> bytes(4 * pixels);
  for (size_t i = 0; i < pixels; ++i) {
    const float a = std::isnan(alpha[i]) ? 0.0f : std::clamp(alpha[i], 0.0f, 1.0f);
    for (int c = 0; c < 3; ++c)
      bytes[4 * i + c] = a > 0.0f ? encode8bit(image.pixels[3 * i + c] / a, output) : 0;
    bytes[4 * i + 3] = uint8_t(std::lround(a * 255.0f));
  }
  return pngOf(bytes, image.width, image.height, 4);
}

}  // namespace candela
