// EXR codec through OpenEXR's C++ API: 32-bit float linear RGB, encoded in memory.
//
// Imf::RgbaOutputFile would store half floats; a plain OutputFile with FLOAT channels keeps
// every rendered value exactly. Reading decodes bands of rows in parallel on oneTBB (an 8k map
// is seconds of zlib on one core), each band through a reader of its own over the same bytes.
#include <IexBaseExc.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfRgbaFile.h>
#include <ImfStdIO.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

#include "image/image_codecs.h"
#include "image/image_io.h"

namespace candela {

namespace {

constexpr const char* kChannels[3] = {"R", "G", "B"};

// Rows a band of a parallel read holds: a multiple of every compression's block of rows (1, 16,
// 32 or 256), so that no block is decoded by two bands.
constexpr int kBandRows = 256;

// An OpenEXR input stream over bytes in memory: every band's reader shares them uncopied.
class MemoryStream : public Imf::IStream {
 public:
  explicit MemoryStream(const std::string& bytes) : Imf::IStream("memory"), bytes_(bytes) {}
  bool read(char c[], int n) override {
    if (n < 0 || uint64_t(n) > bytes_.size() - position_)
      throw IEX_NAMESPACE::InputExc("unexpected end of file");
    std::memcpy(c, bytes_.data() + position_, size_t(n));
    position_ += uint64_t(n);
    return position_ < bytes_.size();
  }
  uint64_t tellg() override { return position_; }
  void seekg(uint64_t position) override {
    position_ = std::min<uint64_t>(position, bytes_.size());
  }

 private:
  const std::string& bytes_;
  uint64_t position_ = 0;
};

}  // namespace

std::string encodeExr(const ImageRGB& image) { return encodeExr(image, {}); }

std::string encodeExr(const ImageRGB& image, const std::vector<ImageLayer>& layers) {
  try {
    Imf::Header header(int(image.width), int(image.height));
    header.compression() = Imf::ZIP_COMPRESSION;
    for (const char* name : kChannels) header.channels().insert(name, Imf::Channel(Imf::FLOAT));

    // OpenEXR's Slice wants a mutable pointer but only reads through it when writing.
    char* base = reinterpret_cast<char*>(const_cast<float*>(image.pixels.data()));
    const size_t xStride = 3 * sizeof(float), yStride = xStride * image.width;
    Imf::FrameBuffer frame;
    for (int c = 0; c < 3; ++c)
      frame.insert(kChannels[c],
                   Imf::Slice(Imf::FLOAT, base + c * sizeof(float), xStride, yStride));

    // Integer layers are converted to uint32 first; the buffers must outlive writePixels.
    std::vector<std::vector<uint32_t>> integers;
    integers.reserve(layers.size());
    for (const ImageLayer& layer : layers) {
      if (layer.width != image.width || layer.height != image.height ||
          layer.pixels.size() != layer.channels.size() * size_t(layer.width) * layer.height)
        throw ImageWriteError("layer " + layer.name + " does not match the image size");
      const size_t n = layer.channels.size();
      char* data = reinterpret_cast<char*>(const_cast<float*>(layer.pixels.data()));
      if (layer.integer) {
        integers.emplace_back(layer.pixels.begin(), layer.pixels.end());
        data = reinterpret_cast<char*>(integers.back().data());
      }
      const Imf::PixelType type = layer.integer ? Imf::UINT : Imf::FLOAT;
      for (size_t c = 0; c < n; ++c) {
        const std::string name =
            layer.ofImage ? layer.channels[c] : layer.name + "." + layer.channels[c];
        header.channels().insert(name, Imf::Channel(type));
        frame.insert(name, Imf::Slice(type, data + c * 4, n * 4, n * 4 * image.width));
      }
    }

    Imf::StdOSStream stream;
    {
      Imf::OutputFile file(stream, header);  // flushes on destruction
      file.setFrameBuffer(frame);
      file.writePixels(int(image.height));
    }
    return stream.str();
  } catch (const ImageWriteError&) {
    throw;
  } catch (const std::exception& e) {
    throw ImageWriteError(std::string("EXR encoding failed: ") + e.what());
  }
}

namespace {

// The data window's size, refused beyond 2^20 a side (a corrupt header could ask for any size).
void checkedWindowSize(const Imath::Box2i& window, uint32_t* width, uint32_t* height) {
  const long long w = (long long)window.max.x - window.min.x + 1;
  const long long h = (long long)window.max.y - window.min.y + 1;
  if (w <= 0 || h <= 0 || w > (1 << 20) || h > (1 << 20))
    throw ImageWriteError("unsupported EXR data window");
  *width = uint32_t(w);
  *height = uint32_t(h);
}

// Opens the EXR in `bytes` and returns read(file, window, width, height), with OpenEXR's errors
// (and a data window too large) as ImageWriteError.
template <typename Read>
auto readExr(const std::string& bytes, Read read) {
  try {
    MemoryStream stream(bytes);
    Imf::InputFile file(stream);
    const Imath::Box2i window = file.header().dataWindow();
    uint32_t width, height;
    checkedWindowSize(window, &width, &height);
    return read(file, window, width, height);
  } catch (const ImageWriteError&) {
    throw;
  } catch (const std::exception& e) {
    throw ImageWriteError(std::string("cannot decode EXR: ") + e.what());
  }
}

}  // namespace

ExrChannels decodeExrChannels(const std::string& bytes) {
  return readExr(bytes, [](Imf::InputFile& file, const Imath::Box2i& window, uint32_t width,
                           uint32_t height) {
    ExrChannels out;
    out.width = width;
    out.height = height;
    Imf::FrameBuffer frame;
    const Imf::ChannelList& list = file.header().channels();
    for (auto it = list.begin(); it != list.end(); ++it)
      out.channels.push_back({it.name(), it.channel().type == Imf::UINT,
                              std::vector<float>(size_t(width) * height)});
    for (ExrChannel& c : out.channels)
      frame.insert(c.name, Imf::Slice::Make(Imf::FLOAT, c.pixels.data(), window, sizeof(float),
                                            sizeof(float) * width));
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);
    return out;
  });
}

