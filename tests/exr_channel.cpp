#include "exr_channel.hpp"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>

namespace ecoview::test {

ExrChannel read_exr_channel(const std::filesystem::path& file) {
  Imf::InputFile input(file.c_str());
  const Imf::Header& header = input.header();
  const Imath::Box2i window = header.dataWindow();
  ExrChannel channel;
  channel.width = window.max.x - window.min.x + 1;
  channel.height = window.max.y - window.min.y + 1;
  const Imf::ChannelList& channels = header.channels();
  int count = 0;
  for (auto c = channels.begin(); c != channels.end(); ++c) ++count;
  if (count != 1) return channel;
  channel.name = channels.begin().name();
  channel.is_float = channels.begin().channel().type == Imf::FLOAT;
  channel.samples.resize(static_cast<std::size_t>(channel.width) * static_cast<std::size_t>(channel.height));
  Imf::FrameBuffer pixels;
  // The slice's origin is where pixel (0, 0) would be, so the window's first pixel lands first.
  char* origin = reinterpret_cast<char*>(channel.samples.data()) -
                 (static_cast<std::ptrdiff_t>(window.min.y) * channel.width + window.min.x) * static_cast<std::ptrdiff_t>(sizeof(float));
  pixels.insert(channel.name, Imf::Slice(Imf::FLOAT, origin, sizeof(float), sizeof(float) * static_cast<std::size_t>(channel.width)));
  input.setFrameBuffer(pixels);
  input.readPixels(window.min.y, window.max.y);
  return channel;
}

}  // namespace ecoview::test
