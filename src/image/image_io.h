// Image files by extension: .png (8-bit, gamma/sRGB and exposure applied), .exr (32-bit float
// linear RGB), .pfm (float linear RGB); .hdr (Radiance RGBE) is read only. Files are written to a temporary name beside the target
// and renamed into place, so an interrupted run never leaves a half-written image.
#pragma once

#include <stdexcept>
#include <string>

#include <vector>

#include "image/image.h"
#include "image/image_layer.h"
#include "image/output_desc.h"

namespace candela {

class ImageWriteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// True when `path` ends in an extension writeImage understands (case-insensitive).
bool isSupportedImagePath(const std::string& path);

// Whether `path` names an EXR file, and whether it names a float (linear) image: EXR, PFM or
// Radiance .hdr; both by its extension, in any case.
bool isExrPath(const std::string& path);
bool isFloatImagePath(const std::string& path);

// Throws ImageWriteError naming `path` and the formats textures are read from (.png, .jpg, .jpeg,
// .webp, .exr, .pfm, .hdr) unless its extension is one of them.
void requireTextureImagePath(const std::string& path);

// Throws ImageWriteError (naming the path and the reason) on failure; leaves no partial file.
// With `alpha` (the alpha pass, one channel: the image is premultiplied by it), a .png is 8-bit
// RGBA of straight colour (the image divided by alpha, as PNG stores it) and an .exr has A beside
// R, G, B; a .pfm, which has no alpha channel, is refused.
void writeImage(const std::string& path, const ImageRGB& image, const OutputDesc& output,
                const ImageLayer* alpha = nullptr);

// The bytes writeImage writes, in the format of `path`'s extension; throws ImageWriteError.
std::string encodeImage(const std::string& path, const ImageRGB& image, const OutputDesc& output,
                        const ImageLayer* alpha = nullptr);

// A multi-layer .exr: the image as R, G, B and each layer's channels beside them (render passes);
// throws ImageWriteError, also for a path that is not .exr.
std::string encodeLayeredExr(const std::string& path, const ImageRGB& image,
                             const std::vector<ImageLayer>& layers);

// One layer of 1, 2 or 3 channels as a .pfm (grey "Pf" or "PF"); throws ImageWriteError, also for
// a path that is not .pfm.
std::string encodeLayerPfm(const std::string& path, const ImageLayer& layer);

// Every channel of an .exr file as float (tests and tools); throws ImageWriteError.
ExrChannels readExrChannels(const std::string& path);

// Reads .exr, .pfm and Radiance .hdr files as linear float RGB (environment maps, tests and
// tools); throws ImageWriteError (the image module's one error type, naming the path) on failure.
ImageRGB readImage(const std::string& path);

// Reads .png (8- or 16-bit), .jpg, .jpeg and .webp files (textures) as RGBA, by their first
// bytes; throws ImageWriteError naming the path on failure.
ImageRgba readImageRgba(const std::string& path);

// The same from a PNG, JPEG or WebP file's bytes held in memory; throws ImageWriteError naming
// `name`.
ImageRgba decodeImageRgbaBytes(const std::string& bytes, const std::string& name);

// Whether this build reads WebP images (Debian's libwebp, CANDELA_WEBP).
bool webpDecoding();

// Whether `path` is a regular file that holds a whole image of its extension's format, by a
// cheap look at its ends: PNG's signature and final IEND chunk, a PFM's header and the size it
// implies, EXR's magic number. What a resumed sequence counts as a finished frame.
bool isCompleteImageFile(const std::string& path);

// 8-bit encoding of one linear value: exposure, the tone map into [0, 1], then the gamma or sRGB
// curve.
uint8_t encode8bit(float linear, const OutputDesc& output);

}  // namespace candela
