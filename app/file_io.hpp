#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace ecoview {

// The bytes of a regular file, or nothing if there is none or it cannot be read.
std::optional<std::string> read_file(const std::filesystem::path& path);

// Writes to a temporary name beside `path` and renames it into place, so `path` is either absent
// or complete. Throws RuntimeFailure naming the file.
void write_file_atomically(const std::filesystem::path& path, std::string_view bytes);

}  // namespace ecoview
