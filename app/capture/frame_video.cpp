#include "app/capture/frame_video.hpp"

#include "app/capture/aov.hpp"
#include "app/capture/png.hpp"
#include "app/capture/video_encoder.hpp"
#include "app/errors.hpp"
#include "app/file_io.hpp"

#include <algorithm>
#include <cctype>

namespace ecoview {
namespace {

std::string size_text(glm::ivec2 size) { return std::to_string(size.x) + "x" + std::to_string(size.y); }

bool has_mp4_extension(const std::string& file) {
  std::string extension = std::filesystem::path(file).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
  return extension == ".mp4";
}

}  // namespace

void check_video_option(const std::string& file, const std::string& out, glm::ivec2 size, bool captures_color) {
  if (file.empty()) return;
  if (!has_mp4_extension(file)) throw InputError("--video: writes H.264 in MP4; name the file FILE.mp4, got '" + file + "'");
  check_output_file("--video", file, out);
  if (size.x % 2 || size.y % 2) {
    throw InputError("--video: H.264 (4:2:0) needs an even width and height, got --size " + size_text(size));
  }
  if (!captures_color) {
    throw InputError("--video: is made from the color PNGs; add color to --aov (a resumed capture reads them back)");
  }
  if (const std::optional<std::string> why = why_no_h264()) throw RuntimeFailure("--video: " + *why);
}

void check_skipped_frames(const std::filesystem::path& out, FrameRange frames, const std::vector<int>& rendered,
                          glm::ivec2 size) {
  for (int frame = frames.begin; frame < frames.end; ++frame) {
    if (std::binary_search(rendered.begin(), rendered.end(), frame)) continue;
    const std::filesystem::path png = aov_file(out, Aov::color, frame);
    const std::optional<glm::ivec2> found = read_png_size(png);
    if (!found) throw InputError("--video: " + png.string() + " is no PNG that can be read; remove it to render it again");
    if (*found != size) {
      throw InputError("--video: " + png.string() + " is " + size_text(*found) + ", not --size " + size_text(size) +
                       "; capture with its size, or --force");
    }
  }
}

void write_frame_video(const std::string& file, const std::filesystem::path& out, FrameRange frames, glm::ivec2 size,
                       double fps) {
  FileInProgress video(file);
  try {
    const std::unique_ptr<VideoEncoder> encoder = open_h264_mp4(video.temporary(), size.x, size.y, fps);
    for (int frame = frames.begin; frame < frames.end; ++frame) {
      const std::filesystem::path png = aov_file(out, Aov::color, frame);
      const std::optional<Image8> color = read_png_rgb(png);
      if (!color || color->width != size.x || color->height != size.y) {
        throw RuntimeFailure(png.string() + " changed while the capture ran; capture again");
      }
      encoder->add(*color);
    }
    encoder->finish();
  } catch (const RuntimeFailure& e) {
    throw RuntimeFailure("--video: " + file + ": " + e.what());
  }
  video.finish();
}

}  // namespace ecoview
