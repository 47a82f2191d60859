// Decoding WebP through Debian's libwebp (CANDELA_HAS_WEBP); see image_codecs.h.
#include <cstdint>
#include <string>

#ifdef CANDELA_HAS_WEBP
#include <webp/decode.h>
#endif

#include "image/image_codecs.h"
#include "image/image_io.h"

namespace candela {

bool isWebpBytes(const std::string& bytes) {
  return bytes.size() >= 12 && bytes.compare(0, 4, "RIFF") == 0 && bytes.compare(8, 4, "WEBP") == 0;
}

bool webpDecoding() {
#ifdef CANDELA_HAS_WEBP
  return true;
#else
  return false;
#endif
}

ImageRgba decodeWebp(const std::string& bytes) {
#ifdef CANDELA_HAS_WEBP
  const auto* data = reinterpret_cast<const uint8_t*>(bytes.data());
  WebPBitstreamFeatures features;
  if (WebPGetFeatures(data, bytes.size(), &features) != VP8_STATUS_OK)
    throw ImageWriteError("not a readable WebP image (its header)");
  if (features.has_animation) throw ImageWriteError("an animated WebP image: expected a still");
  ImageRgba image;
  image.width = uint32_t(features.width);
  image.height = uint32_t(features.height);
  image.channels = features.has_alpha ? 4 : 3;
  image.bits = 8;
  image.pixels8.resize(size_t(4) * image.width * image.height);
  if (!WebPDecodeRGBAInto(data, bytes.size(), image.pixels8.data(), image.pixels8.size(),
                          int(4 * image.width)))
    throw ImageWriteError("not a readable WebP image (its pixels)");
  return image;
#else
  (void)bytes;
  throw ImageWriteError(
      "a WebP image, and this build of candela reads none (built without "
      "libwebp-dev)");
#endif
}

}  // namespace candela
