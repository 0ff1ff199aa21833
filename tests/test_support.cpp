#include "test_support.hpp"

#include <stb/stb_image.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace ecoview::test {

PngImage load_png(const std::filesystem::path& file, int channels) {
  PngImage image;
  int in_file = 0;
  unsigned char* data = stbi_load(file.c_str(), &image.width, &image.height, &in_file, channels);
  if (data == nullptr) return {};
  image.samples.assign(data, data + static_cast<std::ptrdiff_t>(image.width) * image.height * channels);
  stbi_image_free(data);
  return image;
}

std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

TempDir::TempDir() {
  std::string pattern = (std::filesystem::temp_directory_path() / "ecoview_test_XXXXXX").string();
  if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
  path_ = pattern;
}

TempDir::~TempDir() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> files_in(const std::filesystem::path& folder) {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

CommandResult run_ecoview(const std::vector<std::string>& args) {
  std::string command = "ecoview";
  for (const std::string& a : args) command.append(" ").append(shell_quote(a));
  return run_shell(command);
}

CommandResult run_shell(const std::string& script) {
  const TempDir streams;
  const std::string command = "ecoview_binary=" + shell_quote(ECOVIEW_BINARY) + "\necoview() { \"$ecoview_binary\" \"$@\"; }\n(" +
                              script + ") >" +
                              shell_quote((streams / "out").string()) + " 2>" + shell_quote((streams / "err").string());
  const int status = std::system(command.c_str());
  CommandResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = read_bytes(streams / "out");
  result.err = read_bytes(streams / "err");
  return result;
}

std::string plant_grid_json(const std::string& species, int count, int per_row, float x0, float dx, float z0, float dz) {
  std::ostringstream s;
  s << R"({"type": "plant", "species": ")" << species << R"(", "positions": [)";
  for (int i = 0; i < count; ++i) {
    s << (i ? ", " : "") << "[" << x0 + static_cast<float>(i % per_row) * dx << ", 0, " << z0 + static_cast<float>(i / per_row) * dz << "]";
  }
  s << "]}";
  return s.str();
}

std::filesystem::path source_dir() { return ECOVIEW_SOURCE_DIR; }
std::filesystem::path shared_testdata_dir() { return source_dir().parent_path() / "shared" / "testdata"; }

}  // namespace ecoview::test
