// Image files by extension: picks the codec, checks the image, and does the file I/O.
#include "image/image_io.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>

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

// The files readImageRgba reads: .png, .jpg, .jpeg, .webp.
bool isRgbaImagePath(const std::string& path) {
  const std::string ext = lowercaseExtension(path);
  return ext == ".png" || ext == ".jpg" || ext == ".jpeg" || ext == ".webp";
}

// An 8- or 16-bit image's bytes by what they start with: WebP, else PNG or JPEG.
ImageRgba decodeRgba(const std::string& bytes) {
  return isWebpBytes(bytes) ? decodeWebp(bytes) : decodeImageRgba(bytes);
}

}  // namespace

bool isSupportedImagePath(const std::string& path) {
  const ImageFormat format = formatOf(path);
  return format != ImageFormat::Unknown && format != ImageFormat::Hdr;
}

bool isExrPath(const std::string& path) { return formatOf(path) == ImageFormat::Exr; }

bool isFloatImagePath(const std::string& path) {
  const ImageFormat format = formatOf(path);
  return format == ImageFormat::Exr || format == ImageFormat::Pfm || format == ImageFormat::Hdr;
}

void requireTextureImagePath(const std::string& path) {
  if (!isFloatImagePath(path) && !isRgbaImagePath(path))
    unsupported(path, ".png, .jpg, .jpeg, .webp, .exr, .pfm or .hdr");
}

void writeImage(const std::string& path, const ImageRGB& image, const OutputDesc& output,
                const ImageLayer* alpha) {
  writeFileAtomically(path, encodeImage(path, image, output, alpha));
}

std::string encodeImage(const std::string& path, const ImageRGB& image, const OutputDesc& output,
                        const ImageLayer* alpha) {
  const ImageFormat format = formatOf(path);
  if (format == ImageFormat::Unknown || format == ImageFormat::Hdr)
    unsupported(path, ".png, .exr or .pfm");
  if (image.width == 0 || image.height == 0) throw ImageWriteError(path + ": the image is empty");
  if (image.pixels.size() != size_t(3) * image.width * image.height)
    throw ImageWriteError(path + ": pixel buffer does not match the image size");
  if (alpha &&
      (alpha->channels.size() != 1 || alpha->width != image.width ||
       alpha->height != image.height ||
       alpha->pixels.size() != alpha->channels.size() * size_t(alpha->width) * alpha->height))
    throw ImageWriteError(path + ": the alpha channel does not match the image size");
  if (alpha && format == ImageFormat::Pfm)
    throw ImageWriteError(path + ": a .pfm has no alpha channel; expected .png or .exr");

  std::string bytes;
  try {
    switch (format) {
      case ImageFormat::Png:
        bytes = alpha ? encodePng(image, output, alpha->pixels) : encodePng(image, output);
        break;
      case ImageFormat::Exr:
        if (alpha) {
          ImageLayer a = *alpha;
          a.ofImage = true;
          bytes = encodeExr(image, {a});
        } else {
          bytes = encodeExr(image);
        }
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
  return bytes;
}

std::string encodeLayeredExr(const std::string& path, const ImageRGB& image,
                             const std::vector<ImageLayer>& layers) {
  if (formatOf(path) != ImageFormat::Exr) unsupported(path, ".exr for an image with layers");
  try {
    return encodeExr(image, layers);
  } catch (const ImageWriteError& e) {
    throw ImageWriteError(path + ": " + e.what());
  }
}

std::string encodeLayerPfm(const std::string& path, const ImageLayer& layer) {
  if (formatOf(path) != ImageFormat::Pfm) unsupported(path, ".pfm for a layer");
  try {
    return encodePfm(layer);
  } catch (const ImageWriteError& e) {
    throw ImageWriteError(path + ": " + e.what());
  }
}

ExrChannels readExrChannels(const std::string& path) {
  if (formatOf(path) != ImageFormat::Exr) unsupported(path, ".exr");
  const std::string bytes = readFileBytes(path);
  try {
    return decodeExrChannels(bytes);
  } catch (const ImageWriteError& e) {
    throw ImageWriteError(path + ": " + e.what());
  }
}

bool isCompleteImageFile(const std::string& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) return false;
  const uintmax_t size = std::filesystem::file_size(path, error);
  if (error || size < 12) return false;
  std::ifstream in(path, std::ios::binary);
  std::string head(64, '\0'), tail(12, '\0');
  in.read(&head[0], std::streamsize(head.size()));
  head.resize(size_t(in.gcount()));
  in.clear();
  in.seekg(-12, std::ios::end);
  in.read(&tail[0], 12);
  if (!in) return false;
  switch (formatOf(path)) {
    case ImageFormat::Png:
      return head.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0 &&
             tail.compare(4, 8, "IEND\xae\x42\x60\x82") == 0;
    case ImageFormat::Exr:
      return head.compare(0, 4, "\x76\x2f\x31\x01") == 0;
    case ImageFormat::Pfm: {
      char kind = 0;
      unsigned long width = 0, height = 0;
      float scale = 0;
      int consumed = 0;
      if (std::sscanf(head.c_str(), "P%c %lu %lu %f%n", &kind, &width, &height, &scale, &consumed) != 4 ||
          (kind != 'F' && kind != 'f'))
        return false;
      const uintmax_t channels = kind == 'F' ? 3 : 1;
      // The header ends with one whitespace byte after the scale.
      return size == uintmax_t(consumed) + 1 + uintmax_t(width) * height * channels * 4;
    }
    default:
      return false;
  }
}

ImageRGB readImage(const std::string& path) {
  if (!isFloatImagePath(path)) unsupported(path, ".exr, .pfm or .hdr for reading");
  const ImageFormat format = formatOf(path);
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

ImageRgba readImageRgba(const std::string& path) {
  if (!isRgbaImagePath(path)) unsupported(path, ".png, .jpg, .jpeg or .webp");
  const std::string bytes = readFileBytes(path);
  try {
    return decodeRgba(bytes);
  } catch (const ImageWriteError& e) {
    throw ImageWriteError(path + ": " + e.what());
  }
}

ImageRgba decodeImageRgbaBytes(const std::string& bytes, const std::string& name) {
  try {
    return decodeRgba(bytes);
  } catch (const ImageWriteError& e) {
    throw ImageWriteError(name + ": " + e.what());
  }
}

}  // namespace candela
