// EXR codec through OpenEXR's C++ API: 32-bit float linear RGB, encoded in memory.
//
// Imf::RgbaOutputFile would store half floats; a plain OutputFile with FLOAT channels keeps
// every rendered value exactly.
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStdIO.h>

#include <exception>

#include "image/image_codecs.h"
#include "image/image_io.h"

namespace candela {

namespace {

constexpr const char* kChannels[3] = {"R", "G", "B"};

}  // namespace

std::string encodeExr(const ImageRGB& image) {
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

    Imf::StdOSStream stream;
    {
      Imf::OutputFile file(stream, header);  // flushes on destruction
      file.setFrameBuffer(frame);
      file.writePixels(int(image.height));
    }
    return stream.str();
  } catch (const std::exception& e) {
    throw ImageWriteError(std::string("EXR encoding failed: ") + e.what());
  }
}

ImageRGB decodeExr(const std::string& bytes) {
  try {
    Imf::StdISStream stream;
    stream.str(bytes);
    Imf::InputFile file(stream);
    const Imath::Box2i window = file.header().dataWindow();
    const long long width = (long long)window.max.x - window.min.x + 1;
    const long long height = (long long)window.max.y - window.min.y + 1;
    if (width <= 0 || height <= 0 || width > (1 << 20) || height > (1 << 20))
      throw ImageWriteError("unsupported EXR data window");

    ImageRGB image{uint32_t(width), uint32_t(height)};
    const size_t xStride = 3 * sizeof(float), yStride = xStride * image.width;
    Imf::FrameBuffer frame;
    for (int c = 0; c < 3; ++c) {
      char* base = reinterpret_cast<char*>(image.pixels.data() + c);
      frame.insert(kChannels[c], Imf::Slice::Make(Imf::FLOAT, base, window, xStride, yStride, 1, 1,
                                                  /*fillValue=*/0.0));
    }
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);
    return image;
  } catch (const ImageWriteError&) {
    throw;
  } catch (const std::exception& e) {
    throw ImageWriteError(std::string("cannot decode EXR: ") + e.what());
  }
}

}  // namespace candela
