// Radiance .hdr (RGBE) decoding through stb_image, in memory.
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

}  // namespace candela
