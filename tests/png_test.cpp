// Our PNG encoder, read back by stb_image (an independent decoder).
#include "app/capture/png.hpp"

#include <stb/stb_image.h>

#include <gtest/gtest.h>

namespace ecoview {
namespace {

TEST(Png, EightBitRgbDecodesToTheSamePixels) {
  Image8 image{37, 11, 3, {}};
  for (int i = 0; i < 37 * 11 * 3; ++i) image.samples.push_back(static_cast<std::uint8_t>((i * 7919) % 251));
  const std::string png = encode_png(image);
  int w = 0, h = 0, channels = 0;
  unsigned char* decoded = stbi_load_from_memory(reinterpret_cast<const unsigned char*>(png.data()),
                                                 static_cast<int>(png.size()), &w, &h, &channels, 0);
  ASSERT_NE(decoded, nullptr) << stbi_failure_reason();
  EXPECT_EQ(w, 37);
  EXPECT_EQ(h, 11);
  EXPECT_EQ(channels, 3);
  EXPECT_TRUE(std::equal(image.samples.begin(), image.samples.end(), decoded));
  stbi_image_free(decoded);
}

TEST(Png, SixteenBitGrayKeepsEveryBit) {
  Image16 image{300, 2, 1, {}};
  for (int i = 0; i < 600; ++i) image.samples.push_back(static_cast<std::uint16_t>(i * 109 + 1));
  const std::string png = encode_png(image);
  int w = 0, h = 0, channels = 0;
  const auto* bytes = reinterpret_cast<const unsigned char*>(png.data());
  ASSERT_TRUE(stbi_is_16_bit_from_memory(bytes, static_cast<int>(png.size())));
  std::uint16_t* decoded = stbi_load_16_from_memory(bytes, static_cast<int>(png.size()), &w, &h, &channels, 0);
  ASSERT_NE(decoded, nullptr) << stbi_failure_reason();
  EXPECT_EQ(channels, 1);
  EXPECT_TRUE(std::equal(image.samples.begin(), image.samples.end(), decoded));
  stbi_image_free(decoded);
}

}  // namespace
}  // namespace ecoview
