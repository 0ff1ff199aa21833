#pragma once
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace pointgen {

// The most bytes ecoview reads from one input file: 2^31 - 1, what stb_image and tinygltf take in
// one piece (their sizes are int and unsigned int).
constexpr std::uint64_t max_input_file_bytes = 0x7fffffff;

// The bytes of the regular file at `path`, or nothing when there is none. Throws FileError naming
// it when it is there but is no regular file (a folder, a device such as /dev/zero, a pipe), is
// larger than max_input_file_bytes or cannot be read. Reads no more than the size it found, so a
// file that grows meanwhile cannot make it read on.
std::optional<std::string> read_input_file(const std::filesystem::path& path);

}  // namespace pointgen
