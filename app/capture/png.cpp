// A PNG encoder for both sample sizes (stb_image_write has no 16-bit output); stb does the deflate.
#include "app/capture/png.hpp"

#include <stb/stb_image.h>

#include <array>
#include <cstdlib>
#include <stdexcept>

// Exported by Debian's libstb but not declared in stb_image_write.h.
extern "C" unsigned char* stbi_zlib_compress(unsigned char* data, int data_len, int* out_len, int quality);

namespace ecoview {
namespace {

std::uint32_t crc32(const std::string& bytes, std::size_t begin) {
  static const std::array<std::uint32_t, 256> table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t n = 0; n < 256; ++n) {
      std::uint32_t c = n;
      for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[n] = c;
    }
    return t;
  }();
  std::uint32_t c = 0xFFFFFFFFu;
  for (std::size_t i = begin; i < bytes.size(); ++i) c = table[(c ^ static_cast<unsigned char>(bytes[i])) & 0xFF] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

void put32(std::string& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<char>((v >> shift) & 0xFF));
}

void put_chunk(std::string& out, const char* type, const std::string& data) {
  put32(out, static_cast<std::uint32_t>(data.size()));
  const std::size_t start = out.size();
  out += type;
  out += data;
  put32(out, crc32(out, start));
}

// `rows`: height rows of `row_bytes` big-endian sample bytes, top row first.
std::string encode(int width, int height, int channels, int bit_depth, const std::string& rows) {
  const std::size_t row_bytes = rows.size() / static_cast<std::size_t>(height);
  // Each row gets the "Up" filter (difference to the row above), which suits smooth renders.
  std::string filtered;
  filtered.reserve(rows.size() + static_cast<std::size_t>(height));
  for (std::size_t y = 0; y < static_cast<std::size_t>(height); ++y) {
    filtered.push_back(y == 0 ? 0 : 2);
    for (std::size_t i = 0; i < row_bytes; ++i) {
      const auto above = y == 0 ? 0 : static_cast<unsigned char>(rows[(y - 1) * row_bytes + i]);
      filtered.push_back(static_cast<char>(static_cast<unsigned char>(rows[y * row_bytes + i]) - above));
    }
  }
  int compressed_size = 0;
  unsigned char* compressed = stbi_zlib_compress(reinterpret_cast<unsigned char*>(filtered.data()),
                                                 static_cast<int>(filtered.size()), &compressed_size, 6);
  if (compressed == nullptr) throw std::bad_alloc();
  const std::string idat(reinterpret_cast<const char*>(compressed), static_cast<std::size_t>(compressed_size));
  std::free(compressed);

  std::string header;
  put32(header, static_cast<std::uint32_t>(width));
  put32(header, static_cast<std::uint32_t>(height));
  header.push_back(static_cast<char>(bit_depth));
  header.push_back(static_cast<char>(channels == 3 ? 2 : channels == 4 ? 6 : 0));  // colour type
  header += std::string(3, '\0');  // deflate, adaptive filtering, no interlace

  std::string png = "\x89PNG\r\n\x1a\n";
  put_chunk(png, "IHDR", header);
  put_chunk(png, "IDAT", idat);
  put_chunk(png, "IEND", "");
  return png;
}

}  // namespace

std::string encode_png(const Image8& image) {
  return encode(image.width, image.height, image.channels, 8,
                std::string(image.samples.begin(), image.samples.end()));
}

std::string encode_png(const Image16& image) {
  std::string rows;
  rows.reserve(image.samples.size() * 2);
  for (std::uint16_t v : image.samples) {
    rows.push_back(static_cast<char>(v >> 8));
    rows.push_back(static_cast<char>(v & 0xFF));
  }
  return encode(image.width, image.height, image.channels, 16, rows);
}

std::optional<Image8> read_png_rgb(const std::filesystem::path& file) {
  Image8 image{0, 0, 3, {}};
  int channels = 0;
  unsigned char* pixels = stbi_load(file.c_str(), &image.width, &image.height, &channels, 3);
  if (pixels == nullptr) return std::nullopt;
  image.samples.assign(pixels, pixels + static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 3);
  stbi_image_free(pixels);
  return image;
}

std::optional<glm::ivec2> read_png_size(const std::filesystem::path& file) {
  glm::ivec2 size;
  int channels = 0;
  if (!stbi_info(file.c_str(), &size.x, &size.y, &channels)) return std::nullopt;
  return size;
}

}  // namespace ecoview
