#pragma once
#include "app/render/image.hpp"

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

namespace ecoview {

// Writes a video file from 8-bit RGB frames of one size, fed in order at a constant rate.
// Throws RuntimeFailure saying what failed (not naming the file: its caller knows the name).
class VideoEncoder {
 public:
  virtual ~VideoEncoder() = default;
  virtual void add(const Image8& rgb) = 0;
  // Ends the file; it is complete once this returns.
  virtual void finish() = 0;
};

// An encoder writing H.264 (4:2:0, BT.709) in MP4 to `file`; width and height must be even.
// FFmpeg's libraries and theirs come to well over 100 MiB, more than the GPU bundle
// (scripts/gpu_bundle.sh) carries, so the encoder is a module, libecoview_video.so, loaded from
// beside the binary (or ../lib) when a video is asked for. Throws RuntimeFailure where it cannot be
// loaded.
std::unique_ptr<VideoEncoder> open_h264_mp4(const std::filesystem::path& file, int width, int height, double fps);

// Why no H.264 video can be written here (the module or its encoder missing); nothing if it can.
std::optional<std::string> why_no_h264();

}  // namespace ecoview

// The module's entry points (h264_mp4_file.cpp), looked up by these names.
extern "C" {
// A new encoder, for the caller to delete.
ecoview::VideoEncoder* ecoview_open_h264_mp4(const char* file, int width, int height, double fps);
// Why this FFmpeg cannot encode H.264, or null where it can.
const char* ecoview_why_no_h264();
}
