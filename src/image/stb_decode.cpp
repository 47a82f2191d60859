// Decoding through stb_image, in memory: Radiance .hdr (RGBE), PNG (8- and 16-bit) and JPEG.
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <string>

#include "image/image_codecs.h"
#include "image/image_io.h"

// The one stb_image implementation in the project, static and limited to the formats read here.
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_NO_STDIO
#define STBI_ONLY_HDR
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#endif
#include <stb_image.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace candela {

ImageRGB decodeHdr(const std::string& bytes) {
  int width = 0, height = 0, channels = 0;
  std::unique_ptr<float, void (*)(void*)> pixels(
      stbi_loadf_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), int(bytes.size()),
                             &width, &height, &channels, 3),
      stbi_image_free);
  if (!pixels)
    throw ImageWriteError(std::string("not a Radiance HDR image (") + stbi_failure_reason() + ")");
  ImageRGB image{static_cast<uint32_t>(width), static_cast<uint32_t>(height)};
  std::copy(pixels.get(), pixels.get() + image.pixels.size(), image.pixels.begin());
  return image;
}

ImageRgba decodeImageRgba(const std::string& bytes) {
  int width = 0, height = 0, channels = 0;
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  const int size = int(bytes.size());
  ImageRgba image;
  image.bits = stbi_is_16_bit_from_memory(data, size) ? 16 : 8;
  // stb returns 8-bit samples as stbi_uc and 16-bit ones as stbi_us, both freed alike.
  std::unique_ptr<void, void (*)(void*)> pixels(
      image.bits == 16
          ? static_cast<void*>(stbi_load_16_from_memory(data, size, &width, &height, &channels, 4))
          : static_cast<void*>(stbi_load_from_memory(data, size, &width, &height, &channels, 4)),
      stbi_image_free);
  if (!pixels)
    throw ImageWriteError(std::string("not a readable PNG or JPEG image (") +
                          stbi_failure_reason() + ")");
  image.width = uint32_t(width);
  image.height = uint32_t(height);
  image.channels = uint32_t(channels);
  const size_t count = size_t(4) * image.width * image.height;
  if (image.bits == 16) {
    const auto* p = static_cast<const uint16_t*>(pixels.get());
    image.pixels16.assign(p, p + count);
  } else {
    const auto* p = static_cast<const uint8_t*>(pixels.get());
    image.pixels8.assign(p, p + count);
  }
  return image;
}

}  // namespace candela
