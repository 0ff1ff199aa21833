#pragma once
#include <stdexcept>
#include <string>

namespace pointgen {

// A file that cannot be used as asked: missing, unreadable, malformed. `what()` names the file.
class FileError : public std::runtime_error {
 public:
  FileError(const std::string& file, const std::string& problem) : std::runtime_error(file + ": " + problem) {}
};

}  // namespace pointgen
