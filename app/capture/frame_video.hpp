#pragma once
#include "app/cli/options.hpp"

#include <glm/vec2.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace ecoview {

// `capture --video`: the capture's colour frames as one MP4 (VideoFile), read back from their
// color PNGs in --out in frame order. Frames rendered now and frames a resumed capture skipped
// are read alike, so a resumed capture's video is the one a single run makes.

// Checks --video before any work (InputError naming it): an .mp4 name that can be written, an
// even frame size, and the color AOV among those captured (the PNGs the video is read from).
void check_video_option(const std::string& file, const std::string& out, glm::ivec2 size, bool captures_color);

// Checks the color PNGs of the frames in `frames` that this run does not render (not in
// `rendered`): each is a PNG of the frame size, else InputError naming it, before any work.
void check_skipped_frames(const std::filesystem::path& out, FrameRange frames, const std::vector<int>& rendered,
                          glm::ivec2 size);

// Writes the video of frames `frames` from their color PNGs in `out`.
void write_frame_video(const std::string& file, const std::filesystem::path& out, FrameRange frames, glm::ivec2 size,
                       double fps);

}  // namespace ecoview
