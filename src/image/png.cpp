// PNG codec: 8-bit RGB through stb_image_write, encoded in memory.
#include <climits>

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

}  // namespace

std::string encodePng(const ImageRGB& image, const OutputDesc& output) {
  // stb works with int sizes and strides.
  if (image.width > uint32_t(INT_MAX / 3) || image.height > uint32_t(INT_MAX))
    throw ImageWriteError("image too large for PNG");

  std::vector<uint8_t> bytes(image.pixels.size());
  for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = encode8bit(image.pixels[i], output);

  std::string png;
  const int stride = int(3 * image.width);
  if (!stbi_write_png_to_func(appendBytes, &png, int(image.width), int(image.height), 3,
                              bytes.data(), stride))
    throw ImageWriteError("PNG encoding failed");
  return png;
}

}  // namespace candela
