// Decoding through stb_image, in memory: Radiance .hdr (RGBE) and 8-bit PNG and JPEG.
#include <algorithm>
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

Image8 decodeImage8(const std::string& bytes) {
  int width = 0, height = 0, channels = 0;
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  if (stbi_is_16_bit_from_memory(data, int(bytes.size())))
    throw ImageWriteError("a 16-bit image; expected 8 bits per channel");
  std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
      stbi_load_from_memory(data, int(bytes.size()), &width, &height, &channels, 4),
      stbi_image_free);
  if (!pixels)
    throw ImageWriteError(std::string("not a readable PNG or JPEG image (") +
                          stbi_failure_reason() + ")");
  Image8 image;
  image.width = uint32_t(width);
  image.height = uint32_t(height);
  image.channels = uint32_t(channels);
  image.pixels.assign(pixels.get(), pixels.get() + size_t(4) * image.width * image.height);
  return image;
}

}  // namespace candela
