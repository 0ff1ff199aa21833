// What `ecoview capture` writes for other tools: an MP4 of the colour frames (--video), float
// AOVs in OpenEXR (--aov-format exr), and one capture split across processes with GNU parallel.
#include "exr_channel.hpp"
#include "test_support.hpp"
#include "video_frames.hpp"

#include <stb/stb_image.h>

#include <cmath>
#include <cstdlib>
#include <limits>

#include <gtest/gtest.h>

namespace ecoview::test {
namespace {

namespace fs = std::filesystem;

// A 16-bit gray PNG's samples.
std::vector<std::uint16_t> load_png16(const fs::path& file) {
  int width = 0, height = 0, channels = 0;
  std::uint16_t* data = stbi_load_16(file.c_str(), &width, &height, &channels, 1);
  if (data == nullptr) return {};
  std::vector<std::uint16_t> samples(data, data + static_cast<std::ptrdiff_t>(width) * height);
  stbi_image_free(data);
  return samples;
}

double mean_difference(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b) {
  if (a.size() != b.size() || a.empty()) return std::numeric_limits<double>::infinity();
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += std::abs(static_cast<int>(a[i]) - static_cast<int>(b[i]));
  return sum / static_cast<double>(a.size());
}

std::string color_png(int frame) {
  char name[32];
  std::snprintf(name, sizeof name, "color_%05d.png", frame);
  return name;
}

// Each frame of the video is the colour PNG of its frame: nearer to it than to any other frame's
// (the path moves the camera), and near in itself (H.264 at high quality, colour at half size).
void expect_the_frames_of(const VideoFrames& video, const fs::path& out, int frames) {
  ASSERT_EQ(static_cast<int>(video.rgb.size()), frames);
  for (int i = 0; i < frames; ++i) {
    double nearest = std::numeric_limits<double>::infinity();
    int nearest_frame = -1;
    for (int j = 0; j < frames; ++j) {
      const double difference = mean_difference(video.rgb[static_cast<std::size_t>(i)], test::load_png(out / color_png(j), 3).samples);
      if (difference < nearest) nearest = difference, nearest_frame = j;
    }
    EXPECT_EQ(nearest_frame, i) << "video frame " << i;
    EXPECT_LT(nearest, 6.0) << "video frame " << i << ": mean difference to its PNG, of 255";
  }
}

const std::vector<std::string> courtyard_path = {"capture", "--scene", "courtyard", "--path", "courtyard", "--fps", "4",
                                                 "--size", "160x90"};

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

TEST(CaptureVideo, TheMp4HoldsEveryFrameAtTheAskedSizeAndRate) {
  const TempDir dir;
  const fs::path video = dir / "flight.mp4";
  const CommandResult r = run_ecoview(with(courtyard_path, {"--frames", "0:5", "--video", video.string(), "--out", (dir / "out").string()}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const VideoFrames frames = read_video_frames(video);
  ASSERT_TRUE(frames.error.empty()) << frames.error;
  EXPECT_EQ(frames.codec, "h264");
  EXPECT_EQ(frames.width, 160);
  EXPECT_EQ(frames.height, 90);
  EXPECT_EQ(frames.rate_num, 4 * frames.rate_den) << frames.rate_num << "/" << frames.rate_den;
  expect_the_frames_of(frames, dir / "out", 5);
  EXPECT_EQ(files_in(dir.path()), (std::vector<std::string>{"flight.mp4", "out"})) << "a temporary file stayed";
}

// Frames a resumed capture skips are read back from their PNGs: the video is the one a single run
// made; and it is made again from frames all there.
TEST(CaptureVideo, AResumedCaptureGivesTheVideoOfAllItsFrames) {
  const TempDir dir;
  const fs::path out = dir / "out", video = dir / "flight.mp4";
  const std::vector<std::string> args = with(courtyard_path, {"--frames", "0:4", "--video", video.string(), "--out", out.string()});
  ASSERT_EQ(run_ecoview(args).exit_code, 0);
  const std::string whole = read_bytes(video);
  fs::remove(video);
  fs::remove(out / color_png(1));
  fs::remove(out / color_png(3));
  const CommandResult resumed = run_ecoview(args);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.out.find("wrote 2 frame(s)"), std::string::npos) << resumed.out;
  const VideoFrames frames = read_video_frames(video);
  expect_the_frames_of(frames, out, 4);
  EXPECT_TRUE(read_bytes(video) == whole) << "the resumed video differs from the whole run's";

  fs::remove(video);
  const CommandResult complete = run_ecoview(args);
  ASSERT_EQ(complete.exit_code, 0) << complete.err;
  EXPECT_NE(complete.out.find("all 4 frames already"), std::string::npos) << complete.out;
  EXPECT_TRUE(read_bytes(video) == whole) << "the video made from frames all there differs from the whole run's";
}

// A video is one size: frames a capture would skip that have another are refused before anything renders.
TEST(CaptureVideo, SkippedFramesOfAnotherSizeAreRefusedBeforeRendering) {
  const TempDir dir;
  const fs::path out = dir / "out";
  ASSERT_EQ(run_ecoview(with(courtyard_path, {"--frames", "0:2", "--out", out.string()})).exit_code, 0);
  fs::remove(out / color_png(1));
  const CommandResult r = run_ecoview({"capture", "--scene", "courtyard", "--path", "courtyard", "--fps", "4", "--size", "64x36",
                                       "--frames", "0:2", "--video", (dir / "v.mp4").string(), "--out", out.string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("color_00000.png is 160x90, not --size 64x36"), std::string::npos) << r.err;
  EXPECT_EQ(files_in(out), std::vector<std::string>{color_png(0)});
  EXPECT_FALSE(fs::exists(dir / "v.mp4"));
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
  const CommandResult again = run_ecoview(with(args, {"--aov-format", "exr", "--out", (dir / "exr").string()}));
  EXPECT_NE(again.out.find("all 1 frames already"), std::string::npos) << "the EXRs were not taken as finished: " << again.out;

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
    const test::PngImage png = test::load_png(dir / "png" / (std::string(aov) + "_00000.png"), 1);
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

// The README's recipe for a capture split across jobs, small and on a light scene: GNU parallel runs
// one capture per frame range into one --out; the frames are the bytes one serial capture writes
// (the PSM takes its near plane from the frame before: Renderer::start_after).
TEST(CaptureSplit, ParallelJobsIntoOneFolderWriteTheFramesOfOneSerialCapture) {
  if (run_shell("command -v parallel").exit_code != 0) GTEST_SKIP() << "GNU parallel is not on PATH";
  const TempDir dir;
  const std::string options = "--scene courtyard --path courtyard --method psm --fps 5 --size 160x90 --aov color,shadow";
  const CommandResult serial = run_shell("ecoview capture " + options + " --frames 0:6 --out " + shell_quote((dir / "serial").string()));
  ASSERT_EQ(serial.exit_code, 0) << serial.err;
  const CommandResult split = run_shell("parallel --will-cite -j3 \"$ecoview_binary\" capture " + options + " --out " +
                                        shell_quote((dir / "split").string()) + " --frames {} ::: 0:2 2:4 4:6");
  ASSERT_EQ(split.exit_code, 0) << split.err;
  const std::vector<std::string> files = files_in(dir / "serial");
  ASSERT_EQ(files.size(), 12u);
  ASSERT_EQ(files_in(dir / "split"), files);
  for (const std::string& file : files) EXPECT_TRUE(read_bytes(dir / "split" / file) == read_bytes(dir / "serial" / file)) << file;
}

}  // namespace
}  // namespace ecoview::test