namespace {

// The channels' names, the first few, for a message: "Z, A".
std::string channelNames(const Imf::ChannelList& list) {
  std::string names;
  int count = 0;
  for (auto it = list.begin(); it != list.end(); ++it, ++count) {
    if (count == 8) return names + ", ...";
    names += (count ? ", " : "") + std::string(it.name());
  }
  return count ? names : "none";
}

// A luminance-chroma file (Y, RY, BY: half floats with subsampled chroma) through the library's
// RGBA interface, which alone converts it; its values are halves already, so nothing is lost.
ImageRGB decodeLuminanceChroma(const std::string& bytes, const Imath::Box2i& window, uint32_t width,
                               uint32_t height) {
  MemoryStream stream(bytes);
  Imf::RgbaInputFile file(stream);
  std::vector<Imf::Rgba> rgba(size_t(width) * height);
  file.setFrameBuffer(rgba.data() - window.min.x - ptrdiff_t(window.min.y) * width, 1, width);
  file.readPixels(window.min.y, window.max.y);
  ImageRGB image{width, height};
  for (size_t i = 0; i < rgba.size(); ++i) {
    image.pixels[3 * i] = rgba[i].r;
    image.pixels[3 * i + 1] = rgba[i].g;
    image.pixels[3 * i + 2] = rgba[i].b;
  }
  return image;
}

}  // namespace

ImageRGB decodeExr(const std::string& bytes) {
  return readExr(bytes, [&bytes](Imf::InputFile& file, const Imath::Box2i& window, uint32_t width,
                                 uint32_t height) {
    const Imf::ChannelList& list = file.header().channels();
    const bool rgb = list.findChannel("R") && list.findChannel("G") && list.findChannel("B");
    const bool grey = !list.findChannel("R") && !list.findChannel("G") && !list.findChannel("B") &&
                      list.findChannel("Y");
    if (grey && (list.findChannel("RY") || list.findChannel("BY")))
      return decodeLuminanceChroma(bytes, window, width, height);
    if (!rgb && !grey)
      throw ImageWriteError("expected the channels R, G and B (or Y, for a grey image), got " +
                            channelNames(list));
    ImageRGB image{width, height};
    const size_t xStride = 3 * sizeof(float), yStride = xStride * width;
    Imf::FrameBuffer frame;
    // Y is read into the red channel and copied to the others (a frame buffer holds a name once).
    for (int c = 0; c < (grey ? 1 : 3); ++c) {
      char* base = reinterpret_cast<char*>(image.pixels.data() + c);
      frame.insert(grey ? "Y" : kChannels[c],
                   Imf::Slice::Make(Imf::FLOAT, base, window, xStride, yStride));
    }
    const int bands = int((height + kBandRows - 1) / kBandRows);
    const auto readBand = [&](Imf::InputFile& reader, int band) {
      reader.setFrameBuffer(frame);
      const int first = window.min.y + band * kBandRows;
      reader.readPixels(first, std::min(window.max.y, first + kBandRows - 1));
    };
    if (bands == 1) {
      readBand(file, 0);
    } else {
      tbb::parallel_for(0, bands, [&](int band) {
        MemoryStream stream(bytes);
        Imf::InputFile reader(stream);
        readBand(reader, band);
      });
    }
    if (grey)
      for (size_t i = 0; i < image.pixels.size(); i += 3)
        image.pixels[i + 1] = image.pixels[i + 2] = image.pixels[i];
    return image;
  });
}

}  // namespace candela
