// What `ecoview capture` writes for other tools: float AOVs in OpenEXR (--aov-format exr).
#include "exr_channel.hpp"
#include "test_support.hpp"

#include <stb/stb_image.h>

#include <cmath>
#include <cstdlib>

#include <gtest/gtest.h>

namespace ecoview::test {
namespace {

namespace fs = std::filesystem;

struct Png {
  int width = 0, height = 0;
  std::vector<unsigned char> samples;
};

// A PNG's pixels with `channels` 8-bit samples each.
Png load_png(const fs::path& file, int channels) {
  Png png;
  int in_file = 0;
  unsigned char* data = stbi_load(file.c_str(), &png.width, &png.height, &in_file, channels);
  if (data == nullptr) return png;
  png.samples.assign(data, data + static_cast<std::ptrdiff_t>(png.width) * png.height * channels);
  stbi_image_free(data);
  return png;
}

// A 16-bit gray PNG's samples.
std::vector<std::uint16_t> load_png16(const fs::path& file) {
  int width = 0, height = 0, channels = 0;
  std::uint16_t* data = stbi_load_16(file.c_str(), &width, &height, &channels, 1);
  if (data == nullptr) return {};
  std::vector<std::uint16_t> samples(data, data + static_cast<std::ptrdiff_t>(width) * height);
  stbi_image_free(data);
  return samples;
}

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

// Seen from straight above, the ground is 10 m away in every pixel that sees it and a 2 m box's top
// 8 m; the frame's edges see the sky. The EXRs hold what the PNGs quantise.
TEST(CaptureExr, FloatAovsHoldWhatThePngsQuantise) {
  const TempDir dir;
  const float far = 40.0f;
  write_text(dir / "above.json", R"({"camera": {"position": [0, 10, 0], "target": [0, 0, 0], "up": [0, 0, -1], "fov_y_deg": 50,
      "near": 0.1, "far": 40},
    "lights": [{"type": "directional", "direction": [0.5, -1, 0.3]}],
    "objects": [{"type": "plane", "center": [0, 0, 0], "size": [8, 8]}, {"type": "box", "min": [-1, 0, -1], "max": [1, 2, 1]}]})");
  const std::vector<std::string> args = {"capture", "--scene", (dir / "above.json").string(), "--size", "160x90",
                                         "--aov", "color,depth,shadow,reference"};
  ASSERT_EQ(run_ecoview(with(args, {"--out", (dir / "png").string()})).exit_code, 0);
  const CommandResult r = run_ecoview(with(args, {"--aov-format", "exr", "--out", (dir / "exr").string()}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(files_in(dir / "exr"),
            (std::vector<std::string>{"color_00000.png", "depth_00000.exr", "reference_00000.exr", "shadow_00000.exr"}));
  EXPECT_TRUE(read_bytes(dir / "exr" / "color_00000.png") == read_bytes(dir / "png" / "color_00000.png"));

  const ExrChannel depth = read_exr_channel(dir / "exr" / "depth_00000.exr");
  const std::vector<std::uint16_t> depth_png = load_png16(dir / "png" / "depth_00000.png");
  ASSERT_EQ(depth.name, "Z");
  ASSERT_TRUE(depth.is_float);
  ASSERT_EQ(depth.width, 160);
  ASSERT_EQ(depth.height, 90);
  ASSERT_EQ(depth.samples.size(), depth_png.size());
  const float step = far / 65534.0f;
  int sky = 0, ground = 0, box_top = 0;
  for (std::size_t i = 0; i < depth.samples.size(); ++i) {
    const float d = depth.samples[i];
    if (depth_png[i] == 65535) {
      ASSERT_TRUE(std::isinf(d) && d > 0) << "pixel " << i << ": no surface in the PNG, " << d << " in the EXR";
      ++sky;
      continue;
    }
    ASSERT_NEAR(d, static_cast<float>(depth_png[i]) * step, step) << "pixel " << i;
    ASSERT_GT(d, 8.0f - 1e-3f) << "pixel " << i << ": nearer than the box's top";
    ASSERT_LT(d, 10.0f + 1e-3f) << "pixel " << i << ": beyond the ground";
    ground += std::abs(d - 10.0f) < 1e-3f;
    box_top += std::abs(d - 8.0f) < 1e-3f;
  }
  EXPECT_GT(sky, 160 * 90 / 10);
  EXPECT_GT(ground, 160 * 90 / 10);
  EXPECT_GT(box_top, 100);

  for (const char* aov : {"shadow", "reference"}) {
    const ExrChannel visibility = read_exr_channel(dir / "exr" / (std::string(aov) + "_00000.exr"));
    const Png png = load_png(dir / "png" / (std::string(aov) + "_00000.png"), 1);
    ASSERT_EQ(visibility.name, "Y") << aov;
    ASSERT_TRUE(visibility.is_float) << aov;
    ASSERT_EQ(visibility.samples.size(), png.samples.size()) << aov;
    int shadowed = 0;
    for (std::size_t i = 0; i < png.samples.size(); ++i) {
      ASSERT_NEAR(visibility.samples[i], png.samples[i] / 255.0f, 0.5f / 255.0f) << aov << " pixel " << i;
      shadowed += visibility.samples[i] < 0.5f;
    }
    EXPECT_GT(shadowed, 100) << aov << ": the box casts no shadow";
  }
}

}  // namespace
}  // namespace ecoview::test
