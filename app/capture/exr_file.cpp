#include "app/capture/exr_file.hpp"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfOutputFile.h>

#include <cstring>

namespace ecoview {
namespace {

// OpenEXR writes through a stream it seeks in (to fill in the table of row offsets at the end);
// this one keeps the bytes, so the file lands whole through write_file_atomically.
class BytesStream : public Imf::OStream {
 public:
  BytesStream() : Imf::OStream("memory") {}
  void write(const char c[], int n) override {
    if (position_ + static_cast<std::size_t>(n) > bytes.size()) bytes.resize(position_ + static_cast<std::size_t>(n));
    std::memcpy(bytes.data() + position_, c, static_cast<std::size_t>(n));
    position_ += static_cast<std::size_t>(n);
  }
  uint64_t tellp() override { return position_; }
  void seekp(uint64_t position) override { position_ = position; }

  std::string bytes;

 private:
  std::size_t position_ = 0;
};

}  // namespace

std::string encode_exr(const Image<float>& image, const char* channel) {
  Imf::Header header(image.width, image.height);
  header.compression() = Imf::ZIP_COMPRESSION;
  header.channels().insert(channel, Imf::Channel(Imf::FLOAT));
  Imf::FrameBuffer pixels;
  char* first = const_cast<char*>(reinterpret_cast<const char*>(image.samples.data()));  // OpenEXR only reads it
  pixels.insert(channel, Imf::Slice(Imf::FLOAT, first, sizeof(float), sizeof(float) * static_cast<std::size_t>(image.width)));
  BytesStream stream;
  {
    Imf::OutputFile file(stream, header);  // its destructor writes the offsets table
    file.setFrameBuffer(pixels);
    file.writePixels(image.height);
  }
  return std::move(stream.bytes);
}

}  // namespace ecoview
