// Loads libecoview_video.so, the H.264 encoder module (video_encoder.hpp), on first use.
#include "app/capture/video_encoder.hpp"

#include "app/errors.hpp"

#include <dlfcn.h>

namespace ecoview {
namespace {

struct VideoModule {
  decltype(&ecoview_open_h264_mp4) open = nullptr;
  decltype(&ecoview_why_no_h264) why_not = nullptr;
  std::string error;  // why it was not loaded
};

// The module beside the binary, or in the ../lib of a bundle; loaded once and never unloaded.
const VideoModule& video_module() {
  static const VideoModule module = [] {
    VideoModule m;
    std::error_code ec;
    const std::filesystem::path binary_folder = std::filesystem::read_symlink("/proc/self/exe", ec).parent_path();
    void* handle = nullptr;
    for (const std::filesystem::path& file : {binary_folder / "libecoview_video.so", binary_folder / ".." / "lib" / "libecoview_video.so"}) {
      if (!std::filesystem::exists(file, ec)) continue;
      handle = ::dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
      if (handle == nullptr) m.error = ::dlerror();
      break;
    }
    if (handle == nullptr) {
      if (m.error.empty()) m.error = "libecoview_video.so is not beside " + binary_folder.string();
      return m;
    }
    m.open = reinterpret_cast<decltype(m.open)>(::dlsym(handle, "ecoview_open_h264_mp4"));
    m.why_not = reinterpret_cast<decltype(m.why_not)>(::dlsym(handle, "ecoview_why_no_h264"));
    if (m.open == nullptr || m.why_not == nullptr) m.error = "libecoview_video.so is not this build's";
    return m;
  }();
  return module;
}

}  // namespace

std::optional<std::string> why_no_h264() {
  const VideoModule& module = video_module();
  if (!module.error.empty()) return "cannot load the video module: " + module.error + " (build it; FFmpeg's libraries must be installed)";
  if (const char* why = module.why_not()) return std::string(why);
  return std::nullopt;
}

std::unique_ptr<VideoEncoder> open_h264_mp4(const std::filesystem::path& file, int width, int height, double fps) {
  if (const std::optional<std::string> why = why_no_h264()) throw RuntimeFailure(*why);
  return std::unique_ptr<VideoEncoder>(video_module().open(file.c_str(), width, height, fps));
}

}  // namespace ecoview
