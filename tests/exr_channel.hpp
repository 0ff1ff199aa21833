#pragma once
#include <filesystem>
#include <string>
#include <vector>

// A one-channel OpenEXR file read back with OpenEXR, for the tests of capture --aov-format exr.
namespace ecoview::test {

struct ExrChannel {
  std::string name;             // the file's only channel; empty if it has another number of them
  bool is_float = false;        // 32-bit float samples
  int width = 0, height = 0;
  std::vector<float> samples;   // rows from the top
};

// Throws what OpenEXR throws where the file cannot be read.
ExrChannel read_exr_channel(const std::filesystem::path& file);

}  // namespace ecoview::test
