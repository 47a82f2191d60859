// Image files by extension: picks the codec, checks the image, and does the file I/O.
#include "image/image_io.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "image/atomic_file.h"
#include "image/image_codecs.h"

namespace candela {

namespace {

enum class ImageFormat { Png, Exr, Pfm, Hdr, Unknown };

std::string lowercaseExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

ImageFormat formatOf(const std::string& path) {
  const std::string ext = lowercaseExtension(path);
  if (ext == ".png") return ImageFormat::Png;
  if (ext == ".exr") return ImageFormat::Exr;
  if (ext == ".pfm") return ImageFormat::Pfm;
  if (ext == ".hdr") return ImageFormat::Hdr;
  return ImageFormat::Unknown;
}

[[noreturn]] void unsupported(const std::string& path, const char* expected) {
  const std::string ext = lowercaseExtension(path);
  throw ImageWriteError(path + ": unsupported image format " +
                        (ext.empty() ? std::string("(no extension)") : "'" + ext + "'") +
                        ", expected " + expected);
}

}  // namespace

bool isSupportedImagePath(const std::string& path) {
  const ImageFormat format = formatOf(path);
  return format != ImageFormat::Unknown && format != ImageFormat::Hdr;
}

void writeImage(const std::string& path, const ImageRGB& image, const OutputDesc& output) {
  const ImageFormat format = formatOf(path);
  if (format == ImageFormat::Unknown || format == ImageFormat::Hdr)
    unsupported(path, ".png, .exr or .pfm");
  if (image.width == 0 || image.height == 0) throw ImageWriteError(path + ": the image is empty");
  if (image.pixels.size() != size_t(3) * image.width * image.height)
    throw ImageWriteError(path + ": pixel buffer does not match the image size");

  std::string bytes;
  try {
    switch (format) {
      case ImageFormat::Png:
        bytes = encodePng(image, output);
        break;
      case ImageFormat::Exr:
        bytes = encodeExr(image);
        break;
      case ImageFormat::Pfm:
        bytes = encodePfm(image);
        break;
      case ImageFormat::Hdr:
      case ImageFormat::Unknown:
        break;  // rejected above
    }
  } catch (const ImageWriteError& e) {
    throw ImageWriteError(path + ": " + e.what());
  }
  writeFileAtomically(path, bytes);
}

ImageRGB readImage(const std::string& path) {
  const ImageFormat format = formatOf(path);
  if (format != ImageFormat::Exr && format != ImageFormat::Pfm && format != ImageFormat::Hdr)
    unsupported(path, ".exr, .pfm or .hdr for reading");
  const std::string bytes = readFileBytes(path);
  try {
    switch (format) {
      case ImageFormat::Exr:
        return decodeExr(bytes);
      case ImageFormat::Hdr:
        return decodeHdr(bytes);
      default:
        return decodePfm(bytes);
    }
  } catch (const ImageWriteError& e) {
    throw ImageWriteError(path + ": " + e.what());
  }
}

}  // namespace candela
