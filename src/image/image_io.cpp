// Image files by extension: picks the codec, checks the image, and does the file I/O.
#include "image/image_io.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "image/atomic_file.h"
#include "image/image_codecs.h"

namespace candela {

namespace {

enum class ImageFormat { Png, Exr, Pfm, Unknown };

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
  return formatOf(path) != ImageFormat::Unknown;
}

void writeImage(const std::string& path, const ImageRGB& image, const OutputDesc& output) {
  const ImageFormat format = formatOf(path);
  if (format == ImageFormat::Unknown) unsupported(path, ".png, .exr or .pfm");
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
  if (format != ImageFormat::Exr && format != ImageFormat::Pfm)
    unsupported(path, ".exr or .pfm for reading");
  const std::string bytes = readFileBytes(path);
  try {
    return format == ImageFormat::Exr ? decodeExr(bytes) : decodePfm(bytes);
  } catch (const ImageWriteError& e) {
    throw ImageWriteError(path + ": " + e.what());
  }
}

}  // namespace candela
