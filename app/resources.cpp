#include "app/resources.hpp"

#include "embedded_files.hpp"

#include <algorithm>

namespace ecoview::resources {

std::optional<std::string_view> find(std::string_view path) {
  for (const embedded::File& file : embedded::files()) {
    if (file.path == path) return file.bytes;
  }
  return std::nullopt;
}

std::vector<std::string> names_in(std::string_view folder, std::string_view ext) {
  std::vector<std::string> names;
  for (const embedded::File& file : embedded::files()) {
    const std::string_view p = file.path;
    if (p.size() > folder.size() + ext.size() && p.substr(0, folder.size()) == folder &&
        p[folder.size()] == '/' && p.substr(p.size() - ext.size()) == ext &&
        p.find('/', folder.size() + 1) == std::string_view::npos) {
      names.emplace_back(p.substr(folder.size() + 1, p.size() - folder.size() - 1 - ext.size()));
    }
  }
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace ecoview::resources
