// Image codecs: in-memory conversions between ImageRGB and the bytes of one file format.
//
// Internal to src/image: image_io.cpp picks a codec by extension and does the file I/O, so the
// codecs never touch the file system. They throw ImageWriteError with a reason but no path
// (the caller prefixes the path it was working on).
#pragma once

#include <string>

#include <vector>

#include "image/image.h"
#include "image/image_layer.h"
#include "image/output_desc.h"

namespace candela {

// 8-bit RGB PNG, tone curve and exposure from `output` (see encode8bit).
std::string encodePng(const ImageRGB& image, const OutputDesc& output);
// 8-bit RGBA PNG of an image premultiplied by `alpha` (one value per pixel in [0, 1]): each
// colour divided by its alpha before the tone curve (PNG's alpha is straight), 0 where alpha is.
std::string encodePng(const ImageRGB& image, const OutputDesc& output,
                      const std::vector<float>& alpha);

// OpenEXR, three 32-bit FLOAT channels R, G, B, lossless ZIP compression, linear values.
std::string encodeExr(const ImageRGB& image);
// The same with each layer's channels beside R, G, B ("depth.Z", ...); integer layers as UINT.
std::string encodeExr(const ImageRGB& image, const std::vector<ImageLayer>& layers);
// Every channel of an EXR, as float.
ExrChannels decodeExrChannels(const std::string& bytes);
// Any scanline or tiled EXR with channels R, G and B (converted to float), or a grey one: Y alone
// (replicated to RGB) or luminance-chroma (Y, RY, BY). Any other set of channels is refused.
ImageRGB decodeExr(const std::string& bytes);

// Portable float map "PF": little-endian floats, rows stored bottom-to-top.
std::string encodePfm(const ImageRGB& image);
// A layer of 1 channel as grey "Pf", of 2 or 3 as "PF" (2 padded with a zero third).
std::string encodePfm(const ImageLayer& layer);
// Accepts "PF" (RGB) and "Pf" (grey, replicated to RGB) in either byte order.
ImageRGB decodePfm(const std::string& bytes);

// Radiance RGBE (.hdr), read only.
ImageRGB decodeHdr(const std::string& bytes);

// PNG (8- or 16-bit) or JPEG, read only, as RGBA.
ImageRgba decodeImageRgba(const std::string& bytes);

// WebP (a still, lossy or lossless, with or without alpha), read only, as 8-bit RGBA, where this
// build has libwebp (webpDecoding()); else it throws saying so. isWebpBytes: the bytes start as
// a WebP file does ("RIFF", a size, "WEBP").
bool isWebpBytes(const std::string& bytes);
ImageRgba decodeWebp(const std::string& bytes);

}  // namespace candela
