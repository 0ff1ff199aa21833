#pragma once
#include <filesystem>
#include <string>
#include <vector>

// A video file read back with FFmpeg's libavformat and libavcodec, for the tests of capture --video.
namespace ecoview::test {

struct VideoFrames {
  std::string codec;                // the video stream's codec, e.g. "h264"
  int width = 0, height = 0;
  int rate_num = 0, rate_den = 1;   // the stream's average frame rate
  std::vector<std::vector<unsigned char>> rgb;  // each decoded frame as 8-bit RGB, rows from the top
  std::string error;                // why the file could not be read; empty if it was
};

VideoFrames read_video_frames(const std::filesystem::path& file);

}  // namespace ecoview::test
